// isosid-info, isosid-diff and isosid-export as a user runs them: output, JSON keys and exit
// statuses.
#include "isosid/format/isolated_probe.hpp"
#include "isosid/format/sid_io.hpp"
#include "support/hdf5_tamper.hpp"
#include "support/lumped_sid.hpp"
#include "support/run_program.hpp"
#include "support/one_line_exit.hpp"

#include <catch2/catch.hpp>
#include <filesystem>
#include <fstream>
#include <nlohmann/json.hpp>
#include <sys/resource.h>
#include <sys/stat.h>

using namespace isosid;
using Catch::Matchers::Contains;

TEST_CASE("isosid-info --json reports mass, centre of mass, inertia, nq and frequencies", "[format][tools]") {
  const test::ScratchDir dir("info");
  auto sid = test::lumped_sid(test::random_lumped_body(12, 5, 4));
  sid.contact_surfaces[0].in_interface = Eigen::Vector4i(1, 1, 1, 0);  // as a Craig-Bampton SID marks them
  format::write_sid(sid, dir.path("a.sid.h5"));
  const auto r = test::run_program(std::string(ISOSID_INFO_EXE) + " --json " + dir.path("a.sid.h5"));
  REQUIRE(r.exit_status == 0);
  const auto j = nlohmann::json::parse(r.out);
  CHECK(j["mass"].get<double>() == Approx(sid.refmod.mass).epsilon(1e-15));
  CHECK(j["center_of_mass"].size() == 3);
  CHECK(j["center_of_mass"][1].get<double>() == Approx(sid.mdCM.M0(1, 0) / sid.refmod.mass).epsilon(1e-12));
  CHECK(j["inertia"][2][2].get<double>() == Approx(sid.J.M0(2, 2)).epsilon(1e-15));
  CHECK(j["nq"] == 5);
  CHECK(j["frequencies_hz"].size() == 5);
  CHECK(j["contact_surfaces"][0]["points"] == 4);
  CHECK(j["contact_surfaces"][0]["points_in_interface"] == 3);
  CHECK(j["nodes"][0]["name"] == "tip");
  CHECK(j["provenance"]["timings_s"]["eigen"].get<double>() == 1.25);

  const auto text = test::run_program(std::string(ISOSID_INFO_EXE) + " " + dir.path("a.sid.h5"));
  CHECK(text.exit_status == 0);
  CHECK_THAT(text.out, Contains("mass") && Contains("contact       face: 4 Gauss points") && Contains("3 points within the interface"));
}

TEST_CASE("the tools exit 2 with one line on bad input", "[format][tools]") {
  const test::ScratchDir dir("bad");
  std::ofstream(dir.path("junk.sid.h5")) << "junk";
  format::write_sid(test::lumped_sid(test::random_lumped_body(8, 3, 1)), dir.path("viewable.sid.h5"));
  const std::string golden = std::string(ISOSID_SOURCE_DIR) + "/tests/golden/sphere_small.sid.h5";  // no viewing mesh
  for (const std::string& cmd : {std::string(ISOSID_INFO_EXE) + " " + dir.path("junk.sid.h5"),
                                 std::string(ISOSID_INFO_EXE) + " " + golden + " --paraview " + dir.path(""),
                                 std::string(ISOSID_INFO_EXE) + " " + dir.path("viewable.sid.h5") + " --paraview " + dir.path("no/such/folder"),
                                 std::string(ISOSID_INFO_EXE) + " " + dir.path("missing.sid.h5"),
                                 std::string(ISOSID_INFO_EXE) + " --no-such-flag x",
                                 std::string(ISOSID_DIFF_EXE) + " " + dir.path("junk.sid.h5") + " " + dir.path("junk.sid.h5"),
                                 std::string(ISOSID_DIFF_EXE) + " a --rtol -1",
                                 std::string(ISOSID_EXPORT_EXE) + " " + dir.path("viewable.sid.h5") + " --format adams-mnf",
                                 std::string(ISOSID_EXPORT_EXE) + " " + dir.path("viewable.sid.h5") + " --format sid-fem -o " + dir.path("no/such/x"),
                                 std::string(ISOSID_EXPORT_EXE) + " " + dir.path("junk.sid.h5") + " --format mbsim-h5",
                                 std::string(ISOSID_EXPORT_EXE) + " " + dir.path("viewable.sid.h5") + " --format sid-fem -o " + dir.path("viewable.sid.h5")}) {
    INFO(cmd);
    const auto r = test::run_program(cmd);
    CHECK(r.exit_status == 2);
    CHECK(std::count(r.err.begin(), r.err.end(), '\n') == 1);
  }
}

TEST_CASE("the tools survive corrupt SIDs that crashed libhdf5: exit 2, one line", "[format][tools][corrupt]") {
  // tests/format/corrupt/README.md says what each file did before: libhdf5 crashed inside its
  // B-tree and global-heap code, or allocated 7.7 GB from a forged shape; a child process now
  // reads an untrusted SID first (format/isolated_probe), and shapes are checked against the
  // file size before any allocation; a child that finds bad input reports it and the parent
  // never reads the file, so libhdf5's own 1.8 GB global-heap allocation stays in the child,
  // under a memory allowance that scales with the file size; a file on which libhdf5 loops for
  // ever is given up after 10 s (64 KB: the base time)
  const std::string dir = ISOSID_CORRUPT_DIR;
  const std::pair<const char*, const char*> cases[] = {
      {"sid_segv_info.sid.h5", "crashed the HDF5 library"},
      {"sid_segv_diff.sid.h5", "crashed the HDF5 library"},
      // a heap over-read: a segfault, or under AddressSanitizer its report and exit 1
      {"sid_globalheap_overflow.sid.h5", "corrupt HDF5 file: reading it"},
      {"sid_memory_blowup.sid.h5", "/terms/ksigma/M0: declares shape (10, 134217729)"},
      {"Ke_inconsistent.sid.h5", "/terms/Ke/M0: diagonal entry 0"},
      {"freq_unsorted.sid.h5", "/refmod/frequencies_hz: not ascending"},
      {"sid_vlen_heap_blowup.sid.h5", "/body/name: is not a readable string dataset"},
      {"sid_hdf5_hang.sid.h5", "did not finish within 10 s"}};
  for (const auto& [file, problem] : cases) {
    for (const std::string& cmd : {std::string(ISOSID_INFO_EXE) + " " + dir + "/" + file,
                                   std::string(ISOSID_DIFF_EXE) + " " + dir + "/" + file + " " + dir + "/" + file}) {
      INFO(cmd);
      const auto r = test::run_program(cmd);
      INFO(r.err);
      CHECK(r.exit_status == 2);
      CHECK(std::count(r.err.begin(), r.err.end(), '\n') == 1);
      CHECK_THAT(r.err, Contains(file) && Contains(problem));
    }
  }
#ifndef ISOSID_UNDER_ASAN  // AddressSanitizer leaves the probe without a memory limit
  // the largest resident set of any program above (and its probe): the 64 KB files must stay
  // far below a 500 MB limit (they take 7.7 GB and 1.8 GB unchecked)
  rusage children{};
  getrusage(RUSAGE_CHILDREN, &children);
  CHECK(children.ru_maxrss < 500 * 1024);  // KiB
#endif
}

TEST_CASE("isosid-diff exits 0 for the same body in another basis and 1 for a different body", "[format][tools]") {
  const test::ScratchDir dir("diff");
  const auto body = test::random_lumped_body(12, 5, 8);
  Eigen::MatrixXd Q = Eigen::MatrixXd::Identity(5, 5);
  Q(2, 2) = -1;
  format::write_sid(test::lumped_sid(body), dir.path("a.sid.h5"));
  format::write_sid(test::lumped_sid(test::rotate_modes(body, Q)), dir.path("b.sid.h5"));
  auto perturbed = test::lumped_sid(body);
  perturbed.refmod.frequencies_hz(4) *= 1.001;  // a stiffer mode 4, consistently in Ke
  perturbed.Ke.M0(4, 4) *= 1.001 * 1.001;
  format::write_sid(perturbed, dir.path("c.sid.h5"));

  const std::string diff = ISOSID_DIFF_EXE;
  const auto same = test::run_program(diff + " " + dir.path("a.sid.h5") + " " + dir.path("b.sid.h5"));
  CHECK(same.exit_status == 0);
  CHECK_THAT(same.out, Contains("equal"));
  const auto differ = test::run_program(diff + " " + dir.path("a.sid.h5") + " " + dir.path("c.sid.h5"));
  CHECK(differ.exit_status == 1);
  CHECK_THAT(differ.out, Contains("frequency of mode 4"));
  const auto loose = test::run_program(diff + " --rtol 0.01 " + dir.path("a.sid.h5") + " " + dir.path("c.sid.h5"));
  CHECK(loose.exit_status == 0);
}

TEST_CASE("isosid-diff refuses a tolerance that is not a finite number >= 0, in one short line", "[format][tools]") {
  const test::ScratchDir dir("diff-rtol");
  const auto body = test::random_lumped_body(12, 5, 8);
  auto stiffer = test::lumped_sid(body);
  stiffer.refmod.frequencies_hz(4) *= 1.1;
  stiffer.Ke.M0(4, 4) *= 1.1 * 1.1;
  format::write_sid(test::lumped_sid(body), dir.path("a.sid.h5"));
  format::write_sid(stiffer, dir.path("b.sid.h5"));
  const std::string diff = std::string(ISOSID_DIFF_EXE) + " " + dir.path("a.sid.h5") + " " + dir.path("b.sid.h5") + " --rtol ";
  for (const char* rtol : {"nan", "NaN", "-nan", "inf", "-inf", "1e400", "-1", "-1e-300", "abc", "0x"}) {
    INFO(rtol);
    const auto r = test::run_program(diff + rtol);
    test::check_one_line_exit(r, 2, "--rtol: must be a finite number >= 0");
    CHECK(r.err.size() < 160);
  }
  CHECK(test::run_program(diff + "0").exit_status == 1);  // exact: the stiffer mode differs
  // a file against itself, and against its copy in another basis, is equal at rtol 0 (to round-off)
  const auto self = test::run_program(std::string(ISOSID_DIFF_EXE) + " --rtol 0 " + dir.path("a.sid.h5") + " " + dir.path("a.sid.h5"));
  CHECK(self.exit_status == 0);
  CHECK_THAT(self.out, Contains("equal within rtol 1e-13"));
  CHECK(test::run_program(diff + "0.5").exit_status == 0);
}

TEST_CASE("isosid-export onto a FIFO is refused in one line and leaves it a FIFO", "[format][tools]") {
  const test::ScratchDir dir("export-fifo");
  format::write_sid(test::lumped_sid(test::random_lumped_body(8, 3, 1)), dir.path("a.sid.h5"));
  REQUIRE(::mkfifo(dir.path("fifo").c_str(), 0600) == 0);
  for (const char* format : {"sid-fem", "mbsim-h5"}) {
    const auto r = test::run_program(std::string(ISOSID_EXPORT_EXE) + " " + dir.path("a.sid.h5") + " --format " + format + " -o " + dir.path("fifo"));
    test::check_one_line_exit(r, 2, "is a FIFO, not a file");
    CHECK(std::filesystem::is_fifo(dir.path("fifo")));
  }
}

TEST_CASE("isosid-info, isosid-diff and isosid-export print the project's version", "[format][tools]") {
  for (const std::string& exe : {std::string(ISOSID_INFO_EXE), std::string(ISOSID_DIFF_EXE), std::string(ISOSID_EXPORT_EXE)}) {
    const auto r = test::run_program(exe + " --version");
    CHECK(r.exit_status == 0);
    CHECK_THAT(r.out, Catch::Matchers::StartsWith(std::filesystem::path(exe).filename().string() + " " + ISOSID_VERSION));
    CHECK(std::count(r.out.begin(), r.out.end(), '\n') == 1);
  }
}
