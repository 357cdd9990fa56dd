// Reduction of a body as its model file's [reduction] table asks: the Craig-Bampton
// interface chosen on the body, the rigid-body fields its constraints admit (Buckens frame)
// and the eigenvalue scale from its material and size, handed to prep::reduce().
#pragma once
#include "assemble/assembly.hpp"
#include "model/body_model.hpp"
#include "reduce/reduction.hpp"

#include <string>
#include <vector>

namespace isosid::prep {

/// The interface DOFs of a Craig-Bampton reduction: all free components of the
/// `interface_points` nodes of the interface surface's side physically nearest to the side's
/// point at `interface_center`; also describes them in words.
std::vector<int> interface_dofs(const BodyModel& body, std::string& description);

/// The massless boundary of a MacNeal reduction: every free DOF of the control points that
/// move a Gauss point of the boundary surface; also describes them in words.
std::vector<int> massless_boundary_dofs(const BodyModel& body, std::string& description);

/// The request for prep::reduce() from the model's [reduction] table.
ReductionRequest reduction_request(const BodyModel& body);

/// Reduces the body as its model file asks. `extra` (free DOFs x k) is added to that basis
/// (a hierarchical body's prolongated coarse modes; none under a massless boundary).
ReducedBasis reduce_body(const BodyModel& body, const SystemMatrices& system, const Eigen::MatrixXd& extra = {});

}  // namespace isosid::prep
