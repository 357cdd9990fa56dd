// Temporary-file-and-rename output; see atomic_output.hpp.
#include "isosid/format/atomic_output.hpp"

#include "isosid/format/error.hpp"
#include "isosid/format/file_kind.hpp"

#include <atomic>
#include <csignal>
#include <cstring>
#include <fcntl.h>
#include <filesystem>
#include <fstream>
#include <unistd.h>

namespace isosid::format {
namespace fs = std::filesystem;

namespace {
// Temporary paths of live outputs, readable from a signal handler: fixed buffers, claimed and
// released through atomic flags (a handler may only unlink, write and _exit)
constexpr int kSlots = 16;
constexpr std::size_t kPathBytes = 4096;
std::atomic<bool> g_used[kSlots];
char g_paths[kSlots][kPathBytes];
const char* g_program = "isosid";

int claim_slot(const std::string& path) {
  if (path.size() >= kPathBytes) return -1;
  for (int i = 0; i < kSlots; ++i) {
    bool expected = false;
    if (g_used[i].load() || !g_used[i].compare_exchange_strong(expected, true)) continue;
    std::memcpy(g_paths[i], path.c_str(), path.size() + 1);
    return i;
  }
  return -1;  // more live outputs than slots: that one is not cleaned on a signal
}

void write_all(const char* text) {
  for (std::size_t n = std::strlen(text); n > 0;) {
    const ssize_t w = ::write(STDERR_FILENO, text, n);
    if (w <= 0) return;
    text += w, n -= std::size_t(w);
  }
}

extern "C" void remove_temporaries_and_exit(int signal) {
  for (int i = 0; i < kSlots; ++i)
    if (g_used[i].load()) ::unlink(g_paths[i]);
  const char* name = signal == SIGINT ? "SIGINT" : signal == SIGTERM ? "SIGTERM" : signal == SIGHUP ? "SIGHUP" : "a signal";
  write_all(g_program);
  write_all(": interrupted by ");
  write_all(name);
  write_all("; nothing was written\n");
  ::_exit(128 + signal);
}
}  // namespace

void remove_temporaries_on_signals(const char* program) {
  g_program = program;
  for (int signal : {SIGINT, SIGTERM, SIGHUP}) std::signal(signal, remove_temporaries_and_exit);
}

AtomicOutput::AtomicOutput(std::string target) : target_(std::move(target)), destination_(target_) {
  require_output_file(target_);
  std::error_code ec;
  // a link to a regular file is written through: the file is replaced, the link stays
  if (fs::is_symlink(target_, ec)) destination_ = fs::canonical(target_).string();
  const fs::path t(destination_);
  const fs::path dir = t.has_parent_path() ? t.parent_path() : fs::path(".");
  if (!fs::is_directory(dir, ec)) throw InputError(target_, "", "output folder '" + dir.string() + "' does not exist");
  static std::atomic<unsigned> counter{0};
  temp_ = (dir / ("." + t.filename().string() + ".tmp-" + std::to_string(::getpid()) + "-" +
                  std::to_string(counter++)))
              .string();
  slot_ = claim_slot(temp_);
}

AtomicOutput::~AtomicOutput() {
  if (!committed_) {
    std::error_code ec;
    fs::remove(temp_, ec);
  }
  if (slot_ >= 0) g_used[slot_].store(false);
}

void AtomicOutput::commit() {
  // fsync before rename: after a crash the target is either the old file or the complete new one.
  const int fd = ::open(temp_.c_str(), O_RDONLY);
  if (fd < 0) throw ComputationError(target_ + ": temporary file " + temp_ + " vanished before commit");
  const int synced = ::fsync(fd);
  ::close(fd);
  if (synced != 0) throw ComputationError(target_ + ": cannot flush temporary file to disk");
  require_output_file(target_);  // what stands there may have changed while the output was written
  std::error_code ec;
  fs::rename(temp_, destination_, ec);
  if (ec) throw ComputationError(target_ + ": cannot rename temporary file onto target: " + ec.message());
  committed_ = true;
  if (slot_ >= 0) g_used[slot_].store(false), slot_ = -1;  // the target is complete: a signal now leaves it
}

void write_text_atomically(const std::string& path, const std::string& text) {
  AtomicOutput out(path);
  {
    std::ofstream f(out.temp_path(), std::ios::binary);
    f << text;
    if (!f.flush()) throw ComputationError(path + ": cannot write");
  }
  out.commit();
}

}  // namespace isosid::format
