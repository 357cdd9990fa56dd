// A5.4 knot refinement; see knot_insertion.hpp.
#include "refine/knot_insertion.hpp"

#include <cmath>

namespace isosid::prep {

RefinedCurve insert_knots(const KnotVector& U, int p, const Eigen::MatrixXd& Pw, const std::vector<double>& X) {
  if (X.empty()) return {U, Pw};
  const int n = basis_count(U, p) - 1, m = n + p + 1, r = int(X.size()) - 1;
  const int a = find_span(U, p, X.front());
  const int b = find_span(U, p, X.back()) + 1;
  RefinedCurve out;
  out.knots.resize(U.size() + Eigen::Index(X.size()));
  out.points.resize(Pw.rows() + Eigen::Index(X.size()), Pw.cols());
  KnotVector& Ub = out.knots;
  Eigen::MatrixXd& Qw = out.points;
  for (int j = 0; j <= a - p; ++j) Qw.row(j) = Pw.row(j);
  for (int j = b - 1; j <= n; ++j) Qw.row(j + r + 1) = Pw.row(j);
  for (int j = 0; j <= a; ++j) Ub(j) = U(j);
  for (int j = b + p; j <= m; ++j) Ub(j + r + 1) = U(j);
  int i = b + p - 1, k = b + p + r;
  for (int j = r; j >= 0; --j) {
    while (X[std::size_t(j)] <= U(i) && i > a) {
      Qw.row(k - p - 1) = Pw.row(i - p - 1);
      Ub(k) = U(i);
      --k;
      --i;
    }
    Qw.row(k - p - 1) = Qw.row(k - p);
    for (int l = 1; l <= p; ++l) {
      const int ind = k - p + l;
      double alfa = Ub(k + l) - X[std::size_t(j)];
      if (std::abs(alfa) == 0.0) {
        Qw.row(ind - 1) = Qw.row(ind);
      } else {
        alfa /= Ub(k + l) - U(i - p + l);
        Qw.row(ind - 1) = alfa * Qw.row(ind - 1) + (1.0 - alfa) * Qw.row(ind);
      }
    }
    Ub(k) = X[std::size_t(j)];
    --k;
  }
  return out;
}

Eigen::MatrixXd knot_insertion_matrix(const KnotVector& U, int p, const std::vector<double>& X) {
  const int n = basis_count(U, p);
  return insert_knots(U, p, Eigen::MatrixXd::Identity(n, n), X).points;
}

}  // namespace isosid::prep
