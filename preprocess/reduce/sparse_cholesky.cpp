// CHOLMOD through Eigen's CholmodSupport; see sparse_cholesky.hpp.
#include "reduce/sparse_cholesky.hpp"

#include "isosid/format/error.hpp"
#include "reduce/blas_threads.hpp"
#include "reduce/memory_budget.hpp"

#include <Eigen/CholmodSupport>
#include <algorithm>

namespace isosid::prep {

struct SparseCholesky::Impl {
  /// Eigen's supernodal LL^T, with access to CHOLMOD's factor for the half solves
  struct Llt : Eigen::CholmodSupernodalLLT<Eigen::SparseMatrix<double>, Eigen::Lower> {
    double factor_bytes() const { return m_cholmodFactor ? double(m_cholmodFactor->xsize) * sizeof(double) : 0.0; }
    cholmod_factor* factor() const { return m_cholmodFactor; }
  };
  mutable Llt llt;
  // CHOLMOD's reused workspaces of the half solves: no allocation per Krylov vector
  mutable cholmod_dense *x = nullptr, *y = nullptr, *e = nullptr;

  ~Impl() {
    cholmod_free_dense(&x, &llt.cholmod());
    cholmod_free_dense(&y, &llt.cholmod());
    cholmod_free_dense(&e, &llt.cholmod());
  }
  /// b <- the solution of CHOLMOD's system `sys` (a triangular solve or a permutation) for b
  void solve_in_place(int sys, Eigen::Ref<Eigen::MatrixXd> b) const {
    cholmod_dense rhs{};
    rhs.nrow = std::size_t(b.rows());
    rhs.ncol = std::size_t(b.cols());
    rhs.d = std::size_t(b.outerStride());
    rhs.nzmax = rhs.d * rhs.ncol;
    rhs.x = b.data();
    rhs.xtype = CHOLMOD_REAL;
    rhs.dtype = CHOLMOD_DOUBLE;
    if (!cholmod_solve2(sys, llt.factor(), &rhs, nullptr, &x, nullptr, &y, &e, &llt.cholmod()))
      throw format::ComputationError("CHOLMOD: a triangular solve failed");
    const double* out = static_cast<const double*>(x->x);
    for (Eigen::Index c = 0; c < b.cols(); ++c) std::copy_n(out + c * Eigen::Index(x->d), b.rows(), b.col(c).data());
  }
};

SparseCholesky::SparseCholesky(const Eigen::SparseMatrix<double>& A, const std::string& what) : impl_(std::make_unique<Impl>()) {
  use_single_threaded_blas();
  impl_->llt.cholmod().print = 0;  // failures become the exception below, not text on stdout (which may be JSON)
  impl_->llt.analyzePattern(A);
  check_memory("refinement", what + " of " + std::to_string(A.rows()) + " DOFs", impl_->llt.factor_bytes());
  {
    const ParallelBlas threads(impl_->llt.cholmod().fl);  // the analysis's count of the factorization's flops
    impl_->llt.factorize(A);
  }
  if (impl_->llt.info() != Eigen::Success)
    throw format::ComputationError("CHOLMOD: the matrix is not positive definite (is the body free of constraints?)");
}

SparseCholesky::~SparseCholesky() = default;

Eigen::Index SparseCholesky::rows() const { return impl_->llt.rows(); }

Eigen::MatrixXd SparseCholesky::solve(const Eigen::MatrixXd& b) const {
  // two triangular solves, each about 2 lnz flops per column; BLAS-3 for many columns
  const ParallelBlas threads(4.0 * impl_->llt.cholmod().lnz * double(b.cols()));
  return impl_->llt.solve(b);
}

void SparseCholesky::solve_lower(Eigen::Ref<Eigen::MatrixXd> b) const {
  impl_->solve_in_place(CHOLMOD_P, b);
  impl_->solve_in_place(CHOLMOD_L, b);
}

void SparseCholesky::solve_upper(Eigen::Ref<Eigen::MatrixXd> b) const {
  impl_->solve_in_place(CHOLMOD_Lt, b);
  impl_->solve_in_place(CHOLMOD_Pt, b);
}

}  // namespace isosid::prep
