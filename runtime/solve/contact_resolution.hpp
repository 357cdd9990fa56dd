// Contact elements that fit the scene's impacts: a body whose model sizes its contact
// elements from an expected contact radius ([contact_resolution], smallest = "contact") is
// rebuilt for the Hertz estimate of this scene (impact_estimate) when its SID was made for a
// larger radius (too coarse) or for one over 25 % smaller (needlessly fine). The rebuilt SID
// records the radius, so the next run of the scene reuses it.
#pragma once
#include "isosid/format/sid.hpp"
#include "scene/scene.hpp"

#include <string>
#include <vector>

namespace isosid::run {

/// Rebuilds (through isosid-prep) the SIDs of `scene`'s flexible bodies, in `sids`, whose
/// contact elements do not fit the estimated impacts; returns the names of the bodies rebuilt.
std::vector<std::string> fit_contact_resolution(const Scene& scene, std::vector<format::Sid>& sids, bool quiet);

}  // namespace isosid::run
