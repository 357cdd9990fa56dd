// Several observers of one run; see observer_list.hpp.
#include "solve/observer_list.hpp"

#include <algorithm>

namespace isosid::run {

void ObserverList::sample(double t, const double* y) {
  for (SimulationObserver* o : observers_) o->sample(t, y);
}

void ObserverList::step(double t, const double* y) {
  for (SimulationObserver* o : observers_) o->step(t, y);
}

void ObserverList::contact_event(int contact, bool closing, double t) {
  for (SimulationObserver* o : observers_) o->contact_event(contact, closing, t);
}

void ObserverList::touch(int contact, double t, const Touch& touch) {
  for (SimulationObserver* o : observers_) o->touch(contact, t, touch);
}

void ObserverList::progress(double t, double end_time, long steps) {
  for (SimulationObserver* o : observers_) o->progress(t, end_time, steps);
}

bool ObserverList::stop_requested() const {
  return std::any_of(observers_.begin(), observers_.end(), [](const SimulationObserver* o) { return o->stop_requested(); });
}

bool ObserverList::interrupt_requested() const {
  return std::any_of(observers_.begin(), observers_.end(), [](const SimulationObserver* o) { return o->interrupt_requested(); });
}

}  // namespace isosid::run
