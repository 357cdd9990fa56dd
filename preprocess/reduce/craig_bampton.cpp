// Craig-Bampton basis; see craig_bampton.hpp.
#include "reduce/craig_bampton.hpp"

#include "isosid/common/progress_line.hpp"
#include "isosid/format/error.hpp"
#include "reduce/modal_analysis.hpp"
#include "reduce/sparse_cholesky.hpp"
#include "reduce/sparse_products.hpp"

#include <algorithm>
#include <memory>

namespace isosid::prep {

Eigen::SparseMatrix<double> submatrix(const Eigen::SparseMatrix<double>& A, const std::vector<int>& rows,
                                      const std::vector<int>& cols) {
  std::vector<int> row_of(std::size_t(A.rows()), -1), col_of(std::size_t(A.cols()), -1);
  for (std::size_t i = 0; i < rows.size(); ++i) row_of[std::size_t(rows[i])] = int(i);
  for (std::size_t j = 0; j < cols.size(); ++j) col_of[std::size_t(cols[j])] = int(j);
  std::vector<Eigen::Triplet<double>> t;
  for (int c = 0; c < A.outerSize(); ++c) {
    if (col_of[std::size_t(c)] < 0) continue;
    for (Eigen::SparseMatrix<double>::InnerIterator it(A, c); it; ++it)
      if (row_of[std::size_t(it.row())] >= 0) t.emplace_back(row_of[std::size_t(it.row())], col_of[std::size_t(c)], it.value());
  }
  Eigen::SparseMatrix<double> S(Eigen::Index(rows.size()), Eigen::Index(cols.size()));
  S.setFromTriplets(t.begin(), t.end());
  return S;
}

Eigen::MatrixXd craig_bampton_basis(const Eigen::SparseMatrix<double>& K, const Eigen::SparseMatrix<double>& M,
                                    const std::vector<int>& interface_dofs, int n_normal) {
  const int n = int(K.rows());
  std::vector<bool> is_interface(std::size_t(n), false);
  for (int d : interface_dofs) is_interface[std::size_t(d)] = true;
  std::vector<int> inner;
  for (int d = 0; d < n; ++d)
    if (!is_interface[std::size_t(d)]) inner.push_back(d);
  if (interface_dofs.empty()) throw format::ComputationError("Craig-Bampton reduction needs at least one interface DOF");
  const auto Koo = submatrix(K, inner, inner), Moo = submatrix(M, inner, inner);
  const auto Koi = submatrix(K, inner, interface_dofs);

  // the interior stiffness is positive definite exactly when the interface fixes the body
  std::unique_ptr<SparseCholesky> interior;
  try {
    common::set_work_step("constraint modes: factorizing the interior stiffness (" + std::to_string(Koo.rows()) + " DOFs)");
    interior = std::make_unique<SparseCholesky>(Koo, "the interior stiffness's factorization");
  } catch (const format::ComputationError&) {
    throw format::ComputationError("Craig-Bampton: the " + std::to_string(interface_dofs.size()) +
                                   " interface DOFs do not fix the body (the interior stiffness is singular); "
                                   "choose more or more widely spread interface points");
  }
  Eigen::MatrixXd basis = Eigen::MatrixXd::Zero(n, n_normal + Eigen::Index(interface_dofs.size()));
  if (n_normal > 0) {
    // the fixed-interface modes through the same factor
    const ModalResult fixed = lowest_elastic_modes(*interior, Koo, Moo, Eigen::MatrixXd(), n_normal);
    for (std::size_t i = 0; i < inner.size(); ++i) basis.row(inner[i]).head(n_normal) = fixed.modes.row(Eigen::Index(i));
  }
  common::set_work_step("constraint modes: " + std::to_string(interface_dofs.size()) + " interface DOFs' solves");
  const Eigen::MatrixXd static_part = -interior->solve(Eigen::MatrixXd(Koi));
  for (std::size_t i = 0; i < inner.size(); ++i) basis.row(inner[i]).tail(static_part.cols()) = static_part.row(Eigen::Index(i));
  for (std::size_t j = 0; j < interface_dofs.size(); ++j) basis(interface_dofs[j], n_normal + Eigen::Index(j)) = 1.0;
  return basis;
}

MasslessBoundaryModel massless_craig_bampton(const Eigen::SparseMatrix<double>& K, const Eigen::SparseMatrix<double>& M,
                                             const Eigen::MatrixXd& rigid, const std::vector<int>& boundary_dofs, int n_modes) {
  if (rigid.cols() > 0)
    throw format::ComputationError("the massless Craig-Bampton variant needs a body its boundary conditions hold; a free body "
                                   "would carry its rigid motion in massless constraint modes (use macneal, which relieves inertia)");
  const Eigen::Index nb = Eigen::Index(boundary_dofs.size());
  const Eigen::MatrixXd cb = craig_bampton_basis(K, M, boundary_dofs, n_modes);
  const Eigen::MatrixXd Theta = cb.leftCols(n_modes);
  // constraint modes less their mass coupling to Theta: Theta vanishes on the boundary, so the
  // boundary rows stay [I 0], and Theta^T M Psi = 0 leaves Theta's motion free of u_b's inertia
  const Eigen::MatrixXd Psi = cb.rightCols(nb) - Theta * (Theta.transpose() * sparse_times(M, cb.rightCols(nb)));
  MasslessBoundaryModel out;
  out.boundary_dofs = boundary_dofs;
  out.T.resize(K.rows(), nb + n_modes);
  out.T << Psi, Theta;
  out.K = projected(K, out.T);
  out.M = Eigen::MatrixXd::Zero(nb + n_modes, nb + n_modes);
  out.M.bottomRightCorner(n_modes, n_modes).setIdentity();
  out.Phi = Theta;
  out.omega2 = out.K.bottomRightCorner(n_modes, n_modes).diagonal();  // Theta^T K Theta, Theta being T's last columns
  return out;
}

}  // namespace isosid::prep
