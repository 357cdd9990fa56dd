// Where a run's results come from: the program's version, the exact command, and the files it
// read with their SHA-256, recorded in summary.json ("provenance") and results.h5 (/provenance)
// so that a result can be traced to, and reproduced from, its inputs.
#pragma once
#include "scene/scene.hpp"

#include <nlohmann/json.hpp>
#include <string>
#include <vector>

namespace isosid::format::h5 {
class Writer;
}

namespace isosid::run {

/// One file a run read.
struct InputRecord {
  std::string role;  ///< "scene", or "model <body>" / "sid <body>"
  std::string path;
  std::string sha256;  ///< of the file as the run found it
};

struct RunProvenance {
  std::string program_version;  ///< `isosid-run --version`
  std::string command_line;     ///< as the shell would take it back
  std::string started_utc;
  std::vector<InputRecord> inputs;
  std::vector<std::string> scene_overrides;  ///< "key = value" set over the scene file, in order
};

/// The provenance of a run of `scene` starting now: the scene file and each body's model and SID
/// files that exist (an adaptive body's SIDs are built during the run and recorded by its phases).
RunProvenance run_provenance(const Scene& scene);

nlohmann::json to_json(const RunProvenance& provenance);

/// The /provenance group of results.h5: program_version, command_line, started_utc, and the
/// inputs as three string lists of one row each (input_roles, input_paths, input_sha256).
void write_provenance(format::h5::Writer& w, const RunProvenance& provenance);

}  // namespace isosid::run
