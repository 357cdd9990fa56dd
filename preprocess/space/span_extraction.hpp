// Bezier extraction of a 1D B-spline basis: on every non-empty knot span the p+1 functions
// living there as combinations of the Bernstein polynomials on that span.
#pragma once
#include "geometry/nurbs_patch.hpp"

#include <Eigen/Dense>
#include <vector>

namespace isosid::prep {

struct SpanExtraction {
  double lo = 0, hi = 0;
  int first_function = 0;  ///< span index - p
  Eigen::MatrixXd C;       ///< (p+1) x (p+1): N_{first+j}(t) = sum_b C(j, b) B_b(t)
};

/// One entry per non-empty span, by collocation at p+1 Chebyshev points of the span.
std::vector<SpanExtraction> span_extractions(const KnotVector& U, int p);

/// Tensor product of 1D extractions, first direction fastest in rows and columns:
/// C(f, b) = prod_d C_d(f_d, b_d).
Eigen::MatrixXd tensor_extraction(const std::vector<const Eigen::MatrixXd*>& C1d);

}  // namespace isosid::prep
