// Lowest eigenpairs of K phi = lambda M phi by block Lanczos on a CHOLMOD factor: of
// K - sigma M (shift-invert; a negative shift keeps it positive definite for free bodies, whose K
// is singular), or of a stiffness factor the caller also uses for its static solves.
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

class SparseCholesky;

/// The n lowest elastic modes through a factor of the stiffness that the caller holds for its
/// own solves as well: of K itself for a body held in place (`rigid` without columns), or for a
/// free body of K with supports on its rigid fields `rigid` (columns), whose solution of a load
/// balanced against R differs from the elastic one by a rigid field (macneal.cpp's `supported`).
/// The modes are mass-normalized and free of rigid content (R^T M phi = 0); no rigid-body modes
/// are returned. Models too small for Lanczos's room (n >= elastic DOFs - 1) take a dense solve
/// of (K, M) instead.
ModalResult lowest_elastic_modes(const SparseCholesky& stiffness, const Eigen::SparseMatrix<double>& K, const Eigen::SparseMatrix<double>& M,
                                 const Eigen::MatrixXd& rigid, int n);

/// (pi c / L)^2 with c = sqrt(E / rho) and L the body's size: the order of its first elastic eigenvalue.
double eigenvalue_scale(double youngs_modulus, double density, double size);

}  // namespace isosid::prep
