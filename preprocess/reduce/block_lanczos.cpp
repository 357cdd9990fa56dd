// Block Lanczos with full orthogonalization and thick restarts; see block_lanczos.hpp.
#include "reduce/block_lanczos.hpp"

#include "isosid/common/dense_decompositions.hpp"
#include "isosid/format/error.hpp"

#include <algorithm>
#include <cmath>
#include <random>
#include <string>

namespace isosid::prep {
namespace {

using Eigen::Index;
using Eigen::MatrixXd;
using Eigen::VectorXd;

/// W <- Q with W = V H + Q R: Q orthonormal and orthogonal to V's columns, R upper triangular
/// (classical Gram-Schmidt against V and then column by column, each pass twice). A column whose
/// remainder vanishes against `scale` (the block spans an invariant subspace) becomes a random
/// direction orthogonal to all others, with a zero row in R. Returns H = V^T W.
MatrixXd orthonormalize(const Eigen::Ref<const MatrixXd>& V, MatrixXd& W, MatrixXd& R, double scale, std::mt19937_64& rng) {
  MatrixXd H = MatrixXd::Zero(V.cols(), W.cols());
  for (int pass = 0; pass < 2 && V.cols() > 0; ++pass) {
    const MatrixXd h = V.transpose() * W;
    W.noalias() -= V * h;
    H += h;
  }
  const Index b = W.cols();
  R = MatrixXd::Zero(b, b);
  std::normal_distribution<double> normal;
  for (Index j = 0; j < b; ++j) {
    auto w = W.col(j);
    const auto Q = W.leftCols(j);
    for (int pass = 0; pass < 2; ++pass) {
      const VectorXd h = Q.transpose() * w;
      w.noalias() -= Q * h;
      R.col(j).head(j) += h;
    }
    const double r = w.norm();
    if (r > 1e-13 * scale) {
      R(j, j) = r;
      w /= r;
      continue;
    }
    // a random direction in place of the vanished one, orthogonal to V and the block's others
    for (Index i = 0; i < w.size(); ++i) w(i) = normal(rng);
    for (int pass = 0; pass < 2; ++pass) {
      if (V.cols() > 0) w.noalias() -= V * (V.transpose() * w).eval();
      w.noalias() -= Q * (Q.transpose() * w).eval();
    }
    w.normalize();
    R.row(j).setZero();
  }
  return H;
}

}  // namespace

BlockLanczosLayout block_lanczos_layout(Index size, int n, const BlockLanczosOptions& options) {
  if (n < 1 || n >= size)
    throw format::ComputationError("block Lanczos: " + std::to_string(n) + " eigenpairs of an operator of size " + std::to_string(size));
  // the remainder of a full basis must still find a block of new directions: room + block <= size
  const Index block = std::clamp<Index>(options.block, 1, std::max<Index>(1, (size - n) / 3));
  const Index room = std::min({size - block, options.rank > 0 ? options.rank : size,
                               options.room > 0 ? options.room : std::max<Index>(3 * Index(n), n + 6 * block)});
  const Index b = std::min(block, (room - n + 1) / 2);
  if (b < 1) throw format::ComputationError("block Lanczos: no room for " + std::to_string(n) + " eigenpairs in " + std::to_string(room));
  // a restart keeps the n wanted Ritz vectors and half of the rest
  return {room, b, n + (room - n - b) / 2};
}

BlockLanczosResult block_lanczos_largest(const BlockOperator& C, Index size, int n, const BlockLanczosOptions& options) {
  const auto [room, b, keep] = block_lanczos_layout(size, n, options);

  std::mt19937_64 rng(options.seed);
  std::normal_distribution<double> normal;
  MatrixXd V(size, room), T = MatrixXd::Zero(room, room), R;
  MatrixXd Y(size, b);
  for (Index i = 0; i < Y.size(); ++i) Y.data()[i] = normal(rng);
  orthonormalize(V.leftCols(0), Y, R, 1.0, rng);
  V.leftCols(b) = Y;

  BlockLanczosResult out;
  Index m = b, done = 0;  // basis columns; of those, the ones whose images are projected
  MatrixXd X;
  for (;;) {
    const Index w = m - done;
    X = V.middleCols(done, w);
    Y.resize(size, w);
    if (options.on_block) options.on_block(out.blocks);
    C(X, Y);
    ++out.blocks;
    const double scale = Y.colwise().norm().maxCoeff();
    const MatrixXd H = orthonormalize(V.leftCols(m), Y, R, scale, rng);
    T.block(0, done, m, w) = H;
    T.block(done, 0, w, m) = H.transpose();
    T.block(done, done, w, w) = 0.5 * (H.bottomRows(w) + H.bottomRows(w).transpose());
    done = m;

    const common::SymmetricEigen eig = common::symmetric_eigen(T.topLeftCorner(m, m));
    const VectorXd theta = eig.values.reverse();
    const MatrixXd S = eig.vectors.rowwise().reverse();
    bool converged = m >= n;  // the first blocks hold fewer Ritz pairs than asked for
    if (converged) {
      const VectorXd residual = (R * S.block(m - w, 0, w, n)).colwise().norm().transpose();
      for (Index i = 0; i < n && converged; ++i) converged = residual(i) <= options.tolerance * std::abs(theta(i));
    }
    if (converged) {
      out.values = theta.head(n);
      out.vectors = V.leftCols(m) * S.leftCols(n);
      return out;
    }
    if (m + w <= room) {
      V.middleCols(m, w) = Y;
      m += w;
      continue;
    }
    // thick restart: the best `keep` Ritz vectors, whose projected matrix is diagonal, and the
    // remainder block (its coupling to them is projected again with its image)
    if (++out.restarts > options.max_restarts)
      throw format::ComputationError("block Lanczos did not converge for " + std::to_string(n) + " eigenpairs after " +
                                     std::to_string(options.max_restarts) + " restarts");
    const MatrixXd ritz = V.leftCols(m) * S.leftCols(keep);
    V.leftCols(keep) = ritz;
    V.middleCols(keep, w) = Y;
    T.setZero();
    T.diagonal().head(keep) = theta.head(keep);
    m = keep + w;
    done = keep;
  }
}

}  // namespace isosid::prep
