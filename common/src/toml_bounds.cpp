// Size and nesting bounds of TOML text; see toml_bounds.hpp.
#include "isosid/common/toml_bounds.hpp"

#include "isosid/format/error.hpp"

#include <vector>

namespace isosid::common {

void check_toml_nesting(const std::string& text, const std::string& path) {
  // A small lexer: strings (basic, literal, multi-line) and comments are skipped; brackets and
  // braces outside them open and close levels; in a key (a line's start up to '=', a table
  // header, an inline table's entry) every '.' adds a level.
  std::vector<char> open;  // '[' or '{' per open level
  bool in_key = true, header = false;
  int key_parts = 0;
  long line = 1;
  auto fail = [&] {
    throw format::InputError(path, "line " + std::to_string(line),
                             "nests deeper than " + std::to_string(kMaxTomlNesting) +
                                 " levels (tables, dotted keys, arrays and inline tables together)");
  };
  auto level = [&] { return int(open.size()) + key_parts; };
  for (std::size_t i = 0; i < text.size(); ++i) {
    const char c = text[i];
    if (c == '\n') {
      ++line;
      if (open.empty() || header) in_key = true, header = false, key_parts = 0;
      continue;
    }
    if (c == '#') {  // comment to the end of the line
      while (i + 1 < text.size() && text[i + 1] != '\n') ++i;
      continue;
    }
    if (c == '"' || c == '\'') {
      const bool multi = text.compare(i, 3, std::string(3, c)) == 0;
      const std::string end = multi ? std::string(3, c) : std::string(1, c);
      std::size_t j = i + end.size();
      for (; j < text.size(); ++j) {
        if (c == '"' && text[j] == '\\') {
          ++j;
          continue;
        }
        if (text[j] == '\n') ++line;
        if (text.compare(j, end.size(), end) == 0) break;
      }
      i = j + end.size() - 1;
      continue;
    }
    if (in_key && c == '.') {
      ++key_parts;
      if (level() > kMaxTomlNesting) fail();
      continue;
    }
    if (c == '=' && in_key && !header) {
      in_key = false;
      key_parts = 0;
      continue;
    }
    if (c == '[' || c == '{') {
      if (c == '[' && open.empty() && in_key) header = true;  // a table header: its parts are keys
      else in_key = c == '{';
      open.push_back(c);
      if (level() > kMaxTomlNesting) fail();
      continue;
    }
    if ((c == ']' || c == '}') && !open.empty()) {
      open.pop_back();
      continue;
    }
    if (c == ',' && !open.empty() && open.back() == '{') in_key = true, key_parts = 0;
  }
}

}  // namespace isosid::common
