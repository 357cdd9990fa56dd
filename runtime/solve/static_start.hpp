// The static start of [R2] Sect. 6 (docs/references.md): bodies with elastic_start = "static" begin
// in their static deflection under everything acting at the initial state (gravity, joints, spin,
// contact), so a mechanism released under gravity does not start ringing about it. Their integrated
// modes move to where their accelerations vanish, and their frames with them so that every joint
// holds (a clamped node stays where it was placed), and the frames of the bodies jointed to
// them follow; the frames' remaining freedom (a pendulum's swing) is left as given.
#pragma once
#include "solve/multibody_system.hpp"

namespace isosid::run {

/// Settles y (the system's initial state) for the bodies flagged in `static_start` (system
/// order) by Newton's method on their accelerations and the joints' residuals, its Jacobian by
/// differences of the right-hand side, each step the least-change one. Throws
/// ComputationError when that finds no equilibrium.
void settle_static_start(const MultibodySystem& system, const std::vector<bool>& static_start, double* y);

}  // namespace isosid::run
