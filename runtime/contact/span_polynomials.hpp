// The B-spline basis of a knot vector as polynomials per knot span: on span s the p + 1
// functions that do not vanish there are polynomials in the local coordinate
// t = (u - U_s) / (U_s+1 - U_s) in [0, 1], whose coefficients are their Taylor coefficients at
// the span's start (The NURBS Book A2.3 there, once per span). Values and first and second
// derivatives then take Horner's rule, about a third of A2.3's work with no divisions: a
// closest-point projection evaluates its master patch thousands of times per step.
#pragma once
#include "isosid/format/bspline_basis.hpp"

#include <vector>

namespace isosid::run {

class SpanPolynomials {
public:
  SpanPolynomials() = default;
  SpanPolynomials(const format::KnotVector& U, int p);

  /// Rows value, d/du, d2/du2 of N_{span-p} .. N_span at u, as format::basis_derivatives(U, p,
  /// span, u, 2) gives them; span as format::find_span finds it for u.
  void evaluate(int span, double u, format::BasisDerivatives& N) const;

private:
  format::KnotVector U_;
  int p_ = 0;
  /// per span index s, function j and power k: coefficients_[(s (p + 1) + j) (p + 1) + k]
  std::vector<double> coefficients_;
};

}  // namespace isosid::run
