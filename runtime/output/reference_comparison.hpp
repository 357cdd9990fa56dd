// The comparison of a run's summary with the scene's [reference] values: which figure of the
// summary each reference names, its value and the signed relative error. A summary written
// by one phase or merged from several (the adaptive loop's) compares alike.
#pragma once
#include <map>
#include <nlohmann/json.hpp>
#include <string>

namespace isosid::run {

/// {key: {reference, value (null if the run has none), rel_error (signed: positive where the
/// run measures more), abs_error where the reference is 0}} for `reference`'s keys, from the
/// summary's contacts (the first), bodies (the first), and monitors (the first point monitor's
/// arrival, the first stress monitor's peak). With `from_hertz`, the first contact's Hertz
/// estimate in the summary adds the reference peak force and contact time (`source`: "hertz").
nlohmann::json compare_with_reference(const nlohmann::json& summary, const std::map<std::string, double>& reference,
                                      bool from_hertz = false);

}  // namespace isosid::run
