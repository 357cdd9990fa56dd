// The record of built SIDs' digests; see sid_digest.hpp.
#include "scene/sid_digest.hpp"

#include "isosid/common/sha256.hpp"

#include <cstdio>
#include <filesystem>
#include <fstream>

namespace isosid::run {
namespace {
std::string digest_file(const std::string& sid) { return sid + ".sha256"; }
}  // namespace

void record_sid_digest(const std::string& sid) {
  const std::string record = digest_file(sid), temporary = record + ".tmp";
  // without a record the SID is probed when read, as any other: nothing here fails the run
  std::string digest;
  try {
    digest = common::sha256_file(sid);
  } catch (...) {
    return;
  }
  {
    std::ofstream out(temporary, std::ios::trunc);
    out << digest << '\n';
    if (!out) {
      std::remove(temporary.c_str());
      return;
    }
  }
  std::error_code ec;
  std::filesystem::rename(temporary, record, ec);
  if (ec) std::remove(temporary.c_str());
}

bool sid_digest_matches(const std::string& sid) {
  std::ifstream in(digest_file(sid));
  std::string recorded;
  if (!(in >> recorded) || recorded.size() != 64) return false;
  try {
    return recorded == common::sha256_file(sid);
  } catch (...) {  // unreadable: the read that follows reports it
    return false;
  }
}

}  // namespace isosid::run
