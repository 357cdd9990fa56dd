// In-process tests of what MultibodySystem tells the user about a set-up: a body that would
// integrate hundreds of modes dynamically draws a warning naming it and the way out.
#include "solve/multibody_system.hpp"
#include "support/lumped_sid.hpp"

#include <catch2/catch.hpp>

using namespace isosid;
using Catch::Matchers::Contains;

TEST_CASE("MultibodySystem: hundreds of dynamic modes draw a warning", "[runtime][unit]") {
  const int nq = int(run::MultibodySystem::kManyDynamicModes) + 10;
  format::Sid sid = test::lumped_sid(test::random_lumped_body(90, nq, 3));
  run::Scene scene;
  scene.file = "in-process";
  scene.simulation.end_time = 1e-3;
  run::BodySpec body;
  body.name = "plate";
  scene.bodies.push_back(body);

  SECTION("all modes dynamic") {
    const run::MultibodySystem system(scene, {sid});
    REQUIRE(system.warnings().size() == 1);
    CHECK_THAT(system.warnings()[0], Contains("body 'plate' integrates " + std::to_string(nq) + " modes dynamically"));
    CHECK_THAT(system.warnings()[0], Contains("high_modes = \"quasistatic\""));
  }
  SECTION("quasistatic asked for, but the SID marks no high modes") {
    scene.bodies[0].high_modes = "quasistatic";
    const run::MultibodySystem system(scene, {sid});
    REQUIRE(system.warnings().size() == 1);
    CHECK_THAT(system.warnings()[0], Contains("set quasistatic_above_hz"));
  }
  SECTION("a split that still keeps hundreds of modes dynamic") {
    scene.bodies[0].high_modes = "quasistatic";
    scene.bodies[0].quasistatic_above_hz = sid.refmod.frequencies_hz(nq - 2);
    const run::MultibodySystem system(scene, {sid});
    REQUIRE(system.warnings().size() == 1);
    CHECK_THAT(system.warnings()[0], Contains("lower quasistatic_above_hz"));
  }
  SECTION("a split that keeps few modes dynamic") {
    scene.bodies[0].high_modes = "quasistatic";
    scene.bodies[0].quasistatic_above_hz = sid.refmod.frequencies_hz(9);
    const run::MultibodySystem system(scene, {sid});
    CHECK(system.warnings().empty());
  }
}
