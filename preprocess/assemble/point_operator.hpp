// Displacement and strain at one point of a body as linear maps of the DOFs of the element
// containing it: u = N u_e, strain = B u_e, stress = D B u_e. Used for error norms, stress
// recovery rows and contact shape rows.
#pragma once
#include "assemble/analysis_space.hpp"
#include "assemble/dof_map.hpp"
#include "assemble/elasticity.hpp"

#include <vector>

namespace isosid::prep {

struct PointOperator {
  Eigen::VectorXd x;                ///< physical point
  double det_J = 0;                 ///< parametric-to-physical Jacobian determinant
  std::vector<int> nodes;           ///< node of each element function
  Eigen::MatrixXd N;                ///< dim x (nf*dim), columns f*dim + a
  Eigen::MatrixXd B;                ///< strain_count x (nf*dim)

  /// u at the point from all nodal displacements (node_count*dim, node-major).
  Eigen::VectorXd displacement(const Eigen::VectorXd& nodal) const;
  Eigen::VectorXd strain(const Eigen::VectorXd& nodal) const;
  /// Local DOF vector gathered from nodal values.
  Eigen::VectorXd gather(const Eigen::VectorXd& nodal) const;
};

PointOperator point_operator(const AnalysisSpace& space, const DofMap& dofs, const Elasticity& elasticity,
                             const Element& element, const double* t);

/// Expands a solution on the free DOFs to all nodal DOFs (fixed components get `fixed_values`
/// if given, else zero).
Eigen::VectorXd expand_to_nodes(const DofMap& dofs, const Eigen::VectorXd& free_values,
                                const Eigen::VectorXd* fixed_values = nullptr);

}  // namespace isosid::prep
