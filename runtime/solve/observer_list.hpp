// Several observers of one run, told in the order they were added: the recorder first (its
// sample solves the static problem at y, which the ParaView frames after it draw), then the
// frames, the progress report, and whatever else watches a run (a study's collector).
#pragma once
#include "solve/simulation.hpp"

#include <vector>

namespace isosid::run {

class ObserverList : public SimulationObserver {
public:
  /// Adds an observer (it must outlive the run); later ones hear of each event after it.
  void add(SimulationObserver& observer) { observers_.push_back(&observer); }

  void sample(double t, const double* y) override;
  void step(double t, const double* y) override;
  void contact_event(int contact, bool closing, double t) override;
  void touch(int contact, double t, const Touch& touch) override;
  void progress(double t, double end_time, long steps) override;
  /// Any observer's request ends the phase.
  bool stop_requested() const override;
  bool interrupt_requested() const override;

private:
  std::vector<SimulationObserver*> observers_;
};

}  // namespace isosid::run
