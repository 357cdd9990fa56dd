// SID loading and rebuilding; see sid_provider.hpp.
#include "scene/sid_provider.hpp"

#include "isosid/format/error.hpp"
#include "isosid/format/sid_io.hpp"

#include <cstdio>
#include <cstdlib>
#include <filesystem>
#include <sys/wait.h>
#include <unistd.h>

namespace isosid::run {
namespace fs = std::filesystem;

namespace {

/// isosid-prep: $ISOSID_PREP, else beside this program (install) or in the build tree, else PATH.
std::string find_prep() {
  if (const char* env = std::getenv("ISOSID_PREP")) return env;
  std::error_code ec;
  const fs::path self = fs::read_symlink("/proc/self/exe", ec);
  if (!ec) {
    for (const fs::path& candidate : {self.parent_path() / "isosid-prep", self.parent_path() / "../preprocess/isosid-prep"})
      if (fs::is_regular_file(candidate, ec)) return fs::weakly_canonical(candidate).string();
  }
  return "isosid-prep";
}

void run_prep(const std::string& model, const std::string& sid, bool quiet) {
  const std::string prep = find_prep();
  if (!quiet) std::fprintf(stderr, "isosid-run: building %s from %s\n", sid.c_str(), model.c_str());
  const pid_t pid = ::fork();
  if (pid < 0) throw format::ComputationError("cannot start isosid-prep");
  if (pid == 0) {
    ::dup2(STDERR_FILENO, STDOUT_FILENO);  // isosid-run's stdout carries only its own output (--json)
    std::vector<const char*> args = {prep.c_str(), model.c_str(), "-o", sid.c_str()};
    if (quiet) args.push_back("-q");
    args.push_back(nullptr);
    ::execvp(prep.c_str(), const_cast<char* const*>(args.data()));
    std::fprintf(stderr, "isosid-run: cannot execute %s (set ISOSID_PREP)\n", prep.c_str());
    ::_exit(127);
  }
  int status = 0;
  ::waitpid(pid, &status, 0);
  const int code = WIFEXITED(status) ? WEXITSTATUS(status) : 1;
  if (code == 2) throw format::InputError(model, "", "isosid-prep refused the model (see its message above)");
  if (code != 0) throw format::ComputationError("isosid-prep failed on " + model + " (exit " + std::to_string(code) + ")");
}

}  // namespace

std::vector<format::Sid> load_sids(const Scene& scene, bool quiet) {
  std::vector<format::Sid> sids;
  for (const BodySpec& b : scene.bodies) {
    if (b.rigid) continue;  // rigid bodies have no SID
    std::error_code ec;
    if (!b.model_file.empty()) {
      const bool stale = !fs::exists(b.sid_file, ec) || fs::last_write_time(b.sid_file, ec) < fs::last_write_time(b.model_file, ec);
      if (stale) run_prep(b.model_file, b.sid_file, quiet);
    }
    sids.push_back(format::read_sid(b.sid_file));
  }
  return sids;
}

}  // namespace isosid::run
