// All-or-nothing output files: write to a temporary file beside the target, then rename.
// A failed or interrupted write never leaves a half-written file at the target path.
#pragma once
#include <string>

namespace isosid::format {

class AtomicOutput {
public:
  /// Chooses a unique temporary path in the folder of `target` (same file system, so the
  /// final rename is atomic). Throws InputError if that folder does not exist, or if
  /// `target` is anything but a regular file or nothing (a directory, a FIFO, a device
  /// node, a socket, a dangling link or a link to one of those): renaming onto it would
  /// replace it. A symbolic link to a regular file is written through.
  explicit AtomicOutput(std::string target);
  AtomicOutput(const AtomicOutput&) = delete;
  AtomicOutput& operator=(const AtomicOutput&) = delete;
  /// Removes the temporary file unless commit() succeeded.
  ~AtomicOutput();

  const std::string& temp_path() const { return temp_; }
  const std::string& target() const { return target_; }
  /// Flushes the temporary file to disk and renames it onto the target (checked again).
  void commit();

private:
  std::string target_;
  std::string destination_;  ///< the target, or the regular file it links to
  std::string temp_;
  bool committed_ = false;
  int slot_ = -1;  ///< where the temporary path is registered for the signal handler
};

/// Makes SIGINT, SIGTERM and SIGHUP remove every temporary file of a live AtomicOutput, print
/// "<program>: interrupted by <signal>; nothing was written" and exit 130 / 143 / 129. For
/// programs whose output only makes sense complete (isosid-prep); isosid-run stops at a
/// sample instead and keeps its results.
void remove_temporaries_on_signals(const char* program);

/// Writes `text` to `path` through an AtomicOutput.
void write_text_atomically(const std::string& path, const std::string& text);

}  // namespace isosid::format
