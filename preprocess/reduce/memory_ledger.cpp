// The ledger of the preparations sharing one machine's memory; see memory_ledger.hpp.
#include "reduce/memory_ledger.hpp"

#include "isosid/common/file_lock.hpp"

#include <sys/stat.h>
#include <unistd.h>

#include <algorithm>
#include <cstdlib>
#include <filesystem>
#include <fstream>
#include <optional>
#include <sstream>

namespace isosid::prep {
namespace {

namespace fs = std::filesystem;

/// A live process's start time (clock ticks after boot, field 22 of /proc/<pid>/stat), or
/// none for a process that ended (also one that is a zombie until its parent reaps it).
std::optional<unsigned long long> start_time(const std::string& pid) {
  std::ifstream in("/proc/" + pid + "/stat");
  std::string line;
  if (!std::getline(in, line)) return std::nullopt;
  const auto name_end = line.rfind(')');  // the command name may hold spaces and parentheses
  if (name_end == std::string::npos) return std::nullopt;
  std::istringstream fields(line.substr(name_end + 1));
  std::string state;
  fields >> state;  // field 3
  if (state == "Z" || state == "X") return std::nullopt;
  std::string skip;
  for (int field = 4; field < 22; ++field) fields >> skip;
  unsigned long long ticks = 0;
  if (!(fields >> ticks)) return std::nullopt;
  return ticks;
}

/// A process's resident memory in bytes (/proc/<pid>/statm), 0 if it cannot be read.
double resident_bytes(const std::string& pid) {
  std::ifstream in("/proc/" + pid + "/statm");
  double size = 0, resident = 0;
  if (!(in >> size >> resident)) return 0;
  return resident * double(::sysconf(_SC_PAGESIZE));
}

/// A folder only this user may write, created if missing; false if it cannot be had.
bool own_folder(const std::string& folder) {
  std::error_code ec;
  fs::create_directories(folder, ec);
  struct stat info {};
  if (::stat(folder.c_str(), &info) != 0 || !S_ISDIR(info.st_mode) || info.st_uid != ::getuid()) return false;
  return ::access(folder.c_str(), W_OK) == 0;
}

}  // namespace

Admission admission(double bytes, double available, const std::vector<LedgerEntry>& others) {
  double growth = 0, returned = 0;
  int growing = 0;
  for (const LedgerEntry& o : others) {
    if (o.waiting) continue;
    ++growing;
    growth += std::max(0.0, o.reserved - o.resident);
    returned += o.resident;
  }
  if (bytes <= available - growth) return Admission::Start;
  return growing > 0 && bytes <= available + returned ? Admission::Wait : Admission::Refuse;
}

std::string ledger_folder() {
  if (const char* set = std::getenv("ISOSID_MEMORY_LEDGER"); set && *set) return set;
  const std::string shm = fs::is_directory("/dev/shm") ? "/dev/shm" : fs::temp_directory_path().string();
  return shm + "/isosid-memory-" + std::to_string(::getuid());
}

MemoryLedger::MemoryLedger(std::string folder) : folder_(std::move(folder)) { usable_ = own_folder(folder_); }

void MemoryLedger::withdraw() {
  if (!usable_) return;
  const common::FileLock lock(folder_ + "/lock", common::FileLock::Mode::Exclusive);
  std::error_code ec;
  fs::remove(fs::path(folder_) / std::to_string(::getpid()), ec);
}

Admission MemoryLedger::request(double bytes, double available) {
  others_growing_ = 0;
  others_growth_ = 0;
  others_resident_ = 0;
  if (!usable_) return admission(bytes, available, {});
  const common::FileLock lock(folder_ + "/lock", common::FileLock::Mode::Exclusive);
  const std::string self = std::to_string(::getpid());
  std::vector<LedgerEntry> others;
  std::error_code ec;
  for (const fs::directory_entry& file : fs::directory_iterator(folder_, ec)) {
    const std::string pid = file.path().filename().string();
    if (pid == self || pid.find_first_not_of("0123456789") != std::string::npos) continue;
    std::ifstream in(file.path());
    unsigned long long recorded = 0;
    LedgerEntry entry;
    int waiting = 0;
    const bool read = bool(in >> recorded >> entry.reserved >> waiting);
    const auto started = start_time(pid);
    if (!read || !started || *started != recorded) {  // ended, or its pid reused since
      in.close();
      fs::remove(file.path(), ec);
      continue;
    }
    entry.waiting = waiting != 0;
    entry.resident = resident_bytes(pid);
    if (!entry.waiting) {
      ++others_growing_;
      others_growth_ += std::max(0.0, entry.reserved - entry.resident);
      others_resident_ += entry.resident;
    }
    others.push_back(entry);
  }
  const Admission decision = admission(bytes, available, others);
  const double resident = resident_bytes(self);
  std::ofstream out(fs::path(folder_) / self, std::ios::trunc);
  const bool starts = decision == Admission::Start;
  out << start_time(self).value_or(0) << ' ' << static_cast<long long>(starts ? resident + bytes : resident) << ' ' << (starts ? 0 : 1) << '\n';
  return decision;
}

}  // namespace isosid::prep
