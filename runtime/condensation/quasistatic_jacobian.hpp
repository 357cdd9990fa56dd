// The stiffness of the quasistatic modes, K_h (diagonal in the SID's normal form, dense for
// massless boundaries and SIDs from elsewhere), and solves with the Newton Jacobian K_h + U V^T
// that the active contact points make of it (one rank-one term u v^T per point). The solve
// picks by size: Woodbury's r x r capacitance for few active points, the n x n Jacobian itself
// once the points outnumber what Woodbury saves. The last few factorizations are kept for
// solves with the same terms: between Newton iterations, and between evaluations of a body
// that does not rotate against a plane, the active points' terms repeat exactly (the stages
// of a step alternate between a handful of active sets: scene A finds 80 % of its solves
// among the last eight).
#pragma once
#include "isosid/common/dense_decompositions.hpp"

#include <Eigen/Dense>
#include <Eigen/SparseCore>

#include <string>
#include <vector>

namespace isosid::run {

class QuasistaticJacobian {
public:
  QuasistaticJacobian() = default;
  /// K_h as the diagonal blocks of the bodies' quasistatic modes; `diagonal`: every block is.
  QuasistaticJacobian(const std::vector<Eigen::MatrixXd>& blocks, bool diagonal);

  Eigen::Index size() const { return stiffness_.size(); }
  /// Smallest diagonal entry of K_h (positive for a solvable problem).
  double smallest_diagonal() const { return size() ? stiffness_.minCoeff() : 0.0; }
  /// Smallest eigenvalue of K_h (0 if it is singular or indefinite): a lower bound of the
  /// Jacobian's without friction, whose contact terms are positive semidefinite.
  double smallest_eigenvalue() const { return smallest_eigenvalue_; }
  /// out = K_h z.
  void multiply(const Eigen::VectorXd& z, Eigen::VectorXd& out) const;
  /// z^T K_h w.
  double product(const Eigen::VectorXd& z, const Eigen::VectorXd& w) const;
  /// Solves (K_h + U V^T) x = b with the first r columns of U and V. `weights`, if given,
  /// stand for U = V diag(weights), weights >= 0 (contact without friction), and U is not read
  /// (the caller need not form it): the Jacobian is then symmetric, and positive definite where
  /// K_h is; its products are then half and its factors Cholesky's (but a dense K_h's Woodbury
  /// keeps its LU of the used rows, from U formed here).
  void solve(const Eigen::MatrixXd& U, const Eigen::MatrixXd& V, Eigen::Index r, const Eigen::VectorXd& b, Eigen::VectorXd& x,
             const Eigen::VectorXd* weights = nullptr) const;

  /// Whether solve_stiffness() can be used: K_h is diagonal, or dense and positive definite
  /// (its inverse is kept).
  bool stiffness_solvable() const { return dense_stiffness_.size() == 0 || dense_inverse_.size() > 0; }
  /// x = K_h^-1 b (where stiffness_solvable()).
  void solve_stiffness(const Eigen::VectorXd& b, Eigen::VectorXd& x) const;
  /// X = K_h^-1 B for a sparse B (gap gradients: each column a few control points' rows),
  /// where stiffness_solvable().
  void solve_stiffness(const Eigen::SparseMatrix<double>& B, Eigen::MatrixXd& X) const;
  /// X = K_b^-1 B for the block K_b of one body, whose rows start at `offset` (B has its
  /// rows), where stiffness_solvable(). K_h has no entries between bodies.
  void solve_stiffness_block(Eigen::Index offset, const Eigen::Ref<const Eigen::MatrixXd>& B, Eigen::Ref<Eigen::MatrixXd> X) const;

  /// Factorizations kept.
  static constexpr std::size_t kKeptFactorizations = 8;

private:
  /// One factorization of K + U V^T: of the n x n Jacobian itself, or Woodbury's capacitance;
  /// without friction (U = V D, D >= 0, K positive definite) by Cholesky's method, except a
  /// dense K's Woodbury (LU of the capacitance from the rows U fills).
  struct Factorization {
    Eigen::MatrixXd U, V;        ///< the terms factored (first `rank` columns; U only if not weighted)
    Eigen::VectorXd weights;     ///< weighted: U = V diag(weights)
    bool weighted = false;
    Eigen::Index rank = -1;      ///< -1: empty
    bool direct = false;
    bool symmetric = false;
    Eigen::MatrixXd scaled_U;    ///< Woodbury: K^-1 U; symmetric: W = K^-1/2 V D^1/2
    /// Woodbury: LU factors of I + V^T K^-1 U; symmetric: the Cholesky factor of I + W^T W
    Eigen::MatrixXd capacitance;
    std::vector<Eigen::Index> pivots;
    Eigen::MatrixXd jacobian;    ///< direct: K + U V^T
    Eigen::PartialPivLU<Eigen::MatrixXd> lu;
    Eigen::LLT<Eigen::MatrixXd> llt;  ///< direct and symmetric
    long last_use = 0;
  };
  /// The kept factorization of these terms, factoring them in place of the least recently used.
  const Factorization& factorization(const Eigen::MatrixXd& U, const Eigen::MatrixXd& V, Eigen::Index r, const Eigen::VectorXd* weights) const;
  /// Factors K + U V^T for the first r columns into f (`weights` as for solve()).
  void factor(const Eigen::MatrixXd& U, const Eigen::MatrixXd& V, Eigen::Index r, const Eigen::VectorXd* weights, Factorization& f) const;
  /// Whether r active terms are factored as the n x n Jacobian (else Woodbury's capacitance).
  bool direct(Eigen::Index r) const;
  /// Sizes every kept factorization's buffers for `capacity` columns of terms.
  void reserve(Eigen::Index capacity) const;
  /// out = A x for a matrix A with K_h's dense blocks (K_h itself or its inverse), block by block.
  void multiply_blocks(const Eigen::MatrixXd& A, const Eigen::VectorXd& x, Eigen::VectorXd& out) const;

  Eigen::VectorXd stiffness_;                 ///< diagonal of K_h
  Eigen::VectorXd inverse_root_stiffness_;    ///< its K^-1/2, for the symmetric capacitance
  mutable Eigen::MatrixXd root_weighted_V_;   ///< V D^1/2 (capacity columns), for the symmetric Jacobian
  mutable Eigen::MatrixXd weighted_V_;        ///< V D: U of weighted terms, for the factors that read U
  Eigen::MatrixXd dense_stiffness_;           ///< K_h if it is not diagonal
  /// (offset, size) of each body's block of a dense K_h: its products and K^-1 U skip the
  /// zeros between bodies (a sphere's and a beam's boundaries: half of the n^2)
  std::vector<std::pair<Eigen::Index, Eigen::Index>> dense_blocks_;
  mutable Eigen::VectorXd block_product_;     ///< K w per block, for product()
  /// K_h^-1 if K_h is dense and positive definite (else empty: the Jacobian is then factored
  /// each time). Kept whole: Woodbury's K^-1 U then reads only the columns where U has
  /// entries, and a contact point moves few coordinates of a massless boundary (its control
  /// points' rows); a matrix product also runs faster than triangular solves.
  Eigen::MatrixXd dense_inverse_;
  mutable std::vector<Eigen::Index> used_rows_;     ///< rows of U with entries
  mutable Eigen::MatrixXd gathered_inverse_, gathered_U_;  ///< K^-1 and U restricted to them
  double smallest_eigenvalue_ = 0;
  mutable std::vector<Factorization> kept_ = std::vector<Factorization>(kKeptFactorizations);
  mutable long uses_ = 0;
  mutable Eigen::Index capacity_ = -1;  ///< columns of terms the buffers hold
  mutable Eigen::VectorXd coefficients_;
};

}  // namespace isosid::run
