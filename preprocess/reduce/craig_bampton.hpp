// Craig-Bampton reduction: fixed-interface normal modes plus static constraint modes of the
// interface DOFs (one per DOF, by a CHOLMOD solve with the interior stiffness).
#pragma once
#include <Eigen/Dense>
#include <Eigen/Sparse>
#include <vector>

namespace isosid::prep {

/// Columns: n_normal interior normal modes (zero on the interface), then one constraint mode
/// per interface DOF (unit there, zero on the other interface DOFs, statically condensed inside).
Eigen::MatrixXd craig_bampton_basis(const Eigen::SparseMatrix<double>& K, const Eigen::SparseMatrix<double>& M,
                                    const std::vector<int>& interface_dofs, int n_normal, double lambda_scale);

/// Rows and columns `keep` of a sparse matrix.
Eigen::SparseMatrix<double> submatrix(const Eigen::SparseMatrix<double>& A, const std::vector<int>& rows,
                                      const std::vector<int>& cols);

}  // namespace isosid::prep
