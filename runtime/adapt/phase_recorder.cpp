// A phase's observer; see phase_recorder.hpp.
#include "adapt/phase_recorder.hpp"

#include "isosid/common/number_text.hpp"

#include <algorithm>

namespace isosid::run {

PhaseRecorder::PhaseRecorder(const Simulation& simulation, const std::vector<bool>& adaptive_contact, const Impact& impact,
                             const std::function<bool()>& stop_requested)
    : Recorder(simulation.system(), simulation.scene()), simulation_(simulation), system_(simulation.system()), adaptive_contact_(adaptive_contact),
      impact_(impact), stop_requested_(stop_requested), restarts_at_start_(simulation.stats().restarts) {
  if (impact_.after >= 0) {  // its surfaces just parted: the next touch is a new impact once they are apart
    system_.touched(std::size_t(impact_.after));
    system_.released(std::size_t(impact_.after));
  }
  if (impact_.contact < 0) return;
  system_.touched(std::size_t(impact_.contact));
  const FloatingBody& body = system_.contacts()[std::size_t(impact_.contact)].body();
  const double* y0 = simulation.state().data();
  touch_in_body_ = body.orientation(y0).conjugate() * (impact_.point - Eigen::Vector3d(body.r(y0)));
}

Eigen::Vector3d PhaseRecorder::region_centre(const double* y) const {
  const FloatingBody& body = system_.contacts()[std::size_t(impact_.contact)].body();
  return Eigen::Vector3d(body.r(y)) + body.orientation(y) * touch_in_body_;
}

void PhaseRecorder::touch(int k, double t, const Touch& touch) {
  Recorder::touch(k, t, touch);
  if (impact_.contact < 0 && adaptive_contact_[std::size_t(k)] && !found_) found_ = Found{k, t, touch};
  if (impact_.contact >= 0 && k != impact_.contact && adaptive_contact_[std::size_t(k)]) overlapping_.push_back({k, t, touch});
}

void PhaseRecorder::contact_event(int k, bool closing, double t) {
  Recorder::contact_event(k, closing, t);
  if (k == impact_.contact && closing) loaded_ = true;
}

void PhaseRecorder::step(double t, const double* y) {
  Recorder::step(t, y);
  if (impact_.contact < 0) return;
  // a touch without load (grazing) is over once the surfaces are clearly apart (the phase
  // starts with them touching, the gap within round-off of zero): by the exact surfaces'
  // closest approach and by every contact point, so that a closest-point search that stopped
  // short on the refined surfaces (a local minimum) cannot end an impact before it is loaded
  if (!loaded_) {
    const double apart = 1e-3 * impact_.width;
    const std::size_t k = std::size_t(impact_.contact);
    if (system_.touch(k, y).gap > apart && system_.contacts()[k].min_gap(y) > apart) impact_over_ = true;
  }
  // the farthest loaded point from the region's centre, in the slave's frame ([R2]'s utilization
  // of the contact interval, measured as a length: contact radius over half the width)
  const SurfaceContact& contact = system_.contacts()[std::size_t(impact_.contact)];
  const Eigen::Quaterniond frame = contact.body().orientation(y);
  const Eigen::Vector3d origin = contact.body().r(y);
  for (const PointLoad& p : contact.point_loads(y))
    reach_ = std::max(reach_, (frame.conjugate() * (p.position - origin) - touch_in_body_).norm());
  if (utilization() > 1) beyond_ = true;
  if (system_.touch_armed(std::size_t(impact_.contact))) impact_over_ = true;
  ++steps_;
  if (loaded_) ++contact_steps_;
  if (contact_steps_ <= impact_.window_contact_steps)
    window_ = {t, peak_force(impact_.contact), steps_};
  if (impact_.stop_on_error && error_.empty() && simulation_.stats().restarts > restarts_at_start_)
    error_ = "a quasistatic solve failed before t = " + common::number_text(t) + " s (its step was retried smaller)";
}

}  // namespace isosid::run
