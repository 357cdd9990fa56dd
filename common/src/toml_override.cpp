// Overrides by dotted key; see toml_override.hpp.
#include "isosid/common/toml_fields.hpp"

#include "isosid/format/error.hpp"

#include <charconv>

namespace isosid::common {
namespace {

std::vector<std::string> split_key(const std::string& key) {
  std::vector<std::string> parts;
  std::size_t start = 0;
  for (;;) {
    const std::size_t dot = key.find('.', start);
    parts.push_back(key.substr(start, dot == std::string::npos ? std::string::npos : dot - start));
    if (dot == std::string::npos) return parts;
    start = dot + 1;
  }
}

/// An array index, or -1 if `part` is not a decimal number.
long index_of(const std::string& part) {
  long index = -1;
  const auto [end, error] = std::from_chars(part.data(), part.data() + part.size(), index);
  return error == std::errc() && end == part.data() + part.size() && index >= 0 ? index : -1;
}

toml::node* child(toml::node& node, const std::string& part, const std::string& file, const std::string& key,
                  const std::string& through) {
  if (toml::array* array = node.as_array()) {
    const long index = index_of(part);
    if (index < 0) throw format::InputError(file, key, "'" + through + "' is an array: index it by a number from 0");
    if (std::size_t(index) >= array->size())
      throw format::InputError(file, key, "'" + through + "' has " + std::to_string(array->size()) + " entries (indices from 0)");
    return array->get(std::size_t(index));
  }
  if (toml::table* table = node.as_table()) {
    if (!table->contains(part))
      throw format::InputError(file, key, "no '" + part + "' in " + (through.empty() ? "the file" : "'" + through + "'") + " to override");
    return table->get(part);
  }
  throw format::InputError(file, key, "'" + through + "' is a value, not a table or an array");
}

/// The value text parsed as TOML (a one-key document).
toml::node& parsed_value(toml::table& holder, const TomlOverride& o, const std::string& file) {
  try {
    holder = toml::parse("value = " + o.value);
  } catch (const toml::parse_error& e) {
    std::string what(e.description());
    for (char& c : what)
      if (c == '\n') c = ' ';
    throw format::InputError(file, o.key, "override value '" + o.value + "' is not a TOML value (" + what + ")");
  }
  return *holder.get("value");
}

}  // namespace

std::vector<TomlOverride> parse_overrides(const std::vector<std::string>& settings, const std::string& option) {
  std::vector<TomlOverride> out;
  for (const std::string& setting : settings) {
    const std::size_t eq = setting.find('=');
    if (eq == std::string::npos || eq == 0) throw format::InputError("", option, "'" + setting + "' is not KEY=VALUE");
    out.push_back({setting.substr(0, eq), setting.substr(eq + 1)});
  }
  return out;
}

void apply_overrides(toml::table& root, const std::vector<TomlOverride>& overrides, const std::string& file) {
  for (const TomlOverride& o : overrides) {
    const std::vector<std::string> parts = split_key(o.key);
    for (const std::string& part : parts)
      if (part.empty()) throw format::InputError(file, o.key, "an override key needs names between its dots");
    toml::node* node = &root;
    std::string through;
    for (std::size_t i = 0; i + 1 < parts.size(); ++i) {
      node = child(*node, parts[i], file, o.key, through);
      through += (through.empty() ? "" : ".") + parts[i];
    }
    toml::table holder;
    toml::node& value = parsed_value(holder, o, file);
    const std::string& last = parts.back();
    if (toml::table* table = node->as_table()) {
      table->insert_or_assign(last, std::move(value));
    } else if (toml::array* array = node->as_array()) {
      const long index = index_of(last);
      if (index < 0) throw format::InputError(file, o.key, "'" + through + "' is an array: index it by a number from 0");
      if (std::size_t(index) >= array->size())
        throw format::InputError(file, o.key, "'" + through + "' has " + std::to_string(array->size()) + " entries (indices from 0)");
      array->replace(array->cbegin() + index, std::move(value));
    } else {
      throw format::InputError(file, o.key, "'" + through + "' is a value, not a table or an array");
    }
  }
}

}  // namespace isosid::common
