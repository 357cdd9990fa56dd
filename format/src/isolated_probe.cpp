// Reading an untrusted file in a child process first; see isolated_probe.hpp.
#include "isosid/format/isolated_probe.hpp"

#include "isosid/format/error.hpp"
#include "isosid/format/hdf5_file.hpp"

#include <algorithm>
#include <atomic>
#include <cerrno>
#include <chrono>
#include <fcntl.h>
#include <csignal>
#include <cstring>
#include <filesystem>
#include <fstream>
#include <new>
#include <sys/resource.h>
#include <sys/wait.h>
#include <thread>
#include <unistd.h>
#include <vector>

#ifdef ISOSID_UNDER_ASAN
#include <sanitizer/common_interface_defs.h>
#endif

namespace isosid::format {
namespace {
enum ChildExit { kRead = 0, kBadInput = 2, kOutOfMemory = 3, kOtherError = 4 };

/// The child's InputError crosses the pipe as its three parts, each ended by a NUL.
void send_input_error(int fd, const InputError& e) {
  std::string text = e.file() + '\0' + e.field() + '\0' + e.problem().substr(0, 2000) + '\0';
  for (std::size_t sent = 0; sent < text.size();) {
    const ssize_t n = write(fd, text.data() + sent, text.size() - sent);
    if (n <= 0) return;
    sent += std::size_t(n);
  }
}

/// The parts sent by send_input_error, read once the child has exited (empty if none).
std::vector<std::string> receive_input_error(int fd) {
  std::string text;
  char buffer[4096];
  for (ssize_t n; (n = read(fd, buffer, sizeof buffer)) > 0;) text.append(buffer, std::size_t(n));
  std::vector<std::string> parts;
  for (std::size_t start = 0, end; (end = text.find('\0', start)) != std::string::npos; start = end + 1)
    parts.push_back(text.substr(start, end - start));
  return parts;
}

#ifndef ISOSID_UNDER_ASAN
/// The process's virtual memory now, bytes (from /proc; 0 if unknown).
long long virtual_memory() {
  std::ifstream statm("/proc/self/statm");
  long long pages = 0;
  statm >> pages;
  return pages * sysconf(_SC_PAGESIZE);
}
#endif
}  // namespace

long long probe_memory_bytes(std::uintmax_t file_bytes) {
  const long double bytes = kProbeBaseMemoryBytes + 3 * h5::most_data_bytes(file_bytes);
  return bytes > 1e18L ? (long long)1e18 : (long long)bytes;
}

int probe_seconds(std::uintmax_t file_bytes) {
  return kProbeBaseSeconds + int(std::min(1e6, double(file_bytes) / kProbeSlowestBytesPerSecond));
}

namespace {
std::atomic<long> started{0};
}  // namespace

long probes_started() { return started.load(); }

void probe_in_child(const std::string& path, const std::function<void()>& read_file) {
  ++started;
  std::error_code ec;
  const std::uintmax_t file_bytes = std::filesystem::file_size(path, ec);
  const long long allowance = probe_memory_bytes(ec ? 0 : file_bytes);
  const int seconds = probe_seconds(ec ? 0 : file_bytes);
  int message[2];
  if (pipe2(message, O_CLOEXEC) != 0) return;  // no pipe to spare: read unprobed rather than not at all
  const pid_t child = fork();
  if (child < 0) {
    close(message[0]), close(message[1]);
    return;
  }
  if (child == 0) {
    close(message[0]);
    // none of the parent's descriptors but the pipe: a lock the parent holds (a results folder's,
    // a study's) must end with the parent, not with a probe still reading when the parent was killed
    if (message[1] > 3) close_range(3, unsigned(message[1]) - 1, 0);
    close_range(unsigned(message[1]) + 1, ~0U, 0);
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
    const long long limit = virtual_memory() + allowance;
    const rlimit memory{rlim_t(limit), rlim_t(limit)};
    setrlimit(RLIMIT_AS, &memory);
#endif
    int status = kRead;
    try {
      read_file();
    } catch (const InputError& e) {
      send_input_error(message[1], e);
      status = kBadInput;
    } catch (const std::bad_alloc&) {
      status = kOutOfMemory;
    } catch (...) {
      status = kOtherError;
    }
    _exit(status);  // no destructors, no HDF5 shutdown, no output of the parent's buffers
  }
  close(message[1]);
  int status = 0;
  const auto start = std::chrono::steady_clock::now(), deadline = start + std::chrono::seconds(seconds);
  for (;;) {
    const pid_t done = waitpid(child, &status, WNOHANG);
    if (done == child) break;
    if (done < 0 && errno != EINTR) {
      close(message[0]);
      return;
    }
    const auto now = std::chrono::steady_clock::now();
    if (now >= deadline) {
      kill(child, SIGKILL);
      waitpid(child, &status, 0);
      close(message[0]);
      throw InputError(path, "", "corrupt HDF5 file: reading it did not finish within " + std::to_string(seconds) + " s");
    }
    // most reads end within milliseconds: poll often at first
    std::this_thread::sleep_for(std::chrono::milliseconds(now - start < std::chrono::milliseconds(100) ? 1 : 10));
  }
  const std::vector<std::string> error = receive_input_error(message[0]);
  close(message[0]);
  if (WIFSIGNALED(status))
    throw InputError(path, "", std::string("corrupt HDF5 file: reading it crashed the HDF5 library (") + strsignal(WTERMSIG(status)) + ")");
  if (WIFEXITED(status) && WEXITSTATUS(status) == kOutOfMemory)
    throw InputError(path, "", "corrupt HDF5 file: reading it needs more than " + std::to_string(allowance >> 20) +
                                   " MiB of memory, more than a file of its size can hold");
  if (WIFEXITED(status) && WEXITSTATUS(status) == kBadInput && error.size() == 3) throw InputError(error[0], error[1], error[2]);
  // any other way out (a sanitizer's exit code after a fault) is a crash too
  if (WIFEXITED(status) && WEXITSTATUS(status) != kRead && WEXITSTATUS(status) != kOtherError)
    throw InputError(path, "", "corrupt HDF5 file: reading it failed inside the HDF5 library (exit " +
                                   std::to_string(WEXITSTATUS(status)) + ")");
}

}  // namespace isosid::format
