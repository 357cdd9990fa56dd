// Shift-invert Lanczos with CHOLMOD; see modal_analysis.hpp.
#include "reduce/modal_analysis.hpp"

#include "isosid/format/error.hpp"

#include <Eigen/CholmodSupport>
#include <Eigen/Eigenvalues>
#include <Spectra/MatOp/SparseSymMatProd.h>
#include <Spectra/SymGEigsShiftSolver.h>
#include <algorithm>
#include <cmath>

namespace isosid::prep {
namespace {

/// Spectra operator y = (K - sigma M)^{-1} x through a supernodal Cholesky factorization.
class CholmodShiftInvert {
public:
  using Scalar = double;
  CholmodShiftInvert(const Eigen::SparseMatrix<double>& K, const Eigen::SparseMatrix<double>& M) : K_(K), M_(M) {}
  Eigen::Index rows() const { return K_.rows(); }
  Eigen::Index cols() const { return K_.cols(); }
  void set_shift(double sigma) {
    const Eigen::SparseMatrix<double> A = K_ - sigma * M_;
    solver_.compute(A);
    if (solver_.info() != Eigen::Success)
      throw format::ComputationError("CHOLMOD factorization of K - sigma M failed (sigma = " + std::to_string(sigma) +
                                     "): the matrices are not positive definite after the shift");
  }
  void perform_op(const double* x_in, double* y_out) const {
    Eigen::Map<const Eigen::VectorXd> x(x_in, rows());
    Eigen::Map<Eigen::VectorXd> y(y_out, rows());
    y = solver_.solve(x);
  }

private:
  const Eigen::SparseMatrix<double>& K_;
  const Eigen::SparseMatrix<double>& M_;
  Eigen::CholmodSupernodalLLT<Eigen::SparseMatrix<double>, Eigen::Lower> solver_;
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
  CholmodShiftInvert op(K, M);
  Spectra::SparseSymMatProd<double> bop(M);
  const Eigen::Index ncv = std::min<Eigen::Index>(K.rows(), std::max<Eigen::Index>(2 * n + 1, n + 20));
  Spectra::SymGEigsShiftSolver<CholmodShiftInvert, Spectra::SparseSymMatProd<double>, Spectra::GEigsMode::ShiftInvert>
      solver(op, bop, n, ncv, sigma);
  solver.init();
  solver.compute(Spectra::SortRule::LargestMagn, 1000, 1e-12, Spectra::SortRule::SmallestAlge);
  if (solver.info() != Spectra::CompInfo::Successful)
    throw format::ComputationError("eigen solver did not converge for " + std::to_string(n) + " modes");
  ModalResult r;
  r.eigenvalues = solver.eigenvalues();
  r.modes = solver.eigenvectors();
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
