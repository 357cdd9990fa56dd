// The results folder of one run; see run_folder.hpp.
#include "output/run_folder.hpp"

#include "isosid/format/atomic_output.hpp"
#include "isosid/format/error.hpp"
#include "isosid/format/file_kind.hpp"

#include <nlohmann/json.hpp>

#include <algorithm>
#include <cerrno>
#include <cstring>
#include <fcntl.h>
#include <filesystem>
#include <sys/file.h>
#include <unistd.h>

namespace isosid::run {
namespace fs = std::filesystem;
namespace {

/// Refuses a results folder that is no folder or cannot be written, or cannot be created.
void require_writable_folder(const std::string& dir) {
  const auto refuse = [&](const std::string& problem) { throw format::InputError("", "-o", dir + problem); };
  std::error_code ec;
  const fs::file_status status = fs::status(dir, ec);
  const bool missing = ec == std::errc::no_such_file_or_directory || ec == std::errc::not_a_directory;
  if (ec && !missing) refuse(": " + ec.message());
  if (status.type() == fs::file_type::directory) {
    if (::access(dir.c_str(), W_OK | X_OK) != 0) refuse(" is a folder this user cannot write");
    return;
  }
  if (!missing && status.type() != fs::file_type::not_found) refuse(" is " + format::what_is_at(dir) + ", not a results folder");
  // created at the start of the run: its nearest existing folder must let it be
  fs::path existing = fs::absolute(dir).parent_path();
  while (!fs::exists(existing, ec) && existing.has_relative_path()) existing = existing.parent_path();
  if (!fs::is_directory(existing, ec)) refuse(" cannot be created: " + existing.string() + " is not a folder");
  if (::access(existing.c_str(), W_OK | X_OK) != 0) refuse(" cannot be created: " + existing.string() + " is not writable");
}

/// The files and folders the scene reads.
std::vector<std::string> scene_inputs(const Scene& scene) {
  std::vector<std::string> inputs{scene.file, scene.adaptive.cache};
  for (const BodySpec& b : scene.bodies) inputs.insert(inputs.end(), {b.sid_file, b.model_file});
  std::erase(inputs, std::string());
  return inputs;
}

/// True if `inner` is `outer` or lies in it (both canonical).
bool within(const fs::path& inner, const fs::path& outer) {
  auto i = inner.begin();
  for (auto o = outer.begin(); o != outer.end(); ++o, ++i)
    if (i == inner.end() || *i != *o) return false;
  return true;
}

}  // namespace

const std::vector<std::string>& RunFolder::outputs() {
  static const std::vector<std::string> names{"results.h5", "summary.json", "paraview", "phases"};
  return names;
}

RunFolder::RunFolder(std::string dir, const Scene& scene) : dir_(std::move(dir)) {
  require_writable_folder(dir_);
  for (const std::string& input : scene_inputs(scene)) {
    const fs::path in = fs::weakly_canonical(input);
    for (const std::string& name : outputs()) {
      const fs::path out = fs::weakly_canonical(fs::path(dir_) / name);
      if (!within(in, out)) continue;
      const std::string place = (fs::path(dir_) / name).string();
      throw format::InputError("", "-o", in == out ? place + " is an input of the scene; the run would replace it (choose another results folder)"
                                                   : place + " holds " + input + ", an input of the scene; the run would remove it (choose another results folder)");
    }
  }
  for (const char* file : {"results.h5", "summary.json"}) format::require_output_file((fs::path(dir_) / file).string());
  if (fs::is_directory(dir_)) lock();
}

RunFolder::~RunFolder() {
  if (lock_fd_ >= 0) ::close(lock_fd_);
}

void RunFolder::lock() {
  const std::string file = (fs::path(dir_) / kLockFile).string();
  const int fd = ::open(file.c_str(), O_RDWR | O_CREAT | O_CLOEXEC | O_NOFOLLOW, 0644);
  if (fd < 0) throw format::InputError(dir_, "", std::string("cannot create the lock file ") + kLockFile + ": " + std::strerror(errno));
  if (::flock(fd, LOCK_EX | LOCK_NB) != 0) {
    const int error = errno;
    char text[32] = {};
    const ssize_t n = ::pread(fd, text, sizeof text - 1, 0);
    ::close(fd);
    if (error != EWOULDBLOCK) throw format::InputError(dir_, "", std::string("cannot lock ") + kLockFile + ": " + std::strerror(error));
    std::string pid(text, std::size_t(std::max<ssize_t>(n, 0)));
    pid.erase(std::find(pid.begin(), pid.end(), '\n'), pid.end());
    throw format::InputError(dir_, "", "another isosid-run (pid " + (pid.empty() ? "unknown" : pid) + ") is writing there");
  }
  // the holder's pid, for the next run's refusal
  const std::string pid = std::to_string(::getpid()) + "\n";
  [[maybe_unused]] const bool written = ::ftruncate(fd, 0) == 0 && ::pwrite(fd, pid.data(), pid.size(), 0) == ssize_t(pid.size());
  lock_fd_ = fd;  // the lock holds without the pid: the refusal then says "pid unknown"
}

void RunFolder::start(const std::string& scene_file) {
  fs::create_directories(dir_);
  if (lock_fd_ < 0) lock();
  for (const std::string& name : outputs()) {
    std::error_code ec;
    fs::remove_all(fs::path(dir_) / name, ec);  // a link is removed, not followed
    if (ec) throw format::InputError("", "-o", (fs::path(dir_) / name).string() + " of an earlier run cannot be removed: " + ec.message());
  }
  const nlohmann::json running = {{"scene", scene_file}, {"status", "running"}};
  format::write_text_atomically((fs::path(dir_) / "summary.json").string(), running.dump(2) + "\n");
}

}  // namespace isosid::run
