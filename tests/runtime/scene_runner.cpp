// Test helpers running scenes; see scene_runner.hpp.
#include "scene_runner.hpp"

#include "isosid/common/cli_guard.hpp"
#include "output/run_folder.hpp"
#include "pipeline/run_scene.hpp"

#include <catch2/catch.hpp>
#include <cmath>
#include <cstdlib>
#include <filesystem>
#include <fstream>
#include <iterator>

namespace isosid::test {

namespace {
/// The scene file run in this process through the pipeline isosid-run calls (run::run_scene),
/// its exit status as isosid-run would give it; the command line's own exit codes, signals
/// and messages are tested on the program itself (run_program).
nlohmann::json run_file(const ScratchDir& dir, const std::string& scene, int expected_status) {
  setenv("ISOSID_PREP", ISOSID_PREP_EXE, 1);  // models are prepared by this build's isosid-prep
  nlohmann::json summary;
  const int status = common::run_guarded("isosid-run", [&] {
    run::Scene parsed = run::read_scene_file(dir.path(scene));
    run::RunFolder folder(dir.path("out-" + scene), parsed);
    const run::RunResult result = run::run_scene(std::move(parsed), folder, run::RunOptions{true});
    summary = result.summary;
    return result.outcome.completed() ? 0 : common::kExitFailure;
  });
  REQUIRE(status == expected_status);
  return expected_status == 0 ? summary : nlohmann::json();
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

std::string coarse_sphere_impactor_text() {
  std::string text = model_text("sphere_impactor_macneal.model.toml");
  for (int direction = 0; direction < 2; ++direction)  // along the surface and in depth
    text = replace(text, "smallest = 0.03e-3\ngrowth = 1.1", "smallest = 0.14e-3\ngrowth = 1.6");
  return text;
}

void write_coarse_sphere_impactor(const ScratchDir& dir) {
  std::ofstream(dir.path("sphere_impactor_macneal.model.toml")) << coarse_sphere_impactor_text();
}

double rel_error(const nlohmann::json& s, const std::string& key) {
  return std::abs(s["reference"][key]["rel_error"].get<double>());  // summary.json's errors are signed
}

}  // namespace isosid::test
