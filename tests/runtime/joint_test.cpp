// Joints (runtime/joint): pendulums against their closed-form periods, reactions against
// statics, a revolute joint holding a body whose principal axes are tilted against its hinge,
// a fixed joint making two bodies one, a chaotic double pendulum's energy and drift, a
// flexible beam swinging from a SID node, and flexible bodies that start in their static
// deflection. Bad joint input: exit 2, one line.
#include "scene_runner.hpp"
#include "support/scene_text.hpp"

#include "isosid/format/hdf5_file.hpp"
#include "isosid/format/sid_io.hpp"

#include <Eigen/Dense>
#include <catch2/catch.hpp>
#include <cmath>
#include <fstream>
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

/// A rigid steel sphere of radius 5 cm named `name`: its table, `lines` (position, velocity ...) appended.
std::string steel_ball(const std::string& name, const std::string& lines) {
  return "[[rigid_body]]\nname = \"" + name + "\"\nshape = \"sphere\"\nradius = 0.05\ndensity = 7850.0\n" + lines + "\n";
}

/// A rigid aluminium box of 0.4 x 0.1 x 0.05 m named `name`: its table, `lines` appended.
std::string aluminium_box(const std::string& name, const std::string& lines) {
  return "[[rigid_body]]\nname = \"" + name + "\"\nshape = \"box\"\nsize = [0.4, 0.1, 0.05]\ndensity = 2700.0\n" + lines + "\n";
}

/// A joint of `type` named `name` on `body`: its table, `lines` (point, node, other, axis) appended.
std::string joint(const std::string& name, const std::string& type, const std::string& body, const std::string& lines) {
  return "[[joint]]\nname = \"" + name + "\"\ntype = \"" + type + "\"\nbody = \"" + body + "\"\n" + lines + "\n";
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
  const json s = run_scene(dir, simulation(period) + steel_ball("bob", "position = " + vec(start)) +
                                    joint("pivot", "spherical", "bob", "point = [0.0, 0.0, 0.0]"));
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
  const json s = run_scene(dir, simulation(period) + aluminium_box("box", "position = " + vec(centre) + "\norientation = " + vec(angles)) +
                                    joint("hinge", "revolute", "box", "point = [0.0, 0.0, 0.0]\naxis = [0.0, 0.0, 1.0]"));
  CHECK((final_position(s, 0) - centre).norm() < 1e-6 * theta * d);
  CHECK(std::abs(final_position(s, 0).z()) < 1e-12);  // no motion along the hinge
  const json& hinge = s["joints"][0];
  CHECK(hinge["max_position_error_m"].get<double>() < 1e-12);
  CHECK(hinge["max_angle_error_rad"].get<double>() < 1e-12);
  CHECK(hinge["peak_torque_n_m"].get<double>() > 0);  // the tilt loads the hinge across its axis
  CHECK(s["energy"]["max_rel_error"].get<double>() < 1e-10);
}


TEST_CASE("joints: a fixed joint makes two bodies fall and spin as one", "[runtime][joint]") {
  // a steel sphere fixed to the end of an aluminium box, thrown spinning under gravity: the
  // pair's centre of mass falls freely, the joint keeps their relative pose, the energy holds
  const Eigen::Vector3d half(0.2, 0.05, 0.025), c_box(0, 0, 0), c_ball(0.25, 0, 0);
  const double m_box = 8 * half.prod() * 2700, m_ball = 4.0 / 3 * M_PI * 0.05 * 0.05 * 0.05 * 7850;
  const Eigen::Vector3d C = (m_box * c_box + m_ball * c_ball) / (m_box + m_ball), V(0.3, 1.0, 0), w(0, 0, 2);
  auto velocity = [&](const Eigen::Vector3d& c) { return Eigen::Vector3d(V + w.cross(c - C)); };
  const double t_end = 0.5;
  const isosid::test::ScratchDir dir("joint-fixed");
  auto moving = [&](const Eigen::Vector3d& c) {
    return "position = " + vec(c) + "\nvelocity = " + vec(velocity(c)) + "\nangular_velocity = " + vec(w);
  };
  const json s = run_scene(dir, simulation(t_end) + aluminium_box("box", moving(c_box)) + steel_ball("ball", moving(c_ball)) +
                                    joint("weld", "fixed", "ball", "other = \"box\"\npoint = [0.2, 0.0, 0.0]"));
  const Eigen::Vector3d C_end = (m_box * final_position(s, 0) + m_ball * final_position(s, 1)) / (m_box + m_ball);
  const Eigen::Vector3d expected = C + V * t_end + 0.5 * Eigen::Vector3d(0, -kG, 0) * t_end * t_end;
  CHECK((C_end - expected).norm() < 1e-9);
  // they stay 0.25 m apart, centre to centre, and spin at the same rate
  CHECK((final_position(s, 1) - final_position(s, 0)).norm() == Approx(0.25).epsilon(1e-9));
  CHECK(s["bodies"][0]["final_angular_velocity"][2].get<double>() == Approx(2.0).epsilon(1e-9));
  CHECK(s["bodies"][1]["final_angular_velocity"][2].get<double>() == Approx(2.0).epsilon(1e-9));
  CHECK(s["joints"][0]["max_angle_error_rad"].get<double>() < 1e-10);
  CHECK(s["energy"]["max_rel_error"].get<double>() < 1e-10);
}

namespace {
/// Planar double pendulum of two rigid bodies on two pin joints: angles from the downward
/// vertical, Lagrange's equations, classic RK4 with a fine fixed step (the independent
/// reference of the joint solver).
Eigen::Vector4d double_pendulum(double m1, double I1, double a1, double l1, double m2, double I2, double a2,
                                Eigen::Vector4d x, double t_end) {
  auto f = [&](const Eigen::Vector4d& s) {
    const double d = s(0) - s(1);
    Eigen::Matrix2d M;
    M << I1 + m1 * a1 * a1 + m2 * l1 * l1, m2 * l1 * a2 * std::cos(d), m2 * l1 * a2 * std::cos(d), I2 + m2 * a2 * a2;
    const Eigen::Vector2d rhs(-m2 * l1 * a2 * std::sin(d) * s(3) * s(3) - (m1 * a1 + m2 * l1) * kG * std::sin(s(0)),
                              m2 * l1 * a2 * std::sin(d) * s(2) * s(2) - m2 * kG * a2 * std::sin(s(1)));
    const Eigen::Vector2d acc = M.partialPivLu().solve(rhs);
    return Eigen::Vector4d(s(2), s(3), acc(0), acc(1));
  };
  const int steps = 200000;
  const double h = t_end / steps;
  for (int i = 0; i < steps; ++i) {
    const Eigen::Vector4d k1 = f(x), k2 = f(x + 0.5 * h * k1), k3 = f(x + 0.5 * h * k2), k4 = f(x + h * k3);
    x += h / 6 * (k1 + 2 * k2 + 2 * k3 + k4);
  }
  return x;
}
}  // namespace

TEST_CASE("joints: a double pendulum of two rigid bodies follows Lagrange's equations", "[runtime][joint]") {
  // released from the horizontal: bob 1 (centre 0.5 m from the pivot, elbow at 0.75 m), bob 2
  // (centre 0.25 m beyond the elbow); after 1 s of large motion both centres against the
  // reference to 1e-6 m (measured 3e-14 m; bob 2 has swung past the vertical)
  const double r = 0.05, m = 4.0 / 3 * M_PI * r * r * r * 7850, I = 0.4 * m * r * r, t_end = 1.0;
  const isosid::test::ScratchDir dir("joint-double");
  const json s = run_scene(dir, simulation(t_end) + steel_ball("upper", "position = [0.5, 0.0, 0.0]") +
                                    steel_ball("lower", "position = [1.0, 0.0, 0.0]") +
                                    joint("shoulder", "spherical", "upper", "point = [0.0, 0.0, 0.0]") +
                                    joint("elbow", "spherical", "lower", "other = \"upper\"\npoint = [0.75, 0.0, 0.0]"));
  const Eigen::Vector4d end = double_pendulum(m, I, 0.5, 0.75, m, I, 0.25, Eigen::Vector4d(M_PI / 2, M_PI / 2, 0, 0), t_end);
  const Eigen::Vector3d upper(0.5 * std::sin(end(0)), -0.5 * std::cos(end(0)), 0);
  const Eigen::Vector3d lower(0.75 * std::sin(end(0)) + 0.25 * std::sin(end(1)), -0.75 * std::cos(end(0)) - 0.25 * std::cos(end(1)), 0);
  CHECK((final_position(s, 0) - upper).norm() < 1e-6);
  CHECK((final_position(s, 1) - lower).norm() < 1e-6);
  for (int k = 0; k < 2; ++k) CHECK(s["joints"][k]["max_position_error_m"].get<double>() < 1e-10);
  CHECK(s["energy"]["max_rel_error"].get<double>() < 1e-9);
}

TEST_CASE("joints: a flexible beam swings from a SID node with the rigid pendulum's period", "[runtime][joint]") {
  // the golden steel beam (0.21 x 0.01 x 0.015 m, 6 modes from 1.2 kHz) hangs from the node at
  // the centre of its end face on a spherical joint, released at 0.01 rad: its lowest mode lies
  // 900 times above the swing, so the period is the rigid physical pendulum's to 1e-6
  // (T = 2 pi sqrt((J_zz + m d^2) / (m g d)) with the SID's mass and inertia); the energy
  // balance holds with the modes' damping counted
  const isosid::format::Sid sid = isosid::format::read_sid(kGolden + "/beam_small.sid.h5");
  const isosid::format::Node& node = sid.nodes.at(0);
  const double m = sid.refmod.mass, theta = 0.01;
  const Eigen::Vector3d cm = sid.mdCM.M0.col(0) / m, pivot_local = node.origin.M0.col(0);
  const double d = (cm - pivot_local).norm();
  const double J_zz = sid.J.M0(2, 2) - m * (cm.x() * cm.x() + cm.y() * cm.y());  // about the centre of mass
  const double period = 2 * M_PI * std::sqrt((J_zz + m * d * d) / (m * kG * d)) * (1 + theta * theta / 16);
  const Eigen::Matrix3d A = Eigen::AngleAxisd(M_PI / 2 + theta, Eigen::Vector3d::UnitZ()).toRotationMatrix();
  const Eigen::Vector3d r = -A * pivot_local;  // the node at the world origin
  // with its modes integrated, and with all of them quasistatic (as an adaptive body's refined
  // model has them): the joint then holds the node as the frame moves it (joint/joint.hpp)
  for (const std::string modes : {"", "high_modes = \"quasistatic\"\nquasistatic_above_hz = 100.0\n"}) {
    INFO(modes);
    const isosid::test::ScratchDir dir(modes.empty() ? "joint-beam" : "joint-beam-quasistatic");
    const json s = run_scene(dir, simulation(period, 1e-9) + R"(
[[flexible_body]]
name = "beam"
sid = ")" + kGolden + R"(/beam_small.sid.h5"
position = )" + vec(r) + R"(
orientation = [0.0, 0.0, )" + number(M_PI / 2 + theta) + R"(]
)" + modes + joint("pivot", "spherical", "beam", "node = \"end\""));
    REQUIRE(s.is_object());
    CHECK(s["bodies"][0]["quasistatic_modes"].get<int>() == (modes.empty() ? 0 : 6));
    // back where it started after one period, to 1e-6 of its swing, and at rest
    const Eigen::Vector3d r_end = final_position(s, 0);
    const Eigen::Vector3d v_end = final_velocity(s, 0);
    CHECK((r_end - r).norm() < 1e-6 * theta * d);
    CHECK(v_end.norm() < 1e-5 * theta * std::sqrt(kG * d));
    CHECK(s["joints"][0]["max_position_error_m"].get<double>() < 1e-10);
    CHECK(s["energy"]["max_rel_error"].get<double>() < 1e-8);
  }
}

TEST_CASE("joints: a clamped beam with a static start stays at rest in its deflection", "[runtime][joint]") {
  // Static equilibrium is what stays at rest: released undeformed (elastic_start = "rest") the
  // golden beam clamped at its end node rings about its deflection under gravity; started in
  // it ("static"), its modes and its frame do not move (the clamped node stays where it was
  // placed) and the clamp carries the weight, m g. Horizontal and inclined, so that bending
  // and axial loads both enter.
  const isosid::format::Sid sid = isosid::format::read_sid(kGolden + "/beam_small.sid.h5");
  const double weight = sid.refmod.mass * kG;
  struct Case {
    const char* name;
    double angle;  // of the beam's axis from horizontal, rad
  };
  for (const Case& c : {Case{"horizontal", 0.0}, Case{"30 degrees down", -M_PI / 6}}) {
    double rest_motion = 0;
    for (const char* start : {"rest", "static"}) {
      const isosid::test::ScratchDir dir(std::string("joint-static-") + start);
      const json s = run_scene(dir, simulation(5e-3, 1e-8) + R"(
[[flexible_body]]
name = "beam"
sid = ")" + kGolden + R"(/beam_small.sid.h5"
orientation = [0.0, 0.0, )" + number(c.angle) + R"(]
elastic_start = ")" + start + "\"\n" + joint("clamp", "fixed", "beam", "node = \"end\""));
      REQUIRE(s.is_object());
      const isosid::format::h5::Reader results(dir.path("out-s.scene.toml/results.h5"));
      const Eigen::MatrixXd q = results.matrix("/bodies/beam/q"), qdot = results.matrix("/bodies/beam/qdot");
      const Eigen::MatrixXd v = results.matrix("/bodies/beam/velocity");
      const double motion = (q.rowwise() - q.row(0)).cwiseAbs().maxCoeff();
      INFO(c.name << ", " << start << " start: modes move by " << motion << " (deflection " << q.row(0).cwiseAbs().maxCoeff()
                  << "), largest modal rate " << qdot.cwiseAbs().maxCoeff() << ", frame speed " << v.cwiseAbs().maxCoeff());
      if (std::string(start) == "rest") {
        rest_motion = motion;
        REQUIRE(rest_motion > 0);  // the undeformed start does ring
        continue;
      }
      // the deflection is there, and nothing moves: what moves is what the static solve leaves
      // in the accelerations, down to its round-off floor (accepted up to 1e-7 of those it
      // removes; Newton's best iterate lands between 1.5e-10 and 4e-9 of them here, depending
      // on the rounding of the joint reactions, and the motion follows at about 5x that)
      CHECK(q.row(0).cwiseAbs().maxCoeff() > 0.1 * rest_motion);
      CHECK(motion < 1e-6 * rest_motion);
      CHECK(v.cwiseAbs().maxCoeff() < 1e-9);
      // the clamp carries the weight to what the static solve leaves in the accelerations (its
      // round-off floor may stand up to 1e-7 of those it removed; measured 1.2e-8 horizontal)
      const auto& force = s["joints"][0]["final_force_n"];
      CHECK(std::abs(Eigen::Vector3d(force[0].get<double>(), force[1].get<double>(), force[2].get<double>()).norm() - weight) <
            1e-7 * weight);
      CHECK(s["joints"][0]["max_position_error_m"].get<double>() < 1e-12);
    }
  }
}

TEST_CASE("static start: a held cantilever sags as far with quasistatic modes as with every mode integrated",
          "[runtime][quasistatic]") {
  // A steel cantilever (210 x 10 x 15 mm, clamped at x = 0), its frame locked and turned, under
  // gravity: its 12 clamped modes integrated, or only the first (190 Hz) with the rest
  // quasistatic, among them the 285 Hz bending that carries most of the sag. The static start
  // solves K q = Ct^T A^T g for the integrated modes, the static solve for the quasistatic ones:
  // both are the one static equilibrium of the reduced model, whichever modes are integrated.
  // A held frame does not accelerate, so gravity must load the quasistatic modes through their
  // Ct rows (nonzero for a clamped body's modes), in body axes; without that load they did not
  // sag at all. The turn makes a gravity taken in world axes show.
  const std::string model = isosid::test::scene_fixture("cantilever.model.toml");
  json summary[2];
  Eigen::VectorXd q[2];
  for (int quasistatic = 0; quasistatic < 2; ++quasistatic) {
    const isosid::test::ScratchDir dir(std::string("held-sag-") + (quasistatic ? "quasistatic" : "integrated"));
    std::ofstream(dir.path("cantilever.model.toml")) << model;
    summary[quasistatic] = run_scene(dir, std::string(R"(
[simulation]
dimension = "3d"
end_time = 1e-4
output_interval = 1e-4
gravity = [0.0, 0.0, -9.81]
[[flexible_body]]
name = "beam"
sid = "cantilever.sid.h5"
model = "cantilever.model.toml"
orientation = [0.4, 0.7, 0.2]
locked = ["x", "y", "z", "rx", "ry", "rz"]
elastic_start = "static"
)") + (quasistatic ? "high_modes = \"quasistatic\"\nquasistatic_above_hz = 250.0\n" : ""));
    REQUIRE(summary[quasistatic].is_object());
    const isosid::format::h5::Reader results(dir.path("out-s.scene.toml/results.h5"));
    q[quasistatic] = results.matrix("/bodies/beam/q").row(0).transpose();  // quasistatic coordinates as solved for
  }
  REQUIRE(summary[1]["bodies"][0]["quasistatic_modes"].get<int>() == 11);
  REQUIRE(summary[0]["bodies"][0]["quasistatic_modes"].get<int>() == 0);
  const double sag = q[0].cwiseAbs().maxCoeff();
  INFO("largest coordinate " << sag << ", largest difference " << (q[1] - q[0]).cwiseAbs().maxCoeff());
  REQUIRE(sag > 0);
  // the static start stops at 1e-10 of the largest acceleration it removes (at its round-off
  // floor it accepts up to 1e-7): a coordinate is then off by that over its mode's stiffness
  // omega^2, against the sag's mode (287 Hz) at most (287 / 192)^2 = 2.2 times as much for the
  // lowest one (measured 2e-11 of the sag); the limit is the floor the static start accepts
  CHECK((q[1] - q[0]).cwiseAbs().maxCoeff() < 1e-7 * sag);
}

TEST_CASE("joints: bad joint input is refused with exit 2", "[runtime][joint][bad-input]") {
  const isosid::test::ScratchDir dir("joint-bad");
  const std::string bob = simulation(1.0) + steel_ball("bob", "position = [0.0, -1.0, 0.0]");
  auto refused = [&](const std::string& joint) { run_scene(dir, bob + joint, 2); };
  SECTION("unknown type") { refused("[[joint]]\nname = \"j\"\ntype = \"prismatic\"\nbody = \"bob\"\npoint = [0.0, 0.0, 0.0]\n"); }
  SECTION("a rigid side without a point") { refused("[[joint]]\nname = \"j\"\ntype = \"spherical\"\nbody = \"bob\"\n"); }
  SECTION("no such body") { refused("[[joint]]\nname = \"j\"\ntype = \"spherical\"\nbody = \"rod\"\npoint = [0.0, 0.0, 0.0]\n"); }
  SECTION("an axis on a spherical joint") {
    refused("[[joint]]\nname = \"j\"\ntype = \"spherical\"\nbody = \"bob\"\npoint = [0.0, 0.0, 0.0]\naxis = [0.0, 0.0, 1.0]\n");
  }
  SECTION("a body jointed to itself") {
    refused("[[joint]]\nname = \"j\"\ntype = \"fixed\"\nbody = \"bob\"\nother = \"bob\"\npoint = [0.0, 0.0, 0.0]\n");
  }
  SECTION("attachments moving apart at the start") {
    run_scene(dir, simulation(1.0) + steel_ball("bob", "position = [0.0, -1.0, 0.0]\nvelocity = [0.0, -0.1, 0.0]") +
                       joint("j", "spherical", "bob", "point = [0.0, 0.0, 0.0]"), 2);
  }
  SECTION("an over-constrained mechanism: a second joint repeats what the first imposes") {
    // a fixed joint holds all six motions; a spherical joint elsewhere repeats three of them
    refused("[[joint]]\nname = \"weld\"\ntype = \"fixed\"\nbody = \"bob\"\npoint = [0.0, 0.0, 0.0]\n"
            "[[joint]]\nname = \"pin\"\ntype = \"spherical\"\nbody = \"bob\"\npoint = [0.0, -1.0, 0.0]\n");
  }
  SECTION("an over-constrained mechanism: two pins at one point") {
    refused("[[joint]]\nname = \"a\"\ntype = \"spherical\"\nbody = \"bob\"\npoint = [0.0, 0.0, 0.0]\n"
            "[[joint]]\nname = \"b\"\ntype = \"spherical\"\nbody = \"bob\"\npoint = [0.0, 0.0, 0.0]\n");
  }
  SECTION("a joint at a node the SID does not have") {
    run_scene(dir, simulation(1.0) + "[[flexible_body]]\nname = \"beam\"\nsid = \"" + kGolden +
                       "/beam_small.sid.h5\"\n[[joint]]\nname = \"j\"\ntype = \"spherical\"\nbody = \"beam\"\nnode = \"tip\"\n",
              2);
  }
  SECTION("a flexible body's node away from the joint's point") {
    run_scene(dir, simulation(1.0) + R"(
[[flexible_body]]
name = "beam"
sid = ")" + kGolden + "/beam_small.sid.h5\"\n" + joint("j", "spherical", "beam", "node = \"end\"\npoint = [0.0, 0.0, 0.0]"), 2);
  }
}
