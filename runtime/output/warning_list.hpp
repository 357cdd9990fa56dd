// A run's warnings in summary.json: "warnings" holds those that call for attention,
// "expected_warnings" those of the kinds the scene declared expected ([output]
// expected_warnings). Both are lists of texts; each text names its cause and its fix.
#pragma once
#include "scene/run_warning.hpp"

#include <nlohmann/json.hpp>
#include <string>
#include <vector>

namespace isosid::run {

/// Whether the scene's expected kinds name `kind`.
bool is_expected(const std::vector<std::string>& expected_kinds, const std::string& kind);

/// Adds one warning to the summary's list it belongs to (both lists are created if missing).
void add_warning(nlohmann::json& summary, const RunWarning& warning, const std::vector<std::string>& expected_kinds);

/// Removes a warning's text from both lists (a phase's warning that the whole run does not bear out).
void remove_warning(nlohmann::json& summary, const std::string& text);

}  // namespace isosid::run
