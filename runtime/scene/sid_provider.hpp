// Loads the SIDs of a scene; a body that names its model file gets its SID (re)built by
// running isosid-prep as a subprocess when the SID is missing or older than the model, so
// the runtime links no preprocessing code.
#pragma once
#include "isosid/format/sid.hpp"
#include "isosid/format/sid_io.hpp"
#include "scene/scene.hpp"

#include <vector>

namespace isosid::run {

/// How to read the scene's SID `file`: the viewing meshes only for ParaView output; without a
/// probe where the file is one this runtime's preparation wrote, unchanged (sid_digest).
format::ReadOptions sid_read_options(const Scene& scene, const std::string& file);

/// The SIDs of the scene's flexible bodies, in order; stale or missing ones are rebuilt first.
std::vector<format::Sid> load_sids(const Scene& scene, bool quiet);

/// A body's SID built from its model file for an expected contact radius (m; the model's
/// [contact_resolution]), and the file it was read from.
struct SizedSid {
  format::Sid sid;
  std::string file;
};

/// The SID of `body`'s model sized for `contact_radius`, from a cache beside the scene's SID
/// (`.isosid-cache/<SID name>-<key>.sid.h5`, the key a hash of the model's content, the radius
/// and the program version): built once by whichever run asks first (under a lock), read by
/// every later one. The SID the scene names is left as it is.
SizedSid sized_sid(const Scene& scene, const BodySpec& body, double contact_radius, bool quiet);

}  // namespace isosid::run
