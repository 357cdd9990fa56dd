// A run's warnings in summary.json; see warning_list.hpp.
#include "output/warning_list.hpp"

#include <algorithm>

namespace isosid::run {

bool is_expected(const std::vector<std::string>& expected_kinds, const std::string& kind) {
  return std::find(expected_kinds.begin(), expected_kinds.end(), kind) != expected_kinds.end();
}

void add_warning(nlohmann::json& summary, const RunWarning& warning, const std::vector<std::string>& expected_kinds) {
  for (const char* key : {"warnings", "expected_warnings"})
    if (!summary.contains(key)) summary[key] = nlohmann::json::array();
  nlohmann::json& list = summary[is_expected(expected_kinds, warning.kind) ? "expected_warnings" : "warnings"];
  if (std::find(list.begin(), list.end(), warning.text) == list.end()) list.push_back(warning.text);
}

void remove_warning(nlohmann::json& summary, const std::string& text) {
  for (const char* key : {"warnings", "expected_warnings"}) {
    if (!summary.contains(key)) continue;
    nlohmann::json& list = summary[key];
    list.erase(std::remove(list.begin(), list.end(), nlohmann::json(text)), list.end());
  }
}

}  // namespace isosid::run
