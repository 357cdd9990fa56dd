// What a run writes, as two tables: every group and dataset of results.h5 and every key of
// summary.json, with its type, shape, units, when it is there and what it means. docs/outputs.md
// is generated from them (isosid-run --describe-outputs), and a test runs scenes of every kind
// and holds their files to the tables both ways: nothing written that a table does not hold,
// nothing in a table that no run writes.
#pragma once
#include <span>
#include <string>
#include <string_view>

namespace isosid::run::outputs {

/// What an item holds. results.h5: Group, Float64 (with a `units` attribute), Integers, Text,
/// Texts. summary.json: the JSON types, several allowed where a value may be null.
enum Type : unsigned {
  Group = 1u << 0,
  Float64 = 1u << 1,
  Integers = 1u << 2,
  Text = 1u << 3,
  Texts = 1u << 4,
  Null = 1u << 5,
  Boolean = 1u << 6,
  Integer = 1u << 7,
  Number = 1u << 8,  ///< a JSON number, integral or not
  String = 1u << 9,
  Array = 1u << 10,
  Object = 1u << 11,
};

struct Item {
  /// results.h5: "/bodies/<body>/position"; summary.json: "contacts[].peak_force_n". A name in
  /// angle brackets stands for any one name (a body's, a contact's, a reference value's).
  std::string_view path;
  unsigned type;            ///< a Type, or several or'ed together (JSON: "number or null")
  std::string_view shape;   ///< results.h5: rows × columns in words ("n × 3": n the samples); JSON: empty
  std::string_view units;   ///< the `units` attribute, or the unit of a JSON number; empty: none
  std::string_view when;    ///< empty: always there; otherwise the condition
  std::string_view meaning;
};

std::span<const Item> results_items();
std::span<const Item> summary_items();

/// The item whose path matches `path` (each "<...>" of the item's path matches one name), or null.
const Item* find(std::span<const Item> items, std::string_view path);

/// docs/outputs.md in full.
std::string markdown();

}  // namespace isosid::run::outputs
