// Contact elements that fit the scene's impacts: a body whose model sizes its contact
// elements from an expected contact radius ([contact_resolution], smallest = "contact") runs on
// a SID built for the Hertz estimate of this scene (impact_estimate) when the scene's SID was
// made for a larger radius (too coarse) or for one over 25 % smaller (needlessly fine). That SID
// comes from a cache beside the scene's (sid_provider's sized_sid): built once per radius, the
// scene's own SID untouched, so runs and a study's cases at other speeds never rebuild in place.
#pragma once
#include "isosid/format/sid.hpp"
#include "scene/scene.hpp"

#include <string>
#include <vector>

namespace isosid::run {

/// Replaces, in `sids`, the SIDs of `scene`'s flexible bodies whose contact elements do not fit
/// the estimated impacts by SIDs sized for them, and points those bodies' sid_file at them (the
/// run's provenance then names the SID it ran on); returns the names of the bodies refitted.
std::vector<std::string> fit_contact_resolution(Scene& scene, std::vector<format::Sid>& sids, bool quiet);

}  // namespace isosid::run
