// Study files and their cases; see study_file.hpp.
#include "study_file.hpp"

#include "isosid/common/number_text.hpp"
#include "isosid/common/toml_fields.hpp"

#include <algorithm>
#include <charconv>
#include <cmath>
#include <filesystem>
#include <numeric>
#include <random>
#include <sstream>

namespace isosid::sweep {
namespace {

/// More cases than any study on one machine or cluster allocation should hold in one table.
constexpr long long kMaxCases = 1'000'000;

/// A number as TOML text: the shortest that reads back to the same double, and a float.
std::string exact_text(double v) {
  if (!std::isfinite(v)) return std::isnan(v) ? "nan" : (v > 0 ? "inf" : "-inf");
  char text[32];
  const auto end = std::to_chars(text, text + sizeof text, v).ptr;
  std::string out(text, end);
  if (out.find_first_of(".e") == std::string::npos) out += ".0";
  return out;
}

/// A value as TOML text: numbers as written (shortest round trip), the rest as TOML prints it.
std::string value_text(const toml::node& node) {
  if (const auto* x = node.as_floating_point()) return exact_text(x->get());
  if (const auto* i = node.as_integer()) return std::to_string(i->get());
  std::ostringstream out;
  node.visit([&out](const auto& v) { out << v; });
  return out.str();
}

/// `count` values from lo to hi, evenly in value or in its logarithm.
std::vector<std::string> spaced(double lo, double hi, int count, bool log_scale) {
  std::vector<std::string> out;
  for (int i = 0; i < count; ++i) {
    const double f = count == 1 ? 0.0 : double(i) / (count - 1);
    double v = log_scale ? std::exp(std::log(lo) + f * (std::log(hi) - std::log(lo))) : lo + f * (hi - lo);
    if (i == 0) v = lo;  // the ends as given, not through exp(log())
    if (i == count - 1 && count > 1) v = hi;
    out.push_back(exact_text(v));
  }
  return out;
}

/// A key's syntax: names between dots, and `model.<body>.<key>` with both parts.
void check_key(const common::TomlView& p, const std::string& key) {
  if (key.empty() || key.front() == '.' || key.back() == '.' || key.find("..") != std::string::npos)
    p.fail("key", "'" + key + "' is not a dotted key (e.g. flexible_body.0.velocity, model.beam.material.density)");
  if (key.rfind("model.", 0) == 0 && key.find('.', 6) == std::string::npos)
    p.fail("key", "'" + key + "': a model key is model.<body>.<key into its model file>");
}

/// `raw` is the [[parameter]] table `p` views (its values may be of any TOML type).
Parameter read_parameter(const common::TomlView& p, const toml::table& raw, Sampling sampling) {
  p.allow_only({"key", "values", "range", "count", "spacing"});
  Parameter out;
  const bool together = raw.get_as<toml::array>("key") != nullptr;
  out.keys = together ? p.strings("key") : std::vector<std::string>{p.string("key")};
  if (out.keys.empty()) p.fail("key", "needs at least one dotted key");
  for (const std::string& key : out.keys) check_key(p, key);
  if (p.has("values") == p.has("range")) p.fail("values", "give either values (a list) or a range [from, to]");
  const std::string spacing = p.string("spacing", "linear");
  if (spacing != "linear" && spacing != "log") p.fail("spacing", "must be \"linear\" or \"log\", is \"" + spacing + "\"");
  out.log_scale = spacing == "log";
  if (p.has("values")) {
    if (sampling == Sampling::LatinHypercube) p.fail("values", "a Latin hypercube samples ranges: give range = [from, to]");
    const toml::array* values = raw.get_as<toml::array>("values");
    if (!values || values->empty()) p.fail("values", "must be a non-empty list");
    for (const toml::node& v : *values) {
      if (!together) {
        out.values.push_back({value_text(v)});
        continue;
      }
      const toml::array* set = v.as_array();  // keys set together: one list of values per case
      if (!set || set->size() != out.keys.size())
        p.fail("values", "with " + std::to_string(out.keys.size()) + " keys set together, each value is a list of " +
                             std::to_string(out.keys.size()) + " (one per key)");
      std::vector<std::string> texts;
      for (const toml::node& x : *set) texts.push_back(value_text(x));
      out.values.push_back(texts);
    }
    return out;
  }
  if (together) p.fail("range", "keys set together take values (a list of lists), not a range");
  const std::vector<double> range = p.numbers("range");
  if (range.size() != 2) p.fail("range", "must be [from, to]");
  out.lo = range[0];
  out.hi = range[1];
  if (out.log_scale && !(out.lo > 0 && out.hi > 0)) p.fail("range", "a log spacing needs positive ends");
  if (sampling == Sampling::LatinHypercube) {
    if (p.has("count")) p.fail("count", "a Latin hypercube takes study.samples points, not a count per parameter");
    return out;
  }
  for (std::string& v : spaced(out.lo, out.hi, p.integer_in("count", 1, 100000), out.log_scale)) out.values.push_back({std::move(v)});
  return out;
}

}  // namespace

std::string Parameter::name() const {
  std::string out;
  for (const std::string& k : keys) out += (out.empty() ? "" : " + ") + k;
  return out;
}

Study read_study_file(const std::string& path) {
  const toml::table root = common::parse_toml_file(path);
  const common::TomlView top(root, path);
  top.allow_only({"scene", "sampling", "samples", "seed", "parameter", "collect"});
  Study s;
  s.file = path;
  s.scene_file = (std::filesystem::path(path).parent_path() / top.string("scene")).lexically_normal().string();
  const std::string sampling = top.string("sampling", "grid");
  if (sampling == "grid") s.sampling = Sampling::Grid;
  else if (sampling == "zip") s.sampling = Sampling::Zip;
  else if (sampling == "latin_hypercube") s.sampling = Sampling::LatinHypercube;
  else top.fail("sampling", "must be \"grid\", \"zip\" or \"latin_hypercube\", is \"" + sampling + "\"");
  if (s.sampling == Sampling::LatinHypercube) {
    s.samples = top.integer_in("samples", 1, int(kMaxCases));
    s.seed = (unsigned long long)top.integer("seed", 1);
  } else {
    for (const char* key : {"samples", "seed"})
      if (top.has(key)) top.fail(key, "only for sampling = \"latin_hypercube\"");
  }
  const std::vector<common::TomlView> parameters = top.tables("parameter");
  for (std::size_t i = 0; i < parameters.size(); ++i)
    s.parameters.push_back(read_parameter(parameters[i], *root["parameter"][i].as_table(), s.sampling));
  if (s.parameters.empty()) top.fail("parameter", "a study needs at least one [[parameter]]");
  std::vector<std::string> varied;
  for (const Parameter& p : s.parameters)
    for (const std::string& key : p.keys) {
      if (std::find(varied.begin(), varied.end(), key) != varied.end()) top.fail("parameter", "key '" + key + "' is varied twice");
      varied.push_back(key);
    }
  if (s.sampling == Sampling::Zip)
    for (const Parameter& p : s.parameters)
      if (p.values.size() != s.parameters.front().values.size())
        top.fail("parameter", "sampling = \"zip\" needs as many values of '" + p.name() + "' as of '" + s.parameters.front().name() + "'");
  if (s.sampling == Sampling::Grid) {
    double cases = 1;
    for (const Parameter& p : s.parameters) cases *= double(p.values.size());
    if (cases > double(kMaxCases)) top.fail("parameter", "the grid has " + common::number_text(cases) + " cases, more than 1e6");
  }
  if (top.has("collect")) s.collect = top.strings("collect");
  return s;
}

std::vector<Case> plan_cases(const Study& study) {
  std::vector<Case> cases;
  const std::size_t np = study.parameters.size();
  if (study.sampling == Sampling::LatinHypercube) {
    // one point in each of `samples` equal strata per parameter, strata paired by seeded
    // shuffles. The engine's raw numbers are the same everywhere (std::mt19937_64 is specified
    // to the bit); the standard library's distributions and shuffle are not, so both are here.
    std::mt19937_64 random(study.seed);
    const auto unit = [&random] { return double(random() >> 11) * 0x1.0p-53; };  // [0, 1)
    const int n = study.samples;
    std::vector<std::vector<std::string>> columns(np);
    for (std::size_t j = 0; j < np; ++j) {
      const Parameter& p = study.parameters[j];
      std::vector<int> strata(std::size_t(n), 0);
      std::iota(strata.begin(), strata.end(), 0);
      for (std::size_t i = strata.size(); i > 1; --i)  // Fisher-Yates
        std::swap(strata[i - 1], strata[std::size_t(unit() * double(i))]);
      for (int i = 0; i < n; ++i) {
        const double f = (strata[std::size_t(i)] + unit()) / n;
        const double v = p.log_scale ? std::exp(std::log(p.lo) + f * (std::log(p.hi) - std::log(p.lo))) : p.lo + f * (p.hi - p.lo);
        columns[j].push_back(exact_text(v));
      }
    }
    for (int i = 0; i < n; ++i) {
      Case c{i, {}};
      for (std::size_t j = 0; j < np; ++j) c.settings.push_back({study.parameters[j].keys.front(), columns[j][std::size_t(i)]});
      cases.push_back(c);
    }
    return cases;
  }
  const auto set = [](Case& c, const Parameter& p, std::size_t value) {
    for (std::size_t k = 0; k < p.keys.size(); ++k) c.settings.push_back({p.keys[k], p.values[value][k]});
  };
  if (study.sampling == Sampling::Zip) {
    for (std::size_t i = 0; i < study.parameters.front().values.size(); ++i) {
      Case c{int(i), {}};
      for (const Parameter& p : study.parameters) set(c, p, i);
      cases.push_back(c);
    }
    return cases;
  }
  std::vector<std::size_t> at(np, 0);  // a mixed-radix counter, the last parameter fastest
  for (int index = 0;; ++index) {
    Case c{index, {}};
    for (std::size_t j = 0; j < np; ++j) set(c, study.parameters[j], at[j]);
    cases.push_back(c);
    std::size_t j = np;
    while (j > 0 && ++at[j - 1] == study.parameters[j - 1].values.size()) at[--j] = 0;
    if (j == 0) return cases;
  }
}

}  // namespace isosid::sweep
