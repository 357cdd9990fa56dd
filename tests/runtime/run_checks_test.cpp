// A scene against its loaded bodies, in-process: a leapfrog step beyond the stability limit of
// the integrated modes and a steady start spinning faster than the lowest natural frequency
// are refused before the run, naming the field; values just inside are kept.
#include "isosid/format/error.hpp"
#include "isosid/format/sid_io.hpp"
#include "solve/simulation.hpp"
#include "solve/step_collapse.hpp"

#include <catch2/catch.hpp>
#include <cmath>
#include <numbers>

using namespace isosid;
using Catch::Matchers::Contains;

namespace {

const std::string kBeam = std::string(ISOSID_GOLDEN_DIR) + "/beam_small.sid.h5";

run::Scene beam_scene() {
  run::Scene scene;
  scene.file = "in-process";
  scene.simulation.dimension = run::Dimension::Solid;
  scene.simulation.end_time = 1e-3;
  scene.simulation.output_interval = 1e-4;
  run::BodySpec beam;
  beam.name = "beam";
  scene.bodies.push_back(beam);
  return scene;
}

}  // namespace

TEST_CASE("run checks: a leapfrog step beyond 2/omega_max of the integrated modes is refused", "[runtime][unit][bad-input]") {
  const format::Sid sid = format::read_sid(kBeam);
  const double limit = 2 / (2 * std::numbers::pi * sid.refmod.frequencies_hz.maxCoeff());
  run::Scene scene = beam_scene();
  scene.simulation.integrator = run::IntegratorKind::Leapfrog;
  scene.simulation.step = 1.01 * limit;
  CHECK_THROWS_WITH(run::Simulation(scene, {sid}),
                    Contains("in-process: simulation.step: ") && Contains("exceeds the leapfrog's stability limit 2/omega_max") &&
                        Contains("of body 'beam'"));
  scene.simulation.step = 0.99 * limit;
  CHECK_NOTHROW(run::Simulation(scene, {sid}));
  // modes made quasistatic are not integrated: their frequencies set no limit
  scene.simulation.step = 1.01 * limit;
  scene.bodies[0].high_modes = "quasistatic";
  scene.bodies[0].quasistatic_above_hz = 0.5 * sid.refmod.frequencies_hz.maxCoeff();
  CHECK_NOTHROW(run::Simulation(scene, {sid}));
}

TEST_CASE("run checks: a steady start spinning faster than the lowest natural frequency is refused", "[runtime][unit][bad-input]") {
  const format::Sid sid = format::read_sid(kBeam);
  const double lowest = 2 * std::numbers::pi * sid.refmod.frequencies_hz.minCoeff();
  run::Scene scene = beam_scene();
  scene.bodies[0].elastic_start = "steady";
  scene.bodies[0].angular_velocity = {0, 0, 1.01 * lowest};
  CHECK_THROWS_WITH(run::Simulation(scene, {sid}), Contains("in-process: flexible_body[0].angular_velocity: ") &&
                                                      Contains("exceeds the lowest natural frequency of 'beam'") &&
                                                      Contains("no steady state"));
  scene.bodies[0].angular_velocity = {0, 0, 0.5 * lowest};
  CHECK_NOTHROW(run::Simulation(scene, {sid}));
  // at rest the spin is the body's own business
  scene.bodies[0].elastic_start = "rest";
  scene.bodies[0].angular_velocity = {0, 0, 1.01 * lowest};
  CHECK_NOTHROW(run::Simulation(scene, {sid}));
}

TEST_CASE("run checks: steps collapsed far below the time scale for long end the run, a dip does not", "[runtime][unit]") {
  // the safety net behind the penalty's ceiling: time scale 1e-6 s, so steps under 1e-15 s count
  const double scale = 1e-6, collapsed = 0.5 * run::kCollapsedStepRatio * scale;
  run::StepCollapse dip(scale);
  double t = 0;
  dip.observe(t);
  for (long i = 0; i + 1 < run::kCollapsedSteps; ++i) dip.observe(t += collapsed);
  dip.observe(t += 1e-9);  // one normal step resets the count
  for (long i = 0; i + 1 < run::kCollapsedSteps; ++i) dip.observe(t += collapsed);
  run::StepCollapse crawl(scale);
  t = 0;
  crawl.observe(t);
  for (long i = 0; i + 1 < run::kCollapsedSteps; ++i) crawl.observe(t += collapsed);
  try {
    crawl.observe(t += collapsed);
    FAIL("not ended");
  } catch (const format::ComputationError& e) {
    CHECK_THAT(e.what(), Contains("the steps collapsed to 5e-16 s") && Contains("for 1000 steps in a row"));
  }
}
