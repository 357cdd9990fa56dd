// Refinement of a NURBS patch direction by direction, on homogeneous coordinates, so the
// geometry (and any field stored in extra point columns) stays unchanged.
#pragma once
#include "geometry/nurbs_patch.hpp"

#include <Eigen/Dense>
#include <vector>

namespace isosid::prep {

/// Applies a 1D refinement matrix T (n_new x n_old) along direction `dir` to the patch's
/// homogeneous control points; `new_knots` and `new_degree` describe the new direction.
void refine_direction(NurbsPatch& patch, int dir, const Eigen::MatrixXd& T, const KnotVector& new_knots,
                      int new_degree);

/// Raises the degree of direction `dir` to `target` (no-op if already there).
void elevate_degree(NurbsPatch& patch, int dir, int target);

/// Inserts the knots X (any order; values equal to existing knots raise multiplicity).
void insert_knots(NurbsPatch& patch, int dir, std::vector<double> X);

/// Splits every non-empty span of direction `dir` into `parts` equal spans.
void subdivide_uniformly(NurbsPatch& patch, int dir, int parts);

}  // namespace isosid::prep
