// The scene reader in-process: values the run could not honour are refused with one message
// naming the field (exit 2 in isosid-run), and their neighbours inside the ranges are kept.
#include "scene/scene.hpp"
#include "isosid/format/error.hpp"
#include "support/run_program.hpp"
#include "support/impact_scene.hpp"
#include "support/scene_text.hpp"

#include <catch2/catch.hpp>
#include <fstream>
#include <string>

using namespace isosid;
using Catch::Matchers::Contains;
using test::replace;

namespace {

const std::string kGolden = ISOSID_GOLDEN_DIR, kModels = ISOSID_MODELS_DIR;

const std::string kImpact = test::golden_impact_scene(kGolden + "/sphere_small.sid.h5");

run::Scene read(const test::ScratchDir& dir, const std::string& text) {
  std::ofstream(dir.path("s.scene.toml")) << text;
  return run::read_scene_file(dir.path("s.scene.toml"));
}

/// The scene is refused with an InputError whose message holds `expected`.
void refused(const test::ScratchDir& dir, const std::string& text, const std::string& expected) {
  INFO(expected);
  try {
    read(dir, text);
    FAIL("accepted");
  } catch (const format::InputError& e) {
    CHECK_THAT(e.what(), Contains(expected));
    CHECK(std::string(e.what()).find('\n') == std::string::npos);
  }
}

}  // namespace

TEST_CASE("scene file: tolerances outside the range the step control can honour are refused", "[runtime][unit][scene][bad-input]") {
  const test::ScratchDir dir("scene-tolerances");
  for (const char* rtol : {"10.0", "1.0", "0.11", "1e-13", "1e-300"})
    refused(dir, replace(kImpact, "rtol = 1e-6", std::string("rtol = ") + rtol), "s.scene.toml: simulation.rtol: must lie in [1e-12, 0.1]");
  for (const char* atol : {"1e300", "1.0", "1.1e-6"})
    refused(dir, replace(kImpact, "atol = 1e-12", std::string("atol = ") + atol), "simulation.atol: must lie in (0, 1e-6]");
  // the ends of the ranges are kept
  const run::Scene loose = read(dir, replace(replace(kImpact, "rtol = 1e-6", "rtol = 0.1"), "atol = 1e-12", "atol = 1e-6"));
  CHECK(loose.simulation.rtol == 0.1);
  CHECK(loose.simulation.atol == 1e-6);
  CHECK(read(dir, replace(kImpact, "rtol = 1e-6", "rtol = 1e-12")).simulation.rtol == 1e-12);
}

TEST_CASE("scene file: expected warnings are kinds the run knows", "[runtime][unit][scene][bad-input]") {
  const test::ScratchDir dir("scene-expected-warnings");
  refused(dir, kImpact + "[output]\nexpected_warnings = [\"resolution\", \"resolutoin\"]\n",
          "output.expected_warnings: 'resolutoin' is no kind of warning (resolution, many_dynamic_modes");
  refused(dir, kImpact + "[output]\nexpected_warnings = \"resolution\"\n", "output.expected_warnings");
  CHECK(read(dir, kImpact + "[output]\nexpected_warnings = [\"resolution\", \"closed_at_end\"]\n").output.expected_warnings ==
        std::vector<std::string>{"resolution", "closed_at_end"});
}

TEST_CASE("scene file: a friction regularization no solver can follow, or one that leaves no friction, is refused",
          "[runtime][unit][scene][bad-input]") {
  const test::ScratchDir dir("scene-regularization");
  const std::string friction = replace(kImpact, "penalty = 5e17", "penalty = 5e17\nfriction = 0.3");
  for (const char* eps : {"1e-300", "9.9e-10", "1.5", "1e300"})
    refused(dir, friction + "regularization = " + eps + "\n", "contact[0].regularization: must lie in [1e-9, 1] m/s");
  CHECK(read(dir, friction + "regularization = 1e-9\n").contacts[0].regularization == 1e-9);
  CHECK(read(dir, friction + "regularization = 1.0\n").contacts[0].regularization == 1.0);
}

TEST_CASE("scene file: motion a planar or axisymmetric scene, or a locked DOF, would drop is refused", "[runtime][unit][scene][bad-input]") {
  const test::ScratchDir dir("scene-motion");
  const std::string along_axis = "an axisymmetric scene moves its bodies along the axis only";
  for (const char* v : {"[5.0, -0.1, 0.0]", "[1e-9, -0.1, 0.0]", "[0.0, -0.1, 0.2]"})
    refused(dir, replace(kImpact, "velocity = [0.0, -0.1, 0.0]", std::string("velocity = ") + v), "flexible_body[0].velocity: " + along_axis);
  for (const char* w : {"[0.0, 0.0, 50.0]", "[0.0, 1.0, 0.0]", "[1e-6, 0.0, 0.0]"})
    refused(dir, replace(kImpact, "velocity = [0.0, -0.1, 0.0]", std::string("velocity = [0.0, -0.1, 0.0]\nangular_velocity = ") + w),
            "flexible_body[0].angular_velocity: " + along_axis);
  for (const char* o : {"[0.0, 0.0, 1.0]", "[0.0, 0.3, 0.0]", "[1e-9, 0.0, 0.0]", "[3.0, 0.0, 0.0]"})
    refused(dir, replace(kImpact, "velocity = [0.0, -0.1, 0.0]", std::string("velocity = [0.0, -0.1, 0.0]\norientation = ") + o),
            "flexible_body[0].orientation: " + along_axis);
  // turned over, the body keeps the axis (a sphere facing up)
  for (const char* o : {"[3.141592653589793, 0.0, 0.0]", "[0.0, 0.0, 3.141592653589793]"})
    CHECK(read(dir, replace(kImpact, "velocity = [0.0, -0.1, 0.0]", std::string("velocity = [0.0, -0.1, 0.0]\norientation = ") + o))
              .bodies[0].tait_bryan.norm() > 3);
  refused(dir, replace(kImpact, "[[fixed_plane]]", "[[rigid_body]]\nname = \"ball\"\nshape = \"sphere\"\nradius = 0.01\ndensity = 1.0\n"
                                                   "position = [0.0, 0.05, 0.0]\nvelocity = [0.1, 0.0, 0.0]\n[[fixed_plane]]"),
          "rigid_body[0].velocity: " + along_axis);
  // a locked DOF of a 3D body drops its velocity just as well
  const std::string solid = replace(kImpact, "dimension = \"axisymmetric\"", "dimension = \"3d\"");
  refused(dir, replace(solid, "velocity = [0.0, -0.1, 0.0]", "velocity = [0.0, -0.1, 0.0]\nlocked = [\"y\"]"),
          "flexible_body[0].velocity: moves along the locked DOF 'y'");
  refused(dir, replace(solid, "velocity = [0.0, -0.1, 0.0]", "velocity = [0.0, -0.1, 0.0]\nangular_velocity = [0.0, 0.0, 1.0]\nlocked = [\"rz\"]"),
          "flexible_body[0].angular_velocity: turns about the locked DOF 'rz'");
  // along the axis, and motion within the plane of a planar scene, are kept
  CHECK(read(dir, kImpact).bodies[0].velocity.y() == -0.1);
  const std::string planar = "a planar scene moves its bodies in the x-y plane only";
  const std::string in_plane = replace(replace(kImpact, "dimension = \"axisymmetric\"", "dimension = \"planar\""), "velocity = [0.0, -0.1, 0.0]",
                                       "velocity = [0.3, -0.1, 0.0]\nangular_velocity = [0.0, 0.0, 5.0]\norientation = [0.0, 0.0, 0.5]");
  CHECK(read(dir, in_plane).bodies[0].angular_velocity.z() == 5.0);
  refused(dir, replace(in_plane, "velocity = [0.3, -0.1, 0.0]", "velocity = [0.3, -0.1, 0.01]"), "flexible_body[0].velocity: " + planar);
  refused(dir, replace(in_plane, "angular_velocity = [0.0, 0.0, 5.0]", "angular_velocity = [1.0, 0.0, 5.0]"),
          "flexible_body[0].angular_velocity: " + planar);
  refused(dir, replace(in_plane, "orientation = [0.0, 0.0, 0.5]", "orientation = [0.0, 0.2, 0.5]"), "flexible_body[0].orientation: " + planar);
  CHECK(read(dir, replace(in_plane, "orientation = [0.0, 0.0, 0.5]", "orientation = [3.141592653589793, 0.0, 0.5]")).bodies[0].tait_bryan.x() > 3);
}

TEST_CASE("scene file: speeds and gravity beyond any solid's are refused under their own names", "[runtime][unit][scene][bad-input]") {
  const test::ScratchDir dir("scene-magnitudes");
  for (const char* v : {"[0.0, -1e308, 0.0]", "[0.0, -2.1e4, 0.0]"})
    refused(dir, replace(kImpact, "velocity = [0.0, -0.1, 0.0]", std::string("velocity = ") + v), "flexible_body[0].velocity: a speed of");
  CHECK(read(dir, replace(kImpact, "velocity = [0.0, -0.1, 0.0]", "velocity = [0.0, -1e4, 0.0]")).bodies[0].velocity.y() == -1e4);
  for (const char* g : {"[0.0, -1e308, 0.0]", "[0.0, -1.1e8, 0.0]"})
    refused(dir, replace(kImpact, "output_interval = 1e-6", std::string("output_interval = 1e-6\ngravity = ") + g),
            "simulation.gravity: ");
  CHECK(read(dir, replace(kImpact, "output_interval = 1e-6", "output_interval = 1e-6\ngravity = [0.0, -1e7, 0.0]")).gravity.y() == -1e7);
}

TEST_CASE("scene file: every named item has a non-empty name without '/', and names are unique", "[runtime][unit][scene][bad-input]") {
  const test::ScratchDir dir("scene-names");
  const std::string problem = ": must be a non-empty name without '/'";
  for (const char* name : {"sph/ere", "/", "a/", ""})
    refused(dir, replace(kImpact, "name = \"sphere\"", std::string("name = \"") + name + "\""), "flexible_body[0].name" + problem);
  refused(dir, replace(kImpact, "name = \"ground\"", "name = \"gro/und\""), "fixed_plane[0].name" + problem);
  refused(dir, replace(kImpact, "name = \"impact\"", "name = \"im/pact\""), "contact[0].name" + problem);
  refused(dir, kImpact + "[[monitor]]\nname = \"v/w\"\nbody = \"sphere\"\nstress = \"axis\"\n", "monitor[0].name" + problem);
  refused(dir, kImpact + "[[rigid_body]]\nname = \"b/all\"\nshape = \"sphere\"\nradius = 0.01\ndensity = 1.0\nposition = [0.0, 0.1, 0.0]\n",
          "rigid_body[0].name" + problem);
  const std::string solid = replace(kImpact, "dimension = \"axisymmetric\"", "dimension = \"3d\"");
  refused(dir, solid + "[[joint]]\nname = \"pi/vot\"\ntype = \"spherical\"\nbody = \"sphere\"\nnode = \"top\"\n", "joint[0].name" + problem);
  const std::string balls = "[[rigid_body]]\nname = \"a\"\nshape = \"sphere\"\nradius = 0.01\ndensity = 1.0\nposition = [0.0, 0.1, 0.0]\n"
                            "[[rigid_body]]\nname = \"b\"\nshape = \"sphere\"\nradius = 0.01\ndensity = 1.0\nposition = [0.0, 0.2, 0.0]\n";
  refused(dir, kImpact + balls + "[[hertz_contact]]\nname = \"a/b\"\nbody = \"a\"\ntarget = \"b\"\nyoungs_modulus = 1e9\npoisson_ratio = 0.3\n",
          "hertz_contact[0].name" + problem);
  refused(dir, kImpact + "[[monitor]]\nname = \"sphere\"\nbody = \"sphere\"\nstress = \"axis\"\n", "monitor[0].name: duplicate name 'sphere'");
}

TEST_CASE("scene file: exact contact under an adaptive integrator is refused", "[runtime][unit][scene][bad-input]") {
  const test::ScratchDir dir("scene-exact");
  refused(dir, replace(kImpact, "target = \"ground\"", "target = \"ground\"\nenforcement = \"exact\""),
          "contact[0].enforcement: exact contact needs integrator = \"leapfrog\"");
  const std::string implicit = replace(kImpact, "rtol = 1e-6", "integrator = \"implicit\"\nrtol = 1e-6");
  refused(dir, replace(implicit, "target = \"ground\"", "target = \"ground\"\nenforcement = \"exact\""),
          "contact[0].enforcement: exact contact needs integrator = \"leapfrog\"");
}

TEST_CASE("scene file: a contact's law is a law of surface contact from the table", "[runtime][unit][scene][bad-input]") {
  const test::ScratchDir dir("scene-law");
  refused(dir, replace(kImpact, "target = \"ground\"", "target = \"ground\"\nlaw = \"hooke\""),
          "contact[0].law: 'hooke' is not a law of surface contact (penalty)");
  // Hertz's law is between two spheres ([[hertz_contact]]), not a pressure on a surface's points
  refused(dir, replace(kImpact, "target = \"ground\"", "target = \"ground\"\nlaw = \"hertz\""),
          "contact[0].law: 'hertz' is not a law of surface contact");
  CHECK(read(dir, replace(kImpact, "target = \"ground\"", "target = \"ground\"\nlaw = \"penalty\"")).contacts[0].law == "penalty");
  CHECK(read(dir, kImpact).contacts[0].law == "penalty");
}

TEST_CASE("scene file: an adaptive body's coarse step limit is held to max_steps like max_step", "[runtime][unit][scene][bad-input]") {
  const test::ScratchDir dir("scene-coarse-step");
  const std::string adaptive = replace(kImpact, "sid = \"" + kGolden + "/sphere_small.sid.h5\"",
                                       "adaptive = true\nmodel = \"" + kModels + "/sphere_axisym_thb.model.toml\"");
  for (const char* step : {"1e-300", "1e-12"})
    refused(dir, adaptive + "[adaptive]\ncoarse_max_step = " + step + "\n",
            "adaptive.coarse_max_step: end_time / coarse_max_step needs at least");
  CHECK(read(dir, adaptive + "[adaptive]\ncoarse_max_step = 1e-10\n").adaptive.coarse_max_step == 1e-10);
}

TEST_CASE("scene file: integrators are named by their table, and the fixed-step one takes a step", "[runtime][unit][scene][bad-input]") {
  const test::ScratchDir dir("scene-integrators");
  // every row's name reads back as its kind, and the message for an unknown one lists them all
  const std::string names = run::integrator_names();
  CHECK(names == "dopri5, implicit, leapfrog");
  for (const run::IntegratorKind kind : {run::IntegratorKind::DormandPrince, run::IntegratorKind::Implicit, run::IntegratorKind::Leapfrog}) {
    const std::optional<run::IntegratorKind> back = run::integrator_named(run::integrator_name(kind));
    REQUIRE(back);
    CHECK(*back == kind);
  }
  CHECK_FALSE(run::integrator_named("euler"));
  CHECK(run::fixed_step(run::IntegratorKind::Leapfrog));
  CHECK_FALSE(run::fixed_step(run::IntegratorKind::DormandPrince));
  CHECK_FALSE(run::fixed_step(run::IntegratorKind::Implicit));
  refused(dir, replace(kImpact, "[simulation]\n", "[simulation]\nintegrator = \"euler\"\n"),
          "simulation.integrator: unknown integrator 'euler' (" + names + ")");
  // a fixed-step scheme needs its step and has no tolerances to honour
  refused(dir, replace(kImpact, "[simulation]\n", "[simulation]\nintegrator = \"leapfrog\"\n"), "simulation.step");
  refused(dir, replace(kImpact, "[simulation]\n", "[simulation]\nintegrator = \"leapfrog\"\nstep = 1e-8\n"),
          "simulation.rtol: not used by the leapfrog integrator");
  CHECK(read(dir, replace(kImpact, "[simulation]\n", "[simulation]\nintegrator = \"implicit\"\n")).simulation.integrator ==
        run::IntegratorKind::Implicit);
}
