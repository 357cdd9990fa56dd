// A run's warnings carry a kind, so that a scene can declare the ones it expects
// ([output] expected_warnings): summary.json then lists those apart from the ones that call for
// attention. docs/diagnostics.md explains each kind.
#pragma once
#include <array>
#include <string>
#include <string_view>

namespace isosid::run {

struct RunWarning {
  std::string kind;  ///< one of kWarningKinds
  std::string text;  ///< cause and fix, one line
};

/// Every kind of warning a run gives.
inline constexpr std::array<std::string_view, 11> kWarningKinds = {
    "resolution",          // contact elements coarser than a/8 of the Hertz estimate
    "many_dynamic_modes",  // hundreds of dynamically integrated modes: tiny explicit steps
    "edge_reached",        // a contact loaded the edge elements of its surface's interval
    "interface_left",      // a contact loaded points beyond its Craig-Bampton interface
    "penalty_too_soft",    // penetration beyond half the Hertz approach
    "never_closed",        // a contact that never closed
    "closed_at_end",       // a contact still closed at the end of the run
    "energy",              // an energy balance off by more than 5 % of the energy in motion
    "reference",           // [reference] source = "hertz" without an estimate to compare
    "adaptive_overlap",    // a contact touched during another contact's refined impact
    "adaptive_fit",        // an impact outgrew the widest refined region tried
};

inline bool is_warning_kind(std::string_view kind) {
  for (const std::string_view k : kWarningKinds)
    if (k == kind) return true;
  return false;
}

}  // namespace isosid::run
