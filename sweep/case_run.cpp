// Running one case; see case_run.hpp.
#include "case_run.hpp"

#include "isosid/format/error.hpp"
#include "model_settings.hpp"
#include "output/run_folder.hpp"
#include "pipeline/run_scene.hpp"
#include "scene/prep_process.hpp"
#include "study_table.hpp"

#include <charconv>
#include <map>
#include <new>

namespace isosid::sweep {
namespace {

nlohmann::json settings_of(const Case& c) {
  nlohmann::json out = nlohmann::json::object();
  for (const common::TomlOverride& s : c.settings) out[s.key] = s.value;
  return out;
}

nlohmann::json row_of(const Case& c, const std::string& status, int exit_class, const std::string& message) {
  return {{"case", c.index}, {"settings", settings_of(c)}, {"status", status}, {"exit_class", exit_class}, {"message", message},
          {"collected", nlohmann::json::object()}, {"wall_time_s", nullptr}, {"cpu_time_s", nullptr},
          {"program_version", nullptr}, {"inputs", nlohmann::json::array()}};
}

}  // namespace

std::string case_input_problem(const Study& study, const Case& c, const std::string& study_dir) {
  static std::map<std::string, std::string> checked;  // model copy -> its problem: each checked once
  try {
    const CaseScene scene = case_scene(study, c, study_dir);
    run::read_scene_file(study.scene_file, scene.settings);
    for (const std::string& copy : scene.model_copies) {
      if (!checked.count(copy)) {
        try {
          run::check_model(copy);
          checked[copy] = "";
        } catch (const format::InputError& e) {
          checked[copy] = e.what();
        }
      }
      if (!checked[copy].empty()) return checked[copy];
    }
    return "";
  } catch (const format::InputError& e) {
    return e.what();
  }
}

nlohmann::json refused_case(const Case& c, const std::string& message) { return row_of(c, "bad input", 2, message); }

nlohmann::json value_at(const nlohmann::json& summary, const std::string& path) {
  const nlohmann::json* at = &summary;
  std::size_t start = 0;
  for (;;) {
    const std::size_t dot = path.find('.', start);
    const std::string part = path.substr(start, dot == std::string::npos ? std::string::npos : dot - start);
    if (at->is_object()) {
      if (!at->contains(part)) return nullptr;
      at = &(*at)[part];
    } else if (at->is_array()) {
      const nlohmann::json* found = nullptr;
      std::size_t index = 0;
      const auto [end, error] = std::from_chars(part.data(), part.data() + part.size(), index);
      if (error == std::errc() && end == part.data() + part.size() && index < at->size()) found = &(*at)[index];
      for (const nlohmann::json& e : *at)
        if (!found && e.is_object() && ((e.contains("name") && e["name"] == part) || (e.contains("label") && e["label"] == part))) found = &e;
      if (!found) return nullptr;
      at = found;
    } else {
      return nullptr;
    }
    if (dot == std::string::npos) return *at;
    start = dot + 1;
  }
}

std::vector<std::string> default_collect(const Study& study) {
  std::vector<std::string> out;
  for (const run::ContactSpec& c : run::read_scene_file(study.scene_file).contacts)
    for (const char* figure : {"peak_force_n", "duration_s", "impulse_ns"}) out.push_back("contacts." + c.name + "." + figure);
  return out;
}

nlohmann::json run_case(const Study& study, const Case& c, const std::string& study_dir, const std::vector<std::string>& collect,
                        const std::function<bool()>& stop_requested) {
  try {
    const std::string folder = case_folder(study_dir, c.index);
    run::Scene scene = run::read_scene_file(study.scene_file, case_scene(study, c, study_dir).settings);
    run::RunFolder results(folder, scene);
    const run::RunResult result = run::run_scene(std::move(scene), results, {true, stop_requested});
    if (!result.started || result.outcome.status == "interrupted") return row_of(c, "interrupted", 130, "");
    nlohmann::json row = row_of(c, result.outcome.status, result.outcome.completed() ? 0 : 1, result.outcome.failure);
    for (const std::string& path : collect) row["collected"][path] = value_at(result.summary, path);
    row["wall_time_s"] = result.summary.value("wall_time_s", 0.0);
    row["cpu_time_s"] = result.summary.value("cpu_time_s", 0.0);
    if (result.summary.contains("provenance")) {
      row["program_version"] = result.summary["provenance"]["program_version"];
      row["inputs"] = result.summary["provenance"]["inputs"];
    }
    return row;
  } catch (const format::InputError& e) {
    return row_of(c, "bad input", 2, e.what());
  } catch (const std::bad_alloc&) {
    return row_of(c, "failed", 1, "out of memory");
  } catch (const std::exception& e) {
    return row_of(c, "failed", 1, e.what());
  }
}

}  // namespace isosid::sweep
