// What --version prints: the project's version (CMake's project version) and the git commit
// the build was configured from, if it was configured in a git checkout.
#pragma once
#include <string>

namespace isosid::common {

/// "<program> <version>", with " (git <commit>)" if the commit is known.
std::string version_line(const std::string& program);

}  // namespace isosid::common
