// [R2] Sect. 4.1 and Fig. 3 (docs/references.md): the penalty factor of an adaptive impact, found
// by trial. The penalty is c_p = m 10^e (eq. 8). Quick increase: short probes of the impact's first
// n_con = 30 contact steps raise the exponent by one while they run without error. Slow
// decrease: an error during the impact lowers the leading digit by one and the run goes on
// from its last good step (adaptive_run).
//
// Where this differs from [R2], and why. [R2]'s quasistatic Newton (a finite-difference
// Jacobian with Broyden updates) fails close above the penalty's converging value, so its
// errors end the increase. Ours has the exact Jacobian and does not fail: scene A's sphere runs
// at 5e24 N/m^3, 10^6 times its converged penalty, but needs 470 times the steps (0.1 s of CPU
// become 53 s) and its peak force drifts by 0.5 % (Gauss points over-constrained); at 1e27,
// +20 %. So the increase also stops once a probe's contact force at the window's end agrees
// with the previous decade's to kForceTolerance (the result no longer depends on the penalty,
// [R2]'s aim in its ref. [16]); it keeps the lower of the two. And a probe that needs
// kStepGrowth times the previous decade's steps for the same window counts as an error (the
// [R2]: "increases the computation time, or the numerical integration might even terminate").
#pragma once
#include <string>
#include <vector>

namespace isosid::run {

/// c_p, N/m^3, with [R2]'s steps: times ten, or one off its leading digit.
class PenaltyFactor {
public:
  explicit PenaltyFactor(double value = 0) : value_(value) {}
  double value() const { return value_; }
  /// The exponent raised by one (quick increase).
  PenaltyFactor raised() const { return PenaltyFactor(10 * value_); }
  /// One off the leading digit (slow decrease): 5e18 -> 4e18, 1e18 -> 9e17, 3.93e17 -> 2.93e17,
  /// 1.5e17 -> 1.4e17 (below 2 the digit after it).
  PenaltyFactor lowered() const;

private:
  double value_;
};

/// What one probe of the quick increase found over the window (the first probe's first
/// kContactSteps contact steps; later probes run to the same time).
struct PenaltyProbe {
  PenaltyFactor penalty;
  double force = 0;   ///< N, magnitude of the contact's force at the window's end
  long steps = 0;     ///< accepted steps over the window
  std::string error;  ///< empty: none (the run failed, a quasistatic solve failed, ...)
};

class PenaltySearch {
public:
  /// [R2]'s n_con: contact steps of a probe.
  static constexpr int kContactSteps = 30;
  /// Relative change of the probe's force over one decade below which the penalty has
  /// converged. It must exceed the drift of over-constrained Gauss points, +0.2 % per fourfold
  /// penalty (bench/RESULTS.md, penalty sweep), 0.33 % per decade; 1 % per decade leaves the
  /// kept penalty's own error at about 0.1 % (the compliance error falls tenfold per decade).
  static constexpr double kForceTolerance = 0.01;
  /// A probe needing this many times the previous decade's steps is an error.
  static constexpr double kStepGrowth = 2;
  /// Probes before the search takes the last one as it is (eight decades).
  static constexpr int kMaxProbes = 8;

  explicit PenaltySearch(PenaltyFactor start) : next_(start) {}

  /// The penalty of the next probe.
  PenaltyFactor next() const { return next_; }
  /// Takes the probe of next(); marks step growth as its error.
  void record(PenaltyProbe probe);
  bool done() const { return done_; }
  /// The penalty the impact runs with (once done).
  PenaltyFactor result() const { return result_; }
  /// Why the search ended there.
  const std::string& reason() const { return reason_; }
  const std::vector<PenaltyProbe>& probes() const { return probes_; }

private:
  PenaltyFactor next_, result_;
  bool done_ = false;
  std::string reason_;
  std::vector<PenaltyProbe> probes_;
};

}  // namespace isosid::run
