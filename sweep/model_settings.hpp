// A study's keys into model files: `model.<body>.<key>` sets <key> in the model file of the
// scene's flexible body <body>. The case's copy of that model, with its values, is written once
// into the study folder under a name from its content (models/<model>-<hash>.model.toml), so
// cases with equal values share it, and its SID is built once beside it (under the SID lock)
// however many cases and ranks read it. The scene then names the copy as the body's model.
#pragma once
#include "study_file.hpp"

#include <string>
#include <vector>

namespace isosid::sweep {

/// What the case's scene is read with: its scene keys as they are and, for each body with
/// model keys, the body's model (and SID) pointed at the model's copy with those values.
struct CaseScene {
  std::vector<common::TomlOverride> settings;
  std::vector<std::string> model_copies;  ///< the copies pointed at (none without model keys)
};

/// The case's CaseScene, its model copies written into `study_dir` if they are not there yet.
/// Throws InputError for an unknown body, a body without a model file, or a key its model file
/// cannot take.
CaseScene case_scene(const Study& study, const Case& c, const std::string& study_dir);

}  // namespace isosid::sweep
