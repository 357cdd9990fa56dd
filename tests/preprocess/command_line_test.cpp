// isosid-prep's command line: flags it cannot all honour are refused in one line (exit 2)
// before any work, never some of them dropped; an output that is no regular file is refused
// before the work too; --version; the reduction's steps in its progress; its memory checks.
#include "preprocess/other_preparation.hpp"
#include "support/run_program.hpp"
#include "support/scene_text.hpp"
#include "support/one_line_exit.hpp"

#include <catch2/catch.hpp>
#include <algorithm>
#include <filesystem>
#include <fstream>
#include <iterator>
#include <sys/stat.h>
#include <sys/wait.h>
#include <unistd.h>

using namespace isosid;
using Catch::Matchers::Contains;

namespace {
const std::string kPrep = ISOSID_PREP_EXE;
const std::string kSphere = std::string(ISOSID_GOLDEN_DIR) + "/sphere_small.model.toml";  // no [refinement.hierarchical]
const std::string kThbSphere = std::string(ISOSID_MODELS_DIR) + "/sphere_axisym_thb.model.toml";
}  // namespace

TEST_CASE("isosid-prep refuses flags that exclude each other, one line each", "[prep][command-line]") {
  const test::ScratchDir dir("prep-flags");
  struct Case {
    std::string arguments, expected;
  };
  const std::vector<Case> cases = {
      {"--modes 6 " + kSphere, "--modes: reports only; it writes no SID (drop -o)"},
      {"--modes 6 --coarse " + kThbSphere, "--modes: reports only; it writes no SID (drop -o)"},
      {"--coarse --refine-at contact:0.05 --refine-width 0.5e-3 " + kThbSphere, "--coarse: and --refine-at exclude each other"},
      {"--coarse " + kSphere, "--coarse: the model has no [refinement.hierarchical]"}};
  for (const Case& c : cases) {
    INFO(c.arguments);
    const auto r = test::run_program(kPrep + " -q " + c.arguments + " -o " + dir.path("x.sid.h5"));
    test::check_one_line_exit(r, 2, c.expected);
    CHECK_FALSE(std::filesystem::exists(dir.path("x.sid.h5")));
  }
  // --modes alone reports, as before
  CHECK(test::run_program(kPrep + " -q --json --modes 6 " + kSphere).exit_status == 0);
}

TEST_CASE("isosid-prep -o onto a FIFO or a folder is refused before the work and leaves it", "[prep][command-line]") {
  const test::ScratchDir dir("prep-special-output");
  REQUIRE(::mkfifo(dir.path("fifo").c_str(), 0600) == 0);
  std::filesystem::create_directory(dir.path("folder"));
  for (const char* name : {"fifo", "folder"}) {
    INFO(name);
    const auto r = test::run_program(kPrep + " " + kSphere + " -o " + dir.path(name));
    // one line: no progress, the refusal comes first
    test::check_one_line_exit(r, 2, "not a file; an output replaces only a regular file");
  }
  CHECK(std::filesystem::is_fifo(dir.path("fifo")));
  CHECK(std::filesystem::is_directory(dir.path("folder")));
}

TEST_CASE("isosid-prep --check reads and checks a model and writes nothing", "[prep][command-line]") {
  const test::ScratchDir dir("prep-check");
  std::filesystem::copy_file(kSphere, dir.path("s.model.toml"));
  const auto valid = test::run_program(kPrep + " --check " + dir.path("s.model.toml"));
  CHECK(valid.exit_status == 0);
  CHECK(valid.err.empty());
  CHECK(std::distance(std::filesystem::directory_iterator(dir.path("")), std::filesystem::directory_iterator()) == 1);
  std::ofstream(dir.path("s.model.toml"), std::ios::app) << "\n[damping]\nkappa = -1.0\n";  // a second [damping] or a bad value
  test::check_one_line_exit(test::run_program(kPrep + " --check " + dir.path("s.model.toml")), 2, "s.model.toml");
  test::check_one_line_exit(test::run_program(kPrep + " --check --modes 4 " + kSphere), 2, "--check: builds nothing: drop --modes");
  test::check_one_line_exit(test::run_program(kPrep + " --check " + kSphere + " -o " + dir.path("x.sid.h5")), 2, "--check: builds nothing: drop -o");
}

TEST_CASE("isosid-prep prints the project's version", "[prep][command-line]") {
  const auto r = test::run_program(kPrep + " --version");
  CHECK(r.exit_status == 0);
  CHECK_THAT(r.out, Catch::Matchers::StartsWith(std::string("isosid-prep ") + ISOSID_VERSION));
}

TEST_CASE("isosid-prep refuses a model above its memory limit before the stage, with the estimate", "[prep][command-line]") {
  const test::ScratchDir dir("prep-memory");
  // the small sphere's stiffness factor (78 DOFs) needs tens of kB: a limit of 1 kB refuses it before the
  // assembly, from the stiffness's pattern, in one line naming the model file, the part of it that
  // sets the size, and the estimate against the limit (the assembly's own estimate and the
  // factorization's at its stage: reduction_test)
  const auto r = test::run_program(kPrep + " -q --memory-limit 1e-6 " + kSphere + " -o " + dir.path("x.sid.h5"));
  CHECK(r.exit_status == 2);
  CHECK_THAT(r.err, Contains(kSphere + ": refinement: the stiffness's factorization of"));
  CHECK_THAT(r.err, Contains("GiB, more than the 1e-06 GiB of --memory-limit"));
  CHECK(std::count(r.err.begin(), r.err.end(), '\n') == 1);
  CHECK_FALSE(std::filesystem::exists(dir.path("x.sid.h5")));
  // the modal report too, and a limit above the estimate changes nothing
  CHECK(test::run_program(kPrep + " -q --memory-limit 1e-6 --modes 6 " + kSphere).exit_status == 2);
  CHECK(test::run_program(kPrep + " -q --memory-limit 8 " + kSphere + " -o " + dir.path("x.sid.h5")).exit_status == 0);
}

TEST_CASE("isosid-prep waits for the memory another preparation on the machine is about to take, and starts once it ends", "[prep][command-line]") {
  const test::ScratchDir dir("prep-ledger");
  const std::string folder = dir.path("ledger");
  // another preparation whose stage will take 1 PB more, ending once isosid-prep waits, as a
  // killed one would: its file stays, and the ledger finds it ended
  const pid_t child = test::fork_other_preparation(folder, 1e15, test::OtherEnds::WhenAnotherWaits);
  const auto r = test::run_program("ISOSID_MEMORY_LEDGER=" + folder + " " + kPrep + " " + kSphere + " -o " + dir.path("x.sid.h5"));
  ::waitpid(child, nullptr, 0);
  CHECK(r.exit_status == 0);
  CHECK_THAT(r.err, Contains("waiting for memory: the stiffness's factorization of"));
  CHECK_THAT(r.err, Contains("1 other preparation(s) running on this machine will take"));
  CHECK(std::filesystem::exists(dir.path("x.sid.h5")));
  CHECK(std::distance(std::filesystem::directory_iterator(folder), std::filesystem::directory_iterator()) == 1);  // the lock file alone
}

TEST_CASE("isosid-prep names the reduction's steps in its progress, one line per kind of step in a log", "[prep][command-line]") {
  const test::ScratchDir dir("prep-steps");
  // the golden beam as a MacNeal model: the stiffness's one factorization, the eigen solve on it, the
  // boundary's statics and its blocks
  std::ifstream in(std::string(ISOSID_GOLDEN_DIR) + "/beam_small.model.toml");
  const std::string golden((std::istreambuf_iterator<char>(in)), std::istreambuf_iterator<char>());
  std::ofstream(dir.path("beam.model.toml"))
      << test::replace(golden, "method = \"modal\"\nnormal_modes = 6", "method = \"macneal\"\nnormal_modes = 6\nboundary_surface = \"contact\"");
  const auto r = test::run_program(kPrep + " " + dir.path("beam.model.toml") + " -o " + dir.path("beam.sid.h5"));  // stderr is no terminal
  REQUIRE(r.exit_status == 0);
  CHECK_THAT(r.err, Contains("macneal reduction ... factorizing the stiffness ("));
  CHECK_THAT(r.err, Contains("macneal reduction ... eigen solve: block Lanczos, "));
  CHECK(r.err.find("sigma") == std::string::npos);  // no second factorization for the eigen solve
  CHECK_THAT(r.err, Contains("macneal reduction ... boundary statics: unit loads 1-"));
  // a log gets the Lanczos count once for so short a solve, not a line per solve
  std::size_t lanczos = 0;
  for (std::size_t at = r.err.find("Lanczos"); at != std::string::npos; at = r.err.find("Lanczos", at + 1)) ++lanczos;
  CHECK(lanczos <= 2);
}

namespace {
/// The kernel set OpenBLAS reported last on stderr ("Core: ..." under OPENBLAS_VERBOSE=2,
/// printed at each load: before and after isosid-prep reruns itself), empty without one.
std::string last_openblas_core(const std::string& err) {
  const auto at = err.rfind("Core: ");
  if (at == std::string::npos) return "";
  return err.substr(at + 6, err.find('\n', at) - at - 6);
}
}  // namespace

TEST_CASE("isosid-prep runs OpenBLAS's kernels for this CPU, not its fallback, unless the user chose one", "[prep][command-line]") {
  // Debian 12's OpenBLAS falls back to its SSE3 (Prescott) kernels on CPUs newer than its
  // release, 2.4x slower in the factorizations
  const auto chosen = test::run_program("env -u OPENBLAS_CORETYPE OPENBLAS_VERBOSE=2 " + kPrep + " --version");
  REQUIRE(chosen.exit_status == 0);
  CHECK_THAT(chosen.out, Catch::Matchers::StartsWith("isosid-prep "));
  const std::string core = last_openblas_core(chosen.err);
  if (core.empty()) {
    WARN("the BLAS is not a DYNAMIC_ARCH OpenBLAS: nothing to choose");
    return;
  }
  __builtin_cpu_init();
  if (__builtin_cpu_supports("avx2") && __builtin_cpu_supports("fma")) CHECK(core != "Prescott");
  const auto user = test::run_program("OPENBLAS_CORETYPE=Prescott OPENBLAS_VERBOSE=2 " + kPrep + " --version");
  CHECK(user.exit_status == 0);
  CHECK(last_openblas_core(user.err) == "Prescott");
}
