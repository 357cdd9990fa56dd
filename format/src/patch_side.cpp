// Patch side names; see patch_side.hpp.
#include "isosid/format/patch_side.hpp"

namespace isosid::format {
namespace {
const char* const kDirectionNames[3] = {"xi", "eta", "zeta"};
}

const char* direction_name(int d) { return kDirectionNames[d]; }

std::string side_name(PatchSide side) { return std::string(kDirectionNames[side.direction]) + std::to_string(side.end); }

std::optional<PatchSide> side_from_name(const std::string& name, int param_dim) {
  for (int d = 0; d < param_dim && d < 3; ++d)
    for (int e = 0; e < 2; ++e)
      if (name == side_name({d, e})) return PatchSide{d, e};
  return std::nullopt;
}

}  // namespace isosid::format
