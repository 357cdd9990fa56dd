// CHOLMOD through Eigen's CholmodSupport; see sparse_cholesky.hpp.
#include "reduce/sparse_cholesky.hpp"

#include "isosid/format/error.hpp"
#include "isosid/common/progress_line.hpp"
#include "reduce/blas_threads.hpp"
#include "reduce/factorization_progress.hpp"
#include "reduce/memory_budget.hpp"
#include "reduce/node_ordering.hpp"

#include <Eigen/CholmodSupport>
#include <algorithm>
#include <cstdint>
#include <cstdio>
#include <vector>

namespace isosid::prep {

struct SparseCholesky::Impl {
  /// Eigen's supernodal LL^T, with access to CHOLMOD's factor for the half solves
  struct Llt : Eigen::CholmodSupernodalLLT<Eigen::SparseMatrix<double>, Eigen::Lower> {
    /// What the numeric factorization of A allocates beyond what is held already (its integer
    /// pattern is the analysis's): the factor's values, the largest supernodal update matrix,
    /// the permuted copy of A's lower triangle that CHOLMOD factors (values and row indices)
    /// and its maps of n entries.
    double factorization_bytes(const Eigen::SparseMatrix<double>& A) const {
      if (!m_cholmodFactor) return 0.0;
      double lower = 0;
      for (Eigen::Index c = 0; c < A.outerSize(); ++c)
        for (Eigen::SparseMatrix<double>::InnerIterator it(A, c); it; ++it) lower += it.row() >= c;
      return double(m_cholmodFactor->xsize + m_cholmodFactor->maxcsize) * sizeof(double) +
             lower * double(sizeof(double) + sizeof(int)) + double(A.rows()) * 4 * sizeof(std::int64_t);
    }
    cholmod_factor* factor() const { return m_cholmodFactor; }
    /// Eigen's analyzePattern with the fill-reducing permutation given (CHOLMOD postorders it)
    void analyze_in_order(const Eigen::SparseMatrix<double>& A, std::vector<int>& perm) {
      if (m_cholmodFactor) cholmod_free_factor(&m_cholmodFactor, &cholmod());
      cholmod_sparse view = Eigen::viewAsCholmod(A.selfadjointView<Eigen::Lower>());
      const int methods = cholmod().nmethods, ordering = cholmod().method[0].ordering;
      cholmod().nmethods = 1;
      cholmod().method[0].ordering = CHOLMOD_GIVEN;
      m_cholmodFactor = cholmod_analyze_p(&view, perm.data(), nullptr, 0, &cholmod());
      cholmod().nmethods = methods;
      cholmod().method[0].ordering = ordering;
      m_isInitialized = true;
      m_info = Eigen::Success;
      m_analysisIsOk = true;
      m_factorizationIsOk = false;
    }
  };
  mutable Llt llt;
  // CHOLMOD's reused workspaces of the half solves: no allocation per Krylov vector
  mutable cholmod_dense *x = nullptr, *y = nullptr, *e = nullptr;

  ~Impl() {
    cholmod_free_dense(&x, &llt.cholmod());
    cholmod_free_dense(&y, &llt.cholmod());
    cholmod_free_dense(&e, &llt.cholmod());
  }
  /// The fill-reducing ordering of A's node graph and CHOLMOD's analysis in it (no factor values).
  void analyze(const Eigen::SparseMatrix<double>& A);
  /// Throws MemoryRefusal, naming the factorization `size`, where the analysed factor exceeds
  /// CHOLMOD's indices (the analysis then made none) or the memory limit.
  void refuse_unless_fits(const Eigen::SparseMatrix<double>& A, const std::string& size) const;
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

void SparseCholesky::Impl::analyze(const Eigen::SparseMatrix<double>& A) {
  const std::string step = common::work_step();
  common::set_work_step((step.empty() ? "" : step + ": ") + "ordering its node graph");
  std::vector<int> order = node_graph_ordering(A, llt.cholmod());
  if (order.empty())
    llt.analyzePattern(A);  // no memory for the node graph: CHOLMOD's analysis says what it can
  else
    llt.analyze_in_order(A, order);
  common::set_work_step(step);
}

void SparseCholesky::Impl::refuse_unless_fits(const Eigen::SparseMatrix<double>& A, const std::string& size) const {
  const cholmod_common& common = llt.cholmod();
  if (!llt.factor()) {
    // the analysis allocates no factor where its size overflows CHOLMOD's 32-bit indices
    // (2^31 entries) or memory ran out; its count of the factor's entries is then the estimate
    char estimate[96] = "";
    if (common.lnz > 0)
      std::snprintf(estimate, sizeof estimate, ": its factor holds about %.3g entries (%.3g GiB)", common.lnz,
                    common.lnz * sizeof(double) / 1073741824.0);
    throw MemoryRefusal("refinement", size + (common.status == CHOLMOD_TOO_LARGE ? " is beyond CHOLMOD's 32-bit indices (2^31 entries)"
                                                                                : " ran out of memory in CHOLMOD's analysis") + estimate);
  }
  check_memory("refinement", size, llt.factorization_bytes(A));
}

namespace {
std::string factorization_name(const std::string& what, const Eigen::SparseMatrix<double>& A) {
  return what + " of " + std::to_string(A.rows()) + " DOFs";
}
}  // namespace

void SparseCholesky::check_fits(const Eigen::SparseMatrix<double>& A, const std::string& what) {
  Impl impl;
  impl.llt.cholmod().print = 0;
  impl.analyze(A);
  impl.refuse_unless_fits(A, factorization_name(what, A));
}

SparseCholesky::SparseCholesky(const Eigen::SparseMatrix<double>& A, const std::string& what) : impl_(std::make_unique<Impl>()) {
  use_single_threaded_blas();
  impl_->llt.cholmod().print = 0;  // failures become the exception below, not text on stdout (which may be JSON)
  const std::string size = factorization_name(what, A);
  cholmod_common& common = impl_->llt.cholmod();
  impl_->analyze(A);
  impl_->refuse_unless_fits(A, size);
  {
    const ParallelBlas threads(common.fl);  // the analysis's count of the factorization's flops
    const FactorizationProgress progress(common.fl, common::work_step());
    impl_->llt.factorize(A);
  }
  if (common.status == CHOLMOD_OUT_OF_MEMORY || common.status == CHOLMOD_TOO_LARGE)
    throw format::ComputationError("CHOLMOD: " + size + " ran out of memory");
  if (impl_->llt.info() != Eigen::Success)
    throw format::ComputationError("CHOLMOD: the matrix is not positive definite (is the body free of constraints?)");
}

SparseCholesky::~SparseCholesky() = default;

Eigen::Index SparseCholesky::rows() const { return impl_->llt.rows(); }

double SparseCholesky::solve_flops(Eigen::Index columns) const { return 4.0 * impl_->llt.cholmod().lnz * double(columns); }

Eigen::MatrixXd SparseCholesky::solve(const Eigen::MatrixXd& b) const {
  const ParallelBlas threads(solve_flops(b.cols()));  // BLAS-3 for many columns
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
