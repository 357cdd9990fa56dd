// SID nodes and stress rows against fields with known answers: a rigid rotation gives
// psi = its angle and phi = its displacement; a uniform dilatation gives a uniform stress;
// on the axis of a body of revolution the hoop stress equals the radial stress.
#include "geometry/primitives.hpp"
#include "sid/node_data.hpp"
#include "sid/stress_rows.hpp"
#include "preprocess/body_fixtures.hpp"

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
  const auto node = prep::node_at(b, {"p", Eigen::Vector3d(0.3, 0.7, 0.2)}, Phi);
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
  const auto node = prep::node_at(b, {"p", Eigen::Vector2d(0.5, 0.5)}, Phi);
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
  const auto s = prep::stress_rows(b, {"axis", Eigen::Vector2d(0.0, 0.0), Eigen::Vector2d(0.0, 1.0), 7}, Phi);
  REQUIRE(s.components == std::vector<std::string>{"rr", "zz", "tt", "rz"});
  const double sigma = E * eps / (1 - 2 * nu);
  for (Eigen::Index i = 0; i < 7; ++i) {
    CHECK(s.position(i, 0) == Approx(0.0).margin(1e-15));  // on the axis
    for (int c = 0; c < 3; ++c) CHECK(s.S(4 * i + c, 0) == Approx(sigma).epsilon(1e-10));
    CHECK(std::abs(s.S(4 * i + 3, 0)) < 1e-10 * sigma);
  }
}
