// Sparse assembly of consistent mass and stiffness matrices (and boundary loads) on the free
// DOFs: compositions of integrands and patterns run by the one element loop (element_loop.hpp).
#pragma once
#include "assemble/body_elasticity.hpp"
#include "assemble/element_pattern.hpp"
#include "space/analysis_space.hpp"
#include "space/dof_map.hpp"

#include <Eigen/Sparse>
#include <functional>

namespace isosid::prep {

struct SystemMatrices {
  SparseMatrix K, M;  ///< free DOFs x free DOFs
};

/// `extra_points` adds Gauss points per direction beyond p+1 (rational integrands).
SystemMatrices assemble_system(const AnalysisSpace& space, const DofMap& dofs, const BodyElasticity& elasticity,
                               int extra_points = 0);

/// Scalar consistent mass over all nodes (no constraints): M_s(i,j) = rho int R_i R_j dV.
/// Every body integral of the SID follows from it (sum = mass, P^T M_s P = int x x^T dm, ...).
SparseMatrix assemble_scalar_mass(const AnalysisSpace& space, const DofMap& dofs, const BodyElasticity& elasticity,
                                  int extra_points = 0);

/// Load vector on the free DOFs of a traction t(x, n) (Pa) applied on a side of a patch.
Eigen::VectorXd assemble_traction(const AnalysisSpace& space, const DofMap& dofs, const BodyElasticity& elasticity,
                                  int patch, PatchSide side,
                                  const std::function<Eigen::VectorXd(const Eigen::VectorXd&, const Eigen::VectorXd&)>& t);

}  // namespace isosid::prep
