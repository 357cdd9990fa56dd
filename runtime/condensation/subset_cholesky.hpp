// The Cholesky factor of a principal block of a fixed symmetric positive definite matrix, kept
// as the block's index set changes: an index that leaves is removed from the factor by a rank-one
// update of the rows after it, one that enters is appended by a forward substitution, each
// O(size^2) where factoring anew is O(size^3). The pressed points of gap space's contact problem
// (penalty_complementarity.hpp) change by a few from one static solve to the next; their block
// is factored this way.
#pragma once
#include <Eigen/Dense>

#include <vector>

namespace isosid::run {

class SubsetCholesky {
public:
  /// The matrix is A + diag(d) (A symmetric), both read in place: they must outlive the factor
  /// and stay as they are while it is used. Forgets the factor.
  void reset(const Eigen::MatrixXd& A, const Eigen::VectorXd& d);

  /// Factors the block of the indices in `members` (each once, any order; `is_member` flags
  /// them by index), from the last factor by removals and appends while those are few, anew
  /// otherwise. False if the block is not positive definite.
  bool follow(const std::vector<Eigen::Index>& members, const std::vector<char>& is_member);
  /// x_i = (M_SS^-1 b_S)_i for the members i of the factored set S; other entries of x untouched.
  void solve(const Eigen::VectorXd& b, Eigen::VectorXd& x);

  /// Factorizations from scratch, and single indices removed or appended, since reset().
  long factorizations() const { return factorizations_; }
  long updates() const { return updates_; }

private:
  double entry(Eigen::Index i, Eigen::Index j) const { return (*A_)(i, j) + (i == j ? (*d_)(i) : 0.0); }
  bool factor_anew(const std::vector<Eigen::Index>& members);
  /// Removes the factor's row and column at position p.
  void remove(Eigen::Index p);
  /// Appends index i as the factor's last row; false if the block would not be positive definite.
  bool append(Eigen::Index i);

  const Eigen::MatrixXd* A_ = nullptr;
  const Eigen::VectorXd* d_ = nullptr;
  Eigen::MatrixXd L_;                 ///< capacity n x n; the factor in its leading order_.size() block
  std::vector<Eigen::Index> order_;   ///< the factored indices, in the factor's order
  std::vector<Eigen::Index> position_;  ///< per index: its place in order_, or -1
  Eigen::VectorXd work_;
  bool factored_ = true;    ///< the last follow()'s outcome
  long since_anew_ = 0;     ///< updates since the last factorization from scratch (their round-off adds up)
  long factorizations_ = 0, updates_ = 0;
};

}  // namespace isosid::run
