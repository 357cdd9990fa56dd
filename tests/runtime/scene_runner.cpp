// Test helpers running isosid-run; see scene_runner.hpp.
#include "scene_runner.hpp"

#include <catch2/catch.hpp>
#include <cmath>
#include <filesystem>
#include <fstream>
#include <iterator>

namespace isosid::test {

namespace {
nlohmann::json run_file(const ScratchDir& dir, const std::string& scene, int expected_status) {
  const auto r = run_program("ISOSID_PREP=" + std::string(ISOSID_PREP_EXE) + " " + ISOSID_RUN_EXE + " -q --json " +
                             dir.path(scene) + " -o " + dir.path("out-" + scene));
  INFO(r.err);
  REQUIRE(r.exit_status == expected_status);
  return expected_status == 0 ? nlohmann::json::parse(r.out) : nlohmann::json();
}
}  // namespace

nlohmann::json run_scene(const ScratchDir& dir, const std::string& text, int expected_status) {
  std::ofstream(dir.path("s.scene.toml")) << text;
  return run_file(dir, "s.scene.toml", expected_status);
}

void copy_model_file(const ScratchDir& dir, const std::string& file) {
  std::filesystem::copy_file(std::string(ISOSID_MODELS_DIR) + "/" + file, dir.path(file),
                             std::filesystem::copy_options::overwrite_existing);
}

nlohmann::json run_seed_scene(const ScratchDir& dir, const std::string& scene, const std::string& model) {
  copy_model_file(dir, scene);
  copy_model_file(dir, model);
  return run_file(dir, scene, 0);
}

std::string model_text(const std::string& file) {
  std::ifstream in(std::string(ISOSID_MODELS_DIR) + "/" + file);
  return std::string((std::istreambuf_iterator<char>(in)), std::istreambuf_iterator<char>());
}

double rel_error(const nlohmann::json& s, const std::string& key) {
  return std::abs(s["reference"][key]["rel_error"].get<double>());  // summary.json's errors are signed
}

}  // namespace isosid::test
