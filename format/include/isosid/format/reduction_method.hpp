// The reduction methods that make a body's SID: their names in model files ([reduction] method)
// and in a SID's /refmod/reduction_method, and what each makes of the body's coordinates. The
// model readers, the reduction, the SID builder and the runtime ask this one table; a new
// method is a row here and its basis in preprocess/reduce/reduction.cpp.
#pragma once
#include <array>
#include <optional>
#include <string>
#include <string_view>

namespace isosid::format {

enum class ReductionMethod { Modal, CraigBampton, Full, MacNeal, CraigBamptonMassless };

struct ReductionMethodTraits {
  ReductionMethod method;
  std::string_view name;              ///< in model files and SIDs
  /// Its last coordinates are a boundary without mass, the displacements of the control points
  /// under a contact surface ([reduction] boundary_surface); the basis is then not M-orthonormal.
  bool massless_boundary;
  /// It has an interface of nodes with constraint modes ([reduction] interface_surface,
  /// interface_points, interface_center): statically exact where contact loads the surface.
  bool interface_nodes;
  /// [reduction] normal_modes must be at least one (the others may keep none).
  bool needs_normal_modes;
  /// Meshed (isoparametric) bodies offer it too.
  bool meshed_bodies;
};

inline constexpr std::array<ReductionMethodTraits, 5> kReductionMethods{{
    // the lowest free-interface normal modes
    {ReductionMethod::Modal, "modal", false, false, true, true},
    // fixed-interface normal modes and the interface's constraint modes
    {ReductionMethod::CraigBampton, "craig-bampton", false, true, false, true},
    // every normal mode of the model (small bodies, references)
    {ReductionMethod::Full, "full", false, false, false, false},
    // free-interface normal modes and a massless boundary that carries the residual flexibility
    {ReductionMethod::MacNeal, "macneal", true, false, true, false},
    // fixed-interface normal modes and a massless boundary as the interface
    {ReductionMethod::CraigBamptonMassless, "craig-bampton-massless", true, false, true, false},
}};

constexpr const ReductionMethodTraits& traits(ReductionMethod method) {
  for (const ReductionMethodTraits& t : kReductionMethods)
    if (t.method == method) return t;
  return kReductionMethods[0];  // unreachable: every enumerator has its row
}

inline std::string name(ReductionMethod method) { return std::string(traits(method).name); }

/// The method of that name, if any (a SID from elsewhere may name another, a rigid body's "rigid").
inline std::optional<ReductionMethod> reduction_method_named(std::string_view name) {
  for (const ReductionMethodTraits& t : kReductionMethods)
    if (t.name == name) return t.method;
  return std::nullopt;
}

/// The names of the methods whose traits pass `keep`, for messages: "a, b or c", each in
/// `quote` marks.
template <class Keep>
std::string reduction_method_names(Keep keep, const std::string& quote = "") {
  std::string out, last;
  for (const ReductionMethodTraits& t : kReductionMethods) {
    if (!keep(t)) continue;
    if (!last.empty()) out += (out.empty() ? "" : ", ") + last;
    last = quote + std::string(t.name) + quote;
  }
  return out.empty() ? last : out + " or " + last;
}
inline std::string reduction_method_names() {
  return reduction_method_names([](const ReductionMethodTraits&) { return true; });
}

}  // namespace isosid::format
