// Runs a scene file through the installed isosid library (what find_package(isosid) gives a
// program of one's own) and prints its first contact's peak force to the last digit.
#include "output/run_folder.hpp"
#include "pipeline/run_scene.hpp"

#include <cstdio>
#include <exception>
#include <utility>

int main(int argc, char** argv) {
  if (argc != 3) {
    std::fprintf(stderr, "usage: run_scene SCENE RESULTS_FOLDER\n");
    return 2;
  }
  try {
    isosid::run::Scene scene = isosid::run::read_scene_file(argv[1]);
    isosid::run::RunFolder folder(argv[2], scene);
    const isosid::run::RunResult result = isosid::run::run_scene(std::move(scene), folder, {.quiet = true});
    std::printf("%.17g\n", result.summary["contacts"][0]["peak_force_n"].get<double>());
    return result.outcome.completed() ? 0 : 1;
  } catch (const std::exception& e) {
    std::fprintf(stderr, "run_scene: %s\n", e.what());
    return 1;
  }
}
