// Overrides of a parsed TOML input by dotted key, e.g. "flexible_body.0.velocity = [0, -0.2, 0]":
// how a script or a study changes one value of a scene or model file without editing it.
// Numbers in a key index arrays of tables (flexible_body.0 is the first [[flexible_body]]).
// (apply_overrides, which needs the parsed table, is declared in toml_fields.hpp.)
#pragma once
#include <string>
#include <vector>

namespace isosid::common {

struct TomlOverride {
  std::string key;    ///< dotted: table keys, and array indices from 0
  std::string value;  ///< a TOML value as written in a file: 0.2, "text", [0.0, -0.2, 0.0], true, {a = 1}
  std::string text() const { return key + " = " + value; }
};

/// Overrides written KEY=VALUE (a command line's); one without '=' or without a key throws
/// InputError naming `option`.
std::vector<TomlOverride> parse_overrides(const std::vector<std::string>& settings, const std::string& option);

}  // namespace isosid::common
