// Loads the SIDs of a scene; a body that names its model file gets its SID (re)built by
// running isosid-prep as a subprocess when the SID is missing or older than the model, so
// the runtime links no preprocessing code.
#pragma once
#include "isosid/format/sid.hpp"
#include "isosid/format/sid_io.hpp"
#include "scene/scene.hpp"

#include <vector>

namespace isosid::run {

/// What the scene needs of its SIDs: the viewing meshes only for ParaView output.
format::ReadOptions sid_read_options(const Scene& scene);

/// The SIDs of the scene's flexible bodies, in order; stale or missing ones are rebuilt first.
std::vector<format::Sid> load_sids(const Scene& scene, bool quiet);

/// Rebuilds a body's SID from its model file for an expected contact radius (m; the model's
/// [contact_resolution]) and reads what the scene needs of it.
format::Sid rebuild_sid(const Scene& scene, const BodySpec& body, double contact_radius, bool quiet);

}  // namespace isosid::run
