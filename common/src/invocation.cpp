// Command line and time of a program's run; see invocation.hpp.
#include "isosid/common/invocation.hpp"

#include <chrono>
#include <ctime>
#include <fstream>
#include <iterator>

namespace isosid::common {
namespace {

bool plain(const std::string& word) {
  if (word.empty()) return false;
  for (const char c : word) {
    const bool alnum = (c >= 'a' && c <= 'z') || (c >= 'A' && c <= 'Z') || (c >= '0' && c <= '9');
    if (!alnum && std::string_view("-_./=:,+@%").find(c) == std::string_view::npos) return false;
  }
  return true;
}

std::string shell_quoted(const std::string& word) {
  if (plain(word)) return word;
  std::string out = "'";
  for (const char c : word) out += c == '\'' ? std::string("'\\''") : std::string(1, c);
  return out + "'";
}

}  // namespace

std::string command_line() {
  std::ifstream in("/proc/self/cmdline", std::ios::binary);
  const std::string raw((std::istreambuf_iterator<char>(in)), std::istreambuf_iterator<char>());
  std::string line;
  std::size_t start = 0;
  while (start < raw.size()) {  // arguments end in NUL each
    std::size_t end = raw.find('\0', start);
    if (end == std::string::npos) end = raw.size();
    if (!line.empty()) line += ' ';
    line += shell_quoted(raw.substr(start, end - start));
    start = end + 1;
  }
  return line;
}

std::string utc_now() {
  const std::time_t t = std::chrono::system_clock::to_time_t(std::chrono::system_clock::now());
  std::tm parts{};
  gmtime_r(&t, &parts);
  char text[32];
  std::strftime(text, sizeof text, "%Y-%m-%dT%H:%M:%SZ", &parts);
  return text;
}

}  // namespace isosid::common
