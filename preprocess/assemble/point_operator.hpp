// Displacement and strain at one point of a body as linear maps of the DOFs of the element
// containing it: u = N u_e, strain = B u_e, stress = D B u_e. Used for error norms, stress
// recovery rows and contact shape rows.
#pragma once
#include "space/analysis_space.hpp"
#include "space/dof_map.hpp"
#include "assemble/body_elasticity.hpp"

#include <optional>
#include <vector>

namespace isosid::prep {

struct PointOperator {
  Eigen::VectorXd x;                ///< physical point
  double det_J = 0;                 ///< parametric-to-physical Jacobian determinant
  std::vector<int> nodes;           ///< node of each element function
  Eigen::MatrixXd N;                ///< dim x (nf*dim), columns f*dim + a
  Eigen::MatrixXd B;                ///< strain_count x (nf*dim)
  Eigen::VectorXd R;                ///< element functions at the point
  Eigen::MatrixXd dR_dx;            ///< nf x dim physical gradients

  /// u at the point from all nodal displacements (node_count*dim, node-major).
  Eigen::VectorXd displacement(const Eigen::VectorXd& nodal) const;
  Eigen::VectorXd strain(const Eigen::VectorXd& nodal) const;
  /// Rows of the element's DOFs (f*dim + a) gathered from nodal rows (node*dim + a), for a
  /// displacement vector or a matrix of modes.
  Eigen::MatrixXd gather(const Eigen::MatrixXd& nodal) const;
};

PointOperator point_operator(const AnalysisSpace& space, const DofMap& dofs, const BodyElasticity& elasticity,
                             const Element& element, const double* t);

/// The element of `patch` containing patch parameter xi and the reference coordinates of xi in
/// it; returns false if xi lies outside the patch.
bool locate(const AnalysisSpace& space, int patch, const Eigen::VectorXd& xi, int& element, double* t);

/// The point operator at parameter xi of `patch` (locate, then point_operator); empty outside the patch.
std::optional<PointOperator> point_operator_at(const AnalysisSpace& space, const DofMap& dofs, const BodyElasticity& elasticity,
                                               int patch, const Eigen::VectorXd& xi);

/// Expands a solution on the free DOFs to all nodal DOFs (fixed components get `fixed_values`
/// if given, else zero).
Eigen::VectorXd expand_to_nodes(const DofMap& dofs, const Eigen::VectorXd& free_values,
                                const Eigen::VectorXd* fixed_values = nullptr);

}  // namespace isosid::prep
