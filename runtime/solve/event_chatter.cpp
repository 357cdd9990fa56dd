// Chattering contact events; see event_chatter.hpp.
#include "solve/event_chatter.hpp"

#include <algorithm>

namespace isosid::run {

bool EventChatter::observe(int contact, double t) {
  if (total_ == 0 || t - start_ > kSpan) {  // a new window from this event
    std::fill(count_.begin(), count_.end(), 0);
    total_ = 0;
    start_ = t;
  }
  ++count_[std::size_t(contact)];
  return ++total_ >= kLimit;
}

int EventChatter::worst() const { return int(std::max_element(count_.begin(), count_.end()) - count_.begin()); }

}  // namespace isosid::run
