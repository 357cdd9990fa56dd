// A run's provenance; see run_provenance.hpp.
#include "output/run_provenance.hpp"

#include "isosid/common/invocation.hpp"
#include "isosid/common/sha256.hpp"
#include "isosid/common/version.hpp"
#include "isosid/format/hdf5_file.hpp"

#include <filesystem>

namespace isosid::run {

RunProvenance run_provenance(const Scene& scene) {
  RunProvenance p{common::version_line("isosid-run"), common::command_line(), common::utc_now(), {}, scene.overrides};
  auto add = [&p](const std::string& role, const std::string& path) {
    std::error_code ec;
    if (path.empty() || !std::filesystem::is_regular_file(path, ec)) return;
    p.inputs.push_back({role, path, common::sha256_file(path)});
  };
  if (scene.text_sha256.empty()) add("scene", scene.file);
  else p.inputs.push_back({"scene", scene.file, scene.text_sha256});  // given as text: no file to hash
  for (const BodySpec& body : scene.bodies) {
    add("model " + body.name, body.model_file);
    add("sid " + body.name, body.sid_file);
  }
  return p;
}

nlohmann::json to_json(const RunProvenance& provenance) {
  nlohmann::json inputs = nlohmann::json::array();
  for (const InputRecord& input : provenance.inputs)
    inputs.push_back({{"role", input.role}, {"path", input.path}, {"sha256", input.sha256}});
  return {{"program_version", provenance.program_version},
          {"command_line", provenance.command_line},
          {"started_utc", provenance.started_utc},
          {"inputs", inputs},
          {"scene_overrides", provenance.scene_overrides}};
}

void write_provenance(format::h5::Writer& w, const RunProvenance& provenance) {
  std::vector<std::string> roles, paths, hashes;
  for (const InputRecord& input : provenance.inputs) {
    roles.push_back(input.role);
    paths.push_back(input.path);
    hashes.push_back(input.sha256);
  }
  w.group("/provenance");
  w.string("/provenance/program_version", provenance.program_version);
  w.string("/provenance/command_line", provenance.command_line);
  w.string("/provenance/started_utc", provenance.started_utc);
  w.strings("/provenance/input_roles", roles);
  w.strings("/provenance/input_paths", paths);
  w.strings("/provenance/input_sha256", hashes);
  if (!provenance.scene_overrides.empty()) w.strings("/provenance/scene_overrides", provenance.scene_overrides);
}

}  // namespace isosid::run
