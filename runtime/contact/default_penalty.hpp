// The penalty factor a contact gets when its scene gives none: c_p = 1000 E* / h, from the
// materials of the bodies in contact (E* the combined plane-strain modulus) and the size h of
// the fine contact elements (the contact resolution of the surfaces).
#pragma once
#include "body/floating_body.hpp"

#include <map>

namespace isosid::run {

/// How many times stiffer than one contact element the penalty layer is: its compliance
/// 1/c_p is 1e-3 of the element's h/E*, so it shifts forces and contact times by about
/// 0.1 % or less (scene A: 0.04 % at 5e18) while costing few extra steps (bench/RESULTS.md).
constexpr double kPenaltyStiffnessRatio = 1000;

/// The length of each element of a contact surface (by element index), m: along a curve (2D,
/// the 2 pi r or thickness divided out of the weights) or the square root of its area (3D).
std::map<int, double> contact_element_lengths(const format::ContactSurface& surface, const format::Sid& sid);

/// The size of a contact surface's fine elements, m: the lower quartile over its elements of
/// their length along a curve (2D, the 2 pi r or thickness divided out of the weights) or the
/// square root of their area (3D).
double contact_element_size(const format::ContactSurface& surface, const format::Sid& sid);

/// Combined modulus E* of two bodies: 1/E* = (1 - nu1^2)/E1 + (1 - nu2^2)/E2; a body without
/// elastic coordinates (rigid) adds nothing. `master` may be null (a fixed surface).
double combined_modulus(const FloatingBody& slave, const FloatingBody* master);

/// c_p = kPenaltyStiffnessRatio E* / h (N/m^3); `master_surface` (may be null) refines h.
double default_penalty(const FloatingBody& slave, const format::ContactSurface& slave_surface, const FloatingBody* master,
                       const format::ContactSurface* master_surface);

}  // namespace isosid::run
