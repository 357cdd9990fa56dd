// Dense decompositions of Eigen::MatrixXd, compiled once in dense_decompositions.cpp. Each costs
// several seconds of compilation in every translation unit that instantiates it, and most
// callers need one result of it, so they call these functions instead of the Eigen classes.
// The results are Eigen's own, computed the same way.
#pragma once
#include <Eigen/Dense>

namespace isosid::common {

struct SymmetricEigen {
  Eigen::VectorXd values;   ///< ascending
  Eigen::MatrixXd vectors;  ///< orthonormal columns, one per value
  bool converged = true;
};

/// Eigenvalues and eigenvectors of a symmetric matrix, from its lower triangle
/// (Eigen::SelfAdjointEigenSolver).
SymmetricEigen symmetric_eigen(const Eigen::MatrixXd& A);
/// Only the eigenvalues, ascending (a cheaper path of the same solver).
Eigen::VectorXd symmetric_eigenvalues(const Eigen::MatrixXd& A);
/// A x = lambda B x for symmetric A and positive definite B; vectors B-orthonormal
/// (Eigen::GeneralizedSelfAdjointEigenSolver).
SymmetricEigen generalized_symmetric_eigen(const Eigen::MatrixXd& A, const Eigen::MatrixXd& B);
/// The minimum-norm least-squares solution of A x = b, A of any shape and rank
/// (Eigen::CompleteOrthogonalDecomposition).
Eigen::VectorXd minimum_norm_solve(const Eigen::MatrixXd& A, const Eigen::VectorXd& b);
/// The full orthogonal factor Q of A = Q R (Eigen::HouseholderQR).
Eigen::MatrixXd qr_orthogonal_factor(const Eigen::MatrixXd& A);

}  // namespace isosid::common

// Decompositions kept as objects (a factorization reused for many solves), and the LU behind a
// dynamic-size matrix's inverse() and determinant(): their factorization is instantiated once,
// in dense_decompositions.cpp.
extern template class Eigen::PartialPivLU<Eigen::MatrixXd>;
extern template class Eigen::ColPivHouseholderQR<Eigen::MatrixXd>;
