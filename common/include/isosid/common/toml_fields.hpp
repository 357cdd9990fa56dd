// Strict reading of TOML input files (models and scenes): every key must be known, every
// number finite and of the right sign, and every problem is an InputError naming the file
// and the dotted field, e.g. "sphere.model.toml: material.poisson_ratio: must be < 0.5".
#pragma once
#include "isosid/common/toml_override.hpp"
#include "isosid/format/error.hpp"

#include <Eigen/Dense>
#include <initializer_list>
#include <optional>
#include <string>
#include <toml++/toml.h>
#include <vector>

namespace isosid::common {

/// Parses a TOML file; syntax errors become InputError with line and column.
toml::table parse_toml_file(const std::string& path);
/// Parses TOML text held in memory, as parse_toml_file() a file's; `origin` names it in errors.
toml::table parse_toml_text(const std::string& text, const std::string& origin);

/// Sets each override in `root` (parsed from `file`), replacing a value or adding a key to an
/// existing table; the reader of the file then checks the result as if it had been written
/// there. A key that leads through a missing table or a missing array entry, or a value that
/// is not TOML, throws InputError naming `file` and the key.
void apply_overrides(toml::table& root, const std::vector<TomlOverride>& overrides, const std::string& file);

class TomlView {
public:
  TomlView(const toml::table& table, std::string file, std::string path = "")
      : table_(&table), file_(std::move(file)), path_(std::move(path)) {}

  /// Refuses keys outside `allowed`.
  void allow_only(std::initializer_list<const char*> allowed) const;
  bool has(const std::string& key) const { return table_->contains(key); }
  bool holds_string(const std::string& key) const;  ///< present and a string (for keys that take a number or a word)
  std::string field(const std::string& key) const { return path_.empty() ? key : path_ + "." + key; }
  const std::string& file() const { return file_; }
  [[noreturn]] void fail(const std::string& key, const std::string& problem) const { throw format::InputError(file_, field(key), problem); }

  TomlView table(const std::string& key) const;            ///< required sub-table
  std::optional<TomlView> optional_table(const std::string& key) const;
  std::vector<TomlView> tables(const std::string& key) const;  ///< array of tables ([[key]]), may be empty

  double number(const std::string& key) const;
  double number(const std::string& key, double fallback) const;
  double positive(const std::string& key) const;
  double positive(const std::string& key, double fallback) const;
  long long integer(const std::string& key) const;
  long long integer(const std::string& key, long long fallback) const;
  /// An integer within [lo, hi]: every count and index read from a file is bounded here,
  /// before it is narrowed to int or sizes anything.
  int integer_in(const std::string& key, int lo, int hi) const;
  int integer_in(const std::string& key, int lo, int hi, int fallback) const;
  std::vector<int> integers_in(const std::string& key, int lo, int hi) const;
  /// A name that becomes part of an HDF5 path or a dotted field: non-empty, without '/'.
  std::string name(const std::string& key) const;
  std::string string(const std::string& key) const;
  std::string string(const std::string& key, const std::string& fallback) const;
  bool boolean(const std::string& key, bool fallback) const;
  std::vector<double> numbers(const std::string& key) const;                 ///< array of numbers
  std::vector<std::vector<double>> number_rows(const std::string& key) const;  ///< array of arrays
  std::vector<long long> integers(const std::string& key) const;
  std::vector<std::string> strings(const std::string& key) const;

private:
  const toml::node& node(const std::string& key) const;
  double as_number(const toml::node& n, const std::string& where) const;
  const toml::table* table_;
  std::string file_, path_;
};

}  // namespace isosid::common
