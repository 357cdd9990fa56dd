// Massless-boundary reductions ([R3], [R4] in docs/references.md). MacNeal's: the reduced model
// keeps the full model's static flexibility at the boundary and its retained free-interface
// frequencies, and its boundary carries no mass; a free body is reduced with inertia relief,
// checked against an independent statically determinate support. The massless Craig-Bampton
// variant: with the boundary held it is the fixed-interface modal model, statically exact, massless
// boundary.
#include "geometry/primitives.hpp"
#include "reduce/craig_bampton.hpp"
#include "reduce/macneal.hpp"
#include "reduce/modal_analysis.hpp"
#include "reduce/mode_basis.hpp"
#include "reduce/sparse_cholesky.hpp"
#include "preprocess/body_fixtures.hpp"

#include <catch2/catch.hpp>

using namespace isosid;
using format::AnalysisType;

namespace {

struct Fixture : test::AssembledBody {
  std::vector<int> boundary;
};

/// A 0.2 x 0.02 m steel strip (plane stress, quadratic, 16 x 2 elements), optionally clamped
/// at xi0; the boundary is every free DOF on its top side (eta1), as a contact surface's would be.
Fixture strip(bool clamped) {
  prep::ModelSpec spec = test::spec_for(prep::primitives::rectangle(0.2, 0.02, 0.0, 0.0), AnalysisType::PlaneStress, 2.1e11,
                                        0.3, 7800, test::uniform({2, 2}, {16, 2}));
  if (clamped) spec.fixed = {{"xi0", {0, 1}}};
  Fixture f{test::assembled(spec), {}};
  f.boundary = test::side_free_dofs(f.body, 0, {1, 1});
  return f;
}

Eigen::MatrixXd unit_columns(Eigen::Index n, const std::vector<int>& dofs) {
  Eigen::MatrixXd E = Eigen::MatrixXd::Zero(n, Eigen::Index(dofs.size()));
  for (std::size_t k = 0; k < dofs.size(); ++k) E(dofs[k], Eigen::Index(k)) = 1.0;
  return E;
}

/// The reduced model's static flexibility at the boundary: [K_r^-1]_bb.
Eigen::MatrixXd reduced_flexibility(const prep::MasslessBoundaryModel& r) {
  return Eigen::MatrixXd(r.K.ldlt().solve(Eigen::MatrixXd::Identity(r.K.rows(), r.K.cols()))).topLeftCorner(r.boundary(), r.boundary());
}

/// Frequencies of the massless-boundary model: the boundary condensed statically (its mass is zero).
Eigen::VectorXd condensed_omega2(const prep::MasslessBoundaryModel& r) {
  const Eigen::Index nb = r.boundary(), nm = r.K.rows() - nb;
  const Eigen::MatrixXd Kc = r.K.bottomRightCorner(nm, nm) -
                             r.K.bottomLeftCorner(nm, nb) * r.K.topLeftCorner(nb, nb).ldlt().solve(r.K.topRightCorner(nb, nm));
  return Eigen::SelfAdjointEigenSolver<Eigen::MatrixXd>(0.5 * (Kc + Kc.transpose())).eigenvalues();
}

double relative(const Eigen::MatrixXd& a, const Eigen::MatrixXd& b) { return (a - b).norm() / b.norm(); }

/// The reduced stiffness is the full one projected on the basis, T^T K T (the reduction forms it
/// in closed form from the boundary's residual flexibility, without that product; the tests'
/// flexibility and frequency checks hold it to the full model).
void check_projected_stiffness(const prep::MasslessBoundaryModel& r, const Eigen::SparseMatrix<double>& K) {
  const Eigen::MatrixXd projected = r.T.transpose() * (K * r.T);
  // the product's own round-off: K (condition ~1e8 on the strip) times T, whose columns carry
  // the solves' relative error, cancels to the much smaller reduced stiffness; measured 1.1e-7
  // in every block. A wrong block of the closed form would differ at order one.
  CHECK(relative(r.K, projected) < 1e-6);
}

}  // namespace

TEST_CASE("MacNeal reduction of a clamped body: boundary flexibility, frequencies, massless boundary", "[macneal]") {
  const Fixture f = strip(true);
  REQUIRE(f.rigid.cols() == 0);
  const int modes = 6;
  const prep::MasslessBoundaryModel r = prep::macneal_reduction(f.sys.K, f.sys.M, f.rigid, f.boundary, modes);
  const Eigen::MatrixXd Eb = unit_columns(f.sys.K.rows(), f.boundary);
  const Eigen::MatrixXd full = Eb.transpose() * prep::SparseCholesky(f.sys.K).solve(Eb);
  // the static flexibility at the boundary is the full model's: exact up to the solves'
  // round-off (condition of K ~ 1e8 here)
  CHECK(relative(reduced_flexibility(r), full) < 1e-8);
  // the retained free-interface modes keep their frequencies
  const Eigen::VectorXd full_omega2 = prep::lowest_modes(f.sys.K, f.sys.M, modes, f.scale).eigenvalues;
  const Eigen::VectorXd reduced = condensed_omega2(r);
  for (int k = 0; k < modes; ++k) CHECK(reduced(k) == Approx(full_omega2(k)).epsilon(1e-10));
  // no mass on the boundary; the boundary coordinates are the boundary DOFs themselves
  CHECK(r.M.topLeftCorner(r.boundary(), r.boundary()).norm() == 0.0);
  CHECK(r.M.topRightCorner(r.boundary(), modes).norm() == 0.0);
  const Eigen::MatrixXd boundary_rows = Eb.transpose() * r.T;
  CHECK(boundary_rows.leftCols(r.boundary()) == Eigen::MatrixXd::Identity(r.boundary(), r.boundary()));
  CHECK(boundary_rows.rightCols(modes).norm() == 0.0);
  check_projected_stiffness(r, f.sys.K);
}

TEST_CASE("MacNeal reduction of a free body uses inertia relief", "[macneal]") {
  const Fixture f = strip(false);
  REQUIRE(f.rigid.cols() == 3);  // x, y and the in-plane rotation
  const int modes = 6;
  const prep::MasslessBoundaryModel r = prep::macneal_reduction(f.sys.K, f.sys.M, f.rigid, f.boundary, modes);
  // independent reference: the loads balanced by rigid-body inertia, a statically determinate
  // support (both directions at one corner, y at the other end), the result's rigid content removed
  const Eigen::Index n = f.sys.K.rows();
  const Eigen::MatrixXd Eb = unit_columns(n, f.boundary);
  const Eigen::MatrixXd MR = f.sys.M * f.rigid;
  const Eigen::MatrixXd G = f.rigid.transpose() * MR;
  const Eigen::MatrixXd balanced = Eb - MR * G.ldlt().solve(f.rigid.transpose() * Eb);
  const auto& nodes = f.body.dofs.node_points();
  int a = 0, b = 0;
  for (int k = 0; k < f.body.dofs.node_count(); ++k) {
    if (nodes.row(k).norm() < nodes.row(a).norm()) a = k;                                   // (0, 0)
    if ((nodes.row(k) - Eigen::RowVector2d(0.2, 0)).norm() < (nodes.row(b) - Eigen::RowVector2d(0.2, 0)).norm()) b = k;  // (0.2, 0)
  }
  const std::vector<int> support = {f.body.dofs.free_index(a, 0), f.body.dofs.free_index(a, 1), f.body.dofs.free_index(b, 1)};
  std::vector<int> keep;
  for (int i = 0; i < n; ++i)
    if (std::find(support.begin(), support.end(), i) == support.end()) keep.push_back(i);
  const Eigen::MatrixXd S = unit_columns(n, keep);
  const Eigen::SparseMatrix<double> Ks = (S.transpose() * f.sys.K * S).sparseView();
  Eigen::MatrixXd u = S * prep::SparseCholesky(Ks).solve(S.transpose() * balanced);
  u -= f.rigid * G.ldlt().solve(MR.transpose() * u);  // no rigid content
  const Eigen::MatrixXd reference = Eb.transpose() * u;
  // the reduction's sprung solve and this support's elimination differ in their round-off
  CHECK(relative(reduced_flexibility(r), reference) < 1e-8);
  const Eigen::VectorXd full_omega2 = prep::lowest_modes(f.sys.K, f.sys.M, modes + 3, f.scale).eigenvalues.tail(modes);
  const Eigen::VectorXd reduced = condensed_omega2(r);
  for (int k = 0; k < modes; ++k) CHECK(reduced(k) == Approx(full_omega2(k)).epsilon(1e-10));
  check_projected_stiffness(r, f.sys.K);
}

TEST_CASE("massless Craig-Bampton: fixed-interface frequencies, boundary flexibility, massless boundary", "[macneal]") {
  const Fixture f = strip(true);
  const int modes = 6;
  const prep::MasslessBoundaryModel r = prep::massless_craig_bampton(f.sys.K, f.sys.M, f.rigid, f.boundary, modes);
  const Eigen::Index nb = r.boundary();
  // the boundary held: the reduced model's frequencies are the full model's with the boundary
  // DOFs fixed (an independent eigen solve of the interior), to the eigen solver's round-off
  std::vector<int> interior;
  for (int i = 0; i < f.sys.K.rows(); ++i)
    if (std::find(f.boundary.begin(), f.boundary.end(), i) == f.boundary.end()) interior.push_back(i);
  const Eigen::VectorXd held = prep::lowest_modes(prep::submatrix(f.sys.K, interior, interior), prep::submatrix(f.sys.M, interior, interior),
                                                  modes, f.scale).eigenvalues;
  const Eigen::VectorXd reduced = Eigen::SelfAdjointEigenSolver<Eigen::MatrixXd>(r.K.bottomRightCorner(modes, modes)).eigenvalues();
  for (int k = 0; k < modes; ++k) CHECK(reduced(k) == Approx(held(k)).epsilon(1e-10));
  // statically exact: the boundary flexibility of the clamped body (condition of K ~ 1e8)
  const Eigen::MatrixXd Eb = unit_columns(f.sys.K.rows(), f.boundary);
  CHECK(relative(reduced_flexibility(r), Eigen::MatrixXd(Eb.transpose() * prep::SparseCholesky(f.sys.K).solve(Eb))) < 1e-8);
  // massless boundary, physical boundary coordinates, and the constraint modes carry no
  // inertia coupling to the modes (Theta^T M Psi = 0, relative to the modes' unit mass)
  CHECK(r.M.topRows(nb).norm() == 0.0);
  const Eigen::MatrixXd boundary_rows = Eb.transpose() * r.T;
  CHECK(boundary_rows.leftCols(nb) == Eigen::MatrixXd::Identity(nb, nb));
  CHECK(boundary_rows.rightCols(modes).norm() == 0.0);
  CHECK((r.Phi.transpose() * (f.sys.M * r.T.leftCols(nb))).norm() < 1e-10);
}

TEST_CASE("massless Craig-Bampton refuses a free body", "[macneal]") {
  const Fixture f = strip(false);
  CHECK_THROWS_WITH(prep::massless_craig_bampton(f.sys.K, f.sys.M, f.rigid, f.boundary, 4),
                    Catch::Matchers::Contains("use macneal"));
}
