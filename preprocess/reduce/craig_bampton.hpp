// Craig-Bampton reduction: fixed-interface normal modes plus static constraint modes of the
// interface DOFs (one per DOF, by a CHOLMOD solve with the interior stiffness).
#pragma once
#include "reduce/massless_boundary.hpp"

#include <Eigen/Dense>
#include <Eigen/Sparse>
#include <vector>

namespace isosid::prep {

/// Columns: n_normal interior normal modes (zero on the interface), then one constraint mode
/// per interface DOF (unit there, zero on the other interface DOFs, statically condensed inside).
Eigen::MatrixXd craig_bampton_basis(const Eigen::SparseMatrix<double>& K, const Eigen::SparseMatrix<double>& M,
                                    const std::vector<int>& interface_dofs, int n_normal);

/// The massless-boundary variant (Monjaraz-Tec, Gross & Krack 2022): coordinates [u_b; eta],
/// the constraint modes made M-orthogonal to the fixed-interface modes Theta (their boundary
/// rows stay [I 0]), the mass carried by Theta alone. With the boundary held, the model is
/// exactly Theta's fixed-interface modal model. Only for a body that its boundary conditions
/// hold (`rigid` empty): a free body's constraint modes would carry massless rigid motion.
MasslessBoundaryModel massless_craig_bampton(const Eigen::SparseMatrix<double>& K, const Eigen::SparseMatrix<double>& M,
                                             const Eigen::MatrixXd& rigid, const std::vector<int>& boundary_dofs, int n_modes);

/// Rows and columns `keep` of a sparse matrix.
Eigen::SparseMatrix<double> submatrix(const Eigen::SparseMatrix<double>& A, const std::vector<int>& rows,
                                      const std::vector<int>& cols);

}  // namespace isosid::prep
