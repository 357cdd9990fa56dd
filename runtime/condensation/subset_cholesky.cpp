// A principal block's Cholesky factor kept as its index set changes; see subset_cholesky.hpp.
#include "condensation/subset_cholesky.hpp"

#include <cmath>

namespace isosid::run {

void SubsetCholesky::reset(const Eigen::MatrixXd& A, const Eigen::VectorXd& d) {
  A_ = &A, d_ = &d;
  const Eigen::Index n = A.rows();
  L_.resize(n, n);
  work_.resize(n);
  order_.clear();
  order_.reserve(std::size_t(n));
  position_.assign(std::size_t(n), -1);
  factored_ = true;
  since_anew_ = factorizations_ = updates_ = 0;
}

bool SubsetCholesky::follow(const std::vector<Eigen::Index>& members, const std::vector<char>& is_member) {
  Eigen::Index leaving = 0;
  for (const Eigen::Index i : order_) leaving += !is_member[std::size_t(i)];
  const Eigen::Index staying = Eigen::Index(order_.size()) - leaving, entering = Eigen::Index(members.size()) - staying;
  const Eigen::Index changes = leaving + entering, size = Eigen::Index(members.size());
  if (changes == 0 && factored_) return true;
  // an update costs about size^2 flops of vector work, a factorization size^3 / 3 in blocks
  // (several times faster per flop): updates pay while they change under an eighth of the
  // block. Their round-off adds up, so a factorization from scratch follows as many updates
  // as the block has rows.
  if (!factored_ || 8 * changes > size || since_anew_ + changes > size) return factored_ = factor_anew(members);
  for (Eigen::Index p = Eigen::Index(order_.size()) - 1; p >= 0; --p)
    if (!is_member[std::size_t(order_[std::size_t(p)])]) remove(p);
  for (const Eigen::Index i : members)
    if (position_[std::size_t(i)] < 0 && !append(i)) return factored_ = factor_anew(members);
  since_anew_ += changes;
  updates_ += changes;
  return factored_ = true;
}

bool SubsetCholesky::factor_anew(const std::vector<Eigen::Index>& members) {
  for (const Eigen::Index i : order_) position_[std::size_t(i)] = -1;
  order_ = members;
  const Eigen::Index r = Eigen::Index(order_.size());
  for (Eigen::Index b = 0; b < r; ++b) {
    position_[std::size_t(order_[std::size_t(b)])] = b;
    for (Eigen::Index a = b; a < r; ++a) L_(a, b) = entry(order_[std::size_t(a)], order_[std::size_t(b)]);
  }
  ++factorizations_;
  since_anew_ = 0;
  if (r == 0) return true;
  // factored in place (an LLT of its own would allocate at every factorization)
  Eigen::Ref<Eigen::MatrixXd> block = L_.topLeftCorner(r, r);
  Eigen::LLT<Eigen::Ref<Eigen::MatrixXd>, Eigen::Lower> llt(block);
  return llt.info() == Eigen::Success;
}

void SubsetCholesky::remove(Eigen::Index p) {
  const Eigen::Index r = Eigen::Index(order_.size()), n = r - 1 - p;
  // Without row and column p, the rows after it keep their product with the rows before, and
  // their own block must also carry what column p carried: L33' L33'^T = L33 L33^T + x x^T,
  // x = L(p+1:, p), a rank-one update (stable: no subtraction).
  auto x = work_.head(n);
  x = L_.col(p).segment(p + 1, n);
  for (Eigen::Index k = 0; k < n; ++k) {
    const Eigen::Index kk = p + 1 + k;
    const double diagonal = L_(kk, kk), root = std::hypot(diagonal, x(k)), c = root / diagonal, s = x(k) / diagonal;
    L_(kk, kk) = root;
    for (Eigen::Index i = k + 1; i < n; ++i) {
      double& l = L_(p + 1 + i, kk);
      l = (l + s * x(i)) / c;
      x(i) = c * x(i) - s * l;
    }
  }
  // close the gap: rows after p move up one, columns after p left one (in place: column by
  // column, each reading rows below and columns right of what it writes)
  for (Eigen::Index j = 0; j + 1 < r; ++j) {
    const Eigen::Index from = j < p ? j : j + 1;
    for (Eigen::Index i = std::max(j, p); i + 1 < r; ++i) L_(i, j) = L_(i + 1, from);
  }
  position_[std::size_t(order_[std::size_t(p)])] = -1;
  order_.erase(order_.begin() + p);
  for (Eigen::Index q = p; q < r - 1; ++q) position_[std::size_t(order_[std::size_t(q)])] = q;
}

bool SubsetCholesky::append(Eigen::Index i) {
  const Eigen::Index r = Eigen::Index(order_.size());
  // the new row l solves L l = M(S, i); its diagonal is sqrt(M(i, i) - l.l)
  auto l = work_.head(r);
  for (Eigen::Index k = 0; k < r; ++k) l(k) = entry(order_[std::size_t(k)], i);
  L_.topLeftCorner(r, r).triangularView<Eigen::Lower>().solveInPlace(l);
  const double pivot = entry(i, i) - l.squaredNorm();
  if (!(pivot > 0) || !std::isfinite(pivot)) return false;
  L_.row(r).head(r) = l.transpose();
  L_(r, r) = std::sqrt(pivot);
  order_.push_back(i);
  position_[std::size_t(i)] = r;
  return true;
}

void SubsetCholesky::solve(const Eigen::VectorXd& b, Eigen::VectorXd& x) {
  const Eigen::Index r = Eigen::Index(order_.size());
  auto y = work_.head(r);
  for (Eigen::Index k = 0; k < r; ++k) y(k) = b(order_[std::size_t(k)]);
  const auto L = L_.topLeftCorner(r, r);
  L.triangularView<Eigen::Lower>().solveInPlace(y);
  L.transpose().triangularView<Eigen::Upper>().solveInPlace(y);
  for (Eigen::Index k = 0; k < r; ++k) x(order_[std::size_t(k)]) = y(k);
}

}  // namespace isosid::run
