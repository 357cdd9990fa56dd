// Loads the SIDs of a scene; a body that names its model file gets its SID (re)built by
// running isosid-prep as a subprocess when the SID is missing or older than the model, so
// the runtime links no preprocessing code.
#pragma once
#include "isosid/format/sid.hpp"
#include "scene/scene.hpp"

#include <vector>

namespace isosid::run {

/// The SIDs of the scene's flexible bodies, in order; stale or missing ones are rebuilt first.
std::vector<format::Sid> load_sids(const Scene& scene, bool quiet);

/// Rebuilds a body's SID from its model file for an expected contact radius (m; the model's
/// [contact_resolution]) and reads it.
format::Sid rebuild_sid(const BodySpec& body, double contact_radius, bool quiet);

}  // namespace isosid::run
