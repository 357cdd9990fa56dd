// A lock file held with flock(2) for an object's lifetime: the kernel releases it when the
// process ends, also by a crash, so no stale lock outlives its holder.
#pragma once
#include <sys/file.h>

#include <cerrno>
#include <fcntl.h>
#include <unistd.h>

#include <string>

namespace isosid::common {

class FileLock {
public:
  enum class Mode {
    Shared,           ///< wait, beside other shared holders
    Exclusive,        ///< wait, alone
    ExclusiveOrNone,  ///< alone or not at all: held() says which
  };
  /// Opens (creating) `path` and locks it. A file that cannot be created holds no lock.
  FileLock(const std::string& path, Mode mode) : fd_(::open(path.c_str(), O_RDWR | O_CREAT | O_CLOEXEC, 0644)) {
    if (fd_ < 0) return;
    const int operation = mode == Mode::Shared ? LOCK_SH : mode == Mode::Exclusive ? LOCK_EX : LOCK_EX | LOCK_NB;
    held_ = lock(operation);
  }
  ~FileLock() {
    if (fd_ >= 0) ::close(fd_);
  }
  FileLock(const FileLock&) = delete;
  FileLock& operator=(const FileLock&) = delete;

  bool held() const { return held_; }
  /// From shared to exclusive (waiting): not atomic, so what the holder decided under the
  /// shared lock must be checked again.
  void make_exclusive() {
    if (fd_ >= 0) held_ = lock(LOCK_EX);
  }

private:
  /// flock, again after a signal interrupted the wait.
  bool lock(int operation) const {
    int result;
    while ((result = ::flock(fd_, operation)) != 0 && errno == EINTR) {
    }
    return result == 0;
  }

  int fd_ = -1;
  bool held_ = false;
};

}  // namespace isosid::common
