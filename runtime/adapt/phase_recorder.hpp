// The observer of one phase of an adaptive run ([R2] Fig. 2, docs/references.md): it records like a
// plain run's Recorder and says when the phase is over: a coarse phase at the first touch of a
// contact with an adaptive body, an impact phase once its contact's surfaces are apart again,
// or as soon as its load reaches beyond the refined region ([R2]: an edge element in
// contact makes the rest of the impact pointless). It measures the region's utilization.
#pragma once
#include "output/recorder.hpp"
#include "solve/simulation.hpp"

#include <functional>
#include <optional>
#include <vector>

namespace isosid::run {

class PhaseRecorder : public Recorder {
public:
  /// A touch of a contact's exact surfaces.
  struct Found {
    int contact;
    double time;
    Touch touch;
  };
  /// The impact of an impact phase: its contact, the centre of the slave's refined region
  /// (world, at the phase's start state; the touch where the slave is not refined) and the
  /// region's width. A coarse phase
  /// after an impact names that impact's contact in `after`.
  struct Impact {
    int contact = -1;
    Eigen::Vector3d point = Eigen::Vector3d::Zero();
    double width = 0;
    bool stop_beyond = true;  ///< stop once the load leaves the refined region (not on the last try)
    int after = -1;
    /// The penalty probes' window (penalty_search.hpp): this many accepted steps since the
    /// contact closed.
    int window_contact_steps = 0;
    /// Stop at the first accepted step after a quasistatic solve failed (a step retried
    /// smaller): [R2]'s error that lowers the penalty.
    bool stop_on_error = false;
  };
  /// An impact phase starts where its contact's surfaces touch: that touch is taken as found,
  /// so the phase ends once they have been apart again after the contact opened.
  /// `adaptive_contact` (per contact: an adaptive body takes part) and `stop_requested` must
  /// outlive the recorder.
  PhaseRecorder(const Simulation& simulation, const std::vector<bool>& adaptive_contact, const Impact& impact,
                const std::function<bool()>& stop_requested);

  void touch(int k, double t, const Touch& touch) override;
  void contact_event(int k, bool closing, double t) override;
  void step(double t, const double* y) override;
  bool stop_requested() const override { return phase_over() || stop_requested_(); }
  /// A signal ends the phase within the step; the loop's own reasons wait for the next sample.
  bool interrupt_requested() const override { return stop_requested_(); }

  /// The phase ended as the loop asks (a touch, an impact over, the load beyond its region, an
  /// error).
  bool phase_over() const { return found_.has_value() || impact_over_ || (beyond_ && impact_.stop_beyond) || !error_.empty(); }
  /// Impact phases: the phase up to its window_contact_steps-th contact step (or so far, if
  /// it has fewer): the step's time, the contact's largest force and the steps up to it.
  struct Window {
    double end = 0, peak_force = 0;
    long steps = 0;
  };
  const Window& window() const { return window_; }
  /// Impact phases: the refined region's centre in the world at state y (it moves with the slave).
  Eigen::Vector3d region_centre(const double* y) const;
  /// The error that stopped the phase (stop_on_error), empty if none.
  const std::string& error() const { return error_; }
  /// Coarse phases: the touch that ended it.
  const std::optional<Found>& found() const { return found_; }
  /// Impact phases: the largest distance of a loaded point from the region's centre over half the width.
  double utilization() const { return reach_ / (impact_.width / 2); }
  /// Touches of other adaptive contacts during this impact (they run on its models).
  const std::vector<Found>& overlapping() const { return overlapping_; }
  /// The load reached beyond the refined region (the phase stopped there unless it was the last try).
  bool beyond() const { return beyond_; }

private:
  const Simulation& simulation_;
  const MultibodySystem& system_;
  const std::vector<bool>& adaptive_contact_;
  Impact impact_;
  const std::function<bool()>& stop_requested_;
  std::optional<Found> found_;
  std::vector<Found> overlapping_;
  Eigen::Vector3d touch_in_body_ = Eigen::Vector3d::Zero();
  double reach_ = 0;
  long restarts_at_start_ = 0;
  int contact_steps_ = 0;
  long steps_ = 0;
  Window window_;
  std::string error_;
  bool loaded_ = false, impact_over_ = false, beyond_ = false;
};

}  // namespace isosid::run
