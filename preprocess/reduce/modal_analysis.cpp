// Block Lanczos with a CHOLMOD factor on a symmetric form of the inverted pencil; see modal_analysis.hpp.
#include "reduce/modal_analysis.hpp"

#include "isosid/common/dense_decompositions.hpp"
#include "isosid/common/progress_line.hpp"

#include "isosid/format/error.hpp"
#include "reduce/blas_threads.hpp"
#include "reduce/block_lanczos.hpp"
#include "reduce/memory_budget.hpp"
#include "reduce/mode_basis.hpp"
#include "reduce/sparse_cholesky.hpp"
#include "reduce/sparse_products.hpp"

#include <algorithm>
#include <cmath>
#include <memory>

namespace isosid::prep {
namespace {

/// The pencil (K, M) inverted through a factorization of A, as an operator symmetric in the
/// Euclidean inner product: C = L^-1 P Q^T M Q P^T L^-T with P A P^T = L L^T. Its eigenpairs are
/// mu = 1 / (lambda - sigma) and chi = L^T P phi, with phi = Q P^T L^-T chi.
/// - Shift-invert: A = K - sigma M and Q = I.
/// - A free body's elastic modes: A = K with supports that hold its rigid fields R (sigma = 0),
///   whose solution of a balanced load differs from the elastic one by a rigid field, and
///   Q = I - R (R^T M R)^-1 R^T M, which removes it. Q A^-1 Q^T is then the inverse of K on the
///   elastic fields, and the rigid fields have mu = 0, below every elastic one.
/// A generalized solver with M-inner products would need about twelve M products per Krylov
/// vector; here a block of vectors costs one M product and one pass of each triangular solve.
class FactoredPencil {
public:
  FactoredPencil(const SparseCholesky& A, const Eigen::SparseMatrix<double>& M, const Eigen::MatrixXd& rigid)
      : A_(A), M_(M), R_(rigid) {
    if (R_.cols() > 0) {
      MR_ = sparse_times(M, R_);
      gram_.compute(R_.transpose() * MR_);
    }
  }

  Eigen::Index rows() const { return M_.rows(); }
  /// Y = C X for a block of Krylov vectors: one pass of each triangular solve over the factor
  void apply(const Eigen::MatrixXd& X, Eigen::MatrixXd& Y) const {
    Y = X;
    A_.solve_upper(Y);
    remove_rigid(Y);
    work_ = sparse_times(M_, Y);  // row by row: one pass over M for the block
    if (R_.cols() > 0) work_.noalias() -= MR_ * gram_.solve(R_.transpose() * work_);  // Q^T
    A_.solve_lower(work_);
    Y = work_;
  }
  /// Floating-point operations of applying the operator to `columns` vectors.
  double apply_flops(Eigen::Index columns) const { return A_.solve_flops(columns); }
  /// phi = Q P^T L^-T chi for orthonormal chi, scaled to unit M-norm: phi^T M phi = chi^T C chi = mu.
  Eigen::MatrixXd mass_normalized_modes(Eigen::MatrixXd chi, const Eigen::VectorXd& mu) const {
    A_.solve_upper(chi);
    remove_rigid(chi);
    for (Eigen::Index c = 0; c < chi.cols(); ++c) chi.col(c) /= std::sqrt(mu(c));
    return chi;
  }

private:
  /// u <- Q u
  template <class Dense>
  void remove_rigid(Dense& u) const {
    if (R_.cols() > 0) u.noalias() -= R_ * gram_.solve(MR_.transpose() * u);
  }

  const SparseCholesky& A_;
  const Eigen::SparseMatrix<double>& M_;
  const Eigen::MatrixXd& R_;
  Eigen::MatrixXd MR_;
  Eigen::LDLT<Eigen::MatrixXd> gram_;
  mutable Eigen::MatrixXd work_;
};

/// Krylov vectors per pass over the factor. On the free beam at a/4 (bench/prep_scaling's
/// model), blocks of 4, 8, 12 and 16 spent 9.7, 7.1, 9.0 and 7.9 s in their solves: larger
/// blocks cost more vectors in all. Eight also keeps up to eightfold frequencies together.
constexpr Eigen::Index kLanczosBlock = 8;

/// The n largest mu of the pencil's operator by block Lanczos; eigenvalues sigma + 1/mu, ascending.
ModalResult lanczos_largest(const FactoredPencil& op, int n, Eigen::Index rank, double sigma) {
  BlockLanczosOptions options;
  options.block = kLanczosBlock;
  options.rank = rank;
  // the count of block solves is the progress: how many it needs is known only at its end
  options.on_block = [&](long done) {
    common::set_work_step("eigen solve: block Lanczos, solve " + std::to_string(done + 1));
  };
  const BlockLanczosLayout layout = block_lanczos_layout(op.rows(), n, options);
  check_memory("reduction.normal_modes",
               "the eigen solve's Krylov basis for " + std::to_string(n) + " modes on " + std::to_string(op.rows()) + " DOFs",
               double(layout.peak_vectors()) * double(op.rows()) * sizeof(double));
  // the block solves are BLAS-3 on both cores when the basis's vectors together are large work
  const ParallelBlas threads(op.apply_flops(layout.room));
  const BlockLanczosResult solved =
      block_lanczos_largest([&](const Eigen::MatrixXd& X, Eigen::MatrixXd& Y) { op.apply(X, Y); }, op.rows(), n, options);
  // mu descending is lambda ascending
  ModalResult r;
  r.eigenvalues = (sigma + solved.values.array().inverse()).matrix();
  r.modes = op.mass_normalized_modes(solved.vectors, solved.values);
  r.iterations = solved.restarts;
  return r;
}

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
  const common::SymmetricEigen dense = common::generalized_symmetric_eigen(Kd, Md);
  if (!dense.converged) throw format::ComputationError("dense generalized eigen solve failed");
  ModalResult r;
  r.eigenvalues = dense.values.head(n);
  r.modes = dense.vectors.leftCols(n);
  return r;
}

/// The n lowest by shift-invert Lanczos; K - sigma M is positive definite for sigma < 0 even
/// with rigid-body modes.
ModalResult lanczos_lowest(const Eigen::SparseMatrix<double>& K, const Eigen::SparseMatrix<double>& M, int n,
                           double sigma) {
  common::set_work_step("eigen solve: factorizing K - sigma M (" + std::to_string(K.rows()) + " DOFs)");
  std::unique_ptr<SparseCholesky> shifted;
  try {
    shifted = std::make_unique<SparseCholesky>(K - sigma * M, "the eigen solve's factorization");
  } catch (const format::ComputationError&) {
    throw format::ComputationError("CHOLMOD factorization of K - sigma M failed (sigma = " + std::to_string(sigma) +
                                   "): the matrices are not positive definite after the shift");
  }
  const Eigen::MatrixXd none;
  // the largest mu = 1 / (lambda - sigma) are the lowest lambda (sigma lies below them all)
  FactoredPencil op(*shifted, M, none);
  return lanczos_largest(op, n, K.rows(), sigma);
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

ModalResult lowest_elastic_modes(const SparseCholesky& stiffness, const Eigen::SparseMatrix<double>& K, const Eigen::SparseMatrix<double>& M,
                                 const Eigen::MatrixXd& rigid, int n) {
  const Eigen::Index nr = rigid.cols(), elastic = M.rows() - nr;
  if (n < 1 || n > elastic)
    throw format::ComputationError("requested " + std::to_string(n) + " elastic modes of a model with " + std::to_string(elastic) +
                                   " elastic DOFs (need 1 <= n <= elastic DOFs)");
  ModalResult r;
  if (n < elastic - 1) {
    FactoredPencil op(stiffness, M, rigid);
    r = lanczos_largest(op, n, elastic, 0.0);
  } else {  // no Krylov room: the dense solve, its rigid-body modes dropped
    r = dense_lowest(K, M, int(nr) + n);
    r.eigenvalues = r.eigenvalues.tail(n).eval();
    r.modes = r.modes.rightCols(n).eval();
    remove_rigid_content(r.modes, M, rigid);
  }
  r.rigid_body_modes = 0;
  return r;
}

}  // namespace isosid::prep
