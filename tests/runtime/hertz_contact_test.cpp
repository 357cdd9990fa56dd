// Hertz's law between rigid spheres (runtime/contact/hertz_contact, [R2]'s reference model "Hertz",
// docs/references.md): a head-on impact of two free spheres against the closed-form solution and
// bad input; and the static start of a rigid ball hanging from a flexible rod (scene E's
// pendulum), whose frame follows the rod's sag.
#include "scene_runner.hpp"
#include "support/impact_scene.hpp"

#include "isosid/format/hdf5_file.hpp"
#include "isosid/format/sid_io.hpp"

#include <catch2/catch.hpp>
#include <cmath>
#include <iomanip>
#include <string>

using nlohmann::json;
using isosid::test::run_scene;
using isosid::test::two_spheres;

TEST_CASE("hertz contact: two rigid spheres meet head-on as Hertz's solution says", "[runtime][hertz]") {
  // Equal steel spheres r = 10 mm closing at 2 v: m* = m/2, R* = r/2, K = 4/3 E* sqrt(R*).
  // Energy 1/2 m* (2v)^2 = 2/5 K d^(5/2) at the deepest overlap d; the contact lasts
  // 2 (d / 2v) int_0^1 (1 - x^(5/2))^(-1/2) dx = (d / 2v) 0.8 B(2/5, 1/2) (Johnson 1985, 11.2).
  const isosid::test::ScratchDir dir("hertz-two-spheres");
  const double v = 0.5, r = 0.01, rho = 7850, E = 2.1e11, nu = 0.3;
  const double m = rho * 4.0 / 3.0 * M_PI * r * r * r, m_star = m / 2, R_star = r / 2;
  const double E_star = E / (2 * (1 - nu * nu)), K = 4.0 / 3.0 * E_star * std::sqrt(R_star);
  const double d = std::pow(5.0 / 4.0 * m_star * 4 * v * v / K, 0.4);
  const double beta = std::tgamma(0.4) * std::tgamma(0.5) / std::tgamma(0.9);
  const double duration = d / (2 * v) * 0.8 * beta, peak = K * std::pow(d, 1.5);
  const json s = run_scene(dir, two_spheres(v));
  REQUIRE(s.is_object());
  const json& h = s["hertz_contacts"][0];
  REQUIRE(h["impacts"].size() == 1);
  const json& impact = h["impacts"][0];
  INFO("peak " << impact["peak_force_n"].get<double>() << " N (Hertz " << peak << "), duration "
               << impact["duration_s"].get<double>() << " s (" << duration << ")");
  // the stiffness itself to round-off
  CHECK(h["stiffness_n_m1_5"].get<double>() == Approx(K).epsilon(1e-12));
  // the peak from the deepest overlap between steps at most 20 ns apart (1/3500 of the
  // contact): even the largest force at the steps would be within 1.5 (pi 20 ns / 2 T)^2 / 2
  // = 1.5e-7 of it; the integration (rtol 1e-10) adds far less
  CHECK(impact["peak_force_n"].get<double>() == Approx(peak).epsilon(2e-6));
  // onset and release interpolate the gap linearly between steps where it moves at 2 v: exact
  // but for its curvature, (2e-8 s)^2 x acceleration / 2v, about 1e-12 s each
  CHECK(impact["duration_s"].get<double>() == Approx(duration).epsilon(1e-6));
  CHECK(impact["start_s"].get<double>() == Approx(2e-7 / (2 * v)).epsilon(1e-6));
  // elastic: the spheres swap their velocities; the energy (kinetic + Hertz) holds
  CHECK(s["bodies"][0]["final_velocity"][0].get<double>() == Approx(-v).epsilon(1e-7));
  CHECK(s["bodies"][1]["final_velocity"][0].get<double>() == Approx(v).epsilon(1e-7));
  CHECK(s["energy"]["max_rel_error"].get<double>() < 1e-8);
  CHECK(impact["impulse_ns"].get<double>() == Approx(2 * m * v).epsilon(1e-5));
}

TEST_CASE("hertz contact: the peak between coarse steps is that of the deepest overlap", "[runtime][hertz]") {
  // Scene E's Hertz variant takes about 20 steps in an impact, and the largest force at the
  // steps fell 0.3 % short of the peak, a sixth of the 2 % tolerance on peak forces. Here dopri5 at
  // rtol 1e-9 (max_step 4 us) takes about 0.4 us near the peak of a 67 us contact: the largest
  // force at the steps missed by 7e-5 before the interpolation (1.5 (pi h / 2T)^2 / 2 = 7e-5 for
  // h = 0.41 us). The cubic through the two steps around the deepest overlap errs by
  // h^4 |g''''| / 384, about 0.5 (h / T)^4 = 7e-10 of the overlap; the integration's own
  // error dominates (the peak lands 2e-8 from Hertz's), well inside 1e-6.
  const isosid::test::ScratchDir dir("hertz-coarse-steps");
  const double v = 0.5, r = 0.01, rho = 7850, E = 2.1e11, nu = 0.3;
  const double m_star = rho * 4.0 / 3.0 * M_PI * r * r * r / 2, R_star = r / 2;
  const double K = 4.0 / 3.0 * E / (2 * (1 - nu * nu)) * std::sqrt(R_star);
  const double d = std::pow(5.0 / 4.0 * m_star * 4 * v * v / K, 0.4), peak = K * std::pow(d, 1.5);
  const json s = run_scene(dir, two_spheres(v, "", "rtol = 1e-9\natol = 1e-14\nmax_step = 4e-6\n"));
  REQUIRE(s.is_object());
  const json& impact = s["hertz_contacts"][0]["impacts"][0];
  INFO(std::setprecision(10) << "peak " << impact["peak_force_n"].get<double>() << " N (Hertz " << peak << "), " << s["steps"].get<long>() << " steps");
  CHECK(impact["peak_force_n"].get<double>() == Approx(peak).epsilon(1e-6));
  // by symmetry the deepest overlap is at the middle of the contact: onset and release are
  // interpolated to about 1e-12 s (test above) and the cubic's minimum to far less, so 1e-6
  // of the time (3e-11 s) leaves a margin of 30
  CHECK(impact["peak_time_s"].get<double>() == Approx(0.5 * (impact["start_s"].get<double>() + s["hertz_contacts"][0]["impacts"][0]["end_s"].get<double>())).epsilon(1e-6));
}

TEST_CASE("static start: a rigid ball hanging from a flexible rod follows its sag", "[runtime][hertz][joint]") {
  // Scene E's pendulum rod (models/pendulum_rod.model.toml, 20 modes) hangs from a hinge at
  // its top with a rigid ball hinged to its lower end. Started in its static deflection, the
  // rod stretches under its own weight and the ball's; the ball's frame follows (the static
  // start moves the frames of the bodies jointed to a settled one; held where it was placed,
  // the ball would pull the hinge apart and no equilibrium exists). Then nothing moves and the
  // top hinge carries both weights.
  const isosid::test::ScratchDir dir("static-hanging-ball");
  isosid::test::copy_model_file(dir, "pendulum_rod.model.toml");
  const double m_ball = 0.1, g = 9.81;
  const json s = run_scene(dir, R"([simulation]
dimension = "3d"
end_time = 2e-3
rtol = 1e-9
atol = 1e-13
output_interval = 1e-5
gravity = [0.0, -9.81, 0.0]
[[flexible_body]]
name = "rod"
sid = "rod.sid.h5"
model = "pendulum_rod.model.toml"
position = [0.0, -0.4, 0.0]
elastic_start = "static"
[[rigid_body]]
name = "ball"
shape = "sphere"
radius = 0.01
mass = 0.1
position = [0.0, -0.41, 0.0]
[[joint]]
name = "suspension"
type = "revolute"
body = "rod"
node = "top"
[[joint]]
name = "elbow"
type = "revolute"
body = "rod"
node = "bottom"
other = "ball"
point = [0.0, -0.4, 0.0]
)");
  REQUIRE(s.is_object());
  const isosid::format::h5::Reader results(dir.path("out-s.scene.toml/results.h5"));
  const Eigen::MatrixXd ball = results.matrix("/bodies/ball/position"), q = results.matrix("/bodies/rod/q");
  const double sag = -0.41 - ball(0, 1);  // the ball's frame moved down with the rod's stretch
  const double motion = (ball.rowwise() - ball.row(0)).cwiseAbs().maxCoeff();
  const double ringing = (q.rowwise() - q.row(0)).cwiseAbs().maxCoeff();
  INFO("sag " << sag << " m, ball motion " << motion << " m, rod modes move by " << ringing << " of " << q.row(0).cwiseAbs().maxCoeff());
  // the stretch under the ball's weight alone is m g l / (E A) = 3.7e-8 m: the ball sits lower
  // by about that, and stays there to a thousandth of it
  CHECK(sag > 1e-8);
  CHECK(sag < 1e-7);
  CHECK(motion < 1e-3 * sag);
  CHECK(ringing < 1e-3 * q.row(0).cwiseAbs().maxCoeff());
  const auto& force = s["joints"][0]["final_force_n"];
  const double rod_mass = isosid::format::read_sid(dir.path("rod.sid.h5")).refmod.mass;
  // the weights, to the static solve's floor (1e-7 of the accelerations it removes)
  CHECK(std::hypot(force[0].get<double>(), force[1].get<double>(), force[2].get<double>()) ==
        Approx((rod_mass + m_ball) * g).epsilon(1e-6));
}

TEST_CASE("hertz contact: bad input is refused with exit 2", "[runtime][hertz][bad-input]") {
  const isosid::test::ScratchDir dir("hertz-bad");
  const std::string good = two_spheres(0.5);
  struct Case {
    const char *from, *to;
  };
  for (const Case& c : {Case{"target = \"b\"", "target = \"nobody\""},
                        Case{"target = \"b\"", "target = \"a\""},
                        Case{"poisson_ratio = 0.3", "poisson_ratio = 0.7"},
                        Case{"youngs_modulus = 2.1e11", "youngs_modulus = -1.0"},
                        Case{"poisson_ratio = 0.3", "poisson_ratio = 0.3\nfriction = 0.1"}}) {
    INFO(c.to);
    const std::string text = isosid::test::replace(good, c.from, c.to);
    run_scene(dir, text, 2);  // exit 2 with one line naming the scene file and field
  }
  // with an adaptive body: its phases' results would be joined without the Hertz contact
  isosid::test::copy_model_file(dir, "pendulum_ball.model.toml");
  run_scene(dir, good + "[[flexible_body]]\nname = \"ball\"\nmodel = \"pendulum_ball.model.toml\"\nadaptive = true\nposition = [0.0, 1.0, 0.0]\n", 2);
}
