// A scene checked against its loaded bodies before the run: values the file reader could not
// judge without the SIDs' materials, elements and frequencies. Each refusal is an InputError
// naming the scene file and the field (exit 2), instead of a run that fails or misleads later.
#pragma once
#include "scene/scene.hpp"
#include "solve/multibody_system.hpp"

#include <string>
#include <vector>

namespace isosid::run {

/// contact[k].penalty: a scene's penalty below kMinPenaltyRatio of the one derived from the
/// contact elements (contact/default_penalty.hpp) lets the bodies pass into each other; one
/// above kMaxPenaltyRatio of it makes steps so short that the run crawls for hours.
void refuse_implausible_penalties(const MultibodySystem& system, const Scene& scene);

/// simulation.step: the leapfrog (Stoermer-Verlet) is stable only for steps below 2/omega of
/// every integrated mode; beyond, the highest grows without bound.
void refuse_unstable_leapfrog_step(const MultibodySystem& system, const Scene& scene);

/// flexible_body[i].angular_velocity: elastic_start = "steady" solves the centrifugal
/// equilibrium, which exists only for spins below the lowest natural frequency (above it
/// the spin softens the body beyond its stiffness).
void refuse_unsteady_spin(const MultibodySystem& system, const Scene& scene);

/// Warnings to print before a run from t0: contacts whose Hertz estimate puts their release
/// after end_time (contact/impact_estimate.hpp, closed_at_end_prediction). The run itself flags
/// a contact still closed at its end (summary.json closed_at_end).
std::vector<std::string> closed_at_end_predictions(const MultibodySystem& system, double t0, double end_time);

}  // namespace isosid::run
