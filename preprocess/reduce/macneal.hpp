// MacNeal's massless-boundary reduction ([R3], [R4] in docs/references.md):
// free-interface normal modes plus residual-flexibility attachment modes of the boundary DOFs.
// Coordinates [u_b; eta]: u_b the physical displacements of the boundary DOFs, which carry no
// mass, eta the amplitudes of the retained elastic modes. A free body is reduced with inertia
// relief: boundary loads are balanced by rigid-body inertia, and the flexibility acts on the
// elastic subspace only (the floating frame carries the rigid motion).
#pragma once
#include "reduce/massless_boundary.hpp"

#include <Eigen/Dense>
#include <Eigen/Sparse>
#include <memory>
#include <vector>

namespace isosid::prep {

/// Reduces (K, M) on the free DOFs to the boundary DOFs plus `n_modes` elastic free-interface
/// modes. `rigid` holds the admissible rigid-body fields (columns; none for a constrained
/// body).
MasslessBoundaryModel macneal_reduction(const Eigen::SparseMatrix<double>& K, const Eigen::SparseMatrix<double>& M,
                                        const Eigen::MatrixXd& rigid, const std::vector<int>& boundary_dofs, int n_modes);

class SparseCholesky;

/// The factor of K (a body held in place, `rigid` without columns), or for a free body of K
/// with springs on nr DOFs where its rigid fields `rigid` are most independent: a load balanced
/// against R then has the elastic solution plus a rigid field. lowest_elastic_modes and
/// elastic_unit_load_response take it.
std::unique_ptr<SparseCholesky> stiffness_factor(const Eigen::SparseMatrix<double>& K, const Eigen::MatrixXd& rigid);

/// The elastic static response to a unit load on each of `dofs` (columns, in their order):
/// K^-1 e_k for a constrained body; for a free one the load is first balanced by rigid-body
/// inertia (e_k <- P e_k, P = I - M R (R^T M R)^-1 R^T, R the rigid fields) and the response is
/// the one without rigid content (R^T M u = 0). `stiffness` from stiffness_factor; the loads
/// are solved in blocks.
Eigen::MatrixXd elastic_unit_load_response(const SparseCholesky& stiffness, const Eigen::SparseMatrix<double>& M,
                                           const Eigen::MatrixXd& rigid, const std::vector<int>& dofs);

}  // namespace isosid::prep
