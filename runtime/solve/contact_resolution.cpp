// Contact elements fitted to the scene's impacts; see contact_resolution.hpp.
#include "solve/contact_resolution.hpp"

#include "scene/sid_provider.hpp"
#include "solve/multibody_system.hpp"

#include <algorithm>
#include <map>

namespace isosid::run {

namespace {
/// A body whose SID can be rebuilt for another contact radius: it names its model file, and its
/// SID was sized from a contact radius ([contact_resolution]).
bool resizable(const BodySpec& body, const format::Sid& sid) {
  return !body.model_file.empty() && sid.discretization && sid.discretization->contact_radius > 0;
}
}  // namespace

std::vector<std::string> fit_contact_resolution(Scene& scene, std::vector<format::Sid>& sids, bool quiet) {
  // the estimates need a whole system (its quasistatic factorizations included): not built
  // when no body could be resized anyway
  bool any_resizable = false;
  std::size_t next = 0;
  for (const BodySpec& body : scene.bodies)
    if (!body.rigid) any_resizable = resizable(body, sids.at(next++)) || any_resizable;
  if (!any_resizable) return {};
  // the finest estimated contact radius of each body over its contacts
  std::map<std::string, double> wanted;
  {
    // the SIDs lent to the probe and given back: a copy would hold every SID twice
    MultibodySystem probe(scene, std::move(sids));
    for (std::size_t k = 0; k < probe.contacts().size(); ++k) {
      const auto& estimate = probe.impact_estimates()[k];
      if (!estimate) continue;
      const SurfaceContact& contact = probe.contacts()[k];
      for (const FloatingBody* b : {&contact.body(), contact.target().body()})
        if (b) wanted[b->name()] = wanted.count(b->name()) ? std::min(wanted[b->name()], estimate->contact_radius) : estimate->contact_radius;
    }
    sids = std::move(probe).release_sids();
  }
  std::vector<std::string> rebuilt;
  std::size_t next_sid = 0;
  for (BodySpec& body : scene.bodies) {
    if (body.rigid) continue;
    format::Sid& sid = sids[next_sid++];
    const auto radius = wanted.find(body.name);
    if (radius == wanted.end() || !resizable(body, sid)) continue;
    const double built_for = sid.discretization->contact_radius;
    // round-off of the estimate (its mass and curvatures come from the SID) must not rebuild
    if (radius->second >= (1 - 1e-6) * built_for && radius->second <= 1.25 * built_for) continue;
    SizedSid sized = sized_sid(scene, body, radius->second, quiet);
    sid = std::move(sized.sid);
    body.sid_file = sized.file;
    rebuilt.push_back(body.name);
  }
  return rebuilt;
}

}  // namespace isosid::run
