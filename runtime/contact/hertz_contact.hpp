// Two rigid spheres touching by Hertz's law (contact/hertz_law.hpp): the reference model "Hertz"
// of [R2] (docs/references.md) for impacts of spheres whose flexibility is local to the contact.
// The spheres overlap by delta = r_a + r_b - |c_a - c_b| and push each other apart along the
// line of centres with the law's force K delta^(3/2), K = 4/3 E* sqrt(R*), 1/E* = (1 - nu_a^2)/E_a
// + (1 - nu_b^2)/E_b, 1/R* = 1/r_a + 1/r_b. Frictionless and undamped: the impact is elastic.
#pragma once
#include "body/floating_body.hpp"
#include "contact/contact_law.hpp"
#include "contact/surface_contact.hpp"
#include "contact/contact_spec.hpp"

namespace isosid::run {

class HertzContact {
public:
  /// `a` and `b`: the spec's rigid spheres of radii ra and rb (centred on their frames).
  HertzContact(const HertzContactSpec& spec, const FloatingBody& a, double ra, const FloatingBody& b, double rb);

  const std::string& name() const { return spec_.name; }
  /// N / m^1.5
  double stiffness() const { return stiffness_; }
  /// The surfaces' distance at y (negative: overlap), m.
  double gap(const double* y) const;
  /// The gap's rate at y (the centres' relative velocity along the line of centres), m/s.
  double gap_rate(const double* y) const;
  /// Adds the force on each sphere to fa and fb; returns the state (force on a, world).
  ContactState apply(const double* y, GeneralizedForce& fa, GeneralizedForce& fb) const;

private:
  HertzContactSpec spec_;
  const FloatingBody &a_, &b_;
  double ra_, rb_, stiffness_;
  std::unique_ptr<ContactLaw> law_;  ///< Hertz's, of stiffness_
};

}  // namespace isosid::run
