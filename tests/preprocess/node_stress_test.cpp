// SID nodes and stress rows against fields with known answers: a rigid rotation gives
// psi = its angle and phi = its displacement; a uniform dilatation gives a uniform stress;
// on the axis of a body of revolution the hoop stress equals the radial stress. Points given
// in metres land where their parameters do; points outside the body go to its surface.
#include "geometry/primitives.hpp"
#include "model/placement.hpp"
#include "sid/node_data.hpp"
#include "sid/stress_rows.hpp"
#include "preprocess/body_fixtures.hpp"

#include <algorithm>
#include <catch2/catch.hpp>

using namespace isosid;
using format::AnalysisType;

TEST_CASE("node phi and psi of a rigid rotation (3D)", "[sid][nodes]") {
  const auto b = prep::build_body(test::spec_for(prep::primitives::box(0.2, 0.1, 0.05), AnalysisType::Solid, 2.1e11, 0.3,
                                                 7850, test::uniform({2, 2, 2}, {2, 2, 1})));
  // one "mode": infinitesimal rotation theta about the axis e, u = theta e x x
  const Eigen::Vector3d e = Eigen::Vector3d(1, -2, 0.5).normalized();
  Eigen::MatrixXd Phi(b.dofs.total_dofs(), 1);
  for (int n = 0; n < b.dofs.node_count(); ++n)
    Phi.block(3 * n, 0, 3, 1) = e.cross(Eigen::Vector3d(b.dofs.node_points().row(n).transpose()));
  const auto node = prep::node_at(b, {"p", {Eigen::Vector3d(0.3, 0.7, 0.2)}}, Phi);
  const Eigen::Vector3d x = node.origin.M0.col(0);
  CHECK((node.phi.col(0) - e.cross(x)).norm() < 1e-14);
  CHECK((node.psi.col(0) - e).norm() < 1e-12);  // the rotation vector, from half the curl
  CHECK((node.AP.M1[0] + node.AP.M1[0].transpose()).norm() < 1e-14);  // a skew matrix
}

TEST_CASE("node psi of an axisymmetric section is a rotation about z", "[sid][nodes]") {
  const auto b = prep::build_body(test::spec_for(prep::primitives::half_disk(0.01), AnalysisType::Axisymmetric, 7e10, 0.3,
                                                 2700, test::uniform({3, 2}, {2, 2})));
  // u_r = 0, u_y = s r: shear of the section, rotation about z by s/2
  const double s = 1e-3;
  Eigen::MatrixXd Phi = Eigen::MatrixXd::Zero(b.dofs.total_dofs(), 1);
  for (int n = 0; n < b.dofs.node_count(); ++n) Phi(2 * n + 1, 0) = s * b.dofs.node_points()(n, 0);
  const auto node = prep::node_at(b, {"p", {Eigen::Vector2d(0.5, 0.5)}}, Phi);
  CHECK(node.psi(2, 0) == Approx(s / 2).epsilon(1e-12));
  CHECK(std::abs(node.psi(0, 0)) + std::abs(node.psi(1, 0)) < 1e-16);
}

TEST_CASE("stress rows: uniform dilatation, and hoop = radial stress on the axis", "[sid][stress]") {
  const double E = 7e10, nu = 0.3;
  const auto b = prep::build_body(test::spec_for(prep::primitives::half_disk(0.01), AnalysisType::Axisymmetric, E, nu,
                                                 2700, test::uniform({3, 2}, {2, 2})));
  // u = eps x (u_r = eps r, u_z = eps z): strain eps in rr, zz, tt; stress E eps / (1 - 2 nu)
  const double eps = 1e-4;
  Eigen::MatrixXd Phi(b.dofs.total_dofs(), 1);
  for (int n = 0; n < b.dofs.node_count(); ++n) Phi.block(2 * n, 0, 2, 1) = eps * b.dofs.node_points().row(n).transpose();
  const auto s = prep::stress_rows(b, {"axis", {Eigen::Vector2d(0.0, 0.0)}, {Eigen::Vector2d(0.0, 1.0)}, 7}, Phi);
  REQUIRE(s.components == std::vector<std::string>{"rr", "zz", "tt", "rz"});
  const double sigma = E * eps / (1 - 2 * nu);
  for (Eigen::Index i = 0; i < 7; ++i) {
    CHECK(s.position(i, 0) == Approx(0.0).margin(1e-15));  // on the axis
    for (int c = 0; c < 3; ++c) CHECK(s.S(4 * i + c, 0) == Approx(sigma).epsilon(1e-10));
    CHECK(std::abs(s.S(4 * i + 3, 0)) < 1e-10 * sigma);
  }
}

namespace {
/// Largest difference between the SID rows of a node and of a stress line.
double node_difference(const format::Node& a, const format::Node& b) {
  return std::max({(a.origin.M0 - b.origin.M0).cwiseAbs().maxCoeff(), (a.phi - b.phi).cwiseAbs().maxCoeff(),
                   (a.psi - b.psi).cwiseAbs().maxCoeff()});
}
}  // namespace

TEST_CASE("a node and a stress line given in metres land on the rows of their parameters", "[sid][nodes][stress]") {
  // an axisymmetric sphere and a 3D ball (rational, curved), four random modes each
  for (const bool solid : {false, true}) {
    INFO((solid ? "ball" : "sphere"));
    const auto b = prep::build_body(test::spec_for(solid ? prep::primitives::ball(0.01) : prep::primitives::half_disk(0.01),
                                                   solid ? AnalysisType::Solid : AnalysisType::Axisymmetric, 7e10, 0.3, 2700,
                                                   solid ? test::uniform({2, 2, 2}, {2, 2, 2}) : test::uniform({3, 2}, {3, 3})));
    const Eigen::MatrixXd Phi = Eigen::MatrixXd::Random(b.dofs.total_dofs(), 4) * 1e-3;
    const prep::NurbsPatch& patch = b.spec.patches[0].patch;
    const Eigen::VectorXd xi = solid ? Eigen::VectorXd(Eigen::Vector3d(0.3, 0.6, 0.2)) : Eigen::VectorXd(Eigen::Vector2d(0.3, 0.6));
    const auto by_parameter = prep::node_at(b, {"p", {xi}}, Phi);
    const auto by_point = prep::node_at(b, {"p", {patch.point(xi), true}}, Phi);
    CHECK(node_difference(by_parameter, by_point) < 1e-12 * Phi.cwiseAbs().maxCoeff() / 0.01);
    // along eta both bodies are straight and evenly parametrized, so both lines sample alike
    Eigen::VectorXd from = xi, to = xi;
    from(1) = 0.1;
    to(1) = 0.9;
    const auto line = prep::stress_rows(b, {"l", {from}, {to}, 6}, Phi);
    const auto physical = prep::stress_rows(b, {"l", {patch.point(from), true}, {patch.point(to), true}, 6}, Phi);
    CHECK((line.position - physical.position).cwiseAbs().maxCoeff() < 1e-15);
    CHECK((line.S - physical.S).cwiseAbs().maxCoeff() < 1e-10 * line.S.cwiseAbs().maxCoeff());
  }
}

TEST_CASE("a point outside the body is placed at the nearest point of its surface", "[placement]") {
  const prep::NurbsPatch disk = prep::primitives::half_disk(0.01);
  const Eigen::Vector2d direction = Eigen::Vector2d(0.6, -0.8);
  const prep::BodyPoint p = prep::nearest_point(disk, 0.0103 * direction);
  CHECK(p.distance == Approx(0.0003).epsilon(1e-10));
  CHECK((p.x - 0.01 * direction).norm() < 1e-12);
  CHECK(p.parameter(1) == Approx(0.0).margin(1e-12));  // the lower arc
  const prep::BodyPoint inside = prep::nearest_point(disk, Eigen::Vector2d(0.004, 0.002));
  CHECK(inside.distance < 1e-17);
  CHECK(prep::placement_tolerance(disk) == Approx(1e-6 * std::sqrt(0.01 * 0.01 + 0.02 * 0.02)));
}
