// A 3D ball dropped on a rigid plane against the axisymmetric model of the same sphere: the 3D
// contact must not be stiffer than the validated 2D one, and the elements' depth under the
// contact decides it.
#include "scene_runner.hpp"
#include "support/scene_text.hpp"

#include <catch2/catch.hpp>
#include <cmath>
#include <fstream>

using namespace isosid;
using nlohmann::json;
using test::replace;

namespace {



// The shipped 3D sphere (steel, r = 5.55 mm, MacNeal), its model `model`, falling at 1.1 m/s
// on its lower pole onto a plane.
std::string ball_scene(const std::string& model) { return test::scene_fixture("ball_on_ground.scene.toml", {{"@MODEL@", model}}); }

// The same sphere as an axisymmetric section with its contact elements at a/8 in both
// directions (the model validated against a finite-sphere FE reference), on the same plane.
json axisymmetric_run(const test::ScratchDir& dir) {
  std::string model = test::model_text("sphere_axisym.model.toml");
  model = replace(model, "youngs_modulus = 7.28e10", "youngs_modulus = 2.1e11");
  model = replace(model, "poisson_ratio = 0.33", "poisson_ratio = 0.3");
  model = replace(model, "density = 2789.0", "density = 7792.0");
  model = replace(model, "radius = 0.01", "radius = 0.00555");
  model = replace(model, "interval = [[0.0, 0.04]]", "interval = [[0.0, 0.1]]");  // 2.5 a of this impact
  model = model.substr(0, model.find("[[stress_line]]"));                        // its line is placed for r = 10 mm
  std::ofstream(dir.path("axisym.model.toml")) << model;
  std::string scene = replace(ball_scene("axisym"), "dimension = \"3d\"", "dimension = \"axisymmetric\"");
  scene = replace(scene, "integrator = \"leapfrog\"\nstep = 0.02e-6", "integrator = \"dopri5\"\nrtol = 1e-6\natol = 1e-12");
  scene = replace(scene, "velocity = [0.0, -1.1, 0.0]", "velocity = [0.0, -1.1, 0.0]\nhigh_modes = \"quasistatic\"");
  return test::run_scene(dir, scene, 0);
}

double relative(const json& a, const json& b, const std::string& key) {
  const double x = a["contacts"][0][key].get<double>(), y = b["contacts"][0][key].get<double>();
  return x / y - 1;
}

}  // namespace

TEST_CASE("a 3D ball on a plane: graded in depth under the contact it agrees with its axisymmetric model",
          "[runtime][contact][3d]") {
  const test::ScratchDir dir("ball-on-plane");
  const json axisymmetric = axisymmetric_run(dir);

  // the shipped ball: 0.14 mm elements at the pole along the surface and in depth (about a/2 of
  // this impact). At a/2 the axisymmetric model itself lies 1-2 % stiff of its converged value
  // and short by up to 2 % (bench contact-convergence), and the 3D pole adds its own discrete
  // scatter: measured +1.4 % in peak force, -3.3 % in duration; a/8 brings both within 0.7 %
  // (bench ball-on-plane)
  test::write_coarse_sphere_impactor(dir);
  const json graded = test::run_scene(dir, ball_scene("sphere_impactor_macneal"), 0);
  const double peak = relative(graded, axisymmetric, "peak_force_n"), duration = relative(graded, axisymmetric, "duration_s");
  INFO("depth-graded 3D ball against the axisymmetric model: peak " << peak << ", duration " << duration);
  CHECK(std::abs(peak) < 0.025);
  CHECK(std::abs(duration) < 0.04);

  // the same ball with its depth elements left a third of the diameter: 11-13 % stiff
  std::ofstream(dir.path("shallow.model.toml"))
      << replace(test::coarse_sphere_impactor_text(),
                 "[[refinement.graded]]\ndirection = \"eta\"\ntoward = 0.0\nsmallest = 0.14e-3\ngrowth = 1.6\n", "");
  const json shallow = test::run_scene(dir, ball_scene("shallow"), 0);
  const double shallow_peak = relative(shallow, axisymmetric, "peak_force_n");
  INFO("3D ball without depth grading: peak " << shallow_peak);
  CHECK(shallow_peak > 0.08);
}

TEST_CASE("a 3D ball on a plane: at a/8, its elements growing by 1.1, it lies within 0.3 % of its axisymmetric model",
          "[runtime][contact][3d][converged]") {
  // The converged case of bench ball-on-plane-grading: the ball's pole at a/8 of this impact's
  // Hertz radius (0.2429 mm), along the surface and in depth, its elements growing by 1.1, its
  // massless boundary the cap within 1.6 a. The axisymmetric model lies within 0.5 % of a
  // finite-sphere FE reference; 3D and 2D must agree to 0.3 % in peak force and duration
  // (measured -0.09 % and -0.25 %; growing by 1.3 instead they differ by 0.7 %, by 1.6 by 1-3 %).
  const test::ScratchDir dir("ball-on-plane-converged");
  const json axisymmetric = axisymmetric_run(dir);
  std::string model = test::coarse_sphere_impactor_text();
  model = replace(model, "[refinement]\n", "[contact_resolution]\ncontact_radius = 0.0002428601408847562\nelements_per_radius = 8\n\n[refinement]\n");
  for (int direction = 0; direction < 2; ++direction)
    model = replace(model, "smallest = 0.14e-3\ngrowth = 1.6", "smallest = \"contact\"\ngrowth = 1.1");
  model = replace(model, "interval = [[0.0, 0.06], [0.0, 1.0]]", "interval = [[0.0, 0.0446], [0.0, 1.0]]");
  std::ofstream(dir.path("converged.model.toml")) << model;
  const json converged = test::run_scene(dir, ball_scene("converged"), 0);
  const double peak = relative(converged, axisymmetric, "peak_force_n"), duration = relative(converged, axisymmetric, "duration_s");
  INFO("converged 3D ball against the axisymmetric model: peak " << peak << ", duration " << duration);
  CHECK(std::abs(peak) < 0.003);
  CHECK(std::abs(duration) < 0.003);
}

TEST_CASE("a 3D ball on a plane: at its equator, refined hierarchically, it agrees with its axisymmetric model",
          "[runtime][contact][3d][converged]") {
  // The ball in spherical coordinates hit on its equator, away from any collapsed edge of its
  // parametrization: THB refinement around the point under a MacNeal boundary, the contact in
  // gap space (tests/scenes/ball_thb_equator.model.toml, at a/4 to keep the test short; bench
  // ball-on-plane-family runs a/8: -0.19 % and -0.12 % there). Measured at a/4: -0.43 % in peak
  // force, -0.19 % in duration; the 1 % bound is a/4's distance from convergence (the pole at
  // a/4 lay 1.5 % off), far below the 11-15 % a stiff 3D contact showed.
  const test::ScratchDir dir("ball-on-plane-equator");
  const json axisymmetric = axisymmetric_run(dir);
  std::ofstream(dir.path("equator.model.toml")) << test::scene_fixture("ball_thb_equator.model.toml");
  const json equator = test::run_scene(dir, test::scene_fixture("ball_equator_on_ground.scene.toml", {{"@MODEL@", "equator"}}), 0);
  const double peak = relative(equator, axisymmetric, "peak_force_n"), duration = relative(equator, axisymmetric, "duration_s");
  INFO("3D ball at its equator against the axisymmetric model: peak " << peak << ", duration " << duration);
  CHECK(std::abs(peak) < 0.01);
  CHECK(std::abs(duration) < 0.01);
  CHECK(equator["contacts"][0]["formulation"] == "gap-space");
}
