// A reduced basis of a body on its free DOFs, and the steps that make every reduction method
// end alike: rigid-body content removed (Buckens frame), M-orthonormal, K-diagonal, sorted.
#pragma once
#include <Eigen/Dense>
#include <Eigen/Sparse>
#include <string>
#include <vector>

#include "isosid/format/analysis_type.hpp"
#include "isosid/format/reduction_method.hpp"

namespace isosid::prep {

struct ReducedBasis {
  Eigen::MatrixXd Phi;        ///< free DOFs x nq: Phi^T M Phi = I, Phi^T K Phi = diag(omega2); MacNeal: see `massless`
  Eigen::VectorXd omega2;     ///< ascending squared angular frequencies (0 for massless coordinates)
  int n_low = 0;              ///< leading normal (low-frequency) modes
  format::ReductionMethod method = format::ReductionMethod::Modal;
  std::string interface;      ///< description of the interface (Craig-Bampton) or massless boundary (MacNeal)
  int removed_rigid = 0;      ///< basis directions dropped as rigid-body content
  /// Craig-Bampton: the free DOFs of its interface, whose constraint modes make the reduction
  /// statically exact there (where contact may load the surface without stiffening it)
  std::vector<int> interface_dofs;
  /// MacNeal: the last coordinates are the displacements of these free DOFs (the massless
  /// boundary, in order). The mass is carried by `inertial` (free DOFs x nq: the free-interface
  /// modes, zero columns for the boundary), so inertial^T M inertial = diag(I, 0) and
  /// Phi^T K Phi is dense.
  std::vector<int> massless_dofs;
  Eigen::MatrixXd inertial;
  /// Phi^T K Phi where the reduction formed it more exactly than the projection (MacNeal: in
  /// closed form); empty: the SID builder projects K.
  Eigen::MatrixXd stiffness;
  Eigen::Index massless() const { return Eigen::Index(massless_dofs.size()); }
  /// The displacement field whose motion carries the mass: Phi itself except for MacNeal.
  const Eigen::MatrixXd& mass_carrying() const { return massless() > 0 ? inertial : Phi; }
};

/// Rigid-body displacement fields on all nodal DOFs (node-major, `dim` per node): translations
/// and rotations about the frame origin in 3D; x, y translation and z-rotation for planar
/// bodies; the axial (y) translation for axisymmetric sections.
Eigen::MatrixXd rigid_nodal_fields(const Eigen::MatrixXd& node_points, format::AnalysisType analysis);

/// Rigid-body displacement fields of the body on its free DOFs (columns), only those that the
/// constraints allow: translations and rotations about the frame origin in 3D; x, y and the
/// z-rotation for planar bodies; the axial translation for axisymmetric bodies.
Eigen::MatrixXd admissible_rigid_fields(const Eigen::MatrixXd& rigid_nodal, const std::vector<int>& free_of_dof);

/// Phi <- (I - R (R^T M R)^-1 R^T M) Phi: no rigid-body content (int Phi dm = 0 and
/// int c x Phi dm = 0, the Buckens conditions).
void remove_rigid_content(Eigen::MatrixXd& Phi, const Eigen::SparseMatrix<double>& M, const Eigen::MatrixXd& R);

/// Makes Phi M-orthonormal and K-diagonal within its span, sorted by frequency; directions
/// whose M-norm is below `rank_tolerance` of the largest are dropped (rank deficiency after
/// rigid-content removal). Returns the squared frequencies.
Eigen::VectorXd orthonormalize(Eigen::MatrixXd& Phi, const Eigen::SparseMatrix<double>& K,
                               const Eigen::SparseMatrix<double>& M, double rank_tolerance = 1e-10);

/// Makes the modes independent of the eigensolver's start (orthonormalize does it): each
/// mode's sign, and the basis of each repeated frequency (omega2 equal to 1e-9), are fixed by
/// the modes' projections on fixed generic vectors of the DOF space. Two runs on the same
/// model then give the same modes, and a refined model's transfer from its coarse model holds
/// for the coarse SID built by another run.
void canonicalize_modes(Eigen::MatrixXd& Phi, const Eigen::VectorXd& omega2);

}  // namespace isosid::prep
