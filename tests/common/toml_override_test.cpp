// Overrides by dotted key: a value replaced, a key added to a table, an array entry replaced,
// and every way a key or a value can be wrong refused naming the file and the key.
#include "isosid/common/toml_fields.hpp"

#include <catch2/catch.hpp>

using namespace isosid;
using Catch::Matchers::Contains;

namespace {
const char* kScene = R"(
[simulation]
end_time = 1e-4
[[flexible_body]]
name = "a"
velocity = [0.0, -0.1, 0.0]
[[flexible_body]]
name = "b"
)";

toml::table overridden(const std::vector<common::TomlOverride>& overrides) {
  toml::table root = toml::parse(kScene);
  common::apply_overrides(root, overrides, "s.scene.toml");
  return root;
}

void refused(const common::TomlOverride& o, const std::string& problem) {
  INFO(o.text());
  CHECK_THROWS_WITH(overridden({o}), Contains("s.scene.toml: " + o.key + ": " + problem));
}
}  // namespace

TEST_CASE("overrides: values replaced and added by dotted key", "[common][unit]") {
  const toml::table root = overridden({{"simulation.end_time", "2e-4"},
                                       {"flexible_body.0.velocity", "[0.0, -0.2, 0.0]"},
                                       {"flexible_body.1.velocity", "[1, 2, 3]"},  // a key added to a table
                                       {"flexible_body.1.velocity.1", "5.5"},      // then one entry of it
                                       {"flexible_body.1.high_modes", "\"quasistatic\""}});
  CHECK(root["simulation"]["end_time"].value<double>() == 2e-4);
  CHECK(root["flexible_body"][0]["velocity"][1].value<double>() == -0.2);
  CHECK(root["flexible_body"][0]["name"].value<std::string>() == "a");  // the rest of the table stays
  CHECK(root["flexible_body"][1]["velocity"][1].value<double>() == 5.5);  // an array entry, in order
  CHECK(root["flexible_body"][1]["velocity"][2].value<int64_t>() == 3);
  CHECK(root["flexible_body"][1]["high_modes"].value<std::string>() == "quasistatic");
}

TEST_CASE("overrides: wrong keys and values are refused naming file and key", "[common][unit]") {
  refused({"nope.end_time", "1"}, "no 'nope' in the file to override");
  refused({"simulation.end_time.x", "1"}, "'simulation.end_time' is a value, not a table or an array");
  refused({"flexible_body.2.velocity", "1"}, "'flexible_body' has 2 entries (indices from 0)");
  refused({"flexible_body.x.velocity", "1"}, "'flexible_body' is an array: index it by a number from 0");
  refused({"flexible_body.a", "1"}, "'flexible_body' is an array: index it by a number from 0");
  refused({"flexible_body.-1.velocity", "1"}, "'flexible_body' is an array: index it by a number from 0");
  refused({"simulation..end_time", "1"}, "an override key needs names between its dots");
  refused({"simulation.end_time", "["}, "override value '[' is not a TOML value");
  refused({"simulation.end_time", ""}, "override value '' is not a TOML value");
  CHECK_THROWS_WITH(common::parse_overrides({"a.b=1", "novalue"}, "--set"), "--set: 'novalue' is not KEY=VALUE");
  CHECK_THROWS_WITH(common::parse_overrides({"=1"}, "--set"), "--set: '=1' is not KEY=VALUE");
  const auto parsed = common::parse_overrides({"a.b=[1, 2]", "c=x=y"}, "--set");
  CHECK(parsed[0].key == "a.b");
  CHECK(parsed[0].value == "[1, 2]");
  CHECK(parsed[1].value == "x=y");  // the first '=' separates
}
