// What a run reports of one Hertz contact between rigid spheres (contact/hertz_contact.hpp):
// its force and overlap at the output samples, and each impact from the accepted steps:
// onset and release (where the surfaces' gap, smooth in time, crosses zero between two
// steps, found by linear interpolation), peak force and its time, impulse. The peak is that
// of the deepest overlap, found between the two steps where the gap's rate changes sign by
// the cubic through their gaps and rates: the largest force at the steps alone falls short by
// up to about 1.5 (pi h / 2 T)^2 / 2 for steps h in an impact of duration T (the overlap's
// shortfall of a half-sine, times the force's 1.5 power; scene E's Hertz variant: 0.3 %).
#pragma once
#include "contact/hertz_contact.hpp"
#include "isosid/format/hdf5_file.hpp"

#include <nlohmann/json.hpp>
#include <vector>

namespace isosid::run {

class HertzContactLog {
public:
  explicit HertzContactLog(const HertzContact& contact) : contact_(contact) {}

  void sample(const ContactState& state);
  void step(double t, const double* y, const ContactState& state);
  /// /hertz_contacts/NAME: force (n x 3, on the body), overlap (n)
  void write(format::h5::Writer& w) const;
  nlohmann::json summary() const;

private:
  struct Impact {
    double start = 0, end = -1, peak_force = 0, peak_time = 0, impulse = 0;
  };
  const HertzContact& contact_;
  std::vector<double> force_, overlap_;  ///< per sample: 3, 1
  std::vector<Impact> impacts_;
  bool started_ = false, touching_ = false;
  double last_t_ = 0, last_gap_ = 0, last_rate_ = 0, last_force_ = 0;
};

}  // namespace isosid::run
