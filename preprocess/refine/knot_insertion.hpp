// Knot insertion of many knots in one sweep (The NURBS Book A5.4, RefineKnotVectCurve),
// on rows of homogeneous control points, and its matrix form.
#pragma once
#include "geometry/nurbs_patch.hpp"

#include <Eigen/Dense>
#include <utility>
#include <vector>

namespace isosid::prep {

struct RefinedCurve {
  KnotVector knots;
  Eigen::MatrixXd points;  ///< rows: refined homogeneous control points
};

/// Inserts the sorted knots X into (U, p) and maps the rows of Pw (one per basis function).
RefinedCurve insert_knots(const KnotVector& U, int p, const Eigen::MatrixXd& Pw, const std::vector<double>& X);

/// A row of a sparse matrix: (column, value), sorted by column.
using SparseRow = std::vector<std::pair<int, double>>;

/// The rows of knot_insertion_matrix with their at most p + 1 nonzeros, in O((n + |X|) p):
/// a level of a deep hierarchical refinement can have tens of thousands of functions.
std::vector<SparseRow> knot_insertion_rows(const KnotVector& U, int p, const std::vector<double>& X);

/// T with N_old = T^T N_new, i.e. new coefficients = T * old coefficients.
Eigen::MatrixXd knot_insertion_matrix(const KnotVector& U, int p, const std::vector<double>& X);

}  // namespace isosid::prep
