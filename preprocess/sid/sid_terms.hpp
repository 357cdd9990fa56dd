// The classic SID body terms (mdCM, J, Ct, Cr, Gr, Ge, Oe with their first-order Taylor parts)
// from the body integrals int c dm, int c c^T dm, int Phi dm, int c_a Phi_b dm and
// int Phi_a^T Phi_b dm, each an exact quadratic form of the scalar consistent mass matrix
// (formulas: docs/references.md [R8], as MBSim's assemble() builds them).
#pragma once
#include "isosid/format/sid.hpp"

#include <Eigen/Dense>
#include <Eigen/Sparse>

namespace isosid::prep {

/// Fills sid.refmod.mass and the terms mdCM, J, Ct, Cr, Gr, Ge, Oe, ksigma. `Phi_nodal` holds
/// the modes on all nodal DOFs (node-major, section components); `node_points` the reference
/// positions. Axisymmetric sections are revolved about y, planar bodies lie in z = 0.
void fill_inertia_terms(format::Sid& sid, const Eigen::SparseMatrix<double>& scalar_mass,
                        const Eigen::MatrixXd& node_points, const Eigen::MatrixXd& Phi_nodal);

/// Rayleigh coefficients from (kappa, f1, f2) ([R1] eq. 26-27).
format::Damping rayleigh_damping(double kappa, double f1_hz, double f2_hz);

}  // namespace isosid::prep
