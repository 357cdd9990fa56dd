// Knot insertion of many knots in one sweep (The NURBS Book A5.4, RefineKnotVectCurve),
// on rows of homogeneous control points, and its matrix form.
#pragma once
#include "geometry/nurbs_patch.hpp"

#include <Eigen/Dense>

namespace isosid::prep {

struct RefinedCurve {
  KnotVector knots;
  Eigen::MatrixXd points;  ///< rows: refined homogeneous control points
};

/// Inserts the sorted knots X into (U, p) and maps the rows of Pw (one per basis function).
RefinedCurve insert_knots(const KnotVector& U, int p, const Eigen::MatrixXd& Pw, const std::vector<double>& X);

/// T with N_old = T^T N_new, i.e. new coefficients = T * old coefficients.
Eigen::MatrixXd knot_insertion_matrix(const KnotVector& U, int p, const std::vector<double>& X);

}  // namespace isosid::prep
