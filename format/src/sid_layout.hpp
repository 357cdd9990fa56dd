// Names and units of the SID datasets in the HDF5 layout (documented in format/README.md),
// shared by the writer, the reader and the validator so that messages name real paths.
#pragma once
#include "isosid/format/sid.hpp"

#include <string>
#include <vector>

namespace isosid::format::layout {

struct TermSpec {
  const char* name;   ///< group below /terms
  const char* units;  ///< [q] is the unit of an elastic coordinate (sqrt(kg)*m for mass-normalized modes)
  Taylor Sid::*member;
};

/// The eleven classic SID body terms in the order of the SID standard.
const std::vector<TermSpec>& terms();

inline std::string term_path(const std::string& term) { return "/terms/" + term; }
inline std::string node_path(const std::string& node) { return "/nodes/" + node; }
inline std::string contact_path(const std::string& name) { return "/contact/" + name; }
inline std::string master_path(const std::string& name) { return "/master/" + name; }
inline std::string stress_path(const std::string& name) { return "/stress/" + name; }

}  // namespace isosid::format::layout
