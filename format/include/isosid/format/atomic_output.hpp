// All-or-nothing output files: write to a temporary file beside the target, then rename.
// A failed or interrupted write never leaves a half-written file at the target path.
#pragma once
#include <string>

namespace isosid::format {

class AtomicOutput {
public:
  /// Chooses a unique temporary path in the folder of `target` (same file system, so the
  /// final rename is atomic). Throws InputError if that folder does not exist.
  explicit AtomicOutput(std::string target);
  AtomicOutput(const AtomicOutput&) = delete;
  AtomicOutput& operator=(const AtomicOutput&) = delete;
  /// Removes the temporary file unless commit() succeeded.
  ~AtomicOutput();

  const std::string& temp_path() const { return temp_; }
  const std::string& target() const { return target_; }
  /// Flushes the temporary file to disk and renames it onto the target.
  void commit();

private:
  std::string target_, temp_;
  bool committed_ = false;
};

/// Writes `text` to `path` through an AtomicOutput.
void write_text_atomically(const std::string& path, const std::string& text);

}  // namespace isosid::format
