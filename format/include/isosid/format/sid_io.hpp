// Reading and writing SID files (HDF5). The layout is documented in format/README.md.
#pragma once
#include "isosid/format/sid.hpp"

#include <functional>
#include <string>

namespace isosid::format {

/// Schema version written to /isosid/version; a reader refuses any other major version.
constexpr int kSchemaVersion = 1;

struct WriteOptions {
  /// Called before each part is written (for progress reports); may throw to abort the write.
  std::function<void(const std::string& part)> on_part;
};

/// Validates `sid` and writes it atomically: a temporary file in the target's folder is
/// renamed onto `path` only after everything was written, so a failed or interrupted
/// write never leaves a half-written file at `path`. Throws InputError on invalid data.
void write_sid(const Sid& sid, const std::string& path, const WriteOptions& options = {});

struct ReadOptions {
  /// Read the viewing mesh (/visual) if there is one: the largest part of a SID built with
  /// [visual], needed only for ParaView output.
  bool visual = true;
  /// Read the file first in a child process (isolated_probe.hpp), which is what keeps a
  /// corrupt file from crashing the program. Off only for a file the caller knows byte for
  /// byte (the runtime's record of the SIDs its preparation wrote, runtime/scene/sid_digest).
  bool probe = true;
};

/// Reads and validates a SID. Throws InputError naming the file, dataset and problem.
Sid read_sid(const std::string& path, const ReadOptions& options = {});

}  // namespace isosid::format
