// Scene and model texts for tests: fixtures from tests/scenes with their placeholders filled
// in, and edits in place.
#pragma once
#include <catch2/catch.hpp>
#include <fstream>
#include <sstream>
#include <stdexcept>
#include <string>
#include <utility>
#include <vector>

namespace isosid::test {

/// `text` with its first `from` replaced by `to` (which must be there).
inline std::string replace(std::string text, const std::string& from, const std::string& to) {
  const auto at = text.find(from);
  REQUIRE(at != std::string::npos);
  return text.replace(at, from.size(), to);
}

/// `text` with every `from` replaced by `to`; `from` must occur. Throws std::runtime_error
/// otherwise (no Catch assertion: tests also build texts at namespace scope).
inline std::string replace_all(std::string text, const std::string& from, const std::string& to) {
  if (text.find(from) == std::string::npos) throw std::runtime_error("the text has no " + from);
  for (auto at = text.find(from); at != std::string::npos; at = text.find(from, at + to.size())) text.replace(at, from.size(), to);
  return text;
}

/// The text of tests/scenes/`name`, each placeholder of `values` (such as "@SID@") replaced
/// wherever it stands (replace_all); each must stand there at least once.
inline std::string scene_fixture(const std::string& name, const std::vector<std::pair<std::string, std::string>>& values = {}) {
  const std::string path = std::string(ISOSID_TEST_SCENES_DIR) + "/" + name;
  std::ifstream file(path);
  if (!file) throw std::runtime_error("test fixture " + path + " cannot be read");
  std::stringstream text;
  text << file.rdbuf();
  std::string s = text.str();
  try {
    for (const auto& [placeholder, value] : values) s = replace_all(std::move(s), placeholder, value);
  } catch (const std::runtime_error& e) {
    throw std::runtime_error("test fixture " + path + ": " + e.what());
  }
  return s;
}

}  // namespace isosid::test
