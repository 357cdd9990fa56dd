// The adaptive run; see adaptive_run.hpp (its phases: adaptive_phases.hpp).
#include "adapt/adaptive_run.hpp"

#include "adapt/adaptive_phases.hpp"
#include "isosid/format/error.hpp"

namespace isosid::run {

AdaptiveRun::AdaptiveRun(Scene scene, RunFolder& folder, bool quiet)
    : scene_(std::move(scene)), folder_(folder), out_dir_(folder.path()), quiet_(quiet) {
  if (!scene_.hertz_contacts.empty())  // the phases' results would be joined without them
    throw format::InputError(scene_.file, "hertz_contact", "Hertz contacts in runs with adaptive bodies are not available yet");
}

AdaptiveRun::Result AdaptiveRun::run(const std::function<bool()>& stop_requested) {
  return AdaptivePhases(scene_, folder_, out_dir_, quiet_, stop_requested).run();
}

}  // namespace isosid::run
