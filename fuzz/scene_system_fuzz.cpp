// Fuzz target: scenes with joints, rigid bodies and [adaptive] tables, followed past the reader
// into the system a run builds: the SIDs loaded, joints bound to their nodes and points,
// the initial and static start states, the refusals that need the bodies (vanishing penalty,
// unstable leapfrog step, unsteady spin, initial penetration) and the closed-at-end prediction.
// Nothing is integrated. Bad input must end in InputError; a start that cannot be computed
// in ComputationError (isosid-run's exit 1). The input is a scene in a folder holding the golden
// SIDs and models (fuzz/seeds/scene_system/ names them by file name); an adaptive scene stops
// after the reader (its models would be built by isosid-prep).
#include "fuzz_input.hpp"
#include "scene/scene.hpp"
#include "scene/sid_provider.hpp"
#include "solve/run_checks.hpp"
#include "solve/simulation.hpp"

#include <filesystem>

namespace {

/// A folder of this process with copies of the golden SIDs and models, removed at its exit.
struct SceneFolder {
  std::filesystem::path dir = "/tmp/isosid-fuzz-system-" + std::to_string(::getpid());
  SceneFolder() {
    std::filesystem::create_directories(dir);
    for (const char* file : {"sphere_small.sid.h5", "sphere_small.model.toml", "beam_small.sid.h5", "beam_small.model.toml"})
      std::filesystem::copy_file(std::filesystem::path(ISOSID_GOLDEN_DIR) / file, dir / file,
                                 std::filesystem::copy_options::overwrite_existing);
  }
  ~SceneFolder() {
    std::error_code ignored;
    std::filesystem::remove_all(dir, ignored);
  }
};

std::string scene_folder() {
  static const SceneFolder folder;
  return folder.dir.string();
}

}  // namespace

extern "C" int LLVMFuzzerTestOneInput(const std::uint8_t* data, std::size_t size) {
  const std::string path = scene_folder() + "/s.scene.toml";
  return isosid::fuzz::load_input_at(data, size, path, [](const std::string& file) {
    isosid::run::Scene scene = isosid::run::read_scene_file(file);
    if (scene.has_adaptive_bodies()) return;
    for (isosid::run::BodySpec& body : scene.bodies) body.model_file.clear();  // no isosid-prep: the SIDs as they are
    try {
      std::vector<isosid::format::Sid> sids = isosid::run::load_sids(scene, true);
      const isosid::run::Simulation simulation(std::move(scene), std::move(sids));
      isosid::run::closed_at_end_predictions(simulation.system(), simulation.time(), simulation.scene().simulation.end_time);
    } catch (const isosid::format::ComputationError&) {  // a start the solvers cannot find: exit 1, not a finding
    }
  });
}
