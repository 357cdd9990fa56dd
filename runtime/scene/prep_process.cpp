// Running isosid-prep; see prep_process.hpp.
#include "scene/prep_process.hpp"

#include "scene/sid_digest.hpp"

#include "isosid/format/error.hpp"

#include <algorithm>
#include <cerrno>
#include <csignal>
#include <cstdio>
#include <cstdlib>
#include <cstring>
#include <fcntl.h>
#include <filesystem>
#include <poll.h>
#include <sched.h>
#include <sys/wait.h>
#include <thread>
#include <unistd.h>
#include <utility>

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

PrepProcess::PrepProcess(pid_t pid_, int output_, std::string model_, std::string sid_, bool quiet_)
    : pid(pid_), output(output_), model(std::move(model_)), sid(std::move(sid_)), quiet(quiet_) {}

PrepProcess::PrepProcess(PrepProcess&& other) noexcept
    : pid(std::exchange(other.pid, -1)),
      output(std::exchange(other.output, -1)),
      model(std::move(other.model)),
      sid(std::move(other.sid)),
      quiet(other.quiet),
      pending(std::move(other.pending)) {}

namespace {
/// waitpid, again after a signal: the child's pid, or -1 with errno set.
pid_t reap(pid_t pid, int* status) {
  pid_t waited;
  while ((waited = ::waitpid(pid, status, 0)) < 0 && errno == EINTR) {
  }
  return waited;
}
}  // namespace

PrepProcess::~PrepProcess() {
  if (output >= 0) ::close(output);
  if (pid > 0) {  // abandoned: isosid-prep writes atomically, so stopping it leaves no half-written SID
    ::kill(pid, SIGTERM);
    reap(pid, nullptr);
  }
}

int usable_cores() {
  cpu_set_t set;
  CPU_ZERO(&set);
  if (::sched_getaffinity(0, sizeof set, &set) == 0) return std::max(1, CPU_COUNT(&set));
  return std::max(1, int(std::thread::hardware_concurrency()));
}

PrepProcess start_prep(const std::string& model, const std::string& sid, const std::vector<std::string>& extra, bool quiet,
                       const std::string& what, int threads) {
  const std::string prep = find_prep();
  if (!quiet) std::fprintf(stderr, "isosid-run: building %s from %s%s\n", sid.c_str(), model.c_str(), what.c_str());
  // everything the child needs is built before fork: only async-signal-safe calls after it
  std::vector<std::string> arguments = {prep, model};
  if (!sid.empty()) arguments.insert(arguments.end(), {"-o", sid});
  if (quiet) arguments.push_back("-q");
  arguments.insert(arguments.end(), extra.begin(), extra.end());
  std::vector<const char*> args;
  for (const std::string& a : arguments) args.push_back(a.c_str());
  args.push_back(nullptr);
  // this program's environment, plus OMP_NUM_THREADS and OPENBLAS_NUM_THREADS (the assembly's
  // threads, a large factorization's) where asked for and the user set none
  const std::string omp_threads = "OMP_NUM_THREADS=" + std::to_string(threads);
  const std::string blas_threads = "OPENBLAS_NUM_THREADS=" + std::to_string(threads);
  std::vector<const char*> env;
  for (char** v = environ; *v; ++v) env.push_back(*v);
  if (threads > 0 && !std::getenv("OMP_NUM_THREADS")) env.push_back(omp_threads.c_str());
  if (threads > 0 && !std::getenv("OPENBLAS_NUM_THREADS")) env.push_back(blas_threads.c_str());
  env.push_back(nullptr);
  const std::string cannot = "isosid-prep: failed: cannot execute " + prep + " (set ISOSID_PREP)\n";

  int channel[2];  // close-on-exec: a build started beside this one must not inherit its pipe
  if (::pipe2(channel, O_CLOEXEC) != 0) throw format::ComputationError("cannot start isosid-prep (no pipe)");
  const pid_t pid = ::fork();
  if (pid < 0) {
    ::close(channel[0]);
    ::close(channel[1]);
    throw format::ComputationError("cannot start isosid-prep");
  }
  if (pid == 0) {
    ::close(channel[0]);
    ::dup2(channel[1], STDERR_FILENO);  // dup2's copies are not close-on-exec
    ::dup2(channel[1], STDOUT_FILENO);  // isosid-run's stdout carries only its own output (--json)
    ::close(channel[1]);
    ::execvpe(prep.c_str(), const_cast<char* const*>(args.data()), const_cast<char* const*>(env.data()));
    [[maybe_unused]] const ssize_t written = ::write(STDERR_FILENO, cannot.data(), cannot.size());
    ::_exit(127);
  }
  ::close(channel[1]);
  return PrepProcess(pid, channel[0], model, sid, quiet);
}

namespace {
/// Passes the complete lines of `process`'s output read so far on (its error line kept in
/// `message`), all of it at the end (`last`).
void take_lines(PrepProcess& process, std::string& message, bool last) {
  std::size_t begin = 0;
  for (std::size_t end; begin < process.pending.size(); begin = end + 1) {
    end = process.pending.find('\n', begin);
    if (end == std::string::npos) {
      if (!last) break;
      end = process.pending.size();
    }
    const std::string text = process.pending.substr(begin, end - begin);
    for (const char* prefix : {"isosid-prep: error: ", "isosid-prep: failed: "})
      if (text.rfind(prefix, 0) == 0) message = text.substr(std::strlen(prefix));
    if (message.empty() && !process.quiet) std::fprintf(stderr, "%s\n", text.c_str());  // its report too: quiet is quiet
  }
  process.pending.erase(0, std::min(begin, process.pending.size()));
}
}  // namespace

void finish_prep(PrepProcess& process, const std::vector<PrepProcess*>& beside) {
  std::string message;  // the program's own "error:" or "failed:" line
  take_lines(process, message, false);  // what was read ahead while another was waited for
  while (process.output >= 0) {
    std::vector<PrepProcess*> readers{&process};
    std::vector<pollfd> fds{{process.output, POLLIN, 0}};
    for (PrepProcess* other : beside)
      if (other->output >= 0) {
        readers.push_back(other);
        fds.push_back({other->output, POLLIN, 0});
      }
    if (::poll(fds.data(), nfds_t(fds.size()), -1) < 0) {
      if (errno == EINTR) continue;
      break;
    }
    for (std::size_t i = 0; i < fds.size(); ++i) {
      if (fds[i].revents == 0) continue;
      if (fds[i].revents & POLLNVAL) {  // not open (any more): nothing to close
        readers[i]->output = -1;
        continue;
      }
      char chunk[65536];
      const ssize_t n = ::read(fds[i].fd, chunk, sizeof chunk);
      if (n > 0)
        readers[i]->pending.append(chunk, std::size_t(n));
      else if (n == 0 || (errno != EINTR && errno != EAGAIN))  // its end (the build closed its output by ending)
        ::close(std::exchange(readers[i]->output, -1));
    }
    take_lines(process, message, false);
  }
  take_lines(process, message, true);
  if (process.output >= 0) ::close(std::exchange(process.output, -1));
  int status = 0;
  const pid_t waited = reap(process.pid, &status);
  const int wait_error = errno;
  process.pid = -1;
  if (waited < 0) throw format::ComputationError("lost isosid-prep on " + process.model + " (waitpid: " + std::strerror(wait_error) + ")");
  const int code = WIFEXITED(status) ? WEXITSTATUS(status) : 1;
  const std::string& model = process.model;
  if (code == 2) {  // "file: field: problem", passed on as this program's own line
    const std::size_t colon = message.find(": ");
    if (colon == std::string::npos) throw format::InputError(model, "", "refused by isosid-prep: " + message);
    throw format::InputError(message.substr(0, colon), "", message.substr(colon + 2));
  }
  if (code != 0)
    throw format::ComputationError("isosid-prep failed on " + model + " (exit " + std::to_string(code) + ")" +
                                   (message.empty() ? "" : ": " + message));
  if (!process.sid.empty()) record_sid_digest(process.sid);
}

void run_prep(const std::string& model, const std::string& sid, const std::vector<std::string>& extra, bool quiet,
              const std::string& what) {
  PrepProcess process = start_prep(model, sid, extra, quiet, what);
  finish_prep(process);
}

void check_model(const std::string& model) {
  PrepProcess process = start_prep(model, "", {"--check"}, true, "");
  finish_prep(process);
}

}  // namespace isosid::run
