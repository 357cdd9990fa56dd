// Strict TOML field access; see toml_fields.hpp.
#include "isosid/common/toml_fields.hpp"

#include "isosid/common/toml_bounds.hpp"
#include "isosid/format/file_kind.hpp"

#include <cmath>
#include <filesystem>
#include <fstream>
#include <iterator>
#include <sstream>

namespace isosid::common {

toml::table parse_toml_file(const std::string& path) {
  format::require_input_file(path);  // a FIFO would block the read, a directory has no text
  std::error_code ec;
  const auto bytes = std::filesystem::file_size(path, ec);
  if (ec) throw format::InputError(path, "", "cannot be read");
  if (bytes > kMaxTomlBytes)
    throw format::InputError(path, "", "larger than " + std::to_string(kMaxTomlBytes >> 20) + " MiB: not a model or scene file");
  std::ifstream in(path, std::ios::binary);
  const std::string text((std::istreambuf_iterator<char>(in)), std::istreambuf_iterator<char>());
  if (!in && !in.eof()) throw format::InputError(path, "", "cannot be read");
  return parse_toml_text(text, path);
}

toml::table parse_toml_text(const std::string& text, const std::string& origin) {
  if (text.size() > kMaxTomlBytes)
    throw format::InputError(origin, "", "larger than " + std::to_string(kMaxTomlBytes >> 20) + " MiB: not a model or scene file");
  check_toml_nesting(text, origin);
  try {
    return toml::parse(text, origin);
  } catch (const toml::parse_error& e) {
    std::ostringstream where;
    where << "line " << e.source().begin.line << ", column " << e.source().begin.column;
    std::string what(e.description());
    for (char& c : what)
      if (c == '\n') c = ' ';
    throw format::InputError(origin, where.str(), "TOML syntax error: " + what);
  }
}

void TomlView::allow_only(std::initializer_list<const char*> allowed) const {
  for (const auto& [key, value] : *table_) {
    bool known = false;
    for (const char* a : allowed) known = known || key.str() == a;
    if (!known) {
      std::string list;
      for (const char* a : allowed) list += (list.empty() ? "" : ", ") + std::string(a);
      fail(std::string(key.str()), "unknown key (allowed here: " + list + ")");
    }
  }
}

const toml::node& TomlView::node(const std::string& key) const {
  const toml::node* n = table_->get(key);
  if (!n) fail(key, "missing");
  return *n;
}

TomlView TomlView::table(const std::string& key) const {
  const toml::table* t = node(key).as_table();
  if (!t) fail(key, "must be a table");
  return TomlView(*t, file_, field(key));
}

std::optional<TomlView> TomlView::optional_table(const std::string& key) const {
  if (!has(key)) return std::nullopt;
  return table(key);
}

std::vector<TomlView> TomlView::tables(const std::string& key) const {
  std::vector<TomlView> out;
  if (!has(key)) return out;
  const toml::array* a = node(key).as_array();
  if (!a) fail(key, "must be an array of tables ([[" + field(key) + "]])");
  for (std::size_t i = 0; i < a->size(); ++i) {
    const toml::table* t = (*a)[i].as_table();
    if (!t) fail(key, "entry " + std::to_string(i) + " is not a table");
    out.emplace_back(*t, file_, field(key) + "[" + std::to_string(i) + "]");
  }
  return out;
}

double TomlView::as_number(const toml::node& n, const std::string& where) const {
  double v = 0;
  if (auto d = n.value_exact<double>())
    v = *d;
  else if (auto i = n.value_exact<int64_t>())
    v = double(*i);
  else
    throw format::InputError(file_, where, "must be a number");
  if (!std::isfinite(v)) throw format::InputError(file_, where, "must be finite");
  return v;
}

double TomlView::number(const std::string& key) const { return as_number(node(key), field(key)); }
double TomlView::number(const std::string& key, double fallback) const { return has(key) ? number(key) : fallback; }

double TomlView::positive(const std::string& key) const {
  const double v = number(key);
  if (!(v > 0)) fail(key, "must be positive, is " + std::to_string(v));
  return v;
}
double TomlView::positive(const std::string& key, double fallback) const { return has(key) ? positive(key) : fallback; }

long long TomlView::integer(const std::string& key) const {
  auto i = node(key).value_exact<int64_t>();
  if (!i) fail(key, "must be an integer");
  return *i;
}
long long TomlView::integer(const std::string& key, long long fallback) const { return has(key) ? integer(key) : fallback; }

namespace {
std::string range_text(long long lo, long long hi) { return "must lie in " + std::to_string(lo) + ".." + std::to_string(hi); }
}  // namespace

int TomlView::integer_in(const std::string& key, int lo, int hi) const {
  const long long v = integer(key);
  if (v < lo || v > hi) fail(key, range_text(lo, hi) + ", is " + std::to_string(v));
  return int(v);
}
int TomlView::integer_in(const std::string& key, int lo, int hi, int fallback) const {
  return has(key) ? integer_in(key, lo, hi) : fallback;
}

std::vector<int> TomlView::integers_in(const std::string& key, int lo, int hi) const {
  std::vector<int> out;
  const auto values = integers(key);
  for (std::size_t i = 0; i < values.size(); ++i) {
    if (values[i] < lo || values[i] > hi)
      throw format::InputError(file_, field(key) + "[" + std::to_string(i) + "]", range_text(lo, hi) + ", is " + std::to_string(values[i]));
    out.push_back(int(values[i]));
  }
  return out;
}

std::string TomlView::name(const std::string& key) const {
  std::string s = string(key);
  if (s.empty() || s.find('/') != std::string::npos) fail(key, "must be a non-empty name without '/'");
  return s;
}

bool TomlView::holds_string(const std::string& key) const { return has(key) && node(key).is_string(); }

std::string TomlView::string(const std::string& key) const {
  auto s = node(key).value_exact<std::string>();
  if (!s) fail(key, "must be a string");
  // names and paths end at a NUL in HDF5 and the file system: refused rather than cut short
  if (s->find('\0') != std::string::npos) fail(key, "contains a NUL character");
  return *s;
}
std::string TomlView::string(const std::string& key, const std::string& fallback) const {
  return has(key) ? string(key) : fallback;
}

bool TomlView::boolean(const std::string& key, bool fallback) const {
  if (!has(key)) return fallback;
  auto b = node(key).value_exact<bool>();
  if (!b) fail(key, "must be true or false");
  return *b;
}

std::vector<double> TomlView::numbers(const std::string& key) const {
  const toml::array* a = node(key).as_array();
  if (!a) fail(key, "must be an array of numbers");
  std::vector<double> out;
  for (std::size_t i = 0; i < a->size(); ++i) out.push_back(as_number((*a)[i], field(key) + "[" + std::to_string(i) + "]"));
  return out;
}

std::vector<std::vector<double>> TomlView::number_rows(const std::string& key) const {
  const toml::array* a = node(key).as_array();
  if (!a) fail(key, "must be an array of arrays of numbers");
  std::vector<std::vector<double>> out;
  for (std::size_t i = 0; i < a->size(); ++i) {
    const toml::array* row = (*a)[i].as_array();
    const std::string where = field(key) + "[" + std::to_string(i) + "]";
    if (!row) throw format::InputError(file_, where, "must be an array of numbers");
    std::vector<double> r;
    for (std::size_t j = 0; j < row->size(); ++j) r.push_back(as_number((*row)[j], where + "[" + std::to_string(j) + "]"));
    out.push_back(std::move(r));
  }
  return out;
}

std::vector<long long> TomlView::integers(const std::string& key) const {
  const toml::array* a = node(key).as_array();
  if (!a) fail(key, "must be an array of integers");
  std::vector<long long> out;
  for (std::size_t i = 0; i < a->size(); ++i) {
    auto v = (*a)[i].value_exact<int64_t>();
    if (!v) throw format::InputError(file_, field(key) + "[" + std::to_string(i) + "]", "must be an integer");
    out.push_back(*v);
  }
  return out;
}

std::vector<std::string> TomlView::strings(const std::string& key) const {
  const toml::array* a = node(key).as_array();
  if (!a) fail(key, "must be an array of strings");
  std::vector<std::string> out;
  for (std::size_t i = 0; i < a->size(); ++i) {
    auto v = (*a)[i].value_exact<std::string>();
    if (!v) throw format::InputError(file_, field(key) + "[" + std::to_string(i) + "]", "must be a string");
    if (v->find('\0') != std::string::npos)
      throw format::InputError(file_, field(key) + "[" + std::to_string(i) + "]", "contains a NUL character");
    out.push_back(*v);
  }
  return out;
}

}  // namespace isosid::common
