// Nesting and size bounds before toml++ parses (common/toml_bounds): hostile depth is refused
// with a line number, ordinary files pass, and values full of dots are not keys.
#include "isosid/common/toml_bounds.hpp"
#include "isosid/common/toml_fields.hpp"
#include "isosid/format/error.hpp"

#include <catch2/catch.hpp>
#include <filesystem>
#include <fstream>

using isosid::common::check_toml_nesting;
using isosid::common::kMaxTomlNesting;

namespace {
std::string repeat(const std::string& s, int n) {
  std::string out;
  for (int i = 0; i < n; ++i) out += s;
  return out;
}
bool refused(const std::string& text) {
  try {
    check_toml_nesting(text, "f.toml");
  } catch (const isosid::format::InputError&) {
    return true;
  }
  return false;
}
}  // namespace

TEST_CASE("TOML bounds: deep dotted keys, headers, arrays and inline tables are refused", "[common][toml]") {
  CHECK(refused("x = 1\n" + repeat("a.", 40000) + "a = 1\n"));  // the reproducer's shape
  CHECK(refused("[" + repeat("t.", kMaxTomlNesting) + "t]\n"));
  CHECK(refused("v = " + repeat("[", kMaxTomlNesting + 1) + repeat("]", kMaxTomlNesting + 1) + "\n"));
  CHECK(refused("v = " + repeat("{ a = ", kMaxTomlNesting + 1) + "1" + repeat(" }", kMaxTomlNesting + 1) + "\n"));
  // the limit itself passes: 64 levels of arrays
  CHECK_FALSE(refused("v = " + repeat("[", kMaxTomlNesting) + repeat("]", kMaxTomlNesting) + "\n"));
  // the line is named
  try {
    check_toml_nesting("x = 1\n\n" + repeat("a.", 100) + "a = 1\n", "f.toml");
    FAIL("not refused");
  } catch (const isosid::format::InputError& e) {
    CHECK(std::string(e.what()).find("line 3") != std::string::npos);
  }
}

TEST_CASE("TOML bounds: ordinary files pass, dots in values and strings are not keys", "[common][toml]") {
  CHECK_FALSE(refused("[body]\nname = \"a.b.c.d.e\"\n[[refinement.graded]]\ndirection = \"xi\"\n"));
  CHECK_FALSE(refused("v = [" + repeat("1.5, ", 10000) + "2.5]\nw = { a = 1.5, b = [2.5, 3.5] }\n"));
  CHECK_FALSE(refused("s = '''\n" + repeat("a.", 1000) + "\n'''\nt = \"" + repeat("x.", 1000) + "\"\n# " + repeat("c.", 1000) + "\n"));
  CHECK_FALSE(refused("m = [\n  [1.0, 2.0],\n  [3.0, 4.0],\n]\nk.l.m = 1.25\n"));
}

TEST_CASE("TOML bounds: every model file of the repository passes", "[common][toml]") {
  int files = 0;
  for (const auto& entry : std::filesystem::directory_iterator(ISOSID_MODELS_DIR)) {
    if (entry.path().extension() != ".toml") continue;
    INFO(entry.path());
    CHECK_NOTHROW(isosid::common::parse_toml_file(entry.path().string()));
    ++files;
  }
  CHECK(files > 5);
}
