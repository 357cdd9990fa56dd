// The viewing mesh against fields with known answers: an affine displacement u = G x is
// reproduced exactly by NURBS (they reproduce linear fields of the control points), so every
// point's displacement rows must give G x and its stress rows the constant D sym(G), also at
// the degenerate points of a ball (poles, axis) and on the axis of an axisymmetric section.
// The points lie on the exact geometry, and the grid counts follow from the element counts.
#include "geometry/primitives.hpp"
#include "sid/visual_mesh.hpp"
#include "preprocess/body_fixtures.hpp"

#include <catch2/catch.hpp>

using namespace isosid;
using format::AnalysisType;

namespace {

/// Nodal values of u = G x (node-major), the modes matrix of one "mode".
Eigen::MatrixXd affine_field(const prep::BodyModel& b, const Eigen::MatrixXd& G) {
  const int dim = b.dofs.dim();
  Eigen::MatrixXd Phi(b.dofs.total_dofs(), 1);
  for (int n = 0; n < b.dofs.node_count(); ++n) Phi.block(dim * n, 0, dim, 1) = G * b.dofs.node_points().row(n).transpose();
  return Phi;
}

}  // namespace

TEST_CASE("viewing mesh of a ball: exact geometry, affine field and constant stress at every point, poles included", "[sid][visual]") {
  const double R = 0.01, E = 2.1e11, nu = 0.3;
  const auto b = prep::build_body(test::spec_for(prep::primitives::ball(R), AnalysisType::Solid, E, nu, 7850,
                                                 test::uniform({2, 2, 2}, {2, 2, 2})));
  Eigen::Matrix3d G;
  G << 1.0, 0.3, -0.2, 0.1, -0.5, 0.4, 0.25, 0.05, 0.7;
  G *= 1e-4;
  const format::VisualMesh v = prep::visual_mesh(b, {2, true}, affine_field(b, G));
  REQUIRE(v.corners_per_cell == 8);
  REQUIRE(v.stress_components == std::vector<std::string>{"xx", "yy", "zz", "xy", "yz", "xz"});
  CHECK(v.cell_count() == Eigen::Index(b.space.elements.size()) * 8);  // 2 x 2 x 2 cells per element

  // sigma = D eps with eps in Voigt order (xx yy zz 2xy 2yz 2xz), from the elasticity the SID uses
  const Eigen::Matrix3d eps = 0.5 * (G + G.transpose());
  Eigen::VectorXd voigt(6);
  voigt << eps(0, 0), eps(1, 1), eps(2, 2), 2 * eps(0, 1), 2 * eps(1, 2), 2 * eps(0, 2);
  const Eigen::VectorXd sigma = b.elasticity.of_patch(0).D() * voigt;
  double largest_radius = 0;
  for (Eigen::Index p = 0; p < v.points(); ++p) {
    const Eigen::Vector3d x = v.position.row(p).transpose();
    largest_radius = std::max(largest_radius, x.norm());
    CHECK(x.norm() <= R * (1 + 1e-12));  // inside the exact sphere
    // displacements: exact up to round-off of the rational basis (1e-12 of |G| R)
    CHECK((v.Phi.middleRows(3 * p, 3).col(0) - G * x).norm() < 1e-12 * G.norm() * R);
    // stresses: constant; degenerate points take theirs a thousandth inside, where the strain
    // of an affine field is the same, so only round-off of the gradients remains (1e-8 of |sigma|)
    CHECK((v.S.middleRows(6 * p, 6).col(0) - sigma).norm() < 1e-8 * sigma.norm());
  }
  CHECK(largest_radius == Approx(R).epsilon(1e-12));  // the surface is drawn on the sphere
}

TEST_CASE("viewing mesh of an axisymmetric section: radial dilatation and axial strain, axis included", "[sid][visual]") {
  const double E = 7e10, nu = 0.3;
  const auto b = prep::build_body(test::spec_for(prep::primitives::half_disk(0.01), AnalysisType::Axisymmetric, E, nu, 2700,
                                                 test::uniform({3, 2}, {3, 2})));
  // u_r = e r, u_z = f z: strains rr = tt = e, zz = f (on the axis too)
  const double e = 1e-4, f = -3e-4;
  const Eigen::Matrix2d G = Eigen::Vector2d(e, f).asDiagonal();
  const format::VisualMesh v = prep::visual_mesh(b, {1, true}, affine_field(b, G));
  REQUIRE(v.corners_per_cell == 4);
  REQUIRE(v.stress_components == std::vector<std::string>{"rr", "zz", "tt", "rz"});
  const double lambda = E * nu / ((1 + nu) * (1 - 2 * nu)), mu = E / (2 * (1 + nu));
  const double s_rr = lambda * (2 * e + f) + 2 * mu * e, s_zz = lambda * (2 * e + f) + 2 * mu * f;
  int on_axis = 0;
  for (Eigen::Index p = 0; p < v.points(); ++p) {
    const Eigen::Vector2d x = v.position.row(p).transpose();
    on_axis += x(0) < 1e-15;
    CHECK((v.Phi.middleRows(2 * p, 2).col(0) - G * x).norm() < 1e-12 * 1e-4 * 0.01);
    // constant up to round-off; the points of the collapsed centre take their strain a
    // thousandth of an element inside, where the inverse Jacobian is ~1e3 larger: 1e-6
    const Eigen::Vector4d s = v.S.middleRows(4 * p, 4).col(0);
    CHECK(s(0) == Approx(s_rr).epsilon(1e-6));
    CHECK(s(1) == Approx(s_zz).epsilon(1e-6));
    CHECK(s(2) == Approx(s_rr).epsilon(1e-6));  // hoop = radial for u_r = e r
    CHECK(std::abs(s(3)) < 1e-6 * std::abs(s_rr));
  }
  CHECK(on_axis > 0);
}

TEST_CASE("viewing mesh of a box: neighbours share their points, without stress rows if asked", "[sid][visual]") {
  const auto b = prep::build_body(test::spec_for(prep::primitives::box(0.3, 0.2, 0.1), AnalysisType::Solid, 2.1e11, 0.3, 7850,
                                                 test::uniform({2, 2, 2}, {3, 2, 1})));
  const format::VisualMesh v = prep::visual_mesh(b, {2, false}, affine_field(b, Eigen::Matrix3d::Identity()));
  // 3 x 2 x 1 elements, 2 cells per direction each: a 6 x 4 x 2 grid of cells, 7 x 5 x 3 points
  CHECK(v.cell_count() == 48);
  CHECK(v.points() == 7 * 5 * 3);
  CHECK(v.S.size() == 0);
  CHECK(v.stress_components.empty());
  // the corners span the box
  CHECK((v.position.colwise().maxCoeff() - v.position.colwise().minCoeff()).transpose().isApprox(Eigen::Vector3d(0.3, 0.2, 0.1), 1e-14));
}
