// Running isosid-prep; see prep_process.hpp.
#include "scene/prep_process.hpp"

#include "isosid/format/error.hpp"

#include <cstdio>
#include <cstdlib>
#include <cstring>
#include <filesystem>
#include <sys/wait.h>
#include <unistd.h>

namespace isosid::run {
namespace fs = std::filesystem;

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

void run_prep(const std::string& model, const std::string& sid, const std::vector<std::string>& extra, bool quiet,
              const std::string& what) {
  const std::string prep = find_prep();
  if (!quiet) std::fprintf(stderr, "isosid-run: building %s from %s%s\n", sid.c_str(), model.c_str(), what.c_str());
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
    for (const std::string& option : extra) args.push_back(option.c_str());
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
      if (message.empty() && !quiet) std::fprintf(stderr, "%s\n", text.c_str());  // its report too: quiet is quiet
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

}  // namespace isosid::run
