// isosid-run on the small golden SIDs: free flight against the closed-form motion, an
// impact that must conserve energy and momentum, and bad scenes refused with one line.
#include "isosid/common/sha256.hpp"
#include "isosid/format/hdf5_file.hpp"
#include "isosid/format/sid_io.hpp"
#include "scene_runner.hpp"
#include "support/bad_input_cases.hpp"
#include "support/impact_scene.hpp"
#include "support/one_line_exit.hpp"

#include <catch2/catch.hpp>
#include <algorithm>
#include <chrono>
#include <cmath>
#include <filesystem>
#include <fstream>
#include <iterator>
#include <nlohmann/json.hpp>
#include <sys/stat.h>

using namespace isosid;
using Catch::Matchers::Contains;
using nlohmann::json;
using test::rel_error;
using test::run_scene;
using test::run_seed_scene;

namespace {
const std::string kGolden = ISOSID_GOLDEN_DIR;

/// Each reference value of `other` lies within `tolerance` (relative) of `reference`'s.
void check_agree(const json& reference, const json& other, std::initializer_list<const char*> keys, double tolerance,
                 const char* reference_name, const char* other_name) {
  for (const char* key : keys) {
    const double a = reference["reference"][key]["value"].get<double>(), b = other["reference"][key]["value"].get<double>();
    INFO(key << ": " << reference_name << " " << a << ", " << other_name << " " << b);
    CHECK(std::abs(a - b) <= tolerance * std::abs(a));
  }
}

using test::replace;

const std::string kImpact = test::golden_impact_scene(kGolden + "/sphere_small.sid.h5");

/// The shell's prefix that limits a command's writes to `kib` KiB: the file size limit (ulimit -f,
/// SIGXFSZ ignored) makes writes fail with EFBIG as a full disk does with ENOSPC.
std::string on_full_disk(int kib) { return "ulimit -f " + std::to_string(kib) + "; trap '' XFSZ; "; }

/// isosid-run of sphere_hertz.scene.toml in `dir` (its model's SID already prepared there)
/// with `options` and its writes limited to `kib` KiB (on_full_disk). The run must end with exit 1
/// and one line that contains `message`; returns its summary.json.
json run_on_full_disk(const test::ScratchDir& dir, int kib, const std::string& options, const std::string& message) {
  const auto run = test::run_program(on_full_disk(kib) + "ISOSID_PREP=" + ISOSID_PREP_EXE + " " +
                                     ISOSID_RUN_EXE + " -q " + options + " " + dir.path("sphere_hertz.scene.toml") + " -o " + dir.path("out"));
  test::check_one_line_exit(run, 1, message);
  std::ifstream in(dir.path("out/summary.json"));
  return json::parse(in);
}
}  // namespace

std::string beam_scene(const std::string& velocity, const std::string& angular_velocity, const std::string& gravity) {
  return R"(
[simulation]
dimension = "3d"
end_time = 0.02
rtol = 1e-10
atol = 1e-14
output_interval = 1e-3
gravity = )" + gravity + R"(
[[flexible_body]]
name = "beam"
sid = ")" + kGolden + R"(/beam_small.sid.h5"
position = [0.0, 1.0, 0.0]
velocity = )" + velocity + R"(
angular_velocity = )" + angular_velocity + "\n";
}

TEST_CASE("free flight under gravity follows the closed-form parabola", "[runtime]") {
  const test::ScratchDir dir("free-flight");
  // Buckens frame: gravity does not excite the modes (Ct = 0), so the frame translates exactly
  const json s = run_scene(dir, beam_scene("[1.0, 2.0, -0.5]", "[0.0, 0.0, 0.0]", "[0.0, -9.81, 0.0]"));
  const double t = 0.02;
  const auto& b = s["bodies"][0];
  // tolerance: rtol 1e-10 over ~1e3 steps of a polynomial solution (DP5 integrates it exactly)
  CHECK(b["final_position"][0].get<double>() == Approx(1.0 * t).epsilon(1e-9));
  CHECK(b["final_position"][1].get<double>() == Approx(1.0 + 2.0 * t - 0.5 * 9.81 * t * t).epsilon(1e-9));
  CHECK(b["final_velocity"][1].get<double>() == Approx(2.0 - 9.81 * t).epsilon(1e-9));
  CHECK(s["energy"]["max_rel_error"].get<double>() < 1e-9);
}

TEST_CASE("a spinning free flexible body conserves energy", "[runtime]") {
  const test::ScratchDir dir("spin");
  // rotation excites the modes through the centrifugal terms (Oe, Gr, Ge): the energy
  // balance checks the quadratic-velocity terms against the mass matrix
  const json s = run_scene(dir, beam_scene("[0.0, 0.0, 0.0]", "[0.5, 3.0, 40.0]", "[0.0, 0.0, 0.0]"));
  CHECK(s["status"] == "completed");
  CHECK(s["energy"]["max_rel_error"].get<double>() < 1e-6);
}

TEST_CASE("a body that never touches reports no rebound against a reference, and its contact warns", "[runtime]") {
  // the golden sphere moving away from its plane: no contact closes, so its final speed is no rebound
  const test::ScratchDir dir("no-touch");
  const json s = run_scene(dir, replace(kImpact, "velocity = [0.0, -0.1, 0.0]", "velocity = [0.0, 0.1, 0.0]") +
                                    "[reference]\nrebound_velocity_m_s = 0.1\n");
  CHECK(s["contacts"][0]["intervals"] == 0);
  CHECK_FALSE(s["contacts"][0]["closed_at_end"].get<bool>());
  CHECK(s["contacts"][0]["never_closed"].get<bool>());
  REQUIRE(s["warnings"].size() == 1);  // (moving away, it has no Hertz estimate to find its elements coarse)
  CHECK_THAT(s["warnings"][0].get<std::string>(), Catch::Matchers::StartsWith("contact 'impact' never closed"));
  CHECK(s["expected_warnings"].empty());
  CHECK(s["reference"]["rebound_velocity_m_s"]["value"].is_null());
  // a scene that expects it lists it apart: its warnings keep only what calls for attention
  const json expected = run_scene(dir, replace(kImpact, "velocity = [0.0, -0.1, 0.0]", "velocity = [0.0, 0.1, 0.0]") +
                                           "[output]\nexpected_warnings = [\"never_closed\"]\n");
  CHECK(expected["warnings"].empty());
  REQUIRE(expected["expected_warnings"].size() == 1);
  CHECK(expected["expected_warnings"][0] == s["warnings"][0]);
}

TEST_CASE("an integration that loses the energy balance is flagged, and a tight one is not", "[runtime]") {
  // rtol 0.1 and atol 1e-6, the loosest tolerances a scene may give: the golden sphere's impact
  // gains about its own energy in motion (measured 1.0 of it); at the scene's 1e-6 it keeps it
  const test::ScratchDir dir("energy-flag");
  const json loose = run_scene(dir, replace(replace(kImpact, "rtol = 1e-6", "rtol = 0.1"), "atol = 1e-12", "atol = 1e-6"));
  CHECK(loose["energy"]["error_too_large"].get<bool>());
  CHECK(loose["energy"]["error_per_energy_in_motion"].get<double>() > 0.05);
  bool warned = false;
  for (const auto& w : loose["warnings"]) warned = warned || w.get<std::string>().rfind("the energy balance is off by", 0) == 0;
  CHECK(warned);
  const json tight = run_scene(dir, kImpact);
  CHECK_FALSE(tight["energy"]["error_too_large"].get<bool>());
  CHECK(tight["energy"]["error_per_energy_in_motion"].get<double>() < 1e-3);
}

TEST_CASE("a contact the Hertz estimate sees closed at end_time is announced before the run", "[runtime]") {
  // the golden sphere touches after 1 us and Hertz releases it tens of us later: an end at 20 us
  // is announced before the run starts, and the run flags the contact closed at its end
  const test::ScratchDir dir("closed-at-end-predicted");
  std::ofstream(dir.path("s.scene.toml")) << replace(kImpact, "end_time = 100e-6", "end_time = 20e-6");
  const auto r = test::run_program(std::string(ISOSID_RUN_EXE) + " --json " + dir.path("s.scene.toml") + " -o " + dir.path("out"));
  REQUIRE(r.exit_status == 0);
  const std::string announced = "isosid-run: warning: contact 'impact' will likely still be closed at simulation.end_time";
  REQUIRE(r.err.find(announced) != std::string::npos);
  CHECK(r.err.find(announced) < r.err.find("completed"));  // before the run's report
  CHECK(json::parse(r.out)["contacts"][0]["closed_at_end"].get<bool>());
  // with time for the whole impact, nothing is announced
  std::ofstream(dir.path("s.scene.toml")) << kImpact;
  const auto whole = test::run_program(std::string(ISOSID_RUN_EXE) + " " + dir.path("s.scene.toml") + " -o " + dir.path("out"));
  REQUIRE(whole.exit_status == 0);
  CHECK(whole.err.find("will likely still be closed") == std::string::npos);
}

TEST_CASE("a scene compared with its own Hertz estimate", "[runtime]") {
  const test::ScratchDir dir("hertz-reference");
  const json s = run_scene(dir, kImpact + "[reference]\nsource = \"hertz\"\nrebound_velocity_m_s = 0.1\n");
  const json& e = s["contacts"][0]["hertz_estimate"];
  for (const char* key : {"peak_force_n", "contact_time_s"}) {
    const json& r = s["reference"][key];
    CHECK(r["source"] == "hertz");
    CHECK(r["reference"].get<double>() == e[key].get<double>());
    // measured against it (the golden sphere, 0.34 elements per contact radius, is 70 % stiff)
    CHECK(r["rel_error"].get<double>() == Approx(r["value"].get<double>() / r["reference"].get<double>() - 1).epsilon(1e-12));
  }
  CHECK_FALSE(s["reference"]["rebound_velocity_m_s"].contains("source"));
  CHECK(s["warnings"].size() == 1);  // the coarse golden sphere's resolution, nothing about the reference
  // a line contact (the planar disk of scene C) has no contact time to compare: said so
  test::copy_model_file(dir, "disk_plane_strain.model.toml");
  const std::string disk = test::model_text("cylinder_friction.scene.toml");
  const json line = run_scene(dir, disk.substr(0, disk.find("[reference]")) + "[reference]\nsource = \"hertz\"\n");
  CHECK(line["reference"]["peak_force_n"]["source"] == "hertz");
  CHECK_FALSE(line["reference"].contains("contact_time_s"));
  REQUIRE(line["warnings"].size() == 1);
  CHECK(line["warnings"][0].get<std::string>().find("line contact") != std::string::npos);
  // another source, or Hertz's figures given twice, are refused
  run_scene(dir, kImpact + "[reference]\nsource = \"finite elements\"\n", 2);
  run_scene(dir, kImpact + "[reference]\nsource = \"hertz\"\npeak_force_n = 52.0\n", 2);
}

TEST_CASE("an elastic sphere impact conserves energy and rebounds", "[runtime]") {
  const test::ScratchDir dir("impact");
  const json s = run_scene(dir, kImpact);
  const auto& c = s["contacts"][0];
  CHECK(c["intervals"] == 1);
  // onset: the lowest Gauss point (0.1 um plus its sagitta above the plane) arrives at 0.1 m/s;
  // root finding on the gap locates it (measured: 3e-11 relative; 1e-8 allows for the gap's
  // resolution of eps x body size)
  const format::Sid sid = format::read_sid(kGolden + "/sphere_small.sid.h5");
  const double lowest = sid.contact_surfaces[0].position.col(1).minCoeff();
  CHECK(c["start_s"].get<double>() == Approx((0.0100001 + lowest) / 0.1).epsilon(1e-8));
  CHECK_FALSE(c["end_s"].is_null());
  // momentum: the impulse turns -0.1 m/s into the rebound velocity
  const double m = 2789.0 * 4.0 / 3.0 * M_PI * 1e-6, v1 = s["bodies"][0]["final_velocity"][1].get<double>();
  CHECK(c["impulse_ns"].get<double>() == Approx(m * (v1 + 0.1)).epsilon(1e-3));
  // elastic impact: only the light modal damping dissipates (0.03 % of the energy here)
  CHECK(v1 == Approx(0.1).epsilon(1e-3));
  CHECK(s["energy"]["max_rel_error"].get<double>() < 1e-4);
  CHECK(std::ifstream(dir.path("out-s.scene.toml/results.h5")).good());
  CHECK(std::ifstream(dir.path("out-s.scene.toml/summary.json")).good());
  // the force spectrum at 0 Hz is the impulse: here of the sampled force, in the summary of the
  // accepted steps' force (1 us samples against ~0.2 us steps: 1e-3)
  const format::h5::Reader results(dir.path("out-s.scene.toml/results.h5"));
  const Eigen::VectorXd nu = results.vector("/contacts/impact/spectrum_frequency"), F = results.vector("/contacts/impact/spectrum_amplitude");
  REQUIRE(nu.size() > 10);
  CHECK(nu(0) == 0);
  CHECK(F(0) == Approx(c["impulse_ns"].get<double>()).epsilon(1e-3));
  CHECK(F.maxCoeff() == F(0));  // a pulse of one sign: |F(nu)| <= F(0)
  // the plot script draws force (with Hertz) and energies from these files
  const auto plot = test::run_program(std::string(ISOSID_SCRIPTS_DIR) + "/plot-results " + dir.path("out-s.scene.toml"));
  INFO(plot.err);
  CHECK(plot.exit_status == 0);
  for (const char* png : {"contact_force.png", "energy.png", "force_spectrum.png"}) {
    std::ifstream f(dir.path("out-s.scene.toml/") + png, std::ios::binary);
    char magic[4] = {};
    f.read(magic, 4);
    CHECK(std::string(magic + 1, 3) == "PNG");
  }
}

TEST_CASE("bad scenes: exit 2 with one line naming file, field and problem", "[runtime]") {
  const test::ScratchDir dir("bad-scenes");
  for (const auto& c : test::bad_input_cases("scenes.toml", {{"impact", kImpact}}, "impact")) {
    std::ofstream(dir.path("s.scene.toml")) << c.text;
    const auto r = test::run_program(std::string(ISOSID_RUN_EXE) + " -q " + dir.path("s.scene.toml") + " -o " + dir.path("out"));
    INFO(c.label << ": " << c.expected << "\n" << r.err);
    test::check_one_line_exit(r, 2, c.expected);
    CHECK_FALSE(std::filesystem::exists(dir.path("out")));  // a refused run leaves no results folder
  }
}

TEST_CASE("a scene or SID that is a FIFO, a folder or a link loop is named for what it is, at once", "[runtime][bad-input]") {
  const test::ScratchDir dir("special-inputs");
  REQUIRE(::mkfifo(dir.path("fifo").c_str(), 0600) == 0);
  std::filesystem::create_directory(dir.path("folder"));
  std::filesystem::create_symlink("loop_b", dir.path("loop_a"));
  std::filesystem::create_symlink("loop_a", dir.path("loop_b"));
  struct Case {
    std::string scene, expected;
  };
  const std::vector<Case> cases = {
      {"fifo", "fifo: is a FIFO, not a file"},
      {"folder", "folder: is a directory, not a file"},
      {"loop_a", "loop_a: too many levels of symbolic links"},
      {"s.scene.toml", "flexible_body[0].sid: is a FIFO, not a file: " + dir.path("fifo")},
      {"l.scene.toml", "flexible_body[0].sid: too many levels of symbolic links: " + dir.path("loop_a")}};
  std::ofstream(dir.path("s.scene.toml")) << replace(kImpact, kGolden + "/sphere_small.sid.h5", dir.path("fifo"));
  std::ofstream(dir.path("l.scene.toml")) << replace(kImpact, kGolden + "/sphere_small.sid.h5", dir.path("loop_a"));
  for (const Case& c : cases) {
    const auto r = test::run_program(std::string(ISOSID_RUN_EXE) + " -q " + dir.path(c.scene) + " -o " + dir.path("out"));
    test::check_one_line_exit(r, 2, c.expected);
  }
}

TEST_CASE("a full disk ends both programs with one line and exit 1, and the run keeps summary.json", "[runtime][faults]") {
  // writes limited as on a full disk (on_full_disk); libhdf5 used to crash at exit after the
  // failed write, and isosid-run lost the whole run
  const test::ScratchDir dir("disk-full");
  test::copy_model_file(dir, "sphere_axisym.model.toml");
  test::copy_model_file(dir, "sphere_hertz.scene.toml");
  // 100 KiB: the SID and results.h5 need more
  const auto prep = test::run_program(on_full_disk(100) + ISOSID_PREP_EXE + " -q " +
                                      dir.path("sphere_axisym.model.toml") + " -o " + dir.path("limited.sid.h5"));
  test::check_one_line_exit(prep, 1, "File too large");
  CHECK_FALSE(std::filesystem::exists(dir.path("limited.sid.h5")));
  // the run itself, with a SID built without the limit
  REQUIRE(test::run_program(std::string(ISOSID_PREP_EXE) + " -q " + dir.path("sphere_axisym.model.toml")).exit_status == 0);
  const json summary = run_on_full_disk(dir, 100, "", "summary.json");
  CHECK(summary["status"] == "completed");
  CHECK(summary.contains("results_h5_error"));
  CHECK(summary["contacts"][0]["peak_force_n"].get<double>() > 50);
  for (const auto& entry : std::filesystem::directory_iterator(dir.path("out")))
    CHECK(entry.path().filename().string().rfind(".results.h5.tmp", 0) != 0);  // no temporary left
}

TEST_CASE("ParaView frames that cannot be written fail the run with exit 1 and keep its results", "[runtime][faults]") {
  const test::ScratchDir dir("paraview-full");
  test::copy_model_file(dir, "sphere_axisym.model.toml");
  test::copy_model_file(dir, "sphere_hertz.scene.toml");
  REQUIRE(test::run_program(std::string(ISOSID_PREP_EXE) + " -q " + dir.path("sphere_axisym.model.toml")).exit_status == 0);
  // 300 KiB: summary.json and a short results.h5 fit, one frame of the sphere (0.37 MB) does not
  const json summary = run_on_full_disk(dir, 300, "--paraview", "body_sphere_00000.vtu: cannot write");
  CHECK(summary["status"] == "failed");
  CHECK(std::filesystem::exists(dir.path("out/results.h5")));
  CHECK(std::filesystem::exists(dir.path("out/paraview/scene.pvd")));  // the frames so far: none
}

TEST_CASE("SIGTERM, SIGINT and SIGHUP stop a run and keep its results so far", "[runtime][signals]") {
  const test::ScratchDir dir("signals");
  // the impact at 1 ns steps: about a second per 100 us simulated, far longer than the test waits
  std::ofstream(dir.path("s.scene.toml")) << replace(kImpact, "end_time = 100e-6", "end_time = 1e-3\nmax_step = 1e-9");
  for (const auto& [signal, status] : std::vector<std::pair<std::string, int>>{{"TERM", 143}, {"INT", 130}, {"HUP", 129}}) {
    const std::string out = dir.path("out-" + signal);
    // started in the background; the signal follows once the run has marked its folder
    const auto r = test::run_program("{ " + std::string(ISOSID_RUN_EXE) + " -q " + dir.path("s.scene.toml") + " -o " + out +
                                     " & pid=$!; for i in $(seq 600); do [ -f " + out + "/summary.json ] && break; sleep 0.05; done; "
                                     "sleep 0.3; kill -" + signal + " $pid; wait $pid; }");
    INFO(signal);
    test::check_one_line_exit(r, status, "isosid-run: interrupted by");
    const json s = json::parse(std::ifstream(out + "/summary.json"));
    CHECK(s["status"] == "interrupted");
    const double reached = s["end_time_s"].get<double>();
    CHECK(reached > 0);
    CHECK(reached < 1e-3);
    // results.h5 is whole and holds the samples so far, up to where the run stopped
    const Eigen::VectorXd time = format::h5::Reader(out + "/results.h5").vector("/time");
    CHECK(time.size() > 1);
    CHECK(time(time.size() - 1) == Approx(reached));
  }
}

TEST_CASE("a signal stops a run within its steps, however far the next sample", "[runtime][signals]") {
  const test::ScratchDir dir("signals-within");
  // the sphere flies away from the plane for 1000 s at steps of 0.1 ms in one output interval:
  // the integrator does not return for minutes
  std::ofstream(dir.path("s.scene.toml")) << replace(replace(replace(kImpact, "end_time = 100e-6", "end_time = 1e3\nmax_step = 1e-4"),
                                                             "output_interval = 1e-6", "output_interval = 1e3"),
                                                     "velocity = [0.0, -0.1, 0.0]", "velocity = [0.0, 0.1, 0.0]");
  const std::string out = dir.path("out");
  const auto r = test::run_program("{ " + std::string(ISOSID_RUN_EXE) + " -q " + dir.path("s.scene.toml") + " -o " + out +
                                   " & pid=$!; for i in $(seq 600); do [ -f " + out + "/summary.json ] && break; sleep 0.05; done; "
                                   "sleep 1; kill -TERM $pid; start=$(date +%s%N); wait $pid; status=$?; "
                                   "echo $(( ($(date +%s%N) - start) / 1000000 )); exit $status; }");
  INFO(r.err);
  CHECK(r.exit_status == 143);
  // acted on at the next step: well within a second (the machine may be loaded)
  CHECK(std::stol(r.out) < 1000);
  const json s = json::parse(std::ifstream(out + "/summary.json"));
  CHECK(s["status"] == "interrupted");
  const Eigen::VectorXd time = format::h5::Reader(out + "/results.h5").vector("/time");
  CHECK(time(time.size() - 1) == Approx(s["end_time_s"].get<double>()));
}

TEST_CASE("a penalty just below the ceiling into a deep overlap still runs", "[runtime][contact]") {
  // 0.1 mm into the plane (0.3 Hertz radii of this coarse sphere) at 1.5e23 N/m^3, just under
  // 1e6 times the derived penalty: the steps shrink but the run completes (measured 659 steps)
  const test::ScratchDir dir("stiff-overlap");
  const std::string scene = replace(replace(kImpact, "penalty = 5e17", "penalty = 1.5e23"), "position = [0.0, 0.0100001, 0.0]",
                                    "position = [0.0, 0.0099, 0.0]");
  std::ofstream(dir.path("s.scene.toml")) << replace(replace(scene, "end_time = 100e-6", "end_time = 5e-6"), "output_interval = 1e-6",
                                                     "output_interval = 1e-6\nallow_initial_penetration = true");
  const auto r = test::run_program(std::string(ISOSID_RUN_EXE) + " -q " + dir.path("s.scene.toml") + " -o " + dir.path("out"));
  INFO(r.err);
  CHECK(r.exit_status == 0);
  const json s = json::parse(std::ifstream(dir.path("out/summary.json")));
  CHECK(s["status"] == "completed");
  CHECK(s["steps"].get<long>() < 100000);
}

TEST_CASE("a step limit reached before any contact does not blame the penalty", "[runtime]") {
  const test::ScratchDir dir("step-limit");
  // 0.1 mm above the plane: no contact within the 100 us, steps of at most 10 us
  std::ofstream(dir.path("s.scene.toml")) << replace(replace(kImpact, "output_interval = 1e-6", "output_interval = 1e-6\nmax_steps = 10\nmax_step = 1e-5"),
                                                     "position = [0.0, 0.0100001, 0.0]", "position = [0.0, 0.0101, 0.0]");
  const auto r = test::run_program(std::string(ISOSID_RUN_EXE) + " -q " + dir.path("s.scene.toml") + " -o " + dir.path("out"));
  INFO(r.err);
  CHECK(r.exit_status == 1);
  CHECK_THAT(r.err, Contains("the step limit max_steps = 10 was reached"));
  CHECK(r.err.find("penalty") == std::string::npos);
}

TEST_CASE("a scene whose model isosid-prep refuses: exit 2 and isosid-prep's one line", "[runtime]") {
  const test::ScratchDir dir("bad-model");
  std::ifstream golden(kGolden + "/sphere_small.model.toml");
  std::string model((std::istreambuf_iterator<char>(golden)), std::istreambuf_iterator<char>());
  std::ofstream(dir.path("bad.model.toml")) << replace(model, "youngs_modulus = 7.28e10", "youngs_modulus = -1.0");
  std::ofstream(dir.path("s.scene.toml")) << replace(kImpact, "sid = \"" + kGolden + "/sphere_small.sid.h5\"",
                                                     "sid = \"bad.sid.h5\"\nmodel = \"bad.model.toml\"");
  const auto r = test::run_program("ISOSID_PREP=" + std::string(ISOSID_PREP_EXE) + " " + ISOSID_RUN_EXE + " -q " +
                                   dir.path("s.scene.toml") + " -o " + dir.path("out"));
  test::check_one_line_exit(r, 2, Contains("isosid-run: error: ") && Contains("bad.model.toml") && Contains("youngs_modulus"));
  CHECK_FALSE(std::filesystem::exists(dir.path("out")));
}

TEST_CASE("bodies may start interpenetrating where the scene allows it", "[runtime]") {
  const test::ScratchDir dir("initial-penetration");
  const std::string scene = replace(replace(kImpact, "position = [0.0, 0.0100001, 0.0]", "position = [0.0, 0.009999, 0.0]"),
                                    "output_interval = 1e-6", "output_interval = 1e-6\nallow_initial_penetration = true");
  const json s = run_scene(dir, scene);
  CHECK(s["status"] == "completed");
  CHECK(s["contacts"][0]["start_s"].get<double>() == 0);  // in contact from the start
}

TEST_CASE("a run that cannot proceed stops naming time and body and keeps its results", "[runtime]") {
  // a penalty near the ceiling (1.5e23 N/m^3) with dynamic constraint modes: the steps shrink;
  // the step limit turns the crawl into a diagnosis instead of a hang
  const test::ScratchDir dir("stalled");
  std::string text = kImpact;
  text.replace(text.find("penalty = 5e17"), 14, "penalty = 1.5e23");
  text.replace(text.find("high_modes = \"quasistatic\""), 26, "high_modes = \"dynamic\"");
  text.replace(text.find("output_interval = 1e-6"), 22, "output_interval = 1e-6\nmax_steps = 3000");
  std::ofstream(dir.path("s.scene.toml")) << text;
  const auto r = test::run_program(std::string(ISOSID_RUN_EXE) + " -q " + dir.path("s.scene.toml") + " -o " + dir.path("out"));
  // one line: ARKODE's own messages are kept, not printed
  test::check_one_line_exit(r, 1, Contains("max_steps = 3000") && Contains("body 'sphere'") && Contains("at t = "));
  const json s = json::parse(std::ifstream(dir.path("out/summary.json")));
  CHECK(s["status"] == "failed");
  CHECK(s["steps"].get<long>() >= 3000);
  CHECK(std::ifstream(dir.path("out/results.h5")).good());
}

TEST_CASE("scene A: sphere on sphere (Hertz) with the Craig-Bampton sphere", "[runtime][seed]") {
  const test::ScratchDir dir("scene-a");
  const json s = run_seed_scene(dir, "sphere_hertz.scene.toml", "sphere_axisym.model.toml");
  // acceptance: 2 % against Hertz (measured +0.83 % and -0.49 %; against the finite sphere of
  // bench/reference +0.11 % and +0.01 %, which bench/contact_convergence tracks)
  CHECK(rel_error(s, "peak_force_n") < 0.02);
  CHECK(rel_error(s, "contact_time_s") < 0.02);
  CHECK(rel_error(s, "rebound_velocity_m_s") < 0.005);  // acceptance: rebound energy 0.5 %
  CHECK(s["contacts"][0]["edge_reached_s"].is_null());  // the contact stays inside its cap
  CHECK(s["contacts"][0]["interface_left_s"].is_null());  // and inside the sphere's interface
  CHECK(s["energy"]["max_rel_error"].get<double>() < 1e-5);
  // von Mises on the axis ([R1] eq. 34, docs/references.md): Hertz peak 0.530 GPa (measured -1.0 %)
  // at 0.49 a below the surface (measured within one 10 um sample of the stress line)
  CHECK(rel_error(s, "peak_von_mises_pa") < 0.03);
  CHECK(std::abs(s["reference"]["peak_von_mises_depth_m"]["value"].get<double>() - 82.3e-6) <= 10e-6);
  // the Hertz estimate from the SID (material, mass, curvature of the master patch at the
  // nearest point) and the initial speed: case A's closed form, 51.70 N, 83.1 us and
  // a = 0.168 mm, to the 4 digits it is given with
  const json& hertz = s["contacts"][0]["hertz_estimate"];
  CHECK(hertz["peak_force_n"].get<double>() == Approx(51.70).epsilon(1e-3));
  CHECK(hertz["contact_time_s"].get<double>() == Approx(83.1e-6).epsilon(1e-3));
  CHECK(hertz["contact_radius_m"].get<double>() == Approx(0.168e-3).epsilon(3e-3));
}

TEST_CASE("a sphere sized from its contact radius is rebuilt for the scene's impact, a contact still closed at the end is flagged", "[runtime][contact]") {
  // scene A at half the speed: Hertz gives a = 0.127 mm instead of the model's 0.168 mm, so
  // isosid-run runs on a SID built with elements of a/8 (the SID records the radius it was sized
  // for), kept in a cache beside the scene's own SID, which stays as it is; a second run reuses it
  const test::ScratchDir dir("contact-fit");
  test::copy_model_file(dir, "sphere_axisym.model.toml");
  std::ifstream in(std::string(ISOSID_MODELS_DIR) + "/sphere_hertz.scene.toml");
  const std::string scene = replace(std::string((std::istreambuf_iterator<char>(in)), std::istreambuf_iterator<char>()),
                                    "velocity = [0.0, -0.1, 0.0]", "velocity = [0.0, -0.05, 0.0]");
  const json slow = run_scene(dir, scene, 0);
  const json& hertz = slow["contacts"][0]["hertz_estimate"];
  // Hertz scales a as v^(2/5): 0.168 mm x 0.5^0.4 (case A's radius, to its 3 digits)
  CHECK(hertz["contact_radius_m"].get<double>() == Approx(0.168e-3 * std::pow(0.5, 0.4)).epsilon(3e-3));
  CHECK(hertz["elements_per_radius"].get<double>() == Approx(8).epsilon(0.01));
  // the slower impact lasts 95.5 us, past the scene's end: flagged, and no rebound is reported
  // while the sphere is still in contact
  REQUIRE(slow["warnings"].size() == 1);
  CHECK(slow["warnings"][0].get<std::string>().find("'impact' is still closed at the end of the run") != std::string::npos);
  CHECK(slow["contacts"][0]["closed_at_end"].get<bool>());
  CHECK(slow["reference"]["rebound_velocity_m_s"]["value"].is_null());
  // the SID the run used, as its provenance says (inputs: scene, model, SID)
  const json& ran_on = slow["provenance"]["inputs"][2];
  REQUIRE(ran_on["role"] == "sid sphere");
  const std::string used = ran_on["path"];
  CHECK(used.find("/.isosid-cache/sphere_axisym-") != std::string::npos);
  const format::Sid sid = format::read_sid(used);
  REQUIRE(sid.discretization);
  // the summary's estimate comes from the refitted SID, whose mass and curvature differ from the
  // first one's in the last digits (measured 1e-10)
  CHECK(sid.discretization->contact_radius == Approx(hertz["contact_radius_m"].get<double>()).epsilon(1e-8));
  CHECK(format::read_sid(dir.path("sphere_axisym.sid.h5")).discretization->contact_radius == Approx(0.168e-3).epsilon(1e-6));  // untouched
  const auto built = std::filesystem::last_write_time(used);
  // run on past the release: the same cached SID serves, nothing to warn about, the rebound is there
  const json whole = run_scene(dir, replace(scene, "end_time = 95e-6", "end_time = 110e-6"), 0);
  CHECK(whole["provenance"]["inputs"][2]["path"] == used);
  CHECK(std::filesystem::last_write_time(used) == built);
  CHECK(whole["warnings"].empty());
  CHECK_FALSE(whole["contacts"][0]["closed_at_end"].get<bool>());
  CHECK(whole["reference"]["rebound_velocity_m_s"]["value"].get<double>() == Approx(0.05).epsilon(1e-3));
  CHECK_FALSE(whole["energy"]["error_too_large"].get<bool>());
}

TEST_CASE("keys dotted 40 000 deep are refused by both programs in one line", "[runtime][bad-input]") {
  // toml++ recursed on them until the stack overflowed; the text is
  // checked for nesting before it is parsed
  const test::ScratchDir dir("deep-toml");
  std::string keys;
  for (int i = 0; i < 40000; ++i) keys += "a.";
  std::ofstream(dir.path("deep.model.toml")) << "x = 1\n" << keys << "a = 1\n";
  std::ofstream(dir.path("deep.scene.toml")) << "x = 1\n" << keys << "a = 1\n";
  for (const std::string& command : {std::string(ISOSID_PREP_EXE) + " -q " + dir.path("deep.model.toml") + " -o " + dir.path("deep.sid.h5"),
                                     std::string(ISOSID_RUN_EXE) + " -q " + dir.path("deep.scene.toml") + " -o " + dir.path("out")}) {
    const auto r = test::run_program(command);
    INFO(command << "\n" << r.err);
    CHECK(r.exit_status == 2);
    CHECK(std::count(r.err.begin(), r.err.end(), '\n') == 1);
    CHECK(r.err.find("line 2: nests deeper than 64 levels") != std::string::npos);
  }
}

TEST_CASE("a SID built from another model than the scene's is refused, one from another version of it rebuilt", "[runtime][sid]") {
  const test::ScratchDir dir("sid-provenance");
  const auto copy = [&](const std::string& from, const std::string& to) {
    std::filesystem::copy_file(from, dir.path(to), std::filesystem::copy_options::overwrite_existing);
  };
  copy(kGolden + "/sphere_small.model.toml", "other.model.toml");
  copy(kGolden + "/sphere_small.sid.h5", "s.sid.h5");  // newer than the model: no rebuild by file times
  const std::string scene = replace(kImpact, "sid = \"" + kGolden + "/sphere_small.sid.h5\"", "sid = \"s.sid.h5\"\nmodel = \"other.model.toml\"");
  std::ofstream(dir.path("s.scene.toml")) << scene;
  const auto r = test::run_program(std::string(ISOSID_RUN_EXE) + " -q " + dir.path("s.scene.toml") + " -o " + dir.path("out"));
  test::check_one_line_exit(r, 2, "flexible_body[0].sid: " + dir.path("s.sid.h5") + " was built from sphere_small.model.toml, not other.model.toml");
  // the same model file name with other content (here: a finer grading): rebuilt from it
  std::ifstream golden_model(kGolden + "/sphere_small.model.toml");
  std::ofstream(dir.path("sphere_small.model.toml"))
      << replace(std::string((std::istreambuf_iterator<char>(golden_model)), std::istreambuf_iterator<char>()), "smallest = 0.5e-3",
                 "smallest = 0.4e-3");
  std::filesystem::last_write_time(dir.path("sphere_small.model.toml"),
                                   std::filesystem::last_write_time(dir.path("s.sid.h5")) - std::chrono::hours(1));
  run_scene(dir, replace(scene, "other.model.toml", "sphere_small.model.toml"), 0);
  const format::Sid rebuilt = format::read_sid(dir.path("s.sid.h5"));
  CHECK(rebuilt.provenance.model_sha256 == common::sha256_file(dir.path("sphere_small.model.toml")));
}

TEST_CASE("a penalty that lets the bodies sink deeper than half their Hertz approach is reported", "[runtime][contact]") {
  // 1e12 N/m^3 on the small sphere (its contact elements derive 1.6e17): above the floor of
  // 1e-8 of that, but the penalty layer, not the sphere, takes the impact
  const test::ScratchDir dir("soft-penalty");
  const json soft = run_scene(dir, replace(replace(kImpact, "penalty = 5e17", "penalty = 1e12"), "end_time = 100e-6", "end_time = 400e-6"), 0);
  const json& contact = soft["contacts"][0];
  CHECK(contact["penalty_too_soft"] == true);
  CHECK(contact["penetration_per_hertz_approach"].get<double>() > 0.5);
  // (besides the golden sphere's coarse contact elements and narrow interface)
  const auto blames_penalty = [](const json& summary) {
    return std::count_if(summary["warnings"].begin(), summary["warnings"].end(), [](const json& w) {
      return w.get<std::string>().find("times the Hertz approach of the bodies") != std::string::npos &&
             w.get<std::string>().find("its penalty (1e+12 N/m^3, scene) is too soft") != std::string::npos;
    });
  };
  CHECK(blames_penalty(soft) == 1);
  // the scene's own penalty penetrates a fraction of a percent of the approach
  const json stiff = run_scene(dir, kImpact, 0);
  CHECK(stiff["contacts"][0]["penalty_too_soft"] == false);
  CHECK(stiff["contacts"][0]["penetration_per_hertz_approach"].get<double>() < 0.01);
  CHECK(blames_penalty(stiff) == 0);
}

TEST_CASE("a contact that outgrows its contact surface is reported", "[runtime][contact]") {
  // scene A's sphere with its contact cap cut to a quarter (0.11 mm of arc against a = 0.168
  // mm): the contact reaches the cap's rim before the peak, and the force beyond is lost
  const test::ScratchDir dir("contact-edge");
  std::ifstream model_in(std::string(ISOSID_MODELS_DIR) + "/sphere_axisym.model.toml");
  std::ofstream(dir.path("sphere_axisym.model.toml"))
      << replace(std::string((std::istreambuf_iterator<char>(model_in)), std::istreambuf_iterator<char>()),
                 "interval = [[0.0, 0.04]]", "interval = [[0.0, 0.01]]");
  test::copy_model_file(dir, "sphere_hertz.scene.toml");
  std::ifstream in(dir.path("sphere_hertz.scene.toml"));
  const json cut = run_scene(dir, std::string((std::istreambuf_iterator<char>(in)), std::istreambuf_iterator<char>()), 0);
  const json& contact = cut["contacts"][0];
  REQUIRE(contact["edge_reached_s"].is_number());
  // before the peak (half the Hertz contact time, 41.6 us; measured 24.9 us)
  CHECK(contact["edge_reached_s"].get<double>() < 41.6e-6);
  REQUIRE(cut["warnings"].size() == 1);
  CHECK(cut["warnings"][0].get<std::string>().find("edge elements of surface 'contact'") != std::string::npos);
}

TEST_CASE("a contact that rolls beyond its Craig-Bampton interface is reported", "[runtime][contact]") {
  // Scene C's disk spun at 1000 rad/s: its rim rolls about 15 mm while it touches. Its 26
  // interface points span +-5.5 mm (the SID rebuilt for this scene's 1.1 mm contact radius);
  // beyond them only normal modes deform the rim, which then presses like a rigid one. With 44
  // points the interface spans the path (bench/stability's spin case).
  const test::ScratchDir dir("interface-left");
  const std::string model = test::model_text("disk_plane_strain.model.toml");
  std::ofstream(dir.path("disk_plane_strain.model.toml")) << model;
  std::ofstream(dir.path("wide.model.toml")) << replace(model, "interface_points = 26", "interface_points = 44");
  std::string scene = test::model_text("cylinder_friction.scene.toml");
  scene = replace(scene, "end_time = 1.0e-3", "end_time = 0.5e-3");
  // 30 um up, turned back by the 0.3 rad it spins while falling: the interface's centre reaches
  // the bottom 0.3 ms on, mid-contact (the contact runs from 5 mm before it to 10.5 mm beyond)
  scene = replace(scene, "position = [0.0, 0.1000001, 0.0]", "position = [0.0, 0.10003, 0.0]\norientation = [0.0, 0.0, -0.3]\nelastic_start = \"steady\"");
  scene = replace(scene, "angular_velocity = [0.0, 0.0, 6.283185307179586]", "angular_velocity = [0.0, 0.0, 1000.0]");
  const json narrow = test::run_scene(dir, scene, 0);
  const json& left = narrow["contacts"][0];
  REQUIRE(left["interface_left_s"].is_number());
  // within the contact (measured at its first step, 5 mm before the interface's centre)
  CHECK(left["interface_left_s"].get<double>() >= left["start_s"].get<double>());
  CHECK(left["interface_left_s"].get<double>() < left["end_s"].get<double>());
  bool warned = false;
  for (const json& w : narrow["warnings"]) warned = warned || w.get<std::string>().find("beyond its Craig-Bampton interface") != std::string::npos;
  CHECK(warned);
  const json wide = test::run_scene(dir, replace(replace(scene, "disk_plane_strain.model.toml", "wide.model.toml"), "disk_plane_strain.sid.h5", "wide.sid.h5"), 0);
  CHECK(wide["contacts"][0]["interface_left_s"].is_null());
  // the rigid rim's peaks (measured 2.57 MN against 0.46 MN)
  CHECK(left["peak_force_n"].get<double>() > 3 * wide["contacts"][0]["peak_force_n"].get<double>());
  // a SID from before the points were marked is rebuilt, and the contact reported as before
  format::Sid old = format::read_sid(dir.path("disk_plane_strain.sid.h5"));
  for (format::ContactSurface& c : old.contact_surfaces) c.in_interface.resize(0);
  format::write_sid(old, dir.path("disk_plane_strain.sid.h5"));
  CHECK(test::run_scene(dir, scene, 0)["contacts"][0]["interface_left_s"] == left["interface_left_s"]);
}

TEST_CASE("scene A: the Craig-Bampton and the full modal sphere agree within 1 %", "[runtime][seed]") {
  // the same IGA model reduced both ways; the full one keeps all 990 modes (814+ of them
  // quasistatic), so the difference is the Craig-Bampton reduction error alone (measured 0.01 %)
  const test::ScratchDir dir("scene-a-full");
  const json full = run_seed_scene(dir, "sphere_hertz_full.scene.toml", "sphere_axisym_full.model.toml");
  // its Craig-Bampton twin: the Craig-Bampton sphere's reduction on the full model's mesh
  std::ofstream(dir.path("cb.model.toml")) << replace(test::model_text("sphere_axisym_full.model.toml"), "method = \"full\"",
                                                      "method = \"craig-bampton\"\nnormal_modes = 6\ninterface_surface = \"contact\"\n"
                                                      "interface_points = 16\ninterface_center = [0.0]");
  const std::string cb_scene = replace(replace(replace(test::model_text("sphere_hertz_full.scene.toml"), "sphere_axisym_full.sid.h5", "cb.sid.h5"),
                                               "sphere_axisym_full.model.toml", "cb.model.toml"),
                                       "quasistatic_above_hz = 310e3", "");
  const json cb = test::run_scene(dir, cb_scene, 0);
  check_agree(full, cb, {"peak_force_n", "contact_time_s"}, 0.01, "full", "Craig-Bampton");
}

TEST_CASE("scene A: the hierarchically refined sphere agrees with the graded one within 1 %", "[runtime][seed][thb]") {
  // the THB sphere's 25 um elements against the graded sphere's a/8 = 21 um (measured: peak
  // force 0.35 % apart, contact time 0.08 %)
  const test::ScratchDir dir("scene-a-thb");
  const json graded = run_seed_scene(dir, "sphere_hertz.scene.toml", "sphere_axisym.model.toml");
  const json thb = run_seed_scene(dir, "sphere_hertz_thb.scene.toml", "sphere_axisym_thb.model.toml");
  check_agree(graded, thb, {"peak_force_n", "contact_time_s"}, 0.01, "graded", "hierarchical");
  CHECK(rel_error(thb, "rebound_velocity_m_s") < 0.005);
  CHECK(thb["energy"]["max_rel_error"].get<double>() < 1e-5);
}

TEST_CASE("scene A: the hierarchically refined sphere under a massless boundary agrees with its Craig-Bampton twin", "[runtime][seed][thb]") {
  // the THB sphere prepared once with MacNeal's reduction, its boundary every refined function
  // on the contact surface: statically exact there, as the Craig-Bampton interface is over
  // the contact (measured: peak force 6e-6 and contact time 5e-7 apart; the two differ only
  // in the dynamic modes they keep beside the contact's statics)
  const test::ScratchDir dir("scene-a-thb-macneal");
  const json cb = run_seed_scene(dir, "sphere_hertz_thb.scene.toml", "sphere_axisym_thb.model.toml");
  const std::string cb_reduction = "method = \"craig-bampton\"\nnormal_modes = 6\ninterface_surface = \"contact\"\n"
                                   "interface_points = 16\ninterface_center = [0.0]";
  std::ofstream(dir.path("macneal.model.toml"))
      << replace(test::model_text("sphere_axisym_thb.model.toml"), cb_reduction, "method = \"macneal\"\nnormal_modes = 6\nboundary_surface = \"contact\"");
  const std::string scene = replace(replace(test::model_text("sphere_hertz_thb.scene.toml"), "sphere_axisym_thb.sid.h5", "macneal.sid.h5"),
                                    "sphere_axisym_thb.model.toml", "macneal.model.toml");
  const json macneal = test::run_scene(dir, scene, 0);
  check_agree(cb, macneal, {"peak_force_n", "contact_time_s"}, 1e-4, "Craig-Bampton", "MacNeal");
  CHECK(macneal["energy"]["max_rel_error"].get<double>() < 1e-5);
}

TEST_CASE("a contact pair of one dynamic and one quasistatic body agrees with the quasistatic pair", "[runtime][contact]") {
  // two small spheres (the golden SID: 4 normal modes and 6 interface modes) meeting head-on;
  // the high modes of each either integrated or held in static equilibrium. A quasistatic
  // Newton at a trial stage that went too deep into contact does not converge (it did at
  // 6.7 us in scene A' with one dynamic sphere): the step is restarted smaller from the last
  // accepted one. Measured: peak force and contact time 0.01 % from the quasistatic pair, energy
  // balance 3e-9 (the difference is the high modes' inertia, which quasistatic modes leave out)
  const test::ScratchDir dir("pair-mixed");
  auto pair = [&](const std::string& upper, const std::string& lower) {
    return run_scene(dir, R"(
[simulation]
dimension = "axisymmetric"
end_time = 100e-6
rtol = 1e-6
atol = 1e-12
output_interval = 1e-6
[[flexible_body]]
name = "upper"
sid = ")" + kGolden + R"(/sphere_small.sid.h5"
position = [0.0, 0.0100001, 0.0]
velocity = [0.0, -0.1, 0.0]
high_modes = ")" + upper + R"("
[[flexible_body]]
name = "lower"
sid = ")" + kGolden + R"(/sphere_small.sid.h5"
position = [0.0, -0.0100001, 0.0]
orientation = [3.141592653589793, 0.0, 0.0]
velocity = [0.0, 0.1, 0.0]
high_modes = ")" + lower + R"("
[[contact]]
name = "impact"
body = "lower"
surface = "contact"
target = "upper"
target_surface = "contact"
penalty = 5e17
)");
  };
  const json quasistatic = pair("quasistatic", "quasistatic");
  for (const auto& [upper, lower] : {std::pair{"dynamic", "quasistatic"}, std::pair{"quasistatic", "dynamic"}}) {
    INFO("upper " << upper << ", lower " << lower);
    const json mixed = pair(upper, lower);
    REQUIRE(mixed["status"] == "completed");
    for (const char* key : {"peak_force_n", "duration_s"})
      CHECK(mixed["contacts"][0][key].get<double>() == Approx(quasistatic["contacts"][0][key].get<double>()).epsilon(1e-3));
    CHECK(mixed["energy"]["max_rel_error"].get<double>() < 1e-6);
  }
}

TEST_CASE("scene A': two flexible spheres meeting head-on agree with scene A within 1 %", "[runtime][seed]") {
  // flexible-flexible contact: the lower sphere's Gauss points on the upper sphere's deformed
  // master patch, both spheres' quasistatic modes solved together (measured: 0.005 % apart)
  const test::ScratchDir dir("scene-a-pair");
  const json plane = run_seed_scene(dir, "sphere_hertz.scene.toml", "sphere_axisym.model.toml");
  const json pair = run_seed_scene(dir, "sphere_pair.scene.toml", "sphere_axisym.model.toml");
  check_agree(plane, pair, {"peak_force_n", "contact_time_s", "rebound_velocity_m_s"}, 0.01, "against the plane", "sphere pair");
  // both spheres rebound with the same speed (momentum is conserved exactly by the reaction)
  const double v_upper = pair["bodies"][0]["final_velocity"][1].get<double>(), v_lower = pair["bodies"][1]["final_velocity"][1].get<double>();
  CHECK(v_upper + v_lower == Approx(0).margin(1e-9));
  CHECK(pair["energy"]["max_rel_error"].get<double>() < 1e-5);
  // twice the speed, half the mass, radius and modulus: the same Hertz impact as on the plane
  // (both curvatures and both materials enter; equal to round-off in the bisection-free closed form)
  for (const char* key : {"peak_force_n", "contact_time_s", "contact_radius_m"})
    CHECK(pair["contacts"][0]["hertz_estimate"][key].get<double>() ==
          Approx(plane["contacts"][0]["hertz_estimate"][key].get<double>()).epsilon(1e-6));
}

TEST_CASE("scene B: rod with a spherical end, wave reflection and contact end", "[runtime][seed]") {
  const test::ScratchDir dir("scene-b");
  const json s = run_seed_scene(dir, "rod_impact.scene.toml", "rod_axisym.model.toml");
  // acceptance: the top velocity starts to reverse (the wave front arrives) at l/c within
  // 2 % (measured 0.97 %); the contact ends within 3 % of the Hertz rod's 544.4 us (measured
  // 1.1 %; see the scene file for why not 2 l/c); energy within 1 %
  for (const auto& [key, tolerance] : {std::pair{"wave_arrival_s", 0.02}, {"contact_end_s", 0.03}, {"rebound_velocity_m_s", 0.02}}) {
    INFO(key);
    CHECK(rel_error(s, key) < tolerance);
  }
  CHECK(s["energy"]["max_rel_error"].get<double>() < 0.01);
  const json& top = s["monitors"][0];
  CHECK(top["reversal_s"].get<double>() > top["arrival_s"].get<double>());
}

TEST_CASE("scene C: rotating disk with friction (momentum balance)", "[runtime][seed]") {
  const test::ScratchDir dir("scene-c");
  const json s = run_seed_scene(dir, "cylinder_friction.scene.toml", "disk_plane_strain.model.toml");
  // acceptance: final velocity and angular velocity within 2 % of the momentum balance
  for (const char* key : {"final_velocity_x_m_s", "final_velocity_y_m_s", "final_angular_velocity_rad_s"}) {
    INFO(key);
    CHECK(rel_error(s, key) < 0.02);
  }
  // friction's work on the quasistatic modes is dissipated too: the balance closes as without
  // friction (measured 1.2e-6 at mu 0.3, 1.0e-6 at mu 0.5, 1.1e-6 frictionless; it was 3.6e-3
  // and 1.0e-2 while that work was left out)
  CHECK(s["energy"]["max_rel_error"].get<double>() < 1e-5);
  std::ifstream in(dir.path("cylinder_friction.scene.toml"));
  const std::string text((std::istreambuf_iterator<char>(in)), std::istreambuf_iterator<char>());
  const json mu05 = test::run_scene(dir, replace(text, "friction = 0.3", "friction = 0.5"), 0);
  CHECK(mu05["energy"]["max_rel_error"].get<double>() < 1e-5);
  CHECK(mu05["energy"]["dissipated_j"].get<double>() > s["energy"]["dissipated_j"].get<double>());
  // line contact: the estimated half-width against the one of the run's own peak line load,
  // b = sqrt(4 P R / (pi E*)) (measured 5.5 % apart: the logarithmic approach law of a
  // cylinder depends on how the body's size is taken; 10 % is ample for choosing a mesh)
  const json& hertz = s["contacts"][0]["hertz_estimate"];
  const double E_star = 2.1e11 / (1 - 0.3 * 0.3), P = s["contacts"][0]["peak_force_n"].get<double>();  // thickness 1 m
  CHECK(hertz["contact_half_width_m"].get<double>() == Approx(std::sqrt(4 * P * 0.1 / (M_PI * E_star))).epsilon(0.1));
  // the model's elements are b/8 there ([contact_resolution]): no warning, no rebuild
  CHECK(s["warnings"].empty());
  // so the normal rebound keeps the impact speed within 0.3 % whatever the spin (with [R1]'s
  // 1 mm elements it was 0.4-1.7 % off and spin-dependent even without friction); the rim slides
  // throughout, so the rigid-body momentum balance holds as at 2 pi rad/s. Measured: -0.18 %
  // at 2 pi, 20 and 60 rad/s; spin 0, where the rim sticks (-0.25 %, 76 s of CPU under
  // regularized friction), is in bench/scene_c_spins.
  CHECK(std::abs(s["bodies"][0]["final_velocity"][1].get<double>() / 0.1 - 1) < 3e-3);
  for (const double spin : {20.0, 60.0}) {
    INFO("spin " << spin << " rad/s");
    const json spun = test::run_scene(dir, replace(text, "angular_velocity = [0.0, 0.0, 6.283185307179586]",
                                                   "angular_velocity = [0.0, 0.0, " + std::to_string(spin) + "]"), 0);
    const json& disk = spun["bodies"][0];
    CHECK(std::abs(disk["final_velocity"][1].get<double>() / 0.1 - 1) < 3e-3);
    // momentum balance, sliding throughout: v_x = -mu 2 v0, omega = spin - 2 mu 2 v0 / R
    CHECK(disk["final_velocity"][0].get<double>() == Approx(-0.06).epsilon(0.02));
    CHECK(disk["final_angular_velocity"][2].get<double>() == Approx(spin - 1.2).epsilon(0.02 * 1.2 / spin));
    CHECK(spun["energy"]["max_rel_error"].get<double>() < 1e-5);
    // the rim rolls 1.2 mm at 60 rad/s, within the interface's +-2.8 mm
    CHECK(spun["contacts"][0]["interface_left_s"].is_null());
  }
}

TEST_CASE("runtime: two runs started together on a model whose SID is missing build it once", "[runtime][sid]") {
  // the SID is checked, built and read under a lock beside it: the second run waits for the
  // first's build and reads it (without the lock both built it, one renaming over the other)
  const test::ScratchDir dir("sid_race");
  std::filesystem::copy_file(std::string(ISOSID_GOLDEN_DIR) + "/sphere_small.model.toml", dir.path("sphere.model.toml"));
  const std::string scene = test::golden_impact_scene("sphere.sid.h5");
  std::ofstream(dir.path("a.scene.toml")) << test::replace(scene, "sid = \"sphere.sid.h5\"", "sid = \"sphere.sid.h5\"\nmodel = \"sphere.model.toml\"");
  const std::string run = std::string("ISOSID_PREP=") + ISOSID_PREP_EXE + " " + ISOSID_RUN_EXE + " " + dir.path("a.scene.toml");
  const auto both = test::run_program("bash -c '" + run + " -o " + dir.path("one") + " & " + run + " -o " + dir.path("two") + " & wait'");
  INFO(both.err);
  std::size_t builds = 0;
  for (std::size_t at = both.err.find("isosid-run: building"); at != std::string::npos; at = both.err.find("isosid-run: building", at + 1)) ++builds;
  CHECK(builds == 1);
  for (const char* out : {"one", "two"})
    CHECK(json::parse(std::ifstream(dir.path(std::string(out) + "/summary.json")))["status"] == "completed");
}
