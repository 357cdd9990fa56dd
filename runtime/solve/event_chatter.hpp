// Contact events faster than any contact can make them. A contact point whose gap changes
// sign back and forth within round-off (a load at the edge of a contact surface, bodies meeting
// beyond their surfaces) stops the integrator at every sign change: the run then takes
// thousands of events per nanosecond and makes no progress in time. A real contact's points
// close and open over the contact's growth, microseconds, so kLimit events within kSpan is
// no contact the run can resolve: the run fails there, with its results so far.
#pragma once
#include <string>
#include <vector>

namespace isosid::run {

class EventChatter {
public:
  static constexpr int kLimit = 1000;
  static constexpr double kSpan = 1e-9;  ///< s

  explicit EventChatter(std::size_t contacts) : count_(contacts, 0) {}
  /// Counts an event of `contact` at t; true once kLimit events fell within kSpan (then
  /// worst() is the contact with most of them).
  bool observe(int contact, double t);
  int worst() const;

private:
  std::vector<int> count_;  ///< per contact, since start_
  int total_ = 0;
  double start_ = -1;       ///< time of the first event counted
};

}  // namespace isosid::run
