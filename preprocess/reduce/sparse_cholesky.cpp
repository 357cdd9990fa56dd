// CHOLMOD through Eigen's CholmodSupport; see sparse_cholesky.hpp.
#include "reduce/sparse_cholesky.hpp"

#include "isosid/format/error.hpp"
#include "reduce/blas_threads.hpp"

#include <Eigen/CholmodSupport>

namespace isosid::prep {

struct SparseCholesky::Impl {
  Eigen::CholmodSupernodalLLT<Eigen::SparseMatrix<double>, Eigen::Lower> llt;
};

SparseCholesky::SparseCholesky(const Eigen::SparseMatrix<double>& A) : impl_(std::make_unique<Impl>()) {
  use_single_threaded_blas();
  impl_->llt.compute(A);
  if (impl_->llt.info() != Eigen::Success)
    throw format::ComputationError("CHOLMOD: the matrix is not positive definite (is the body free of constraints?)");
}

SparseCholesky::~SparseCholesky() = default;

Eigen::MatrixXd SparseCholesky::solve(const Eigen::MatrixXd& b) const { return impl_->llt.solve(b); }

}  // namespace isosid::prep
