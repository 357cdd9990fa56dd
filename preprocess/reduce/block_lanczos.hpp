// The largest eigenpairs of a symmetric operator by block Lanczos: the operator is applied to
// blocks of vectors. For a 3D body's shift-inverted pencil each application is a pass of two
// triangular solves over a factor of a gigabyte or more; a block of vectors shares the pass and
// runs as matrix-matrix (BLAS-3) work.
//
// The basis is kept orthonormal in full (classical Gram-Schmidt, twice, as BLAS-3 products), the
// projected matrix is formed from those projections, and the basis restarts thickly from its
// best Ritz vectors when it reaches its room. A Ritz pair (theta, V s) has the residual
// ||C V s - theta V s|| = ||R s_last||, with R the triangle of the last block's remainder and
// s_last the last block's rows of s; the pairs are accepted when that residual is below
// `tolerance` times theta.
#pragma once
#include <Eigen/Dense>

#include <cstdint>
#include <functional>

namespace isosid::prep {

/// Y = C X for a block X (size x b); Y is sized by the caller.
using BlockOperator = std::function<void(const Eigen::MatrixXd& X, Eigen::MatrixXd& Y)>;

struct BlockLanczosOptions {
  Eigen::Index block = 8;        ///< vectors per application of the operator
  Eigen::Index room = 0;         ///< basis columns before a restart; 0: max(3 n, n + 6 block); at most the size less a block
  /// the operator's rank where it is below the size (a free body's rigid fields have mu = 0):
  /// the basis stays within it; 0: the size
  Eigen::Index rank = 0;
  double tolerance = 1e-12;      ///< relative residual of an accepted Ritz pair
  int max_restarts = 200;
  std::uint64_t seed = 20261129; ///< of the first block (the result is reproducible)
  /// called before each application of the operator with the count of blocks applied so far
  std::function<void(long)> on_block;
};

struct BlockLanczosResult {
  Eigen::VectorXd values;   ///< the n largest eigenvalues, descending
  Eigen::MatrixXd vectors;  ///< orthonormal, one per value
  long blocks = 0;          ///< applications of the operator
  int restarts = 0;
};

/// The basis the solve works in: its room, the block size within it (blocks shrink for small
/// operators) and how many Ritz vectors a restart keeps.
struct BlockLanczosLayout {
  Eigen::Index room = 0, block = 0, keep = 0;
  /// Vectors of the operator's size held at the peak (the basis, the Ritz vectors of a restart,
  /// the block in flight and its image): the solve's memory over sizeof(double) size.
  Eigen::Index peak_vectors() const { return room + keep + 3 * block; }
};

/// The layout block_lanczos_largest uses for n eigenpairs of an operator of the given size.
/// Throws format::ComputationError for a request no basis can serve.
BlockLanczosLayout block_lanczos_layout(Eigen::Index size, int n, const BlockLanczosOptions& options = {});

/// The n largest eigenpairs of the symmetric operator C of the given size. Throws
/// format::ComputationError when they have not converged after `max_restarts` restarts.
BlockLanczosResult block_lanczos_largest(const BlockOperator& C, Eigen::Index size, int n, const BlockLanczosOptions& options = {});

}  // namespace isosid::prep
