// Reduced models with a massless boundary ([R3], [R4] in docs/references.md): the
// boundary DOFs stay physical coordinates u_b and carry no mass, the mass rides on modal
// coordinates eta. Made by MacNeal's method (reduce/macneal) or the massless Craig-Bampton
// variant (reduce/craig_bampton).
#pragma once
#include "reduce/mode_basis.hpp"

#include <Eigen/Dense>
#include <vector>

namespace isosid::prep {

struct MasslessBoundaryModel {
  std::vector<int> boundary_dofs;  ///< free DOF indices, in the order of u_b
  Eigen::MatrixXd T;               ///< free DOFs x (nb + nm): u = T [u_b; eta]; its boundary rows are [I 0]
  Eigen::MatrixXd K;               ///< (nb + nm)^2, T^T K T
  Eigen::MatrixXd M;               ///< diag(0_bb, I): the boundary carries no mass (not T^T M T, by design)
  Eigen::MatrixXd Phi;             ///< free DOFs x nm: the modes that carry the mass (M-normalized)
  Eigen::VectorXd omega2;          ///< their squared frequencies
  Eigen::Index boundary() const { return Eigen::Index(boundary_dofs.size()); }
};

/// The model as a basis in the runtime's order: the modes' coordinates eta first (they carry
/// the mass and are integrated), the massless boundary DOFs last (solved statically).
ReducedBasis massless_boundary_basis(const MasslessBoundaryModel& m);

}  // namespace isosid::prep
