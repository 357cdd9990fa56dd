// Sides of a NURBS patch and their names, shared by the preprocessor (which writes a contact
// surface's side into the SID) and the SID validator (which checks its points lie on it).
#pragma once
#include <optional>
#include <string>

namespace isosid::format {

/// A boundary side: the face where parameter `direction` is at its lower (end 0) or upper (end 1) bound.
struct PatchSide {
  int direction = 0;
  int end = 0;
  bool operator==(const PatchSide&) const = default;
};

/// Name of parametric direction d: xi, eta, zeta.
const char* direction_name(int d);

/// Canonical side names: xi0, xi1, eta0, eta1, zeta0, zeta1.
std::string side_name(PatchSide side);
std::optional<PatchSide> side_from_name(const std::string& name, int param_dim);

}  // namespace isosid::format
