// Running scenes from tests, in process through the library's pipeline: scenes given as text or
// copied from models/, SIDs built from their model files through isosid-prep (ISOSID_PREP).
#pragma once
#include "support/run_program.hpp"
#include "support/scene_text.hpp"

#include <nlohmann/json.hpp>
#include <string>

namespace isosid::test {

/// Writes `text` as dir/s.scene.toml, runs it and returns its summary (null unless it
/// succeeded); `expected_status`: the exit status isosid-run would give (2 bad input, 1 failed).
nlohmann::json run_scene(const ScratchDir& dir, const std::string& text, int expected_status = 0);
/// Copies a file of models/ into dir.
void copy_model_file(const ScratchDir& dir, const std::string& file);
/// Copies a scene of models/ and its model into dir and runs it.
nlohmann::json run_seed_scene(const ScratchDir& dir, const std::string& scene, const std::string& model);
/// The text of a file of models/.
std::string model_text(const std::string& file);
/// The sphere of the sphere-on-beam scenes (models/sphere_impactor_macneal.model.toml) with its
/// contact elements at 0.14 mm growing by 1.6, about a/2 of those impacts, instead of the shipped
/// a/8 growing by 1.1: seconds to prepare where the shipped mesh takes a minute and 3 GB. The
/// runtime's contact paths are tested on it.
std::string coarse_sphere_impactor_text();
/// Writes it into dir as sphere_impactor_macneal.model.toml.
void write_coarse_sphere_impactor(const ScratchDir& dir);
/// The size of the relative error of a [reference] value in a summary (stored signed).
double rel_error(const nlohmann::json& summary, const std::string& key);

}  // namespace isosid::test
