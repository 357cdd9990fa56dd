// Consistency checks of a SID: shapes against nq, finite values, symmetry, positive mass.
#pragma once
#include "isosid/format/sid.hpp"

#include <string>

namespace isosid::format {

/// Throws InputError(file, field, problem) for the first inconsistency found.
void validate_sid(const Sid& sid, const std::string& file);

}  // namespace isosid::format
