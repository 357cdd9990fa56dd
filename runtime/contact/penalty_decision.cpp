// The one place a contact's penalty is decided; see penalty_decision.hpp.
#include "contact/penalty_decision.hpp"

#include "contact/default_penalty.hpp"

namespace isosid::run {

double derived_penalty(const SurfaceContact& contact, double contact_radius) {
  const FloatingBody* master = contact.target().body();
  return default_penalty(contact.body(), contact.surface(), master, master ? master->contact_surface(contact.spec().target_surface) : nullptr,
                         contact_radius);
}

ContactPenalty decide_penalty(const SurfaceContact& contact, const std::optional<ContactPenalty>& given, double contact_radius) {
  if (given) return *given;
  if (contact.spec().penalty > 0) return {contact.spec().penalty, "scene"};
  const double from_elements = derived_penalty(contact, 0);
  const double fitted = derived_penalty(contact, contact_radius);
  // elements larger than the contact radius (or no radius known) rule
  if (fitted == from_elements) return {from_elements, "derived: 1000 E*/h"};
  return {fitted, "derived: 1000 E*/a"};
}

}  // namespace isosid::run
