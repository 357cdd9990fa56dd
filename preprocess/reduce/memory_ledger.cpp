// The ledger of the preparations sharing one machine's memory; see memory_ledger.hpp.
#include "reduce/memory_ledger.hpp"

#include "isosid/common/file_lock.hpp"

#include <sys/stat.h>
#include <unistd.h>

#include <algorithm>
#include <cerrno>
#include <cstdio>
#include <cstdlib>
#include <cstring>
#include <filesystem>
#include <fstream>
#include <optional>
#include <sstream>

namespace isosid::prep {
namespace {

namespace fs = std::filesystem;

const std::string kPrefix = "pid-";

struct ProcessState {
  unsigned long long start_ticks = 0;  ///< clock ticks after boot (field 22 of /proc/<pid>/stat)
  bool stopped = false;                ///< by a signal or a tracer (state T or t)
};

/// A live process's start time and whether it is stopped, or none for a process that ended
/// (also one that is a zombie until its parent reaps it).
std::optional<ProcessState> process_state(const std::string& pid) {
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
  ProcessState out;
  if (!(fields >> out.start_ticks)) return std::nullopt;
  out.stopped = state == "T" || state == "t";
  return out;
}

/// A process's resident memory in bytes (/proc/<pid>/statm), 0 if it cannot be read.
double resident_bytes(const std::string& pid) {
  std::ifstream in("/proc/" + pid + "/statm");
  double size = 0, resident = 0;
  if (!(in >> size >> resident)) return 0;
  return resident * double(::sysconf(_SC_PAGESIZE));
}

/// The folder, created if missing (mode 0700); empty if it can be used, else why not.
std::string own_folder(const std::string& folder) {
  std::error_code ec;
  fs::create_directories(fs::path(folder).parent_path(), ec);
  if (::mkdir(folder.c_str(), 0700) != 0 && errno != EEXIST) return std::strerror(errno);
  struct stat info {};
  if (::lstat(folder.c_str(), &info) != 0) return std::strerror(errno);
  if (!S_ISDIR(info.st_mode)) return "it is not a folder";
  if (info.st_uid != ::getuid()) return "another user owns it";
  if ((info.st_mode & 077) != 0 && ::chmod(folder.c_str(), 0700) != 0) return std::strerror(errno);
  return "";
}

/// The pid a ledger file's name gives, or empty for a file of another name.
std::string pid_of(const std::string& name) {
  if (name.size() <= kPrefix.size() || name.compare(0, kPrefix.size(), kPrefix) != 0) return "";
  const std::string pid = name.substr(kPrefix.size());
  return pid.find_first_not_of("0123456789") == std::string::npos ? pid : "";
}

}  // namespace

Growers growers(const std::vector<LedgerEntry>& others) {
  Growers g;
  for (const LedgerEntry& o : others) {
    const double coming = std::max(0.0, o.reserved - o.resident);
    if (o.waiting) {
      g.promised += coming;
      continue;
    }
    ++g.count;
    g.growth += coming;
    g.resident += o.resident;
  }
  return g;
}

Admission admission(double bytes, double available, const std::vector<LedgerEntry>& others) {
  const Growers g = growers(others);
  if (bytes <= available - g.growth - g.promised) return Admission::Start;
  return g.count > 0 && bytes <= available + g.resident ? Admission::Wait : Admission::Refuse;
}

std::string ledger_folder() {
  std::error_code ec;
  if (const char* set = std::getenv("ISOSID_MEMORY_LEDGER"); set && *set) {
    const fs::path absolute = fs::absolute(set, ec);
    return ec ? std::string(set) : absolute.string();
  }
  fs::path base = fs::is_directory("/dev/shm", ec) ? fs::path("/dev/shm") : fs::temp_directory_path(ec);
  if (ec || base.empty()) base = "/tmp";
  return (base / ("isosid-memory-" + std::to_string(::getuid()))).string();
}

double own_resident_bytes() { return resident_bytes(std::to_string(::getpid())); }

MemoryLedger::MemoryLedger(std::string folder) : folder_(std::move(folder)) { problem_ = own_folder(folder_); }

void MemoryLedger::withdraw() {
  if (!usable()) return;
  const common::FileLock lock(folder_ + "/lock", common::FileLock::Mode::Exclusive);
  std::error_code ec;
  fs::remove(fs::path(folder_) / (kPrefix + std::to_string(::getpid())), ec);
}

void MemoryLedger::update(const Decide& decide) {
  const std::string self = std::to_string(::getpid());
  std::optional<common::FileLock> lock;
  if (usable()) lock.emplace(folder_ + "/lock", common::FileLock::Mode::Exclusive);
  if (!lock || !lock->held()) {  // no ledger: this process alone
    decide({}, resident_bytes(self));
    return;
  }
  std::vector<LedgerEntry> others;
  std::error_code ec;
  for (const fs::directory_entry& file : fs::directory_iterator(folder_, ec)) {
    std::string name = file.path().filename().string();
    const bool unfinished = name.size() > 4 && name.compare(name.size() - 4, 4, ".new") == 0;  // a record its writer did not rename
    if (unfinished) name.resize(name.size() - 4);
    const std::string pid = pid_of(name);
    if (pid.empty() || pid == self) continue;
    if (unfinished) {
      if (!process_state(pid)) fs::remove(file.path(), ec);
      continue;
    }
    std::ifstream in(file.path());
    unsigned long long recorded = 0;
    LedgerEntry entry;
    int waiting = 0;
    const bool read = bool(in >> recorded >> entry.reserved >> waiting);
    const auto state = process_state(pid);
    if (!read || !state || state->start_ticks != recorded) {  // ended, or its pid reused since
      in.close();
      fs::remove(file.path(), ec);
      continue;
    }
    entry.waiting = waiting != 0 || state->stopped;  // a stopped process is not waited for
    entry.resident = resident_bytes(pid);
    others.push_back(entry);
  }
  const LedgerRecord record = decide(others, resident_bytes(self));
  // written beside and renamed over: a reader sees the old record or the new, never a part
  const fs::path file = fs::path(folder_) / (kPrefix + self), written = fs::path(folder_) / (kPrefix + self + ".new");
  {
    std::ofstream out(written, std::ios::trunc);
    out << process_state(self).value_or(ProcessState{}).start_ticks << ' ' << static_cast<long long>(record.reserved) << ' '
        << (record.waiting ? 1 : 0) << '\n';
    if (!out.flush()) {
      out.close();
      fs::remove(written, ec);
      return;
    }
  }
  fs::rename(written, file, ec);
}

Admission MemoryLedger::request(double bytes, double available, Growers* others) {
  Admission decision = Admission::Start;
  update([&](const std::vector<LedgerEntry>& entries, double resident) {
    decision = admission(bytes, available, entries);
    if (others) *others = growers(entries);
    return decision == Admission::Start ? LedgerRecord{resident + bytes, false} : LedgerRecord{resident, true};
  });
  return decision;
}

}  // namespace isosid::prep
