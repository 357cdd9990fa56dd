// Solves with a symmetric positive definite sparse matrix through CHOLMOD (supernodal LL^T).
#pragma once
#include <Eigen/Dense>
#include <Eigen/Sparse>
#include <memory>

namespace isosid::prep {

class SparseCholesky {
public:
  /// Factorizes A; throws ComputationError if A is not positive definite.
  explicit SparseCholesky(const Eigen::SparseMatrix<double>& A);
  ~SparseCholesky();
  SparseCholesky(const SparseCholesky&) = delete;
  SparseCholesky& operator=(const SparseCholesky&) = delete;
  Eigen::MatrixXd solve(const Eigen::MatrixXd& b) const;

private:
  struct Impl;
  std::unique_ptr<Impl> impl_;
};

}  // namespace isosid::prep
