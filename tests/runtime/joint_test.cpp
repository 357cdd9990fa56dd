// Joints (runtime/joint): pendulums against their closed-form periods, reactions against
// statics, a revolute joint holding a body whose principal axes are tilted against its hinge,
// a fixed joint making two bodies one, a chaotic double pendulum's energy and drift, and a
// flexible beam swinging from a SID node. Bad joint input: exit 2, one line.
#include "scene_runner.hpp"

#include <Eigen/Dense>
#include <catch2/catch.hpp>
#include <cmath>
#include <string>

using nlohmann::json;
using isosid::test::run_scene;

namespace {
const std::string kGolden = ISOSID_GOLDEN_DIR;
constexpr double kG = 9.81;

std::string number(double x) {
  char s[40];
  std::snprintf(s, sizeof s, "%.17g", x);
  return s;
}
std::string vec(const Eigen::Vector3d& v) { return "[" + number(v.x()) + ", " + number(v.y()) + ", " + number(v.z()) + "]"; }

std::string simulation(double end_time, double rtol = 1e-10) {
  return "[simulation]\ndimension = \"3d\"\nend_time = " + number(end_time) + "\nrtol = " + number(rtol) +
         "\natol = 1e-12\noutput_interval = " + number(end_time / 200) + "\ngravity = [0.0, -9.81, 0.0]\n";
}

Eigen::Vector3d final_position(const json& s, int body) {
  const auto& p = s["bodies"][body]["final_position"];
  return {p[0].get<double>(), p[1].get<double>(), p[2].get<double>()};
}
Eigen::Vector3d final_velocity(const json& s, int body) {
  const auto& p = s["bodies"][body]["final_velocity"];
  return {p[0].get<double>(), p[1].get<double>(), p[2].get<double>()};
}
}  // namespace

TEST_CASE("joints: a rigid sphere on a spherical joint swings with the physical pendulum's period", "[runtime][joint]") {
  // steel sphere r 5 cm, 1 m below the pivot, released at 0.01 rad: T = 2 pi sqrt(I_O / (m g L))
  // (1 + theta^2 / 16). After one period it is back where it started and at rest; the pivot
  // carries m g cos(theta) there
  const double r = 0.05, rho = 7850, L = 1, theta = 0.01;
  const double m = 4.0 / 3 * M_PI * r * r * r * rho, I_O = 0.4 * m * r * r + m * L * L;
  const double period = 2 * M_PI * std::sqrt(I_O / (m * kG * L)) * (1 + theta * theta / 16);
  const Eigen::Vector3d start(L * std::sin(theta), -L * std::cos(theta), 0);
  const isosid::test::ScratchDir dir("joint-pendulum");
  const json s = run_scene(dir, simulation(period) + R"(
[[rigid_body]]
name = "bob"
shape = "sphere"
radius = 0.05
density = 7850.0
position = )" + vec(start) + R"(
[[joint]]
name = "pivot"
type = "spherical"
body = "bob"
point = [0.0, 0.0, 0.0]
)");
  // the period to 1e-6 (the amplitude term is 6e-6; measured: back to 2e-12 m, at rest to 7e-12 m/s,
  // against a peak speed of 0.031 m/s)
  CHECK((final_position(s, 0) - start).norm() < 1e-6 * theta * L);
  CHECK(final_velocity(s, 0).norm() < 1e-6 * theta * std::sqrt(kG * L));
  const json& pivot = s["joints"][0];
  CHECK(pivot["max_position_error_m"].get<double>() < 1e-12);
  CHECK(std::hypot(pivot["final_force_n"][0].get<double>(), pivot["final_force_n"][1].get<double>()) ==
        Approx(m * kG * std::cos(theta)).epsilon(1e-9));
  CHECK(s["energy"]["max_rel_error"].get<double>() < 1e-10);
}

TEST_CASE("joints: a revolute joint holds a tilted box to its hinge", "[runtime][joint]") {
  // a box 0.4 x 0.1 x 0.05 m turned 30 degrees about y, hinged about the world z axis at a point
  // 0.3 m above its centre: its principal axes are tilted against the hinge, so swinging makes
  // gyroscopic and inertial moments across the hinge that the joint must carry. It swings
  // about z only, with the period of I_zz about the hinge: T = 2 pi sqrt(I_O / (m g d))
  const Eigen::Vector3d half(0.2, 0.05, 0.025);
  const double rho = 2700, m = 8 * half.prod() * rho, d = 0.3, theta = 0.01, tilt = M_PI / 6;
  const Eigen::Vector3d I_principal(m / 3 * (half.y() * half.y() + half.z() * half.z()), m / 3 * (half.x() * half.x() + half.z() * half.z()),
                                    m / 3 * (half.x() * half.x() + half.y() * half.y()));
  const Eigen::Matrix3d R = Eigen::AngleAxisd(tilt, Eigen::Vector3d::UnitY()).toRotationMatrix();
  const Eigen::Matrix3d I_world = R * I_principal.asDiagonal() * R.transpose();
  const double period = 2 * M_PI * std::sqrt((I_world(2, 2) + m * d * d) / (m * kG * d)) * (1 + theta * theta / 16);
  // rotate the hanging box by theta about the hinge axis through the pivot at the origin
  const Eigen::Matrix3d swing = Eigen::AngleAxisd(theta, Eigen::Vector3d::UnitZ()).toRotationMatrix();
  const Eigen::Vector3d centre = swing * Eigen::Vector3d(0, -d, 0);
  const Eigen::Vector3d angles = (swing * R).eulerAngles(0, 1, 2);  // x-y-z Tait-Bryan, as the scene takes them
  const isosid::test::ScratchDir dir("joint-revolute");
  const json s = run_scene(dir, simulation(period) + R"(
[[rigid_body]]
name = "box"
shape = "box"
size = [0.4, 0.1, 0.05]
density = 2700.0
position = )" + vec(centre) + R"(
orientation = )" + vec(angles) + R"(
[[joint]]
name = "hinge"
type = "revolute"
body = "box"
point = [0.0, 0.0, 0.0]
axis = [0.0, 0.0, 1.0]
)");
  CHECK((final_position(s, 0) - centre).norm() < 1e-6 * theta * d);
  CHECK(std::abs(final_position(s, 0).z()) < 1e-12);  // no motion along the hinge
  const json& hinge = s["joints"][0];
  CHECK(hinge["max_position_error_m"].get<double>() < 1e-12);
  CHECK(hinge["max_angle_error_rad"].get<double>() < 1e-12);
  CHECK(hinge["peak_torque_n_m"].get<double>() > 0);  // the tilt loads the hinge across its axis
  CHECK(s["energy"]["max_rel_error"].get<double>() < 1e-10);
}
