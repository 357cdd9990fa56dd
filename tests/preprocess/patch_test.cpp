// Patch test on distorted patches: boundary values of a linear displacement field give that
// field exactly inside, with constant strain (case G, docs/references.md). Tolerance 1e-10
// relative: the solve is exact up to round-off amplified by the condition of K.
// With non-uniform weights the integrands are rational and the (p+1)-point Gauss rule is not
// exact, so the discrete divergence theorem holds only up to quadrature error; the rational
// cases therefore integrate with 6 extra points (measured: 1e-7 at +2, 1e-8 at +4, < 1e-10
// at +6). Polynomial distortions pass with the default rule.
#include "assemble/point_operator.hpp"
#include "space/reference_rule.hpp"
#include "geometry/primitives.hpp"
#include "reduce/sparse_cholesky.hpp"
#include "refine/patch_refinement.hpp"
#include "preprocess/body_fixtures.hpp"

#include <catch2/catch.hpp>
#include <random>

using namespace isosid;
using format::AnalysisType;

namespace {

const int kRationalExtraPoints = 6;

/// Moves interior control points and, if `rational`, changes interior weights by up to 20 %.
prep::NurbsPatch distort(prep::NurbsPatch p, double amount, unsigned seed, bool rational = true) {
  std::mt19937 gen(seed);
  std::uniform_real_distribution<double> u(-1, 1);
  const auto n = p.counts();
  for (int i = 0; i < p.count(); ++i) {
    int rest = i;
    bool interior = true;
    for (int c : n) {
      const int k = rest % c;
      rest /= c;
      interior = interior && k > 0 && k < c - 1;
    }
    if (!interior) continue;
    for (int a = 0; a < p.phys_dim(); ++a) p.points(i, a) += amount * u(gen);
    if (rational) p.weights(i) *= 1 + 0.2 * u(gen);
  }
  return p;
}

/// Prescribes u = field(x) on the boundary nodes, solves, and returns the worst relative
/// nodal error and the worst deviation of the strain from `strain` at Gauss points.
template <class Field>
std::pair<double, double> run_patch_test(const prep::BodyModel& body, Field field, const Eigen::VectorXd& strain,
                                         int extra_points) {
  // nothing fixed: all DOFs free
  const auto sys = prep::assemble_system(body.space, body.dofs, body.elasticity, extra_points);
  const int dim = body.dofs.dim(), n = body.dofs.total_dofs();
  std::vector<bool> prescribed(std::size_t(n), false);
  Eigen::VectorXd exact(n);
  for (int node = 0; node < body.dofs.node_count(); ++node)
    exact.segment(node * dim, dim) = field(Eigen::VectorXd(body.dofs.node_points().row(node).transpose()));
  for (int node : test::boundary_nodes(body))
    for (int a = 0; a < dim; ++a) prescribed[std::size_t(node * dim + a)] = true;
  std::vector<int> inner, outer;
  for (int i = 0; i < n; ++i) (prescribed[std::size_t(i)] ? outer : inner).push_back(i);
  REQUIRE(!inner.empty());
  Eigen::SparseMatrix<double> Kii(Eigen::Index(inner.size()), Eigen::Index(inner.size()));
  Eigen::MatrixXd Kib = Eigen::MatrixXd::Zero(Eigen::Index(inner.size()), Eigen::Index(outer.size()));
  std::vector<int> where(static_cast<std::size_t>(n));
  for (std::size_t k = 0; k < inner.size(); ++k) where[std::size_t(inner[k])] = int(k);
  for (std::size_t k = 0; k < outer.size(); ++k) where[std::size_t(outer[k])] = int(k);
  std::vector<Eigen::Triplet<double>> t;
  for (int c = 0; c < sys.K.outerSize(); ++c)
    for (Eigen::SparseMatrix<double>::InnerIterator it(sys.K, c); it; ++it) {
      const int r = int(it.row());
      if (prescribed[std::size_t(r)]) continue;
      if (prescribed[std::size_t(c)])
        Kib(where[std::size_t(r)], where[std::size_t(c)]) += it.value();
      else
        t.emplace_back(where[std::size_t(r)], where[std::size_t(c)], it.value());
    }
  Kii.setFromTriplets(t.begin(), t.end());
  Eigen::VectorXd ub(Eigen::Index(outer.size()));
  for (std::size_t k = 0; k < outer.size(); ++k) ub(Eigen::Index(k)) = exact(outer[k]);
  const Eigen::VectorXd ui = prep::SparseCholesky(Kii).solve(-Kib * ub);
  Eigen::VectorXd u = exact;
  for (std::size_t k = 0; k < inner.size(); ++k) u(inner[k]) = ui(Eigen::Index(k));
  const double nodal_error = (u - exact).cwiseAbs().maxCoeff() / exact.cwiseAbs().maxCoeff();
  double strain_error = 0;
  const prep::ReferenceRule rule = prep::reference_rule(body.space);
  for (const auto& e : body.space.elements)
    for (int q = 0; q < rule.size(); ++q) {
      const auto op = prep::point_operator(body.space, body.dofs, body.elasticity, e, rule.points.col(q).data());
      REQUIRE(op.det_J > 0);  // a valid (unfolded) distortion
      strain_error = std::max(strain_error, (op.strain(u) - strain).cwiseAbs().maxCoeff() / strain.cwiseAbs().maxCoeff());
    }
  return {nodal_error, strain_error};
}

prep::NurbsPatch refined(prep::NurbsPatch p, std::vector<int> degrees, int parts) {
  for (std::size_t d = 0; d < degrees.size(); ++d) {
    prep::elevate_degree(p, int(d), degrees[d]);
    prep::subdivide_uniformly(p, int(d), parts);
  }
  return p;
}

}  // namespace

TEST_CASE("patch test on a distorted rational plane-stress patch", "[assemble][patch]") {
  const auto patch = distort(refined(prep::primitives::rectangle(2.0, 1.0), {3, 2}, 3), 0.04, 1);
  const auto body = prep::build_body(test::spec_for(patch, AnalysisType::PlaneStress, 2e11, 0.3, 7800));
  // u = a + G x with G = [[1e-3, 2e-4], [-5e-4, 3e-4]]: strain (xx, yy, xy) = (1e-3, 3e-4, -3e-4)
  auto field = [](const Eigen::VectorXd& x) {
    return Eigen::Vector2d(1e-4 + 1e-3 * x(0) + 2e-4 * x(1), -2e-4 - 5e-4 * x(0) + 3e-4 * x(1));
  };
  const auto [nodal, strain] = run_patch_test(body, field, Eigen::Vector3d(1e-3, 3e-4, -3e-4), 6);
  CHECK(nodal < 1e-10);
  CHECK(strain < 1e-10);
}

TEST_CASE("patch test on a distorted rational 3D patch", "[assemble][patch]") {
  const auto patch = distort(refined(prep::primitives::box(1.0, 0.6, 0.4), {2, 2, 2}, 2), 0.03, 2);
  const auto body = prep::build_body(test::spec_for(patch, AnalysisType::Solid, 2e11, 0.3, 7800));
  Eigen::Matrix3d G;
  G << 1e-3, 2e-4, -1e-4, 3e-4, -4e-4, 2e-4, 1e-4, 5e-4, 6e-4;
  auto field = [&](const Eigen::VectorXd& x) { return Eigen::Vector3d(Eigen::Vector3d(1e-5, 2e-5, -3e-5) + G * x); };
  Eigen::VectorXd strain(6);  // xx yy zz xy yz xz (engineering shear)
  strain << G(0, 0), G(1, 1), G(2, 2), G(0, 1) + G(1, 0), G(1, 2) + G(2, 1), G(0, 2) + G(2, 0);
  const auto [nodal, strain_error] = run_patch_test(body, field, strain, 6);
  CHECK(nodal < 1e-10);
  CHECK(strain_error < 1e-10);
}

TEST_CASE("patch test on a distorted axisymmetric patch", "[assemble][patch]") {
  // u_r = c r, u_z = d z + e is the linear field of constant axisymmetric strain (rr = tt = c, zz = d)
  const auto patch = distort(refined(prep::primitives::rectangle(0.5, 1.0, 0.2, 0.0), {2, 3}, 3), 0.03, 3);
  const auto body = prep::build_body(test::spec_for(patch, AnalysisType::Axisymmetric, 7e10, 0.33, 2700));
  auto field = [](const Eigen::VectorXd& x) { return Eigen::Vector2d(1e-3 * x(0), -4e-4 * x(1) + 1e-5); };
  const auto [nodal, strain] = run_patch_test(body, field, Eigen::Vector4d(1e-3, -4e-4, 1e-3, 0.0), 6);
  CHECK(nodal < 1e-10);
  CHECK(strain < 1e-10);
}

TEST_CASE("patch test on polynomially distorted patches with the default Gauss rule", "[assemble][patch]") {
  const auto plane = distort(refined(prep::primitives::rectangle(2.0, 1.0), {3, 2}, 3), 0.04, 4, false);
  const auto body2 = prep::build_body(test::spec_for(plane, AnalysisType::PlaneStrain, 2e11, 0.3, 7800));
  auto field2 = [](const Eigen::VectorXd& x) { return Eigen::Vector2d(2e-4 * x(1), 1e-3 * x(0) - 3e-4 * x(1)); };
  const auto [n2, s2] = run_patch_test(body2, field2, Eigen::Vector3d(0.0, -3e-4, 1.2e-3), 0);
  CHECK(n2 < 1e-10);
  CHECK(s2 < 1e-10);
  const auto solid = distort(refined(prep::primitives::box(1.0, 0.6, 0.4), {2, 2, 2}, 2), 0.03, 5, false);
  const auto body3 = prep::build_body(test::spec_for(solid, AnalysisType::Solid, 2e11, 0.3, 7800));
  auto field3 = [](const Eigen::VectorXd& x) { return Eigen::Vector3d(1e-3 * x(2), 0.0, 1e-3 * x(0)); };
  Eigen::VectorXd strain(6);
  strain << 0, 0, 0, 0, 0, 2e-3;
  const auto [n3, s3] = run_patch_test(body3, field3, strain, 0);
  CHECK(n3 < 1e-10);
  CHECK(s3 < 1e-10);
}

TEST_CASE("patch test on a three-level THB mesh of a distorted rational patch", "[assemble][patch][thb]") {
  auto ref = test::uniform({3, 2}, {1, 1});
  prep::HierarchicalRequest h;
  h.box = {{0.3, 0.6}, {0.25, 0.75}};
  h.elements_across = 8;
  ref.hierarchical = h;
  const auto patch = distort(refined(prep::primitives::rectangle(2.0, 1.0), {3, 2}, 3), 0.04, 5);
  const auto body = prep::build_body(test::spec_for(patch, AnalysisType::PlaneStress, 2e11, 0.3, 7800, ref));
  REQUIRE(body.hierarchy->mesh.levels() >= 3);
  auto field = [](const Eigen::VectorXd& x) {
    return Eigen::Vector2d(1e-4 + 1e-3 * x(0) + 2e-4 * x(1), -2e-4 - 5e-4 * x(0) + 3e-4 * x(1));
  };
  const auto [nodal, strain] = run_patch_test(body, field, Eigen::Vector3d(1e-3, 3e-4, -3e-4), kRationalExtraPoints);
  CHECK(nodal < 1e-10);
  CHECK(strain < 1e-10);
}
