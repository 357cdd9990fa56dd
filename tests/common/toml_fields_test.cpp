// Bounded integers and names of TOML input files (common/toml_fields): every integer is held to
// its range before it is narrowed, so 2^31 cannot wrap negative nor 2^32 + 4 become 4, and a
// name that would become an HDF5 path is refused.
#include "isosid/common/toml_fields.hpp"
#include "isosid/format/error.hpp"

#include <catch2/catch.hpp>

using isosid::common::TomlView;
using Catch::Matchers::Contains;

namespace {
/// The message of what `f` throws, "" if it throws nothing.
template <class F>
std::string refusal(F&& f) {
  try {
    f();
  } catch (const isosid::format::InputError& e) {
    return e.what();
  }
  return "";
}
}  // namespace

TEST_CASE("TOML fields: integers are bounded before they are narrowed", "[common][toml]") {
  const toml::table t = toml::parse("a = 2147483648\nb = 4294967297\nc = -1\nd = 7\nlist = [4294967300, 2]\nok = [1, 8]\n");
  const TomlView v(t, "f.toml", "reduction");
  CHECK_THAT(refusal([&] { v.integer_in("a", 1, 2000000); }), Contains("f.toml: reduction.a: must lie in 1..2000000, is 2147483648"));
  CHECK_THAT(refusal([&] { v.integer_in("b", 1, 2000000); }), Contains("reduction.b: must lie in 1..2000000, is 4294967297"));
  CHECK_THAT(refusal([&] { v.integer_in("c", 0, 10); }), Contains("reduction.c: must lie in 0..10, is -1"));
  CHECK(v.integer_in("d", 1, 7) == 7);
  CHECK(v.integer_in("missing", 1, 7, 3) == 3);
  CHECK_THAT(refusal([&] { v.integers_in("list", 1, 8); }), Contains("reduction.list[0]: must lie in 1..8, is 4294967300"));
  CHECK(v.integers_in("ok", 1, 8) == std::vector<int>{1, 8});
}

TEST_CASE("TOML fields: names are non-empty and without '/'", "[common][toml]") {
  const toml::table t = toml::parse("a = \"sph/ere\"\nb = \"\"\nc = \"/\"\nd = \"sphere\"\n");
  const TomlView v(t, "f.toml", "flexible_body[0]");
  for (const char* key : {"a", "b", "c"})
    CHECK_THAT(refusal([&] { v.name(key); }), Contains(std::string("flexible_body[0].") + key + ": must be a non-empty name without '/'"));
  CHECK(v.name("d") == "sphere");
}
