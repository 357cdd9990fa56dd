// Test support: an observer of the steps at which a simulation's first contact is paired in gap
// space (condensation/gap_pairing.hpp), for tests that check the pairs there.
#pragma once
#include "solve/multibody_system.hpp"
#include "solve/simulation.hpp"

namespace isosid::test {

struct PairedStepObserver : run::SimulationObserver {
  const run::Simulation* simulation = nullptr;  ///< set before the run
  int paired_steps = 0;
  void sample(double, const double*) override {}
  void contact_event(int, bool, double) override {}
  void step(double, const double* y) override {
    const run::SurfaceContact& c = simulation->system().contacts()[0];
    if (!c.gap_pairing().paired()) return;
    ++paired_steps;
    paired_step(c, c.gap_pairing(), y);
  }
  /// Called after each step at y at which the contact is paired.
  virtual void paired_step(const run::SurfaceContact& contact, const run::GapPairing& pairing, const double* y) = 0;
};

}  // namespace isosid::test
