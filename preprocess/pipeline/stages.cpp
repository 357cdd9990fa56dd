// Progress observers of the pipeline's stages; see stages.hpp.
#include "pipeline/stages.hpp"

#include <cstdio>

namespace isosid::prep {

StageObserver& no_progress() {
  static StageObserver silent;
  return silent;
}

void StderrProgress::started(const std::string& /*stage*/, const std::string& what) {
  std::fprintf(stderr, "%s: %s ...\n", program_.c_str(), what.c_str());
}

void StderrProgress::finished(const std::string& stage, double seconds) {
  std::fprintf(stderr, "%s: %s done in %.3f s\n", program_.c_str(), stage.c_str(), seconds);
}

}  // namespace isosid::prep
