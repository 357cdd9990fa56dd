// Temporary-file-and-rename output; see atomic_output.hpp.
#include "isosid/format/atomic_output.hpp"

#include "isosid/format/error.hpp"

#include <atomic>
#include <fcntl.h>
#include <filesystem>
#include <fstream>
#include <unistd.h>

namespace isosid::format {
namespace fs = std::filesystem;

AtomicOutput::AtomicOutput(std::string target) : target_(std::move(target)) {
  const fs::path t(target_);
  const fs::path dir = t.has_parent_path() ? t.parent_path() : fs::path(".");
  std::error_code ec;
  if (!fs::is_directory(dir, ec)) throw InputError(target_, "", "output folder '" + dir.string() + "' does not exist");
  if (fs::is_directory(t, ec)) throw InputError(target_, "", "output path is a directory");
  static std::atomic<unsigned> counter{0};
  temp_ = (dir / ("." + t.filename().string() + ".tmp-" + std::to_string(::getpid()) + "-" +
                  std::to_string(counter++)))
              .string();
}

AtomicOutput::~AtomicOutput() {
  if (!committed_) {
    std::error_code ec;
    fs::remove(temp_, ec);
  }
}

void AtomicOutput::commit() {
  // fsync before rename: after a crash the target is either the old file or the complete new one.
  const int fd = ::open(temp_.c_str(), O_RDONLY);
  if (fd < 0) throw ComputationError(target_ + ": temporary file " + temp_ + " vanished before commit");
  const int synced = ::fsync(fd);
  ::close(fd);
  if (synced != 0) throw ComputationError(target_ + ": cannot flush temporary file to disk");
  std::error_code ec;
  fs::rename(temp_, target_, ec);
  if (ec) throw ComputationError(target_ + ": cannot rename temporary file onto target: " + ec.message());
  committed_ = true;
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
