// B-spline basis functions and derivatives on open knot vectors, shared by the preprocessor
// (geometry, refinement) and the runtime (master patches of flexible contact targets)
// (The NURBS Book, algorithms A2.1 FindSpan, A2.2 BasisFuns, A2.3 DersBasisFuns).
#pragma once
#include <Eigen/Dense>
#include <string>
#include <vector>

namespace isosid::format {

using KnotVector = Eigen::VectorXd;

/// Number of basis functions of degree p on U.
inline int basis_count(const KnotVector& U, int p) { return int(U.size()) - p - 1; }

/// Span index i with U[i] <= u < U[i+1]; u at the upper end returns the last non-empty span.
int find_span(const KnotVector& U, int p, double u);

/// The p+1 non-zero basis functions N_{span-p..span}(u).
void basis_functions(const KnotVector& U, int p, int span, double u, double* N);

/// Degrees up to this are supported (the work arrays live on the stack).
inline constexpr int kMaxDegree = 15;
/// Row k: k-th derivative of the p+1 non-zero functions at u, k = 0..n_ders (fixed capacity,
/// so evaluation does not allocate: the runtime projects on master patches in its hot loop).
using BasisDerivatives = Eigen::Matrix<double, Eigen::Dynamic, Eigen::Dynamic, 0, kMaxDegree + 1, kMaxDegree + 1>;
BasisDerivatives basis_derivatives(const KnotVector& U, int p, int span, double u, int n_ders);

/// Distinct knot values, ascending.
std::vector<double> unique_knots(const KnotVector& U);

/// Checks that U is a valid open (clamped) knot vector for degree p; throws InputError(file, field, ...).
void validate_knot_vector(const KnotVector& U, int p, const std::string& file, const std::string& field);

}  // namespace isosid::prep
