// Quasistatic high-frequency modes (seed 001): instead of integrating the stiff constraint
// modes, solve their static equilibrium Omega_h^2 q_h = Psi_h^T F(q) under the contact forces
// at every evaluation, by Newton's method with the exact contact Jacobian.
#pragma once
#include "body/flexible_body.hpp"
#include "contact/plane_contact.hpp"

#include <vector>

namespace isosid::run {

/// Updates body.quasistatic_modes() for state y (warm-started from their last values);
/// returns the Newton iterations. Throws ComputationError if Newton does not converge.
int solve_quasistatic_modes(const FlexibleBody& body, const std::vector<const PlaneContact*>& contacts, const double* y);

}  // namespace isosid::run
