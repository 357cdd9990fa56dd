// How much of each mode is beam motion: the share of its kinetic energy carried by the mean
// translation of the body's cross-sections. [R3] (docs/references.md) labels a beam's bending modes
// in the impact direction 1F, 2F, ...; a bending mode in direction d moves its sections along d as
// wholes (share along d near 1), an axial mode along the axis, while torsion and cross-section
// modes leave the sections' means at rest (shares near 0). isosid-run labels modes from these
// shares.
#pragma once
#include <Eigen/Dense>
#include <Eigen/Sparse>

namespace isosid::prep {

struct SectionTranslation {
  Eigen::Vector3d long_axis = Eigen::Vector3d::Zero();  ///< body frame: the sections' normal
  Eigen::MatrixXd shares;  ///< columns x 3: share of the column's kinetic energy per body-frame axis; empty: no long axis
};

/// `modes` on all nodal DOFs (node-major, dim per node, fixed components zero), `node_points`
/// their control points, `scalar_mass` the body's nodes x nodes mass matrix for one component.
/// The long axis is the principal axis of the control points' mass distribution with the
/// largest second moment; the sections are `sections` slabs of equal width across it. A slab's
/// field translates the control points lying in it (the functions' mass lies around their
/// control points), and a column's share along axis a is the kinetic energy of its
/// M-orthogonal projection onto those fields' span, component a. Columns without kinetic
/// energy (massless boundary coordinates) get zero shares; a column's shares sum to at most 1
/// (exactly 1 for rigid translations). A body whose largest second moment exceeds the next by
/// less than 5 % has no long axis: no shares (empty) then.
SectionTranslation section_translation(const Eigen::MatrixXd& modes, const Eigen::MatrixXd& node_points,
                                       const Eigen::SparseMatrix<double>& scalar_mass, int sections = 64);

}  // namespace isosid::prep
