// A5.4 knot refinement; see knot_insertion.hpp.
#include "refine/knot_insertion.hpp"

#include <cmath>

namespace isosid::prep {

namespace {

/// The NURBS Book A5.4 (RefineKnotVectCurve) on rows of any kind: `P` holds one row per old
/// basis function, `Q` receives one per new one; combine(a, alfa, b) = alfa a + (1 - alfa) b.
template <class Row, class Combine>
KnotVector refine_rows(const KnotVector& U, int p, const std::vector<double>& X, const std::vector<Row>& P, std::vector<Row>& Q,
                       Combine combine) {
  const int n = basis_count(U, p) - 1, m = n + p + 1, r = int(X.size()) - 1;
  const int a = find_span(U, p, X.front());
  const int b = find_span(U, p, X.back()) + 1;
  KnotVector Ub(U.size() + Eigen::Index(X.size()));
  Q.assign(P.size() + X.size(), Row());
  for (int j = 0; j <= a - p; ++j) Q[std::size_t(j)] = P[std::size_t(j)];
  for (int j = b - 1; j <= n; ++j) Q[std::size_t(j + r + 1)] = P[std::size_t(j)];
  for (int j = 0; j <= a; ++j) Ub(j) = U(j);
  for (int j = b + p; j <= m; ++j) Ub(j + r + 1) = U(j);
  int i = b + p - 1, k = b + p + r;
  for (int j = r; j >= 0; --j) {
    while (X[std::size_t(j)] <= U(i) && i > a) {
      Q[std::size_t(k - p - 1)] = P[std::size_t(i - p - 1)];
      Ub(k) = U(i);
      --k;
      --i;
    }
    Q[std::size_t(k - p - 1)] = Q[std::size_t(k - p)];
    for (int l = 1; l <= p; ++l) {
      const int ind = k - p + l;
      double alfa = Ub(k + l) - X[std::size_t(j)];
      if (std::abs(alfa) == 0.0) {
        Q[std::size_t(ind - 1)] = Q[std::size_t(ind)];
      } else {
        alfa /= Ub(k + l) - U(i - p + l);
        Q[std::size_t(ind - 1)] = combine(Q[std::size_t(ind - 1)], alfa, Q[std::size_t(ind)]);
      }
    }
    Ub(k) = X[std::size_t(j)];
    --k;
  }
  return Ub;
}

}  // namespace

RefinedCurve insert_knots(const KnotVector& U, int p, const Eigen::MatrixXd& Pw, const std::vector<double>& X) {
  if (X.empty()) return {U, Pw};
  std::vector<Eigen::RowVectorXd> P(static_cast<std::size_t>(Pw.rows())), Q;
  for (Eigen::Index j = 0; j < Pw.rows(); ++j) P[std::size_t(j)] = Pw.row(j);
  RefinedCurve out;
  out.knots = refine_rows(U, p, X, P, Q, [](const Eigen::RowVectorXd& a, double alfa, const Eigen::RowVectorXd& b) -> Eigen::RowVectorXd {
    return alfa * a + (1.0 - alfa) * b;
  });
  out.points.resize(Eigen::Index(Q.size()), Pw.cols());
  for (std::size_t j = 0; j < Q.size(); ++j) out.points.row(Eigen::Index(j)) = Q[j];
  return out;
}

std::vector<SparseRow> knot_insertion_rows(const KnotVector& U, int p, const std::vector<double>& X) {
  const int n = basis_count(U, p);
  std::vector<SparseRow> P(static_cast<std::size_t>(n)), Q;
  for (int j = 0; j < n; ++j) P[std::size_t(j)] = {{j, 1.0}};
  if (X.empty()) return P;
  refine_rows(U, p, X, P, Q, [](const SparseRow& a, double alfa, const SparseRow& b) {
    SparseRow sum;  // merge by column (both sorted)
    std::size_t i = 0, j = 0;
    while (i < a.size() || j < b.size()) {
      if (j == b.size() || (i < a.size() && a[i].first < b[j].first)) {
        sum.emplace_back(a[i].first, alfa * a[i].second), ++i;
      } else if (i == a.size() || b[j].first < a[i].first) {
        sum.emplace_back(b[j].first, (1.0 - alfa) * b[j].second), ++j;
      } else {
        sum.emplace_back(a[i].first, alfa * a[i].second + (1.0 - alfa) * b[j].second), ++i, ++j;
      }
    }
    return sum;
  });
  return Q;
}

Eigen::MatrixXd knot_insertion_matrix(const KnotVector& U, int p, const std::vector<double>& X) {
  const std::vector<SparseRow> rows = knot_insertion_rows(U, p, X);
  Eigen::MatrixXd T = Eigen::MatrixXd::Zero(Eigen::Index(rows.size()), basis_count(U, p));
  for (std::size_t j = 0; j < rows.size(); ++j)
    for (const auto& [k, value] : rows[j]) T(Eigen::Index(j), k) = value;
  return T;
}

}  // namespace isosid::prep
