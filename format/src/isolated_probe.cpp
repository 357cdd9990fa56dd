// Reading an untrusted file in a child process first; see isolated_probe.hpp.
#include "isosid/format/isolated_probe.hpp"

#include "isosid/format/error.hpp"

#include <cerrno>
#include <fcntl.h>
#include <csignal>
#include <cstring>
#include <fstream>
#include <new>
#include <sys/resource.h>
#include <sys/wait.h>
#include <thread>
#include <unistd.h>

#if defined(__SANITIZE_ADDRESS__)
#define ISOSID_UNDER_ASAN 1
#elif defined(__has_feature)
#if __has_feature(address_sanitizer)
#define ISOSID_UNDER_ASAN 1
#endif
#endif

#ifdef ISOSID_UNDER_ASAN
#include <sanitizer/common_interface_defs.h>
#endif

namespace isosid::format {
namespace {
enum ChildExit { kRead = 0, kBadInput = 2, kOutOfMemory = 3, kOtherError = 4 };

/// The process's virtual memory now, bytes (from /proc; 0 if unknown).
long long virtual_memory() {
  std::ifstream statm("/proc/self/statm");
  long long pages = 0;
  statm >> pages;
  return pages * sysconf(_SC_PAGESIZE);
}
}  // namespace

void probe_in_child(const std::string& path, const std::function<void()>& read) {
  const long long limit = virtual_memory() + kProbeMemoryBytes;
  const pid_t child = fork();
  if (child < 0) return;  // no child to spare: read unprobed rather than not at all
  if (child == 0) {
    // silent: a crash report (a sanitizer's) must not add lines to the program's one-line message
    const int null = open("/dev/null", O_WRONLY);
    if (null >= 0) dup2(null, STDERR_FILENO), dup2(null, STDOUT_FILENO);
    // a fault kills the child plainly: the parent's handlers (a sanitizer's, a fuzzer's that
    // would record the input as its own crash) have no business here
    for (const int signal : {SIGSEGV, SIGBUS, SIGABRT, SIGFPE, SIGILL, SIGTRAP}) std::signal(signal, SIG_DFL);
#ifdef ISOSID_UNDER_ASAN
    __sanitizer_set_death_callback(nullptr);  // nor a sanitizer's death callback (libFuzzer records inputs there)
#endif
#ifndef ISOSID_UNDER_ASAN  // AddressSanitizer reserves terabytes of address space up front
    const rlimit memory{rlim_t(limit), rlim_t(limit)};
    setrlimit(RLIMIT_AS, &memory);
#endif
    int status = kRead;
    try {
      read();
    } catch (const InputError&) {
      status = kBadInput;
    } catch (const std::bad_alloc&) {
      status = kOutOfMemory;
    } catch (...) {
      status = kOtherError;
    }
    _exit(status);  // no destructors, no HDF5 shutdown, no output of the parent's buffers
  }
  int status = 0;
  for (int waited_ms = 0;; waited_ms += 10) {
    const pid_t done = waitpid(child, &status, WNOHANG);
    if (done == child) break;
    if (done < 0 && errno != EINTR) return;
    if (waited_ms >= kProbeSeconds * 1000) {
      kill(child, SIGKILL);
      waitpid(child, &status, 0);
      throw InputError(path, "", "corrupt HDF5 file: reading it did not finish within " + std::to_string(kProbeSeconds) + " s");
    }
    std::this_thread::sleep_for(std::chrono::milliseconds(waited_ms < 100 ? 1 : 10));
  }
  if (WIFSIGNALED(status))
    throw InputError(path, "", std::string("corrupt HDF5 file: reading it crashed the HDF5 library (") + strsignal(WTERMSIG(status)) + ")");
  if (WIFEXITED(status) && WEXITSTATUS(status) == kOutOfMemory)
    throw InputError(path, "", "corrupt HDF5 file: its datasets claim more than " + std::to_string(kProbeMemoryBytes >> 20) +
                                   " MiB of memory");
  // any other way out (a sanitizer's exit code after a fault) is a crash too
  if (WIFEXITED(status) && WEXITSTATUS(status) != kRead && WEXITSTATUS(status) != kBadInput && WEXITSTATUS(status) != kOtherError)
    throw InputError(path, "", "corrupt HDF5 file: reading it failed inside the HDF5 library (exit " +
                                   std::to_string(WEXITSTATUS(status)) + ")");
}

}  // namespace isosid::format
