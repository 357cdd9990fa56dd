// isosid-prep run as a subprocess: the runtime links no preprocessing code, but builds SIDs
// on demand (stale SIDs of a scene, the contact-sized rebuild, refined models at an impact).
#pragma once
#include <string>
#include <vector>

namespace isosid::run {

/// isosid-prep: $ISOSID_PREP, else beside this program (install) or in the build tree, else PATH.
std::string find_prep();

/// Runs isosid-prep on `model`, writing `sid`, with further options `extra` (e.g. --coarse).
/// Its progress lines pass through to stderr (`what` says why it runs); its one-line error is
/// held back and becomes this program's: InputError for a refused model (its exit 2),
/// ComputationError for any other failure.
void run_prep(const std::string& model, const std::string& sid, const std::vector<std::string>& extra, bool quiet,
              const std::string& what);

}  // namespace isosid::run
