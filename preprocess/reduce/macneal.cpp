// MacNeal reduction; see macneal.hpp.
#include "reduce/macneal.hpp"

#include "isosid/format/error.hpp"
#include "reduce/modal_analysis.hpp"
#include "reduce/mode_basis.hpp"
#include "reduce/sparse_cholesky.hpp"
#include "reduce/sparse_products.hpp"

#include <Eigen/Cholesky>
#include <cmath>

namespace isosid::prep {

Eigen::MatrixXd elastic_static_response(const Eigen::SparseMatrix<double>& K, const Eigen::SparseMatrix<double>& M,
                                        const Eigen::MatrixXd& rigid, const Eigen::MatrixXd& loads, double lambda_scale) {
  if (rigid.cols() == 0) return SparseCholesky(K).solve(loads);
  // P = I - M R (R^T M R)^-1 R^T removes the loads' rigid-body resultants; the response is
  // kept free of rigid content by the projection the reduction bases use (remove_rigid_content)
  const Eigen::MatrixXd MR = M * rigid;
  const Eigen::LDLT<Eigen::MatrixXd> gram(rigid.transpose() * MR);
  auto balance = [&](const Eigen::MatrixXd& f) -> Eigen::MatrixXd { return f - MR * gram.solve(rigid.transpose() * f); };
  auto elastic = [&](Eigen::MatrixXd u) {
    remove_rigid_content(u, M, rigid);
    return u;
  };
  // K is singular on the rigid fields: solve with the shifted K + s M, which differs from K
  // only by s M; the iteration u += (K + s M)^-1 (L - K u) contracts by s / (s + omega_1^2) on
  // the elastic subspace (s = 1e-3 of the eigenvalue scale: about 1e-3 per pass)
  const double s = 1e-3 * lambda_scale;
  const Eigen::SparseMatrix<double> shifted = K + s * M;
  const SparseCholesky factor(shifted);
  const Eigen::MatrixXd L = balance(loads);
  Eigen::MatrixXd u = elastic(factor.solve(L));
  // each pass is a solve with every load column (tens of GFlop for a fine 3D body): stop at
  // round-off, or when a pass no longer gains (the correction stagnates at the solves' noise)
  double previous = INFINITY;
  for (int pass = 0; pass < 20; ++pass) {
    const Eigen::MatrixXd r = L - K * u;
    const Eigen::MatrixXd du = elastic(factor.solve(balance(r)));
    u += du;
    const double change = du.norm();
    if (change <= 1e-14 * u.norm() || change > 0.5 * previous) break;
    previous = change;
  }
  return u;
}

MasslessBoundaryModel macneal_reduction(const Eigen::SparseMatrix<double>& K, const Eigen::SparseMatrix<double>& M,
                                        const Eigen::MatrixXd& rigid, const std::vector<int>& boundary_dofs, int n_modes,
                                        double lambda_scale) {
  const Eigen::Index n = K.rows(), nb = Eigen::Index(boundary_dofs.size()), nr = rigid.cols();
  if (nb == 0) throw format::ComputationError("a massless-boundary reduction needs boundary DOFs");
  const ModalResult modes = lowest_modes(K, M, n_modes + int(nr), lambda_scale);
  // the elastic modes in normal form within their span: on finely graded bodies the Lanczos
  // vectors of close or repeated frequencies leave M-orthogonality errors far above the
  // runtime's 1e-8 check on Me = diag(I, 0)
  Eigen::MatrixXd Phi = modes.modes.rightCols(n_modes);
  remove_rigid_content(Phi, M, rigid);
  const Eigen::VectorXd omega2 = orthonormalize(Phi, K, M);
  if (Phi.cols() != n_modes) throw format::ComputationError("the retained modes are not independent of the rigid-body motions");
  Eigen::MatrixXd Eb = Eigen::MatrixXd::Zero(n, nb);
  for (Eigen::Index k = 0; k < nb; ++k) Eb(boundary_dofs[std::size_t(k)], k) = 1.0;
  const Eigen::MatrixXd Phi_b = Eb.transpose() * Phi;
  // residual flexibility: the static response to unit boundary loads less the retained modes' share
  const Eigen::MatrixXd F = elastic_static_response(K, M, rigid, Eb, lambda_scale);
  const Eigen::MatrixXd dF = F - Phi * omega2.cwiseInverse().asDiagonal() * Phi_b.transpose();
  Eigen::MatrixXd dF_bb = Eb.transpose() * dF;
  dF_bb = 0.5 * (dF_bb + dF_bb.transpose());
  const Eigen::LLT<Eigen::MatrixXd> residual(dF_bb);
  if (residual.info() != Eigen::Success)
    throw format::ComputationError("the boundary's residual flexibility is not positive definite (boundary DOFs that "
                                   "the retained modes already describe, or constrained ones)");
  // attachment modes scaled to unit boundary displacements; modes with zero boundary displacement
  MasslessBoundaryModel out;
  out.boundary_dofs = boundary_dofs;
  out.T.resize(n, nb + n_modes);
  out.T.leftCols(nb) = residual.solve(dF.transpose()).transpose();  // dF dK_bb
  out.T.rightCols(n_modes) = Phi - out.T.leftCols(nb) * Phi_b;
  // the boundary rows are [I 0] by construction; the solves leave round-off there (1e-11 on
  // the test strip), which is set exact: u_b are the boundary DOFs themselves
  for (Eigen::Index k = 0; k < nb; ++k) out.T.row(boundary_dofs[std::size_t(k)]) = Eigen::RowVectorXd::Unit(nb + n_modes, k);
  out.K = projected(K, out.T);
  out.M = Eigen::MatrixXd::Zero(nb + n_modes, nb + n_modes);
  out.M.bottomRightCorner(n_modes, n_modes).setIdentity();
  out.Phi = Phi;
  out.omega2 = omega2;
  return out;
}

}  // namespace isosid::prep
