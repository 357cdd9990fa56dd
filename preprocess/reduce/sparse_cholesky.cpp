// CHOLMOD through Eigen's CholmodSupport; see sparse_cholesky.hpp.
#include "reduce/sparse_cholesky.hpp"

#include "isosid/format/error.hpp"
#include "reduce/blas_threads.hpp"
#include "reduce/memory_budget.hpp"

#include <Eigen/CholmodSupport>

namespace isosid::prep {

struct SparseCholesky::Impl {
  /// Eigen's supernodal LL^T, with the symbolic factor's size (after analyzePattern)
  struct Llt : Eigen::CholmodSupernodalLLT<Eigen::SparseMatrix<double>, Eigen::Lower> {
    double factor_bytes() const { return m_cholmodFactor ? double(m_cholmodFactor->xsize) * sizeof(double) : 0.0; }
  } llt;
};

SparseCholesky::SparseCholesky(const Eigen::SparseMatrix<double>& A) : impl_(std::make_unique<Impl>()) {
  use_single_threaded_blas();
  impl_->llt.analyzePattern(A);
  check_memory("refinement", "the sparse factorization of " + std::to_string(A.rows()) + " DOFs", impl_->llt.factor_bytes());
  impl_->llt.factorize(A);
  if (impl_->llt.info() != Eigen::Success)
    throw format::ComputationError("CHOLMOD: the matrix is not positive definite (is the body free of constraints?)");
}

SparseCholesky::~SparseCholesky() = default;

Eigen::MatrixXd SparseCholesky::solve(const Eigen::MatrixXd& b) const { return impl_->llt.solve(b); }

}  // namespace isosid::prep
