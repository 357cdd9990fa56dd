// What stands at a path, for the programs' refusals: an input must be a regular file (a FIFO
// would block its reader, a directory or a device is no SID or model), and an output may
// only replace a regular file (renaming onto a device node or a FIFO would replace it).
#pragma once
#include <string>

namespace isosid::format {

/// What stands at `path` (links followed), as messages name it: "a file", "a directory", "a
/// FIFO", "a socket", "a character device", "a block device"; "" if nothing does.
std::string what_is_at(const std::string& path);

/// Empty if `path` names a regular file (symbolic links followed); otherwise the problem, as
/// InputError's: "file not found", "is a directory, not a file", "is a FIFO, not a file",
/// "is a socket, not a file", "is a character device, not a file", "too many levels of
/// symbolic links", "is a symbolic link to a missing file", "cannot be read: <reason>".
std::string input_file_problem(const std::string& path);

/// Throws InputError(path, "", problem) unless input_file_problem(path) is empty.
void require_input_file(const std::string& path);

/// Empty if an output may be written at `path`: nothing is there, or a regular file
/// (symbolic links followed) is; otherwise the problem, as above.
std::string output_file_problem(const std::string& path);

/// Throws InputError(path, "", problem) unless output_file_problem(path) is empty: what the
/// programs check of an output before any work, and AtomicOutput before it renames.
void require_output_file(const std::string& path);

}  // namespace isosid::format
