// isosid-run's results folder as a user meets it: -o that is no folder, or that holds an input
// the run would replace, is refused in one line before any work; a folder another run writes
// is refused naming that run; a rerun leaves nothing of the earlier run; a run that fails
// before its first sample still ends with one "failed:" line and exit 1. Also --version.
#include "scene_runner.hpp"
#include "support/impact_scene.hpp"

#include <catch2/catch.hpp>
#include <algorithm>
#include <fcntl.h>
#include <filesystem>
#include <fstream>
#include <iterator>
#include <nlohmann/json.hpp>
#include <sys/file.h>
#include <sys/stat.h>
#include <unistd.h>

using namespace isosid;
using Catch::Matchers::Contains;
namespace fs = std::filesystem;

namespace {
const std::string kGolden = ISOSID_GOLDEN_DIR;

/// A short impact of the golden sphere; `sid` relative to the scene or absolute.
std::string impact_scene(const std::string& sid) {
  return test::replace(test::golden_impact_scene(sid), "end_time = 100e-6", "end_time = 20e-6");
}

test::ProgramResult run(const std::string& scene, const std::string& out) {
  return test::run_program(std::string(ISOSID_RUN_EXE) + " -q " + scene + " -o " + out);
}

std::string text_of(const std::string& path) {
  std::ifstream in(path);
  return {std::istreambuf_iterator<char>(in), {}};
}

int lines(const std::string& text) { return int(std::count(text.begin(), text.end(), '\n')); }
}  // namespace

TEST_CASE("isosid-run -o onto a file or a FIFO: exit 2, one line, before any work", "[runtime][results-folder]") {
  const test::ScratchDir dir("run-output-kind");
  std::ofstream(dir.path("s.scene.toml")) << impact_scene(kGolden + "/sphere_small.sid.h5");
  std::ofstream(dir.path("regfile")) << "x";
  REQUIRE(::mkfifo(dir.path("fifo").c_str(), 0600) == 0);
  const std::vector<std::pair<std::string, std::string>> cases = {
      {dir.path("regfile"), "-o: " + dir.path("regfile") + " is a file, not a results folder"},
      {dir.path("s.scene.toml"), "is a file, not a results folder"},
      {dir.path("fifo"), "is a FIFO, not a results folder"},
      {dir.path("regfile/out"), "cannot be created: " + dir.path("regfile") + " is not a folder"}};
  for (const auto& [out, expected] : cases) {
    const auto r = run(dir.path("s.scene.toml"), out);
    INFO(r.err);
    CHECK(r.exit_status == 2);
    CHECK_THAT(r.err, Contains(expected));
    CHECK(lines(r.err) == 1);
  }
  CHECK(text_of(dir.path("regfile")) == "x");
  CHECK(fs::is_fifo(dir.path("fifo")));
}

TEST_CASE("isosid-run -o onto the scene's folder never replaces an input named results.h5 or summary.json", "[runtime][results-folder]") {
  const test::ScratchDir dir("run-output-inputs");
  fs::copy_file(kGolden + "/sphere_small.sid.h5", dir.path("results.h5"));
  fs::copy_file(kGolden + "/sphere_small.sid.h5", dir.path("summary.json"));
  for (const std::string input : {"results.h5", "summary.json"}) {
    std::ofstream(dir.path("s.scene.toml")) << impact_scene(input);
    const auto r = run(dir.path("s.scene.toml"), dir.dir());
    INFO(r.err);
    CHECK(r.exit_status == 2);
    CHECK_THAT(r.err, Contains("-o: ") && Contains(input + " is an input of the scene; the run would replace it"));
    CHECK(lines(r.err) == 1);
    CHECK(text_of(dir.path(input)) == text_of(kGolden + "/sphere_small.sid.h5"));
  }
}

TEST_CASE("isosid-run into a folder another isosid-run writes: exit 2 naming its pid", "[runtime][results-folder]") {
  const test::ScratchDir dir("run-output-locked");
  std::ofstream(dir.path("s.scene.toml")) << impact_scene(kGolden + "/sphere_small.sid.h5");
  fs::create_directory(dir.path("out"));
  // the lock as a run holds it: flock on the folder's lock file, the holder's pid in it
  const int fd = ::open(dir.path("out/.isosid-run.lock").c_str(), O_RDWR | O_CREAT, 0644);
  REQUIRE(fd >= 0);
  REQUIRE(::flock(fd, LOCK_EX) == 0);
  REQUIRE(::write(fd, "4242\n", 5) == 5);
  const auto busy = run(dir.path("s.scene.toml"), dir.path("out"));
  CHECK(busy.exit_status == 2);
  CHECK(busy.err == "isosid-run: error: " + dir.path("out") + ": another isosid-run (pid 4242) is writing there\n");
  CHECK_FALSE(fs::exists(dir.path("out/summary.json")));
  ::close(fd);  // that run is over
  const auto released = run(dir.path("s.scene.toml"), dir.path("out"));
  INFO(released.err);
  CHECK(released.exit_status == 0);
}

TEST_CASE("a rerun into a results folder leaves nothing of the earlier run", "[runtime][results-folder]") {
  const test::ScratchDir dir("run-output-rerun");
  std::ofstream(dir.path("s.scene.toml")) << impact_scene(kGolden + "/sphere_small.sid.h5");
  REQUIRE(run(dir.path("s.scene.toml"), dir.path("out")).exit_status == 0);
  // what an earlier run with frames, or an adaptive one, leaves beside results.h5 and summary.json
  fs::create_directories(dir.path("out/paraview"));
  fs::create_directories(dir.path("out/phases/00-coarse"));
  std::ofstream(dir.path("out/paraview/scene.pvd")) << "<VTKFile/>";
  std::ofstream(dir.path("out/phases/00-coarse/summary.json")) << "{}";
  std::ofstream(dir.path("out/notes.txt")) << "the user's";
  REQUIRE(run(dir.path("s.scene.toml"), dir.path("out")).exit_status == 0);
  CHECK_FALSE(fs::exists(dir.path("out/paraview")));
  CHECK_FALSE(fs::exists(dir.path("out/phases")));
  CHECK(fs::exists(dir.path("out/results.h5")));
  CHECK(text_of(dir.path("out/notes.txt")) == "the user's");
}

TEST_CASE("a run that fails before its first sample ends with one failed: line and exit 1", "[runtime][results-folder]") {
  // q0 far beyond any deformation: the run fails at its start (with -1e308 the quasistatic
  // solve of the first sample, which crashed write_results)
  const test::ScratchDir dir("run-fails-at-start");
  for (const std::string q0 : {"1e308", "1e200", "-1e308"}) {
    INFO(q0);
    std::ofstream(dir.path("s.scene.toml")) << test::replace(impact_scene(kGolden + "/sphere_small.sid.h5"), "high_modes",
                                                             "q0 = [" + q0 + ", 0.0, 0.0, 0.0]\nhigh_modes");
    const auto r = run(dir.path("s.scene.toml"), dir.path("out"));
    INFO(r.err);
    CHECK(r.exit_status == 1);
    CHECK(lines(r.err) == 1);
    CHECK_THAT(r.err, Contains("isosid-run: failed: "));
    const auto summary = nlohmann::json::parse(text_of(dir.path("out/summary.json")));
    CHECK(summary["status"] == "failed");
    CHECK(fs::exists(dir.path("out/results.h5")));
  }
}

TEST_CASE("isosid-run prints the project's version", "[runtime][results-folder]") {
  const auto r = test::run_program(std::string(ISOSID_RUN_EXE) + " --version");
  CHECK(r.exit_status == 0);
  CHECK_THAT(r.out, Catch::Matchers::StartsWith(std::string("isosid-run ") + ISOSID_VERSION));
}
