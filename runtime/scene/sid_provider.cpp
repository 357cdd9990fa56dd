// SID loading and rebuilding; see sid_provider.hpp.
#include "scene/sid_provider.hpp"

#include "isosid/format/error.hpp"
#include "isosid/format/sid_io.hpp"

#include <cstdio>
#include <cstdlib>
#include <cstring>
#include <filesystem>
#include <sys/wait.h>
#include <unistd.h>
#include <vector>

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

/// Runs isosid-prep on `model` (with --contact-radius if `contact_radius` > 0). Its progress
/// lines pass through to stderr; its one-line error is held back and becomes this program's
/// one line (exit 2 for a refused model).
void run_prep(const std::string& model, const std::string& sid, bool quiet, double contact_radius = 0) {
  const std::string prep = find_prep();
  char radius[32];
  std::snprintf(radius, sizeof radius, "%.17g", contact_radius);
  if (!quiet)
    std::fprintf(stderr, "isosid-run: building %s from %s%s%s\n", sid.c_str(), model.c_str(),
                 contact_radius > 0 ? " for a contact radius of " : "", contact_radius > 0 ? radius : "");
  int channel[2];
  if (::pipe(channel) != 0) throw format::ComputationError("cannot start isosid-prep (no pipe)");
  const pid_t pid = ::fork();
  if (pid < 0) throw format::ComputationError("cannot start isosid-prep");
  if (pid == 0) {
    ::close(channel[0]);
    ::dup2(channel[1], STDERR_FILENO);
    ::dup2(channel[1], STDOUT_FILENO);  // isosid-run's stdout carries only its own output (--json)
    ::close(channel[1]);
    std::vector<const char*> args = {prep.c_str(), model.c_str(), "-o", sid.c_str()};
    if (quiet) args.push_back("-q");
    if (contact_radius > 0) args.insert(args.end(), {"--contact-radius", radius});
    args.push_back(nullptr);
    ::execvp(prep.c_str(), const_cast<char* const*>(args.data()));
    std::fprintf(stderr, "isosid-prep: failed: cannot execute %s (set ISOSID_PREP)\n", prep.c_str());
    ::_exit(127);
  }
  ::close(channel[1]);
  std::string message;  // the program's own "error:" or "failed:" line
  if (FILE* output = ::fdopen(channel[0], "r")) {
    char* line = nullptr;
    std::size_t capacity = 0;
    for (ssize_t n; (n = ::getline(&line, &capacity, output)) > 0;) {
      std::string text(line, std::size_t(n));
      if (text.back() == '\n') text.pop_back();
      for (const char* prefix : {"isosid-prep: error: ", "isosid-prep: failed: "})
        if (text.rfind(prefix, 0) == 0) message = text.substr(std::strlen(prefix));
      if (message.empty()) std::fprintf(stderr, "%s\n", text.c_str());
    }
    std::free(line);
    std::fclose(output);
  }
  int status = 0;
  ::waitpid(pid, &status, 0);
  const int code = WIFEXITED(status) ? WEXITSTATUS(status) : 1;
  if (code == 2) {  // "file: field: problem", passed on as this program's own line
    const std::size_t colon = message.find(": ");
    if (colon == std::string::npos) throw format::InputError(model, "", "refused by isosid-prep: " + message);
    throw format::InputError(message.substr(0, colon), "", message.substr(colon + 2));
  }
  if (code != 0)
    throw format::ComputationError("isosid-prep failed on " + model + " (exit " + std::to_string(code) + ")" +
                                   (message.empty() ? "" : ": " + message));
}

}  // namespace

format::ReadOptions sid_read_options(const Scene& scene) {
  format::ReadOptions options;
  options.visual = scene.output.paraview;
  return options;
}

std::vector<format::Sid> load_sids(const Scene& scene, bool quiet) {
  std::vector<format::Sid> sids;
  for (const BodySpec& b : scene.bodies) {
    if (b.rigid) continue;  // rigid bodies have no SID
    std::error_code ec;
    if (!b.model_file.empty()) {
      const bool stale = !fs::exists(b.sid_file, ec) || fs::last_write_time(b.sid_file, ec) < fs::last_write_time(b.model_file, ec);
      if (stale) run_prep(b.model_file, b.sid_file, quiet);
    }
    sids.push_back(format::read_sid(b.sid_file, sid_read_options(scene)));
  }
  return sids;
}

format::Sid rebuild_sid(const Scene& scene, const BodySpec& body, double contact_radius, bool quiet) {
  run_prep(body.model_file, body.sid_file, quiet, contact_radius);
  return format::read_sid(body.sid_file, sid_read_options(scene));
}

}  // namespace isosid::run
