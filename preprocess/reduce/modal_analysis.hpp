// Lowest eigenpairs of K phi = lambda M phi: Spectra's shift-invert Lanczos with a CHOLMOD
// factorization of K - sigma M. A negative shift keeps K - sigma M positive definite for
// free bodies, whose K is singular.
#pragma once
#include <Eigen/Dense>
#include <Eigen/Sparse>

namespace isosid::prep {

struct ModalResult {
  Eigen::VectorXd eigenvalues;   ///< ascending, omega^2 (1/s^2); rigid-body ones are round-off around 0
  Eigen::MatrixXd modes;         ///< mass-normalized: modes^T M modes = I
  int rigid_body_modes = 0;      ///< eigenvalues recognised as zero
  int iterations = 0;            ///< Lanczos restarts
  Eigen::VectorXd frequencies_hz() const;
};

/// The n lowest modes (Lanczos, or a dense solve when n is close to the size). `lambda_scale` estimates the first elastic eigenvalue (e.g. (pi c / L)^2):
/// the shift is -0.1 lambda_scale, so zero and the first elastic eigenvalues stay well apart
/// after inversion, and eigenvalues below 1e-4 lambda_scale count as rigid-body modes (they
/// are returned as computed: round-off around zero).
ModalResult lowest_modes(const Eigen::SparseMatrix<double>& K, const Eigen::SparseMatrix<double>& M, int n,
                         double lambda_scale);

/// (pi c / L)^2 with c = sqrt(E / rho) and L the body's size: the order of its first elastic eigenvalue.
double eigenvalue_scale(double youngs_modulus, double density, double size);

}  // namespace isosid::prep
