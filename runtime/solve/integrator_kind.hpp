// The integrators a scene can name. Each kind is one row of the table in time_integrator.cpp:
// its name in scene files, whether it steps at the scene's fixed `step` or chooses its steps
// within rtol/atol, and the factory that builds it.
#pragma once
#include <optional>
#include <string>
#include <string_view>

namespace isosid::run {

enum class IntegratorKind { DormandPrince, Implicit, Leapfrog };

/// The kind a scene file names, if any.
std::optional<IntegratorKind> integrator_named(std::string_view name);
/// The kind's name in scene files.
const char* integrator_name(IntegratorKind kind);
/// The names of all kinds, "a, b, c", for messages.
std::string integrator_names();
/// True for a scheme that steps at the scene's fixed `step` (no step-size control).
bool fixed_step(IntegratorKind kind);

}  // namespace isosid::run
