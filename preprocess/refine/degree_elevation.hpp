// Order elevation of a B-spline space: the degree rises by t and every distinct knot's
// multiplicity rises by t, so the continuity is kept and the old space is a subspace.
#pragma once
#include "geometry/nurbs_patch.hpp"

#include <Eigen/Dense>

namespace isosid::prep {

/// Knot vector of the elevated space.
KnotVector elevated_knots(const KnotVector& U, int p, int t);

/// T (n_new x n_old): new coefficients = T * old coefficients, so the curve is unchanged.
/// Computed by exact collocation at the Greville points of the new space (the old curve lies
/// in the new space, so interpolation reproduces it; this replaces A5.9's knot-removal step,
/// which is delicate to port, by a well-conditioned banded solve).
Eigen::MatrixXd degree_elevation_matrix(const KnotVector& U, int p, int t);

}  // namespace isosid::prep
