// Contact solved in gap space (condensation/gap_space_solve.hpp) against the general path on the
// same SIDs: the seed sphere on a short free beam, both massless boundaries condensed onto the
// sphere's contact points. The two differ only in the pairing: gap space keeps each point's
// target point and normal from when it was paired, the general path projects every point anew
// at every pass. So on one discretization they must give one impact.
#include "isosid/format/sid_io.hpp"
#include "scene/scene.hpp"
#include "paired_step_observer.hpp"
#include "scene_runner.hpp"
#include "support/impact_scene.hpp"
#include "support/scene_text.hpp"
#include "support/one_line_exit.hpp"

#include <catch2/catch.hpp>
#include <algorithm>
#include <cmath>
#include <cstdio>
#include <fstream>
#include <nlohmann/json.hpp>

using namespace isosid;
using nlohmann::json;

namespace {
double relative(const json& a, const json& b) { return std::abs(a.get<double>() / b.get<double>() - 1); }

/// The impact's figures of two runs of one scene that must agree: to `tolerance`, the duration
/// to `duration_tolerance`.
void check_same_impact(const json& gap, const json& general, double tolerance, double duration_tolerance) {
  const json &c = gap["contacts"][0], &g = general["contacts"][0];
  CHECK(relative(c["peak_force_n"], g["peak_force_n"]) < tolerance);
  CHECK(relative(c["duration_s"], g["duration_s"]) < duration_tolerance);
  CHECK(relative(c["impulse_ns"], g["impulse_ns"]) < tolerance);
  CHECK(relative(gap["bodies"][0]["final_velocity"][1], general["bodies"][0]["final_velocity"][1]) < tolerance);
}
/// While the contact is paired, evaluates every pair as the run does and through the pair's
/// own displacement rows, and keeps the largest difference of the deformed points.
struct FactoredRowsObserver : test::PairedStepObserver {
  bool slave_factored = false, target_factored = false;
  double largest_difference = 0, largest_displacement = 0;  ///< m
  void paired_step(const run::SurfaceContact& c, const run::GapPairing& pairing, const double* y) override {
    slave_factored = slave_factored || pairing.slave_factored();
    target_factored = target_factored || pairing.target_factored();
    const run::GapPairing::Poses poses = pairing.poses(y);
    run::GapPairing::Evaluation e;
    for (std::size_t k = 0; k < pairing.pairs().size(); ++k) {
      const run::GapPairing::Pair& p = pairing.pairs()[k];
      pairing.evaluate(poses, k, e);
      // as evaluate() forms them from the rows: the reference point, then the rows' product added
      Eigen::Vector3d slave = c.surface().position.row(p.g).transpose(), target = p.target_point;
      p.slave_rows.add_product(*poses.q_slave, slave);
      p.target_rows.add_product(*poses.q_target, target);
      largest_displacement = std::max({largest_displacement, (slave - c.surface().position.row(p.g).transpose()).norm(),
                                       (target - p.target_point).norm()});
      largest_difference = std::max({largest_difference, (e.slave_point - slave).norm(), (e.target_point - target).norm()});
    }
  }
};

/// Runs dir's sphere_on_free_beam scene in gap space in process (its SIDs prepared by a run
/// through isosid-run) with a FactoredRowsObserver.
FactoredRowsObserver run_observed(const test::ScratchDir& dir, const std::string& body_lines) {
  std::string scene = test::sphere_on_free_beam_scene("formulation = \"gap-space\"\n");
  for (const std::string model : {"model = \"beam.model.toml\"", "model = \"sphere_impactor_macneal.model.toml\""})
    scene = test::replace(scene, model, model + "\n" + body_lines);
  REQUIRE_FALSE(test::run_scene(dir, scene).is_null());
  const run::Scene parsed = run::read_scene_file(dir.path("s.scene.toml"));
  run::Simulation simulation(parsed, {format::read_sid(parsed.bodies[0].sid_file), format::read_sid(parsed.bodies[1].sid_file)});
  FactoredRowsObserver observer;
  observer.simulation = &simulation;
  REQUIRE(simulation.run(observer).completed());
  return observer;
}
}  // namespace

TEST_CASE("gap space: dense rows are evaluated through the control points that carry them, to round-off", "[runtime][gap-space]") {
  // Craig-Bampton bodies whose high modes are quasistatic: every mode moves every surface
  // control point, so each point's rows fill all modes (300-500 per row) and the pairs are
  // evaluated through their control points' displacements. A massless boundary's rows read
  // a point's few control points' own coordinates: they stay the cheaper form.
  const test::ScratchDir dir("gap-space-factored");
  std::string sphere = test::coarse_sphere_impactor_text(), beam = test::free_beam_model();
  std::ofstream(dir.path("sphere_impactor_macneal.model.toml")) << sphere;
  std::ofstream(dir.path("beam.model.toml")) << beam;
  const FactoredRowsObserver macneal = run_observed(dir, "");
  CHECK(macneal.paired_steps > 100);
  CHECK_FALSE(macneal.slave_factored);
  CHECK_FALSE(macneal.target_factored);
  CHECK(macneal.largest_difference == 0);

  // the interfaces: all 145 control points of the sphere's lower side, the beam's 100 nearest
  // the impact
  sphere = test::replace(sphere, "method = \"macneal\"", "method = \"craig-bampton\"");
  sphere = test::replace(sphere, "boundary_surface = \"contact\"", "interface_surface = \"contact\"\ninterface_points = 145\ninterface_center = [0.0, 0.5]");
  beam = test::replace(beam, "method = \"macneal\"", "method = \"craig-bampton\"");
  beam = test::replace(beam, "boundary_surface = \"impact\"", "interface_surface = \"impact\"\ninterface_points = 100\ninterface_center = [0.5, 0.5]");
  std::ofstream(dir.path("sphere_impactor_macneal.model.toml")) << sphere;
  std::ofstream(dir.path("beam.model.toml")) << beam;
  std::remove(dir.path("sphere.sid.h5").c_str()), std::remove(dir.path("beam.sid.h5").c_str());
  const FactoredRowsObserver cb = run_observed(dir, "high_modes = \"quasistatic\"");
  INFO("largest difference " << cb.largest_difference << " m of displacements up to " << cb.largest_displacement << " m");
  CHECK(cb.paired_steps > 100);
  CHECK(cb.slave_factored);
  CHECK(cb.target_factored);
  // the same sums in another order. A row's terms cancel to far below their size (the
  // interface modes' columns are orders above the normal modes'), so the round-off is 1e-11 of
  // the displacement (measured 8.4e-17 m of 8.0e-6 m); a wrong carrier would be off by the
  // displacement itself
  CHECK(cb.largest_displacement > 1e-6);
  CHECK(cb.largest_difference < 1e-9 * cb.largest_displacement);
}

TEST_CASE("gap space: impacts on a beam equal the general path's on the same SIDs, slides re-pair, a second impact pairs again", "[runtime][massless][gap-space]") {
  const test::ScratchDir dir("gap-space");
  test::write_coarse_sphere_impactor(dir);
  std::ofstream(dir.path("beam.model.toml")) << test::free_beam_model();
  const std::string gap_space = "formulation = \"gap-space\"\n";

  // centric: the points approach along their pairs, one pairing holds the whole impact. The
  // shipped sphere on the 210 mm beam (0.14 mm elements under the contact, half its radius)
  // agrees to 0.007 % in peak force and 2e-5 % in duration (bench/RESULTS.md,
  // "gap-space-two-paths"). This beam's quadratic elements are 0.3 mm, a whole contact radius:
  // the deformed surface's normal turns within an element, and the general path, which follows
  // it, releases the last points 0.07 us (0.22 %) later than the pairs' normals do (measured;
  // peak force +0.04 %, impulse and rebound 5e-5)
  const json general = test::run_scene(dir, test::sphere_on_free_beam_scene(""));
  const json gap = test::run_scene(dir, test::sphere_on_free_beam_scene(gap_space));
  check_same_impact(gap, general, 5e-4, 3e-3);
  CHECK(general["contacts"][0]["formulation"] == "general");
  CHECK_FALSE(general["contacts"][0].contains("pairs"));
  const json& c = gap["contacts"][0];
  CHECK(c["formulation"] == "gap-space");
  CHECK(c["pairs"].get<int>() > 0);
  CHECK(c["pairings"].get<int>() == 1);
  CHECK(c["repairings"].get<int>() == 0);
  // only the pairs within the Hertz estimate's reach are condensed, and none beyond pressed
  INFO("pairs " << c["pairs"] << ", condensed " << c["condensed_points"]);
  CHECK(c["condensed_points"].get<int>() < c["pairs"].get<int>());
  CHECK(c["reach_widenings"].get<int>() == 0);
  // the steps' time split by load: every step counted once, and the loaded ones span the
  // contact in 0.1 us steps (within a step at either end)
  const json& split = gap["step_time_s"];
  CHECK(split["loaded_steps"].get<long>() + split["unloaded_steps"].get<long>() == gap["steps"].get<long>());
  CHECK(std::abs(double(split["loaded_steps"].get<long>()) - c["duration_s"].get<double>() / 0.1e-6) <= 2);
  CHECK(split["loaded"].get<double>() > 0);
  CHECK(split["loaded"].get<double>() + split["unloaded"].get<double>() <= gap["wall_time_s"].get<double>());
  // the beam's modes take the same energy (1F and 3F carry 4-9 % of it); found by label, since
  // an index may hold a mode the impact does not excite, whose share is round-off (1e-31)
  for (const std::string label : {"1F", "3F"}) {
    const auto share = [&](const json& contact) {
      for (const json& mode : contact["impact_modes"]["modes"])
        if (mode["label"] == label) return mode["energy_ratio"].get<double>();
      FAIL("no mode labelled " << label);
      return 0.0;
    };
    INFO(label);
    CHECK(share(c) > 0.01);
    CHECK(relative(share(c), share(general["contacts"][0])) < 1e-3);
  }

  // sliding along the beam at 0.5 m/s (frictionless): the points slide past their pairs by
  // about 16 um over the impact, and the contact is paired again each time they pass a quarter
  // of their spacing (43 times; measured against the general path as above: peak +0.04 %,
  // duration -0.19 %)
  const std::string oblique = "[0.5, -1.1, 0.0]";
  const json general_slide = test::run_scene(dir, test::sphere_on_free_beam_scene("", oblique));
  const json gap_slide = test::run_scene(dir, test::sphere_on_free_beam_scene(gap_space, oblique));
  CHECK(gap_slide["contacts"][0]["repairings"].get<int>() > 10);
  check_same_impact(gap_slide, general_slide, 5e-4, 3e-3);

  // the beam held and a strong gravity (5e3 m/s^2) bring the sphere back: it rises 64 um, the
  // pairing is released at 19 um and its pairs watch the gap until it closes again, when the
  // contact is paired anew (measured: both impacts end within 3e-6 of each other's time)
  std::string bounce = test::replace(test::sphere_on_free_beam_scene(""), "end_time = 40e-6", "end_time = 480e-6\ngravity = [0.0, -5e3, 0.0]");
  bounce = test::replace(bounce, "model = \"beam.model.toml\"", "model = \"beam.model.toml\"\nlocked = [\"x\", \"y\", \"z\", \"rx\", \"ry\", \"rz\"]");
  const json general_bounce = test::run_scene(dir, bounce);
  const json gap_bounce = test::run_scene(dir, bounce + gap_space);
  REQUIRE(general_bounce["contacts"][0]["intervals"].get<int>() == 2);
  CHECK(gap_bounce["contacts"][0]["intervals"].get<int>() == 2);
  CHECK(gap_bounce["contacts"][0]["pairings"].get<int>() == 2);
  CHECK(relative(gap_bounce["contacts"][0]["end_s"], general_bounce["contacts"][0]["end_s"]) < 1e-4);
  check_same_impact(gap_bounce, general_bounce, 5e-4, 3e-3);
}

TEST_CASE("gap space: a contact it cannot solve is refused in one line naming the field", "[runtime][gap-space]") {
  const test::ScratchDir dir("gap-space-refused");
  test::write_coarse_sphere_impactor(dir);
  std::ofstream(dir.path("beam.model.toml")) << test::free_beam_model();
  for (const std::string& lines : {std::string("formulation = \"gap-space\"\nfriction = 0.2\n"),
                                   std::string("formulation = \"gap-space\"\nenforcement = \"exact\"\n"),
                                   std::string("formulation = \"condensed\"\n")}) {
    std::ofstream(dir.path("s.scene.toml")) << test::sphere_on_free_beam_scene(lines);
    const auto r = test::run_program(std::string(ISOSID_RUN_EXE) + " " + dir.path("s.scene.toml") + " -o " + dir.path("out"));
    INFO(lines);
    test::check_one_line_exit(r, 2, "contact[0].formulation: ");
  }
}

TEST_CASE("gap space: a contact that outgrows its Hertz estimate widens its condensed points and presses as on the general path", "[runtime][massless][gap-space]") {
  const test::ScratchDir dir("gap-space-widened");
  test::write_coarse_sphere_impactor(dir);
  std::ofstream(dir.path("beam.model.toml")) << test::free_beam_model();
  // the sphere lands at 0.2 m/s on the held beam under a gravity of 1e5 m/s^2 (its weight 560
  // N) and stays on it: the estimate at the pairing counts the approach speed alone, so the
  // contact grows beyond the points it first condenses, whose pairs beyond then show gaps that
  // would close. Widened, the forces are those of every pair condensed (measured with the reach
  // unbounded: peak force 7e-12 apart). Against the general path, which follows the deformed
  // normals the pairs keep (see above), measured: largest force 1.4e-5, impulse over 120 us 3.8e-4
  std::string scene = test::replace(test::sphere_on_free_beam_scene("", "[0.0, -0.2, 0.0]"), "end_time = 40e-6", "end_time = 120e-6\ngravity = [0.0, -1e5, 0.0]");
  scene = test::replace(scene, "model = \"beam.model.toml\"", "model = \"beam.model.toml\"\nlocked = [\"x\", \"y\", \"z\", \"rx\", \"ry\", \"rz\"]");
  const json general = test::run_scene(dir, scene);
  const json gap = test::run_scene(dir, scene + "formulation = \"gap-space\"\n");
  const json& c = gap["contacts"][0];
  INFO("pairs " << c["pairs"] << ", condensed " << c["condensed_points"] << ", widened " << c["reach_widenings"] << ", peak "
                << c["peak_force_n"] << " / " << general["contacts"][0]["peak_force_n"]);
  CHECK(c["reach_widenings"].get<int>() > 0);
  CHECK(c["condensed_points"].get<int>() < c["pairs"].get<int>());
  CHECK(relative(c["peak_force_n"], general["contacts"][0]["peak_force_n"]) < 5e-4);
  CHECK(relative(c["impulse_ns"], general["contacts"][0]["impulse_ns"]) < 1e-3);
}
