// The one place a contact's penalty is decided. The system applies it to every contact when it
// takes its starting state (MultibodySystem::estimate_impacts): a penalty given for the run (a
// caller's, such as the adaptive loop's penalty search), else the scene's, else the default
// rule's 1000 E*/max(a, h) (contact/default_penalty.hpp) with the contact radius a of the
// impact's latest Hertz estimate (at that state, or at an earlier one where the bodies do not
// approach there).
#pragma once
#include "contact/surface_contact.hpp"

#include <optional>
#include <vector>

namespace isosid::run {

/// Per contact, in the scene's order: a penalty given for one run in place of the scene's
/// (empty, or shorter than the contacts: none given).
using GivenPenalties = std::vector<std::optional<ContactPenalty>>;

/// The default rule's penalty for the contact's surfaces and materials at a contact radius, m
/// (0: unknown, from the contact elements alone).
double derived_penalty(const SurfaceContact& contact, double contact_radius);

/// The contact's penalty: `given` where set, else the scene's, else derived at the contact radius
/// its impact is expected to reach, m (0: unknown, from the contact elements alone).
ContactPenalty decide_penalty(const SurfaceContact& contact, const std::optional<ContactPenalty>& given, double contact_radius);

}  // namespace isosid::run
