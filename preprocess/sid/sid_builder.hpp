// From an assembled, reduced body to a complete SID: body terms, modal mass, stiffness and
// Rayleigh damping, contact surfaces with master patches, nodes, stress rows, provenance.
#pragma once
#include "assemble/assembly.hpp"
#include "model/body_model.hpp"
#include "reduce/reduction.hpp"
#include "isosid/format/sid.hpp"

namespace isosid::prep {

/// The interface DOFs of a Craig-Bampton reduction: all free components of the
/// `interface_points` nodes of the interface surface's side physically nearest to the side's
/// point at `interface_center`; also describes them in words.
std::vector<int> interface_dofs(const BodyModel& body, std::string& description);

/// The request for prep::reduce() from the model's [reduction] table.
ReductionRequest reduction_request(const BodyModel& body);

/// Reduces the body as its model file asks: admissible rigid fields, the request, and the
/// eigenvalue scale from its material and size.
/// `extra` (free DOFs x k) is added to the basis the model file asks for.
ReducedBasis reduce_body(const BodyModel& body, const SystemMatrices& system, const Eigen::MatrixXd& extra = {});

/// Modes on all nodal DOFs (fixed components zero), node-major.
Eigen::MatrixXd nodal_modes(const DofMap& dofs, const Eigen::MatrixXd& Phi_free);

/// Builds the SID (provenance timings are left to the caller).
format::Sid build_sid(const BodyModel& body, const SystemMatrices& system, const SparseMatrix& scalar_mass,
                      const ReducedBasis& basis);

}  // namespace isosid::prep
