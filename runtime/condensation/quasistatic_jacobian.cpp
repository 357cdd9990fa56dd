// Stiffness of the quasistatic modes and its Newton Jacobian; see quasistatic_jacobian.hpp.
#include "condensation/quasistatic_jacobian.hpp"

#include "isosid/common/dense_decompositions.hpp"

#include <algorithm>
#include <cmath>

namespace isosid::run {

QuasistaticJacobian::QuasistaticJacobian(const std::vector<Eigen::MatrixXd>& blocks, bool diagonal) {
  Eigen::Index n = 0;
  for (const Eigen::MatrixXd& K : blocks) n += K.rows();
  stiffness_.resize(n);
  Eigen::Index at = 0;
  for (const Eigen::MatrixXd& K : blocks) stiffness_.segment(at, K.rows()) = K.diagonal(), at += K.rows();
  if (diagonal) {
    smallest_eigenvalue_ = n ? std::max(0.0, stiffness_.minCoeff()) : 0.0;
    inverse_root_stiffness_ = stiffness_.cwiseMax(0.0).cwiseSqrt().cwiseInverse();  // used only where K is positive
    return;
  }
  dense_stiffness_ = Eigen::MatrixXd::Zero(n, n);
  block_product_.resize(n);
  at = 0;
  for (const Eigen::MatrixXd& K : blocks) {
    dense_stiffness_.block(at, at, K.rows(), K.rows()) = K;
    if (K.rows() > 0) dense_blocks_.emplace_back(at, K.rows());
    at += K.rows();
  }
  // K_h does not change: inverted once, it serves every Woodbury solve (a massless boundary
  // without contact then costs a matrix-vector product per Newton step, not a factorization).
  // It is block diagonal, one block per body: factored, inverted and its spectrum bounded
  // block by block, at a fraction of the whole matrix's cubic cost.
  dense_inverse_ = Eigen::MatrixXd::Zero(n, n);
  smallest_eigenvalue_ = n ? INFINITY : 0.0;
  for (const auto& [first, nb] : dense_blocks_) {
    const auto K = dense_stiffness_.block(first, first, nb, nb);
    const Eigen::LLT<Eigen::MatrixXd> llt(K);
    if (llt.info() != Eigen::Success) dense_inverse_.resize(0, 0);
    if (dense_inverse_.size()) dense_inverse_.block(first, first, nb, nb) = llt.solve(Eigen::MatrixXd::Identity(nb, nb));
    smallest_eigenvalue_ = std::min(smallest_eigenvalue_, common::symmetric_eigenvalues(K)(0));
  }
  smallest_eigenvalue_ = std::max(0.0, smallest_eigenvalue_);
  used_rows_.resize(std::size_t(n));
}

void QuasistaticJacobian::multiply_blocks(const Eigen::MatrixXd& A, const Eigen::VectorXd& x, Eigen::VectorXd& out) const {
  out.resize(x.size());
  for (const auto& [at, nb] : dense_blocks_) out.segment(at, nb).noalias() = A.block(at, at, nb, nb) * x.segment(at, nb);
}

void QuasistaticJacobian::multiply(const Eigen::VectorXd& z, Eigen::VectorXd& out) const {
  if (dense_stiffness_.size()) {
    multiply_blocks(dense_stiffness_, z, out);
  } else {
    out = stiffness_.cwiseProduct(z);
  }
}

double QuasistaticJacobian::product(const Eigen::VectorXd& z, const Eigen::VectorXd& w) const {
  if (dense_stiffness_.size()) {
    multiply(w, block_product_);
    return z.dot(block_product_);
  }
  double sum = 0;
  for (Eigen::Index i = 0; i < z.size(); ++i) sum += z(i) * stiffness_(i) * w(i);
  return sum;
}

namespace {
/// LU factors with partial pivoting of the leading r x r block of A, in place (row k was
/// swapped with pivots[k]). Eigen's decompositions would allocate per call for a size that
/// changes with the active set; this runs in the right-hand side, which must not.
void factor_leading_block(Eigen::MatrixXd& A, Eigen::Index r, std::vector<Eigen::Index>& pivots) {
  for (Eigen::Index k = 0; k < r; ++k) {
    Eigen::Index pivot = k;
    A.col(k).segment(k, r - k).cwiseAbs().maxCoeff(&pivot);
    pivot += k;
    pivots[std::size_t(k)] = pivot;
    if (pivot != k) A.row(k).head(r).swap(A.row(pivot).head(r));
    A.col(k).segment(k + 1, r - k - 1) /= A(k, k);
    for (Eigen::Index j = k + 1; j < r; ++j) A.col(j).segment(k + 1, r - k - 1) -= A(k, j) * A.col(k).segment(k + 1, r - k - 1);
  }
}
/// Solves with factor_leading_block's factors: the first r entries of b become x.
void solve_leading_block(const Eigen::MatrixXd& LU, Eigen::Index r, const std::vector<Eigen::Index>& pivots, Eigen::VectorXd& b) {
  for (Eigen::Index k = 0; k < r; ++k)
    if (pivots[std::size_t(k)] != k) std::swap(b(k), b(pivots[std::size_t(k)]));
  for (Eigen::Index k = 0; k < r; ++k) b.segment(k + 1, r - k - 1) -= b(k) * LU.col(k).segment(k + 1, r - k - 1);
  for (Eigen::Index k = r - 1; k >= 0; --k) {
    b(k) /= LU(k, k);
    b.head(k) -= b(k) * LU.col(k).head(k);
  }
}
/// Cholesky factor L of the leading r x r block of the symmetric A, from its lower triangle
/// and into it (left-looking: each column less the products of those before it); false if a
/// pivot is not positive. Allocation-free as factor_leading_block.
bool cholesky_leading_block(Eigen::MatrixXd& A, Eigen::Index r) {
  for (Eigen::Index k = 0; k < r; ++k) {
    A.col(k).segment(k, r - k).noalias() -= A.block(k, 0, r - k, k) * A.row(k).head(k).transpose();
    const double pivot = A(k, k);
    if (!(pivot > 0)) return false;
    A.col(k).segment(k, r - k) /= std::sqrt(pivot);
  }
  return true;
}
}  // namespace

namespace {
/// The first r columns of A and B are equal (stops at the first difference).
bool same_columns(const Eigen::MatrixXd& A, const Eigen::MatrixXd& B, Eigen::Index r) {
  return A.rows() == B.rows() && std::equal(A.data(), A.data() + A.rows() * r, B.data());
}
}  // namespace

bool QuasistaticJacobian::direct(Eigen::Index r) const {
  // the n x n Jacobian itself (forming and factoring it: n^2 r + n^3 / 3, half that when
  // symmetric) when that is cheaper than Woodbury's r x r capacitance: with a diagonal K_h
  // (n r^2 + r^3 / 3, or half) once more contact terms are active than there are modes; with
  // a dense K_h and its kept inverse (2 n m r + n r^2 for U's m used rows) once r passes about n / 4
  return dense_stiffness_.size() ? (dense_inverse_.size() == 0 || 4 * r > size()) : r > size();
}

void QuasistaticJacobian::reserve(Eigen::Index capacity) const {
  // every kept factorization at once: one first used late in a run must not allocate either
  capacity_ = capacity;
  for (Factorization& f : kept_) {
    f.rank = -1;  // its terms are gone with the resize
    f.U.resize(size(), capacity), f.V.resize(size(), capacity), f.weights.resize(capacity);
    f.scaled_U.resize(size(), capacity), f.capacitance.resize(capacity, capacity);
    f.pivots.resize(std::size_t(capacity));
    if (direct(capacity)) {  // either factorization of the Jacobian may come
      f.jacobian.resize(size(), size());
      f.lu = Eigen::PartialPivLU<Eigen::MatrixXd>(size());
      // sized by factoring I: LLT's size constructor leaves its status unset, which a copy reads
      if (smallest_eigenvalue_ > 0) f.llt.compute(Eigen::MatrixXd::Identity(size(), size()));
    }
  }
  coefficients_.resize(capacity);
  root_weighted_V_.resize(size(), capacity), weighted_V_.resize(size(), capacity);
  if (dense_inverse_.size()) gathered_inverse_.resize(size(), size()), gathered_U_.resize(size(), capacity);
}

const QuasistaticJacobian::Factorization& QuasistaticJacobian::factorization(const Eigen::MatrixXd& U, const Eigen::MatrixXd& V,
                                                                             Eigen::Index r, const Eigen::VectorXd* weights) const {
  ++uses_;
  // buffers sized to the columns' capacity: no allocation once the largest active set has been seen
  if (V.cols() > capacity_) reserve(V.cols());
  Factorization* oldest = &kept_.front();
  // with weights U = V D: the weights (r numbers, which tell most active sets apart at once)
  // and V name the terms, without U's n r
  auto same_terms = [&](const Factorization& f) {
    if (f.rank != r || f.weighted != (weights != nullptr)) return false;
    if (weights) return std::equal(weights->data(), weights->data() + r, f.weights.data()) && same_columns(f.V, V, r);
    return same_columns(f.V, V, r) && same_columns(f.U, U, r);
  };
  for (Factorization& f : kept_) {
    if (same_terms(f)) {
      f.last_use = uses_;
      return f;
    }
    if (f.last_use < oldest->last_use) oldest = &f;
  }
  factor(U, V, r, weights, *oldest);
  oldest->last_use = uses_;
  return *oldest;
}

void QuasistaticJacobian::solve_stiffness(const Eigen::VectorXd& b, Eigen::VectorXd& x) const {
  if (dense_stiffness_.size()) {
    multiply_blocks(dense_inverse_, b, x);
  } else {
    x = b.cwiseQuotient(stiffness_);
  }
}

void QuasistaticJacobian::solve_stiffness(const Eigen::SparseMatrix<double>& B, Eigen::MatrixXd& X) const {
  if (dense_stiffness_.size())
    X.noalias() = dense_inverse_ * B;  // K^-1 is symmetric: the columns B selects
  else
    X = stiffness_.cwiseInverse().asDiagonal() * Eigen::MatrixXd(B);
}

void QuasistaticJacobian::solve_stiffness_block(Eigen::Index offset, const Eigen::Ref<const Eigen::MatrixXd>& B,
                                                Eigen::Ref<Eigen::MatrixXd> X) const {
  const Eigen::Index nb = B.rows();
  if (dense_stiffness_.size())
    X.noalias() = dense_inverse_.block(offset, offset, nb, nb) * B;
  else
    X = stiffness_.segment(offset, nb).cwiseInverse().asDiagonal() * B;
}

void QuasistaticJacobian::factor(const Eigen::MatrixXd& U_all, const Eigen::MatrixXd& V_all, Eigen::Index r, const Eigen::VectorXd* weights,
                                 Factorization& f) const {
  const auto V = V_all.leftCols(r);
  const bool dense = dense_stiffness_.size() > 0;
  f.weighted = weights != nullptr;
  if (f.weighted) f.weights.head(r) = weights->head(r);
  else f.U.leftCols(r) = U_all.leftCols(r);
  f.V.leftCols(r) = V;
  f.rank = r;
  f.direct = direct(r);
  // Without friction K + V D V^T is symmetric, and positive definite where K is: Cholesky's
  // factors from the lower triangle's products (half of them) of the Jacobian, or of Woodbury's
  // capacitance on K^-1/2 (K + V D V^T) K^-1/2 = I + W W^T, W = K^-1/2 V D^1/2: I + W^T W. A
  // dense K's Woodbury keeps the gathered LU below, which reads only the rows U fills.
  f.symmetric = weights && r > 0 && smallest_eigenvalue_ > 0 && (f.direct || !dense) && weights->head(r).minCoeff() >= 0;
  if (f.symmetric) {
    const auto root_weights = weights->head(r).cwiseSqrt().asDiagonal();
    if (f.direct) {
      auto W = root_weighted_V_.leftCols(r);
      W.noalias() = V * root_weights;
      if (dense) {
        f.jacobian = dense_stiffness_;
      } else {
        f.jacobian.setZero();
        f.jacobian.diagonal() = stiffness_;
      }
      f.jacobian.selfadjointView<Eigen::Lower>().rankUpdate(W);
      f.llt.compute(f.jacobian);
      if (f.llt.info() == Eigen::Success) return;
    } else {
      auto W = f.scaled_U.leftCols(r);
      W.noalias() = inverse_root_stiffness_.asDiagonal() * V * root_weights;
      auto capacitance = f.capacitance.topLeftCorner(r, r);
      capacitance.setIdentity();
      capacitance.selfadjointView<Eigen::Lower>().rankUpdate(W.transpose());
      if (cholesky_leading_block(f.capacitance, r)) return;
    }
    f.symmetric = false;  // not positive definite in round-off after all: the LU factors below
  }
  // the terms' U where the weights stand for it (the symmetric factors above never read it)
  if (weights) weighted_V_.leftCols(r).noalias() = V * weights->head(r).asDiagonal();
  const auto U = (weights ? weighted_V_ : U_all).leftCols(r);
  if (f.direct) {
    f.jacobian.noalias() = U * V.transpose();
    if (dense) f.jacobian += dense_stiffness_;
    else f.jacobian.diagonal() += stiffness_;
    f.lu.compute(f.jacobian);
    return;
  }
  // Woodbury: (K + U V^T)^-1 b = K^-1 b - K^-1 U (I + V^T K^-1 U)^-1 V^T K^-1 b
  if (r == 0) return;
  auto scaled_U = f.scaled_U.leftCols(r);
  if (dense) {
    // per body block: its rows of K^-1 U from its columns of K^-1 where U has entries
    for (const auto& [at, nb] : dense_blocks_) {
      Eigen::Index m = 0;
      for (Eigen::Index i = at; i < at + nb; ++i)
        if (!U.row(i).isZero(0.0)) used_rows_[std::size_t(m++)] = i;
      for (Eigen::Index k = 0; k < m; ++k) {
        const Eigen::Index i = used_rows_[std::size_t(k)];
        gathered_inverse_.col(k).head(nb) = dense_inverse_.col(i).segment(at, nb);  // = row i: K^-1 is symmetric
        gathered_U_.row(k).head(r) = U.row(i);
      }
      if (m == 0) scaled_U.middleRows(at, nb).setZero();
      else scaled_U.middleRows(at, nb).noalias() = gathered_inverse_.topLeftCorner(nb, m) * gathered_U_.topLeftCorner(m, r);
    }
  } else {
    scaled_U = U.array().colwise() / stiffness_.array();
  }
  auto capacitance = f.capacitance.topLeftCorner(r, r);
  capacitance.setIdentity();
  capacitance.noalias() += V.transpose() * f.scaled_U.leftCols(r);
  factor_leading_block(f.capacitance, r, f.pivots);
}

void QuasistaticJacobian::solve(const Eigen::MatrixXd& U, const Eigen::MatrixXd& V, Eigen::Index r, const Eigen::VectorXd& b,
                                Eigen::VectorXd& x, const Eigen::VectorXd* weights) const {
  const Factorization& f = factorization(U, V, r, weights);
  if (f.direct) {
    if (f.symmetric) x = f.llt.solve(b);
    else x = f.lu.solve(b);
    return;
  }
  if (f.symmetric) {
    // x = K^-1/2 (I - W (I + W^T W)^-1 W^T) K^-1/2 b, the capacitance as L L^T
    x = b.cwiseProduct(inverse_root_stiffness_);
    const auto W = f.scaled_U.leftCols(r);
    auto c = coefficients_.head(r);
    c.noalias() = W.transpose() * x;
    const auto L = f.capacitance.topLeftCorner(r, r).triangularView<Eigen::Lower>();
    L.solveInPlace(c);
    L.transpose().solveInPlace(c);
    x.noalias() -= W * c;
    x.array() *= inverse_root_stiffness_.array();
    return;
  }
  solve_stiffness(b, x);
  if (r == 0) return;
  coefficients_.head(r).noalias() = f.V.leftCols(r).transpose() * x;
  solve_leading_block(f.capacitance, r, f.pivots, coefficients_);
  x.noalias() -= f.scaled_U.leftCols(r) * coefficients_.head(r);
}

}  // namespace isosid::run
