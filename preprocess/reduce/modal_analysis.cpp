// Shift-invert Lanczos with CHOLMOD on a symmetric form of the pencil; see modal_analysis.hpp.
#include "reduce/modal_analysis.hpp"

#include "isosid/common/progress_line.hpp"

#include "isosid/format/error.hpp"
#include "reduce/blas_threads.hpp"
#include "reduce/memory_budget.hpp"

#include <Eigen/CholmodSupport>
#include <Eigen/Eigenvalues>
#include <Spectra/SymEigsSolver.h>
#include <algorithm>
#include <cholmod.h>
#include <cmath>

namespace isosid::prep {
namespace {

/// The shift-inverted pencil as an operator symmetric in the Euclidean inner product:
/// C = L^-1 P M P^T L^-T with P (K - sigma M) P^T = L L^T (CHOLMOD, supernodal). Its
/// eigenpairs are mu = 1 / (lambda - sigma) and chi = L^T P phi. Spectra's generalized solver
/// works with M-inner products instead and spent three quarters of the rod's eigen solve on
/// about twelve M products per Krylov vector; here a vector costs one M product and the two
/// triangular solves of one factor solve.
class ShiftedPencil {
public:
  using Scalar = double;
  ShiftedPencil(const Eigen::SparseMatrix<double>& K, const Eigen::SparseMatrix<double>& M, double sigma) : M_(M) {
    use_single_threaded_blas();
    cholmod_start(&common_);
    common_.supernodal = CHOLMOD_SUPERNODAL;
    common_.print = 0;  // failures become the exception below, not text on stdout (which may be JSON)
    const Eigen::SparseMatrix<double> A = K - sigma * M;
    cholmod_sparse a = Eigen::viewAsCholmod(A.selfadjointView<Eigen::Lower>());
    common::set_work_step("eigen solve: factorizing K - sigma M (" + std::to_string(K.rows()) + " DOFs)");
    factor_ = cholmod_analyze(&a, &common_);
    if (factor_) {
      try {
        check_memory("refinement", "the eigen solve's factorization of " + std::to_string(K.rows()) + " DOFs",
                     double(factor_->xsize) * sizeof(double));
      } catch (...) {
        release();
        throw;
      }
      cholmod_factorize(&a, factor_, &common_);
    }
    if (!factor_ || common_.status != CHOLMOD_OK || factor_->minor < factor_->n) {
      release();
      throw format::ComputationError("CHOLMOD factorization of K - sigma M failed (sigma = " + std::to_string(sigma) +
                                     "): the matrices are not positive definite after the shift");
    }
    work_.resize(K.rows());
  }
  ShiftedPencil(const ShiftedPencil&) = delete;
  ShiftedPencil& operator=(const ShiftedPencil&) = delete;
  ~ShiftedPencil() { release(); }

  Eigen::Index rows() const { return M_.rows(); }
  Eigen::Index cols() const { return M_.rows(); }
  void perform_op(const double* x_in, double* y_out) const {
    // Lanczos's count of solves is its progress: how many it needs is known only at its end
    common::set_work_step("eigen solve: Lanczos, solve " + std::to_string(++solves_));
    Eigen::Map<Eigen::VectorXd> y(y_out, rows());
    y = Eigen::Map<const Eigen::VectorXd>(x_in, rows());
    solve_in_place(CHOLMOD_Lt, y);
    solve_in_place(CHOLMOD_Pt, y);
    work_.noalias() = M_ * y;
    solve_in_place(CHOLMOD_P, work_);
    solve_in_place(CHOLMOD_L, work_);
    y = work_;
  }
  /// phi = P^T L^-T chi for orthonormal chi, scaled to unit M-norm: phi^T (K - sigma M) phi
  /// = chi^T chi = 1 and M phi = mu (K - sigma M) phi, so phi^T M phi = mu (> 0).
  Eigen::MatrixXd mass_normalized_modes(Eigen::MatrixXd chi, const Eigen::VectorXd& mu) const {
    solve_in_place(CHOLMOD_Lt, chi);
    solve_in_place(CHOLMOD_Pt, chi);
    for (Eigen::Index c = 0; c < chi.cols(); ++c) chi.col(c) /= std::sqrt(mu(c));
    return chi;
  }

private:
  /// b <- the solution of CHOLMOD's system `sys` (a triangular solve or a permutation) for b.
  template <class Dense>
  void solve_in_place(int sys, Dense& b) const {
    cholmod_dense rhs{};
    rhs.nrow = std::size_t(b.rows());
    rhs.ncol = std::size_t(b.cols());
    rhs.nzmax = rhs.nrow * rhs.ncol;
    rhs.d = rhs.nrow;
    rhs.x = b.data();
    rhs.xtype = CHOLMOD_REAL;
    rhs.dtype = CHOLMOD_DOUBLE;
    // X, Y and E are CHOLMOD's reused workspaces: no allocation per Krylov vector
    if (!cholmod_solve2(sys, factor_, &rhs, nullptr, &x_, nullptr, &y_, &e_, &common_))
      throw format::ComputationError("CHOLMOD solve failed in the eigen solver");
    std::copy_n(static_cast<const double*>(x_->x), rhs.nzmax, b.data());
  }
  void release() {
    cholmod_free_dense(&x_, &common_);
    cholmod_free_dense(&y_, &common_);
    cholmod_free_dense(&e_, &common_);
    cholmod_free_factor(&factor_, &common_);
    cholmod_finish(&common_);
  }

  const Eigen::SparseMatrix<double>& M_;
  mutable cholmod_common common_;
  cholmod_factor* factor_ = nullptr;
  mutable cholmod_dense *x_ = nullptr, *y_ = nullptr, *e_ = nullptr;
  mutable Eigen::VectorXd work_;
  mutable long solves_ = 0;
};

}  // namespace

Eigen::VectorXd ModalResult::frequencies_hz() const {
  return eigenvalues.cwiseMax(0.0).cwiseSqrt() / (2 * M_PI);
}

double eigenvalue_scale(double youngs_modulus, double density, double size) {
  return std::pow(M_PI * std::sqrt(youngs_modulus / density) / size, 2);
}

namespace {

/// All modes by a dense generalized eigen solve (small models, or n close to the size).
ModalResult dense_lowest(const Eigen::SparseMatrix<double>& K, const Eigen::SparseMatrix<double>& M, int n) {
  use_single_threaded_blas();
  if (K.rows() > 6000)
    throw format::ComputationError("a dense eigen solve of " + std::to_string(K.rows()) + " DOFs is too large (limit 6000)");
  const Eigen::MatrixXd Kd = K, Md = M;
  Eigen::GeneralizedSelfAdjointEigenSolver<Eigen::MatrixXd> dense(Kd, Md);
  if (dense.info() != Eigen::Success) throw format::ComputationError("dense generalized eigen solve failed");
  ModalResult r;
  r.eigenvalues = dense.eigenvalues().head(n);
  r.modes = dense.eigenvectors().leftCols(n);
  return r;
}

/// The n lowest by shift-invert Lanczos; K - sigma M is positive definite for sigma < 0 even
/// with rigid-body modes.
ModalResult lanczos_lowest(const Eigen::SparseMatrix<double>& K, const Eigen::SparseMatrix<double>& M, int n,
                           double sigma) {
  ShiftedPencil op(K, M, sigma);
  const Eigen::Index ncv = std::min<Eigen::Index>(K.rows(), std::max<Eigen::Index>(2 * n + 1, n + 20));
  Spectra::SymEigsSolver<ShiftedPencil> solver(op, n, ncv);
  solver.init();
  // the largest mu = 1 / (lambda - sigma) are the lowest lambda (sigma lies below them all)
  solver.compute(Spectra::SortRule::LargestAlge, 1000, 1e-12, Spectra::SortRule::SmallestAlge);
  if (solver.info() != Spectra::CompInfo::Successful)
    throw format::ComputationError("eigen solver did not converge for " + std::to_string(n) + " modes");
  // SmallestAlge sorts mu ascending, which is lambda descending: reverse to ascending lambda
  const Eigen::VectorXd mu = solver.eigenvalues().reverse();
  const Eigen::MatrixXd chi = solver.eigenvectors().rowwise().reverse();
  ModalResult r;
  r.eigenvalues = (sigma + mu.array().inverse()).matrix();
  r.modes = op.mass_normalized_modes(chi, mu);
  r.iterations = int(solver.num_iterations());
  return r;
}

}  // namespace

ModalResult lowest_modes(const Eigen::SparseMatrix<double>& K, const Eigen::SparseMatrix<double>& M, int n,
                         double lambda_scale) {
  const Eigen::Index size = K.rows();
  if (n < 1 || n > size)
    throw format::ComputationError("requested " + std::to_string(n) + " modes of a model with " +
                                   std::to_string(size) + " free DOFs (need 1 <= n <= DOFs)");
  if (!(lambda_scale > 0)) throw format::ComputationError("eigenvalue scale must be positive");
  // Lanczos needs n < size - 1 Krylov room; a dense solve does not
  ModalResult r = n >= size - 1 ? dense_lowest(K, M, n) : lanczos_lowest(K, M, n, -0.1 * lambda_scale);
  for (Eigen::Index i = 0; i < r.eigenvalues.size(); ++i)
    if (std::abs(r.eigenvalues(i)) < 1e-4 * lambda_scale) ++r.rigid_body_modes;
  return r;
}

}  // namespace isosid::prep
