// Solves with a symmetric positive definite sparse matrix through CHOLMOD (supernodal LL^T):
// whole solves, and the factor's two halves for operators that need A^-1 split symmetrically
// (the eigen solver's), so that one factorization serves both.
#pragma once
#include <Eigen/Dense>
#include <Eigen/Sparse>
#include <memory>
#include <string>

namespace isosid::prep {

class SparseCholesky {
public:
  /// Factorizes A (P A P^T = L L^T, P CHOLMOD's fill-reducing ordering); throws
  /// ComputationError if A is not positive definite, MemoryRefusal if the factor would not fit.
  /// `what` names the factorization in the memory refusal.
  explicit SparseCholesky(const Eigen::SparseMatrix<double>& A, const std::string& what = "the sparse factorization");
  ~SparseCholesky();
  /// Throws the MemoryRefusal the constructor would for A's pattern (its values are not read):
  /// A's analysis alone, no factor. Asked before A's values exist, it refuses up front what
  /// cannot fit even with nothing else held.
  static void check_fits(const Eigen::SparseMatrix<double>& A, const std::string& what);
  SparseCholesky(const SparseCholesky&) = delete;
  SparseCholesky& operator=(const SparseCholesky&) = delete;

  Eigen::Index rows() const;
  /// A^-1 b
  Eigen::MatrixXd solve(const Eigen::MatrixXd& b) const;
  /// b <- L^-1 P b, in place
  void solve_lower(Eigen::Ref<Eigen::MatrixXd> b) const;
  /// b <- P^T L^-T b, in place; solve_upper(solve_lower(b)) = A^-1 b
  void solve_upper(Eigen::Ref<Eigen::MatrixXd> b) const;
  /// Floating-point operations of whole solves for `columns` right-hand sides (two triangular
  /// solves of about 2 nnz(L) each).
  double solve_flops(Eigen::Index columns) const;

private:
  struct Impl;
  std::unique_ptr<Impl> impl_;
};

}  // namespace isosid::prep
