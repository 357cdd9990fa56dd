// The runtime's record of the SIDs its preparation wrote: `<sid>.sha256` beside each, the
// SHA-256 of the file as isosid-prep left it. A SID whose bytes still have that digest is the
// file libhdf5 itself wrote, so reading it needs no probe in a child process (the probe guards
// against corrupt files crashing libhdf5, and reading a SID twice cost the sphere on the beam
// at a/8 about 0.8 s of its 3.6 s); any other SID, or one changed since, is probed as before.
#pragma once
#include <string>

namespace isosid::run {

/// Writes `<sid>.sha256` for the SID just built (atomically: a temporary renamed over it).
void record_sid_digest(const std::string& sid);

/// True if `<sid>.sha256` exists and holds the digest of the file's current bytes.
bool sid_digest_matches(const std::string& sid);

}  // namespace isosid::run
