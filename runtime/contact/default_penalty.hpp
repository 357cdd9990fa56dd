// The penalty factor a contact gets when its scene gives none: c_p = 1000 E* / L, from the
// materials of the bodies in contact (E* the combined plane-strain modulus) and the length L
// over which the contact carries load: the Hertz contact radius a the impact will reach, or
// the size h of the fine contact elements where that is larger or unknown.
#pragma once
#include <string>
#include "body/floating_body.hpp"

#include <map>

namespace isosid::run {

/// How many times stiffer than the contact patch the penalty layer is: its compliance 1/c_p
/// is 1e-3 of a/E*, so it lengthens contact times by about 0.1 % (bench/RESULTS.md,
/// contact-convergence). Scaled by the element size h instead (the rule used before), the
/// penalty grows as the mesh is refined and the Gauss points' gaps, each forced to zero,
/// over-constrain the surface: at a/32 a steel sphere's peak force rose by 0.2 % for every
/// fourfold increase beyond about 100 E*/h (bench/RESULTS.md, penalty sweep).
constexpr double kPenaltyStiffnessRatio = 1000;

/// The softest penalty a scene may give, relative to the one derived from the contact
/// elements (1000 E*/h): 1e-8 of it, c_p = 1e-5 E*/h, is a layer 1e5 times as compliant as an
/// element's depth of the material, which then takes the impact instead of the bodies: scene
/// A's sphere (2.9e18 N/m^3 derived) would sink about 60 um (20 Hertz approaches) into its
/// plane. Softer ones (scene A at 1e-300 N/m^3) let the bodies pass through each other. The
/// stability suite's soft case, scene A at 1e12 N/m^3 (rebound and energy kept), is 3.4e-7 of it.
constexpr double kMinPenaltyRatio = 1e-8;

/// The stiffest penalty a scene may give, relative to the derived one: 1e6 of it, a layer 1e9
/// times stiffer than an element's depth of the material. The derived penalty already moves
/// forces by under 0.1 % (its layer is 1000 times stiffer than the contact patch); a stiffer
/// one only shortens the steps, as the square root of its ratio. Scene A at 1.7e10 of it
/// (5e28 N/m^3) stepped at 1e-7 of its contact time and would have crawled for hours; the
/// stability suite's stiffest case is 340 times the derived penalty.
constexpr double kMaxPenaltyRatio = 1e6;

/// The deepest penetration of the contact points, relative to the Hertz approach of the
/// bodies, that a plausible penalty leaves: the derived penalty penetrates by about 1e-3 of
/// the approach (its layer is 1000 times stiffer than the contact patch); at half the
/// approach the layer takes a third of the impact's compliance and the force and contact time
/// are the penalty's rather than the bodies'. Deeper runs get a warning blaming the penalty.
constexpr double kMaxPenetrationPerApproach = 0.5;

/// The length of each element of a contact surface (by element index), m: along a curve (2D,
/// the 2 pi r or thickness divided out of the weights) or the square root of its area (3D).
std::map<int, double> contact_element_lengths(const format::ContactSurface& surface, const format::Sid& sid);

/// The size of a contact surface's fine elements, m: the lower quartile over its elements of
/// their length along a curve (2D, the 2 pi r or thickness divided out of the weights) or the
/// square root of their area (3D).
double contact_element_size(const format::ContactSurface& surface, const format::Sid& sid);

/// Combined modulus E* of two bodies: 1/E* = (1 - nu1^2)/E1 + (1 - nu2^2)/E2; a body without
/// elastic coordinates (rigid) adds nothing. `master` may be null (a fixed surface). The
/// patches name whose material applies in a body of several patches (format::material_of).
double combined_modulus(const FloatingBody& slave, const FloatingBody* master, const std::string& slave_patch = "",
                        const std::string& master_patch = "");

/// c_p = kPenaltyStiffnessRatio E* / max(a, h) (N/m^3), h the contact element size of both
/// surfaces (`master_surface` may be null), a the expected contact radius or half-width (0:
/// unknown, h alone).
double default_penalty(const FloatingBody& slave, const format::ContactSurface& slave_surface, const FloatingBody* master,
                       const format::ContactSurface* master_surface, double contact_radius = 0);

}  // namespace isosid::run
