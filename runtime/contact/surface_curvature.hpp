// Principal curvatures of a contact surface at a point, for the Hertz estimate of an impact
// (impact_estimate). Positive where the surface is convex, i.e. bends away from its outward
// normal.
#pragma once
#include "contact/deformed_patch.hpp"

namespace isosid::run {

/// Principal curvatures (1/m) of an evaluated patch point with outward unit normal
/// `outward` (body frame):
/// - a surface (3D): the eigenvalues of the shape operator, from the first and second
///   fundamental forms;
/// - a curve of an axisymmetric body (x the radius): the meridional curvature and the
///   circumferential one, n_x / x (equal to the meridional one on the axis);
/// - a curve of a planar body: its curvature, and 0 along the thickness.
Eigen::Vector2d principal_curvatures(const DeformedPatch::Point& point, const Eigen::Vector3d& outward, int parameter_dim,
                                     bool axisymmetric);

}  // namespace isosid::run
