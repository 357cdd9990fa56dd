// The guard against chattering contact events: kLimit events within kSpan stop a run, events
// spread as a real contact's are (one per point per microsecond) never do.
#include "solve/event_chatter.hpp"

#include <catch2/catch.hpp>

using isosid::run::EventChatter;

TEST_CASE("contact events faster than any contact are chatter", "[chatter]") {
  SECTION("a point that flips within round-off: kLimit events 1e-14 s apart") {
    EventChatter chatter(2);
    int events = 0;
    bool stop = false;
    for (double t = 0.97896; !stop && events < 10 * EventChatter::kLimit; t += 1e-14, ++events) stop = chatter.observe(1, t);
    CHECK(stop);
    CHECK(events == EventChatter::kLimit);
    CHECK(chatter.worst() == 1);
  }
  SECTION("the contact with most of the events is named") {
    EventChatter chatter(3);
    bool stop = false;
    for (int i = 0; !stop; ++i) stop = chatter.observe(i % 4 == 0 ? 0 : 2, 1.0 + 1e-15 * i);
    CHECK(chatter.worst() == 2);
  }
  SECTION("a fine impact: 2000 points closing and opening over 70 us never stop it") {
    EventChatter chatter(1);
    bool stop = false;
    for (int i = 0; i < 4000; ++i) stop = stop || chatter.observe(0, 0.28 + 70e-6 * i / 4000);
    CHECK_FALSE(stop);
  }
  SECTION("bursts of just under kLimit events, each more than kSpan after the last, never stop it") {
    EventChatter chatter(1);
    bool stop = false;
    for (int burst = 0; burst < 5; ++burst)
      for (int i = 0; i < EventChatter::kLimit - 1; ++i) stop = stop || chatter.observe(0, burst * 2 * EventChatter::kSpan + 1e-15 * i);
    CHECK_FALSE(stop);
  }
}
