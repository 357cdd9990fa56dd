// MacNeal reduction; see macneal.hpp.
#include "reduce/macneal.hpp"

#include "isosid/common/dense_decompositions.hpp"
#include "isosid/common/progress_line.hpp"
#include "isosid/format/error.hpp"
#include "reduce/modal_analysis.hpp"
#include "reduce/memory_budget.hpp"
#include "reduce/mode_basis.hpp"
#include "reduce/sparse_cholesky.hpp"
#include "reduce/sparse_products.hpp"

#include <Eigen/Cholesky>
#include <Eigen/QR>
#include <algorithm>
#include <memory>

namespace isosid::prep {

namespace {

/// Columns solved together: the solves' BLAS-3 blocks stay efficient, and the loads and
/// solutions in flight stay a few n x kBlock matrices beside the result.
constexpr Eigen::Index kBlock = 256;

/// A free body's stiffness made definite without changing its response to balanced loads: a
/// spring on each of nr DOFs where the rigid fields are most independent (QR with column pivoting
/// of R^T picks them). A balanced load's solutions are u* + R c; exactly one of them vanishes on
/// those DOFs (R is invertible there), so the springs carry nothing and that one solves the
/// sprung system too: one factorization and one solve, whatever the springs' stiffness (K's mean
/// diagonal keeps the factor's pivots of one scale).
Eigen::SparseMatrix<double> supported(const Eigen::SparseMatrix<double>& K, const Eigen::MatrixXd& rigid) {
  const Eigen::ColPivHouseholderQR<Eigen::MatrixXd> qr(rigid.transpose());
  if (qr.rank() < rigid.cols()) throw format::ComputationError("the body's rigid-body fields are not independent");
  const double spring = K.diagonal().mean();
  Eigen::SparseMatrix<double> sprung = K;
  for (Eigen::Index k = 0; k < rigid.cols(); ++k) {
    const Eigen::Index dof = qr.colsPermutation().indices()(k);
    sprung.coeffRef(dof, dof) += spring;
  }
  return sprung;
}

}  // namespace

Eigen::MatrixXd elastic_unit_load_response(const SparseCholesky& stiffness, const Eigen::SparseMatrix<double>& M,
                                           const Eigen::MatrixXd& rigid, const std::vector<int>& dofs) {
  const Eigen::Index n = M.rows(), nb = Eigen::Index(dofs.size()), nr = rigid.cols();
  // P = I - M R (R^T M R)^-1 R^T removes the loads' rigid-body resultants (inertia relief)
  const Eigen::MatrixXd MR = nr > 0 ? sparse_times(M, rigid) : Eigen::MatrixXd(n, 0);
  const Eigen::LDLT<Eigen::MatrixXd> gram(rigid.transpose() * MR);
  Eigen::MatrixXd u(n, nb);
  for (Eigen::Index first = 0; first < nb; first += kBlock) {
    const Eigen::Index width = std::min(kBlock, nb - first);
    common::set_work_step("boundary statics: unit loads " + std::to_string(first + 1) + "-" + std::to_string(first + width) + " of " +
                          std::to_string(nb));
    Eigen::MatrixXd loads = Eigen::MatrixXd::Zero(n, width);
    for (Eigen::Index k = 0; k < width; ++k) loads(dofs[std::size_t(first + k)], k) = 1.0;
    if (nr > 0) loads.noalias() -= MR * gram.solve(rigid.transpose() * loads);
    u.middleCols(first, width) = stiffness.solve(loads);
  }
  remove_rigid_content(u, M, rigid);  // the one solution without rigid content (R^T M u = 0)
  return u;
}

std::unique_ptr<SparseCholesky> stiffness_factor(const Eigen::SparseMatrix<double>& K, const Eigen::MatrixXd& rigid) {
  common::set_work_step("factorizing the stiffness (" + std::to_string(K.rows()) + " DOFs)");
  return std::make_unique<SparseCholesky>(rigid.cols() > 0 ? supported(K, rigid) : K, "the stiffness's factorization");
}

MasslessBoundaryModel macneal_reduction(const Eigen::SparseMatrix<double>& K, const Eigen::SparseMatrix<double>& M,
                                        const Eigen::MatrixXd& rigid, const std::vector<int>& boundary_dofs, int n_modes) {
  const Eigen::Index n = K.rows(), nb = Eigen::Index(boundary_dofs.size());
  if (nb == 0) throw format::ComputationError("a massless-boundary reduction needs boundary DOFs");
  // the basis T and the modes, with a block of loads and solutions in flight
  check_memory("reduction.boundary_surface", "the MacNeal basis of " + std::to_string(nb) + " boundary DOFs on " + std::to_string(n) + " DOFs",
               double(n) * double(nb + 2 * n_modes + 3 * std::min(kBlock, nb)) * sizeof(double));
  // one factorization serves the eigen solve and the boundary statics
  const std::unique_ptr<SparseCholesky> stiffness = stiffness_factor(K, rigid);
  const ModalResult modes = lowest_elastic_modes(*stiffness, K, M, rigid, n_modes);
  // the elastic modes in normal form within their span: on finely graded bodies the Lanczos
  // vectors of close or repeated frequencies leave M-orthogonality errors far above the
  // runtime's 1e-8 check on Me = diag(I, 0)
  Eigen::MatrixXd Phi = modes.modes.rightCols(n_modes);
  remove_rigid_content(Phi, M, rigid);
  const Eigen::VectorXd omega2 = orthonormalize(Phi, K, M);
  if (Phi.cols() != n_modes) throw format::ComputationError("the retained modes are not independent of the rigid-body motions");
  Eigen::MatrixXd Phi_b(nb, n_modes);
  for (Eigen::Index k = 0; k < nb; ++k) Phi_b.row(k) = Phi.row(boundary_dofs[std::size_t(k)]);

  MasslessBoundaryModel out;
  out.boundary_dofs = boundary_dofs;
  out.T.resize(n, nb + n_modes);
  // residual flexibility dF: the static response to unit boundary loads less the retained
  // modes' share, formed in place of the attachment modes it becomes
  auto attachment = out.T.leftCols(nb);
  attachment = elastic_unit_load_response(*stiffness, M, rigid, boundary_dofs);
  common::set_work_step("attachment modes");
  attachment.noalias() -= Phi * (omega2.cwiseInverse().asDiagonal() * Phi_b.transpose());
  Eigen::MatrixXd dF_bb(nb, nb);
  for (Eigen::Index k = 0; k < nb; ++k) dF_bb.row(k) = attachment.row(boundary_dofs[std::size_t(k)]);
  dF_bb = 0.5 * (dF_bb + dF_bb.transpose());
  const Eigen::LLT<Eigen::MatrixXd> residual(dF_bb);
  if (residual.info() != Eigen::Success)
    throw format::ComputationError("the boundary's residual flexibility is not positive definite (boundary DOFs that "
                                   "the retained modes already describe, or constrained ones)");
  // attachment modes scaled to unit boundary displacements, dF dF_bb^-1 = dF U^-1 L^-1 in place
  residual.matrixU().solveInPlace<Eigen::OnTheRight>(attachment);
  residual.matrixL().solveInPlace<Eigen::OnTheRight>(attachment);
  // modes with zero boundary displacement
  out.T.rightCols(n_modes) = Phi;
  out.T.rightCols(n_modes).noalias() -= attachment * Phi_b;
  // the boundary rows are [I 0] by construction; the solves leave round-off there (1e-11 on
  // the test strip), which is set exact: u_b are the boundary DOFs themselves
  for (Eigen::Index k = 0; k < nb; ++k) out.T.row(boundary_dofs[std::size_t(k)]) = Eigen::RowVectorXd::Unit(nb + n_modes, k);
  // T^T K T without its n (nb + nm)^2 product: K dF = P E_b and Phi^T K dF = 0 make it
  //   [ dF_bb^-1              -dF_bb^-1 Phi_b                     ]
  //   [ -Phi_b^T dF_bb^-1     Lambda + Phi_b^T dF_bb^-1 Phi_b     ]
  const Eigen::MatrixXd K_bb = residual.solve(Eigen::MatrixXd::Identity(nb, nb));
  const Eigen::MatrixXd K_bm = -K_bb * Phi_b;
  out.K.resize(nb + n_modes, nb + n_modes);
  out.K.topLeftCorner(nb, nb) = 0.5 * (K_bb + K_bb.transpose());
  out.K.topRightCorner(nb, n_modes) = K_bm;
  out.K.bottomLeftCorner(n_modes, nb) = K_bm.transpose();
  Eigen::MatrixXd K_mm = -Phi_b.transpose() * K_bm;
  K_mm.diagonal() += omega2;
  out.K.bottomRightCorner(n_modes, n_modes) = 0.5 * (K_mm + K_mm.transpose());
  out.M = Eigen::MatrixXd::Zero(nb + n_modes, nb + n_modes);
  out.M.bottomRightCorner(n_modes, n_modes).setIdentity();
  out.Phi = Phi;
  out.omega2 = omega2;
  return out;
}

}  // namespace isosid::prep
