// Editing scene and model texts in place, for tests.
#pragma once
#include <catch2/catch.hpp>
#include <string>

namespace isosid::test {

/// `text` with its first `from` replaced by `to` (which must be there).
inline std::string replace(std::string text, const std::string& from, const std::string& to) {
  const auto at = text.find(from);
  REQUIRE(at != std::string::npos);
  return text.replace(at, from.size(), to);
}

}  // namespace isosid::test
