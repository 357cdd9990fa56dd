// In-process tests of MultibodySystem: what it tells the user about a set-up (a body that
// would integrate hundreds of modes dynamically draws a warning naming it and the way out),
// and its answer to a repeated right-hand side.
#include "isosid/format/sid_io.hpp"
#include "scene/scene.hpp"
#include "solve/multibody_system.hpp"
#include "support/lumped_sid.hpp"
#include "support/run_program.hpp"

#include <fstream>

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

TEST_CASE("MultibodySystem: a repeated right-hand side answers from the call before, and only then", "[runtime][unit]") {
  const test::ScratchDir dir("repeated_rhs");
  std::ofstream(dir.path("s.scene.toml")) << "[simulation]\ndimension = \"axisymmetric\"\nend_time = 1e-4\n"
                                          << "[[flexible_body]]\nname = \"sphere\"\nsid = \"" << ISOSID_GOLDEN_DIR
                                          << "/sphere_small.sid.h5\"\nposition = [0.0, 0.0099995, 0.0]\nvelocity = [0.0, -0.1, 0.0]\n"
                                          << "high_modes = \"quasistatic\"\n[[fixed_plane]]\nname = \"ground\"\n"
                                          << "[[contact]]\nname = \"c\"\nbody = \"sphere\"\nsurface = \"contact\"\ntarget = \"ground\"\n"
                                          << "penalty = 5e17\n";
  const run::Scene scene = run::read_scene_file(dir.path("s.scene.toml"));
  const run::MultibodySystem system(scene, {format::read_sid(scene.bodies[0].sid_file)});
  Eigen::VectorXd y1(system.size()), y2, first(system.size()), other(system.size()), again(system.size()), repeat(system.size());
  system.initial_state(y1.data());  // 0.5 um into the plane: the static solve has contact to resolve
  y2 = y1;
  y2(1) -= 2e-7;
  system.rhs(0, y1.data(), first.data());
  REQUIRE(first.norm() > 0);
  system.rhs(0, y2.data(), other.data());
  REQUIRE((other - first).norm() > 1e-3 * first.norm());  // the states differ in their contact forces
  const long repeated = system.rhs_cost().repeated;
  system.rhs(0, y1.data(), again.data());  // not the state of the call before: evaluated anew
  CHECK(system.rhs_cost().repeated == repeated);
  // from another warm start the static solve ends elsewhere within its tolerance (1e-11 of the
  // solution); the forces agree far inside this bound
  CHECK((again - first).norm() <= 1e-8 * first.norm());
  system.rhs(0, y1.data(), repeat.data());  // the state of the call before: its answer
  CHECK(system.rhs_cost().repeated == repeated + 1);
  CHECK(repeat == again);
}
