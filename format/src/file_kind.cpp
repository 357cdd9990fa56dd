// What stands at a path; see file_kind.hpp.
#include "isosid/format/file_kind.hpp"

#include "isosid/format/error.hpp"

#include <cerrno>
#include <cstring>
#include <sys/stat.h>

namespace isosid::format {
namespace {

/// What a stat(2) mode is, as the messages name it.
std::string noun(mode_t mode) {
  if (S_ISREG(mode)) return "a file";
  if (S_ISDIR(mode)) return "a directory";
  if (S_ISFIFO(mode)) return "a FIFO";
  if (S_ISSOCK(mode)) return "a socket";
  if (S_ISCHR(mode)) return "a character device";
  if (S_ISBLK(mode)) return "a block device";
  return "";
}

/// The problem of a path that exists (stat succeeded) but is no regular file.
std::string kind_problem(mode_t mode) {
  const std::string what = noun(mode);
  return what.empty() ? "is not a regular file" : "is " + what + ", not a file";
}

/// stat(2) of `path` with links followed: "" for a regular file, "missing" for nothing there
/// (not even a dangling link), otherwise the problem.
std::string classify(const std::string& path) {
  struct stat st {};
  if (::stat(path.c_str(), &st) == 0) return S_ISREG(st.st_mode) ? "" : kind_problem(st.st_mode);
  const int error = errno;
  if (error == ENOENT) {
    struct stat link {};
    return ::lstat(path.c_str(), &link) == 0 && S_ISLNK(link.st_mode) ? "is a symbolic link to a missing file" : "missing";
  }
  if (error == ENOTDIR) return "missing";  // a folder of the path is a file: nothing can be there
  if (error == ELOOP) return "too many levels of symbolic links";
  return std::string("cannot be read: ") + std::strerror(error);
}

}  // namespace

std::string what_is_at(const std::string& path) {
  struct stat st {};
  if (::stat(path.c_str(), &st) != 0) return "";
  const std::string what = noun(st.st_mode);
  return what.empty() ? "not a regular file" : what;
}

std::string input_file_problem(const std::string& path) {
  const std::string problem = classify(path);
  return problem == "missing" ? "file not found" : problem;
}

void require_input_file(const std::string& path) {
  if (const std::string problem = input_file_problem(path); !problem.empty()) throw InputError(path, "", problem);
}

std::string output_file_problem(const std::string& path) {
  const std::string problem = classify(path);
  return problem == "missing" ? "" : problem;
}

void require_output_file(const std::string& path) {
  if (const std::string problem = output_file_problem(path); !problem.empty())
    throw InputError(path, "", problem + "; an output replaces only a regular file");
}

}  // namespace isosid::format
