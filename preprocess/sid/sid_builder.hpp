// From an assembled, reduced body to a complete SID: body terms, modal mass, stiffness and
// Rayleigh damping, contact surfaces with master patches, nodes, stress rows, provenance.
#pragma once
#include "assemble/assembly.hpp"
#include "model/body_model.hpp"
#include "reduce/mode_basis.hpp"
#include "isosid/format/sid.hpp"

namespace isosid::prep {

/// Modes on all nodal DOFs (fixed components zero), node-major.
Eigen::MatrixXd nodal_modes(const DofMap& dofs, const Eigen::MatrixXd& Phi_free);

/// Builds the SID (provenance timings are left to the caller).
format::Sid build_sid(const BodyModel& body, const SystemMatrices& system, const SparseMatrix& scalar_mass,
                      const ReducedBasis& basis);

}  // namespace isosid::prep
