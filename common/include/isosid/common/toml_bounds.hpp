// Bounds checked on a TOML text before toml++ parses it: its size, and how deeply tables,
// dotted keys, arrays and inline tables nest. toml++ descends recursively, so a hostile file
// of keys dotted 40 000 deep overflows the stack; real model and scene files nest 3 deep.
#pragma once
#include <string>

namespace isosid::common {

constexpr std::size_t kMaxTomlBytes = std::size_t{16} << 20;  ///< 16 MiB
constexpr int kMaxTomlNesting = 64;

/// Throws format::InputError naming `path` and the line when `text` nests deeper than
/// kMaxTomlNesting levels (dotted key parts, table header parts, open arrays and inline tables).
void check_toml_nesting(const std::string& text, const std::string& path);

}  // namespace isosid::common
