// Checks of [adaptive] interval_width; see interval_width.hpp.
#include "adapt/interval_width.hpp"

#include "isosid/common/number_text.hpp"
#include "isosid/format/error.hpp"

#include <algorithm>
#include <cmath>
#include <limits>

namespace isosid::run {

namespace {

/// The diagonal of the bounding box of a master patch's control points, m (0 if the SID has none).
double surface_extent(const format::Sid& sid, const std::string& surface) {
  for (const format::ContactSurface& s : sid.contact_surfaces) {
    if (s.name != surface) continue;
    const format::MasterPatch* m = format::find_master_patch(sid, s.master_patch);
    if (!m || m->control_points.rows() == 0) return 0;
    return (m->control_points.colwise().maxCoeff() - m->control_points.colwise().minCoeff()).norm();
  }
  return 0;
}

/// Calls f(body, surface, extent) for each surface of an adaptive body that contact c refines.
template <typename F>
void for_each_refined_surface(const Scene& scene, const std::vector<format::Sid>& coarse_sids, const ContactSpec& c, F f) {
  for (const auto& [body, surface] : {std::pair{c.body, c.surface}, std::pair{c.target, c.target_surface}}) {
    const BodySpec* b = scene.body(body);
    if (!b || !b->adaptive || surface.empty()) continue;
    // the SIDs are the flexible bodies', in order
    const auto index = std::count_if(scene.bodies.data(), b, [](const BodySpec& o) { return !o.rigid; });
    const double extent = surface_extent(coarse_sids[std::size_t(index)], surface);
    if (extent > 0) f(body, surface, extent);
  }
}

}  // namespace

IntervalDecision decide_interval(double utilization, bool beyond, double width) {
  IntervalDecision d;
  const double toward_target = width * std::clamp(utilization / kTargetUtilization, 0.5, kMaxWidening);
  if (beyond) {
    d.next_width = kMaxWidening * width;
    d.reason = "load beyond the refined region";
  } else if (utilization == 0) {
    d.acceptable = true;
    d.next_width = width;
    d.reason = "nothing loaded (the surfaces grazed)";
    d.learned = false;
  } else if (utilization > kMaxUtilization) {
    d.next_width = toward_target;
    d.reason = "region too narrow";
  } else if (utilization < kMinUtilization) {
    d.next_width = toward_target;
    d.reason = "region too wide";
  } else {
    d.acceptable = true;
    d.next_width = toward_target;
    d.reason = "acceptable";
  }
  return d;
}

double widest_interval(const Scene& scene, const std::vector<format::Sid>& coarse_sids, const ContactSpec& c) {
  double widest = std::numeric_limits<double>::infinity();
  for_each_refined_surface(scene, coarse_sids, c, [&](const std::string&, const std::string&, double extent) { widest = std::min(widest, extent); });
  return widest;
}

void check_interval_width_fits(const Scene& scene, const std::vector<format::Sid>& coarse_sids) {
  const double width = scene.adaptive.interval_width;
  if (!(width > 0)) return;  // from each impact's Hertz estimate
  for (const ContactSpec& c : scene.contacts)
    for_each_refined_surface(scene, coarse_sids, c, [&](const std::string& body, const std::string& surface, double extent) {
      if (width > extent)
        throw format::InputError(scene.file, "adaptive.interval_width",
                                 common::number_text(width) + " m is wider than contact surface '" + surface + "' of '" + body + "' (" +
                                     common::number_text(extent) + " m across): the refined region is centred on a touch of it");
    });
}

void check_interval_width_reaches(const Scene& scene, const std::string& contact, double estimated_width, int tries,
                                  double growth_per_try) {
  const double width = scene.adaptive.interval_width, reach = width * std::pow(growth_per_try, tries - 1);
  if (width > 0 && estimated_width > 0 && reach < estimated_width)
    throw format::InputError(scene.file, "adaptive.interval_width",
                             common::number_text(width) + " m cannot hold contact '" + contact + "': its Hertz width at the touch is " +
                                 common::number_text(estimated_width) + " m, and " + std::to_string(tries) + " tries widen a region " +
                                 common::number_text(reach / width) + " times at most (leave interval_width out to start from the estimate)");
}

}  // namespace isosid::run
