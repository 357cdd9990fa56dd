// Model keys of a study; see model_settings.hpp.
#include "model_settings.hpp"

#include "isosid/common/sha256.hpp"
#include "isosid/common/toml_fields.hpp"
#include "isosid/format/atomic_output.hpp"
#include "isosid/format/error.hpp"
#include "scene/scene.hpp"

#include <algorithm>
#include <cstring>
#include <filesystem>
#include <sstream>

namespace isosid::sweep {
namespace {
namespace fs = std::filesystem;

constexpr const char* kModelPrefix = "model.";

/// A body's model keys, with the key inside its model file.
struct ModelKeys {
  std::string body;
  std::vector<common::TomlOverride> settings;
};

/// A string as a TOML value.
std::string toml_string(const std::string& text) {
  std::ostringstream out;
  out << toml::value<std::string>(text);
  return out.str();
}

/// A model's copy in the study folder (absolute) and the SID built from it, beside it.
struct ModelCopy {
  std::string model, sid;
};

/// The case's copy of `model_file` with the body's keys, written if new.
ModelCopy model_copy(const Study& study, const std::string& model_file, const ModelKeys& keys, const std::string& study_dir) {
  toml::table model = common::parse_toml_file(model_file);
  std::vector<common::TomlOverride> named = keys.settings;
  for (common::TomlOverride& s : named) s.key = kModelPrefix + keys.body + "." + s.key;
  try {
    common::apply_overrides(model, keys.settings, model_file);
  } catch (const format::InputError& e) {  // named by the study's key, not the model's
    throw format::InputError(study.file, "parameter", e.what());
  }
  std::ostringstream text;
  text << "# " << model_file << " as isosid-sweep set it:";
  for (const common::TomlOverride& s : named) text << " " << s.text() << ";";
  text << "\n" << model << "\n";
  const std::string name = fs::path(model_file).filename().string();
  const fs::path stem =
      fs::absolute(fs::path(study_dir) / "models" / (name.substr(0, name.find('.')) + "-" + common::sha256_hex(text.str()).substr(0, 16)));
  const ModelCopy copy{stem.string() + ".model.toml", stem.string() + ".sid.h5"};
  std::error_code ec;
  if (!fs::exists(copy.model, ec)) {  // equal copies by any rank: the rename leaves one whole file
    fs::create_directories(stem.parent_path());
    format::write_text_atomically(copy.model, text.str());
  }
  return copy;
}

/// The case's settings split into the scene's and each body's model keys.
std::vector<common::TomlOverride> split(const Case& c, std::vector<ModelKeys>& models) {
  std::vector<common::TomlOverride> scene;
  for (const common::TomlOverride& s : c.settings) {
    if (s.key.rfind(kModelPrefix, 0) != 0) {
      scene.push_back(s);
      continue;
    }
    const std::size_t dot = s.key.find('.', std::strlen(kModelPrefix));
    const std::string body = s.key.substr(std::strlen(kModelPrefix), dot - std::strlen(kModelPrefix));
    auto it = std::find_if(models.begin(), models.end(), [&](const ModelKeys& m) { return m.body == body; });
    if (it == models.end()) it = models.insert(models.end(), ModelKeys{body, {}});
    it->settings.push_back({s.key.substr(dot + 1), s.value});
  }
  return scene;
}

}  // namespace

CaseScene case_scene(const Study& study, const Case& c, const std::string& study_dir) {
  std::vector<ModelKeys> models;
  CaseScene out{split(c, models), {}};
  if (models.empty()) return out;
  const run::Scene scene = run::read_scene_file(study.scene_file, out.settings);
  for (const ModelKeys& keys : models) {
    int index = 0;  // among the [[flexible_body]] tables, which come first in scene.bodies
    const run::BodySpec* body = nullptr;
    for (const run::BodySpec& b : scene.bodies) {
      if (b.rigid) continue;
      if (b.name == keys.body) {
        body = &b;
        break;
      }
      ++index;
    }
    if (!body) throw format::InputError(study.file, "parameter", "model." + keys.body + ": the scene has no flexible body '" + keys.body + "'");
    if (body->model_file.empty())
      throw format::InputError(study.file, "parameter", "model." + keys.body + ": body '" + keys.body + "' names no model file in the scene");
    const ModelCopy copy = model_copy(study, body->model_file, keys, study_dir);
    const std::string at = "flexible_body." + std::to_string(index) + ".";
    out.settings.push_back({at + "model", toml_string(copy.model)});
    if (!body->adaptive)  // its SID beside the copy, built from it once (an adaptive body's come from the run's cache)
      out.settings.push_back({at + "sid", toml_string(copy.sid)});
    out.model_copies.push_back(copy.model);
  }
  return out;
}

}  // namespace isosid::sweep
