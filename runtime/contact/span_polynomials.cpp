// B-spline basis functions as polynomials per knot span; see span_polynomials.hpp.
#include "contact/span_polynomials.hpp"

namespace isosid::run {

SpanPolynomials::SpanPolynomials(const format::KnotVector& U, int p) : U_(U), p_(p) {
  const int m = p + 1, last = format::basis_count(U, p) - 1;
  coefficients_.assign(std::size_t(last + 1) * std::size_t(m * m), 0.0);
  for (int s = p; s <= last; ++s) {
    const double h = U(s + 1) - U(s);
    if (!(h > 0)) continue;  // an empty span: find_span never returns it
    // N_j(U_s + t h) = sum_k N_j^(k)(U_s) h^k / k! t^k
    const format::BasisDerivatives D = format::basis_derivatives(U, p, s, U(s), p);
    double scale = 1;  // h^k / k!
    for (int k = 0; k <= p; ++k) {
      for (int j = 0; j <= p; ++j) coefficients_[std::size_t((s * m + j) * m + k)] = D(k, j) * scale;
      scale *= h / double(k + 1);
    }
  }
}

void SpanPolynomials::evaluate(int span, double u, format::BasisDerivatives& N) const {
  const int m = p_ + 1;
  const double h = U_(span + 1) - U_(span), t = (u - U_(span)) / h;
  N.setZero(3, m);
  for (int j = 0; j < m; ++j) {
    // Horner's rule with its first two derivatives in t
    const double* c = &coefficients_[std::size_t((span * m + j) * m)];
    double value = c[p_], first = 0, half_second = 0;
    for (int k = p_ - 1; k >= 0; --k) {
      half_second = half_second * t + first;
      first = first * t + value;
      value = value * t + c[k];
    }
    N(0, j) = value;
    N(1, j) = first / h;
    N(2, j) = 2 * half_second / (h * h);
  }
}

}  // namespace isosid::run
