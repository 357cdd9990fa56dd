// What a contact's impact will look like, estimated by Hertz theory before the run: the
// contact radius it will reach, set against the size of the contact elements there. Forces
// converge from a/h = 8 on (bench/RESULTS.md, contact-convergence: within 0.3 % of the
// finite-sphere reference for three spheres), so a coarser contact resolution gets a
// warning that names the element size to use.
#pragma once
#include "contact/surface_contact.hpp"

#include <optional>
#include <string>

namespace isosid::run {

/// Contact elements per Hertz contact radius (or half-width) from which peak forces and
/// contact times have converged to 0.3 %.
constexpr double kConvergedElementsPerContactRadius = 8;

struct ImpactEstimate {
  bool line_contact = false;     ///< planar bodies: a cylinder's line contact (per unit thickness)
  double approach_speed = 0;     ///< m/s, along the normal at the nearest points
  double contact_radius = 0;     ///< m: the Hertz radius a (point contact) or half-width b (line contact)
  double peak_force = 0;         ///< N (point contact; line contact: times the slave's thickness)
  double contact_time = 0;       ///< s; 0 where Hertz gives no closed form (line contact)
  double approach = 0;           ///< m, the bodies' largest approach; 0 where Hertz gives no closed form (line contact)
  double element_size = 0;       ///< m, the slave's contact element at its nearest point
  double gap = 0;                ///< m, between the nearest points at the estimate's state
  double elements_per_radius() const { return contact_radius / element_size; }
};

/// The Hertz estimate of a contact at state y, from its nearest pair of points: both bodies'
/// materials and curvatures there (principal directions taken as aligned), their masses
/// (rotation ignored) and the approach speed along the normal. None when the bodies do not
/// approach, or when the surfaces there are flat or conforming (no Hertz contact).
std::optional<ImpactEstimate> estimate_impact(const SurfaceContact& contact, const double* y);

/// The warning, before a run from t0, that the contact will still be closed at end_time: flying
/// at its approach speed it touches at t0 + gap / speed and Hertz releases it a contact time
/// later (gravity or other loads make it earlier; the run's own check is after it). "" when the
/// estimate puts the release before end_time, the touch after it, or has no contact time.
std::string closed_at_end_prediction(const SurfaceContact& contact, const ImpactEstimate& estimate, double t0, double end_time);

/// The warning for an estimate coarser than kConvergedElementsPerContactRadius, or "".
std::string resolution_warning(const SurfaceContact& contact, const ImpactEstimate& estimate);

}  // namespace isosid::run
