// B-spline basis evaluation; see bspline_basis.hpp.
#include "isosid/format/bspline_basis.hpp"

#include "isosid/format/error.hpp"

#include <cmath>

namespace isosid::format {

int find_span(const KnotVector& U, int p, double u) {
  const int n = basis_count(U, p) - 1;
  if (u >= U(n + 1)) return n;
  if (u <= U(p)) return p;
  int low = p, high = n + 1, mid = (low + high) / 2;
  while (u < U(mid) || u >= U(mid + 1)) {
    if (u < U(mid))
      high = mid;
    else
      low = mid;
    mid = (low + high) / 2;
  }
  return mid;
}

void basis_functions(const KnotVector& U, int p, int span, double u, double* N) {
  double left[16], right[16];
  N[0] = 1.0;
  for (int j = 1; j <= p; ++j) {
    left[j] = u - U(span + 1 - j);
    right[j] = U(span + j) - u;
    double saved = 0.0;
    for (int r = 0; r < j; ++r) {
      const double temp = N[r] / (right[r + 1] + left[j - r]);
      N[r] = saved + right[r + 1] * temp;
      saved = left[j - r] * temp;
    }
    N[j] = saved;
  }
}

BasisDerivatives basis_derivatives(const KnotVector& U, int p, int span, double u, int n_ders) {
  BasisDerivatives ndu(p + 1, p + 1), a(2, p + 1), ders = BasisDerivatives::Zero(n_ders + 1, p + 1);
  double left[16], right[16];
  ndu(0, 0) = 1.0;
  for (int j = 1; j <= p; ++j) {
    left[j] = u - U(span + 1 - j);
    right[j] = U(span + j) - u;
    double saved = 0.0;
    for (int r = 0; r < j; ++r) {
      ndu(j, r) = right[r + 1] + left[j - r];  // lower triangle: knot differences
      const double temp = ndu(r, j - 1) / ndu(j, r);
      ndu(r, j) = saved + right[r + 1] * temp;  // upper triangle: basis functions
      saved = left[j - r] * temp;
    }
    ndu(j, j) = saved;
  }
  for (int j = 0; j <= p; ++j) ders(0, j) = ndu(j, p);
  for (int r = 0; r <= p; ++r) {
    int s1 = 0, s2 = 1;
    a(0, 0) = 1.0;
    for (int k = 1; k <= n_ders && k <= p; ++k) {
      double d = 0.0;
      const int rk = r - k, pk = p - k;
      if (r >= k) {
        a(s2, 0) = a(s1, 0) / ndu(pk + 1, rk);
        d = a(s2, 0) * ndu(rk, pk);
      }
      const int j1 = rk >= -1 ? 1 : -rk;
      const int j2 = (r - 1 <= pk) ? k - 1 : p - r;
      for (int j = j1; j <= j2; ++j) {
        a(s2, j) = (a(s1, j) - a(s1, j - 1)) / ndu(pk + 1, rk + j);
        d += a(s2, j) * ndu(rk + j, pk);
      }
      if (r <= pk) {
        a(s2, k) = -a(s1, k - 1) / ndu(pk + 1, r);
        d += a(s2, k) * ndu(r, pk);
      }
      ders(k, r) = d;
      std::swap(s1, s2);
    }
  }
  double factor = p;
  for (int k = 1; k <= n_ders && k <= p; ++k) {
    ders.row(k) *= factor;
    factor *= (p - k);
  }
  return ders;
}

std::vector<double> unique_knots(const KnotVector& U) {
  std::vector<double> out;
  for (Eigen::Index i = 0; i < U.size(); ++i)
    if (out.empty() || U(i) > out.back()) out.push_back(U(i));
  return out;
}

void validate_knot_vector(const KnotVector& U, int p, const std::string& file, const std::string& field) {
  using format::InputError;
  if (p < 1 || p > 10) throw InputError(file, field, "degree " + std::to_string(p) + " outside 1..10");
  for (Eigen::Index i = 0; i < U.size(); ++i)
    if (!std::isfinite(U(i))) throw InputError(file, field, "non-finite knot at " + std::to_string(i));
  if (U.size() < 2 * (p + 1))
    throw InputError(file, field, "degree " + std::to_string(p) + " too high for " + std::to_string(U.size()) +
                                      " knots (need at least " + std::to_string(2 * (p + 1)) + ")");
  for (Eigen::Index i = 1; i < U.size(); ++i)
    if (U(i) < U(i - 1)) throw InputError(file, field, "knots not non-decreasing at index " + std::to_string(i));
  const Eigen::Index m = U.size() - 1;
  for (int i = 1; i <= p; ++i)
    if (U(i) != U(0) || U(m - i) != U(m))
      throw InputError(file, field, "knot vector must be open: first and last knots repeated p+1 = " +
                                        std::to_string(p + 1) + " times");
  if (!(U(m) > U(0))) throw InputError(file, field, "knot vector spans an empty interval");
  for (Eigen::Index i = p + 1; i < m - p; ++i) {
    Eigen::Index mult = 1;
    while (i + mult < m - p && U(i + mult) == U(i)) ++mult;
    if (mult > p)
      throw InputError(file, field, "interior knot " + std::to_string(U(i)) + " repeated " + std::to_string(mult) +
                                        " times; at most p = " + std::to_string(p) + " keeps the patch connected");
    i += mult - 1;
  }
}

}  // namespace isosid::prep
