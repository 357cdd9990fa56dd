// The contact laws of the table (contact/contact_law.hpp): each is checked for what every
// contact path relies on (pressure, stiffness and energy of one potential, and the effective
// gap's sign), and the penalty and Hertz laws against their closed forms.
#include "contact/contact_law.hpp"

#include <algorithm>
#include <catch2/catch.hpp>
#include <cmath>

using namespace isosid::run;

namespace {

/// Every law of the table, at a scale of its kind's size (c_p = 1e15 N/m^3, K = 1e10 N/m^1.5).
std::vector<std::pair<std::string, std::unique_ptr<ContactLaw>>> all_laws() {
  std::vector<std::pair<std::string, std::unique_ptr<ContactLaw>>> laws;
  for (const ContactLaw::Kind kind : {ContactLaw::Kind::Pressure, ContactLaw::Kind::Point})
    for (const std::string& name : contact_law_names(kind))
      laws.emplace_back(name, make_contact_law(name, {kind == ContactLaw::Kind::Pressure ? 1e15 : 1e10}));
  return laws;
}

}  // namespace

TEST_CASE("contact laws: pressure, stiffness and energy are one potential's, zero where the point is free", "[runtime][unit][contact]") {
  const auto laws = all_laws();
  REQUIRE(laws.size() >= 2);
  for (const auto& [name, law] : laws) {
    INFO(name);
    REQUIRE(law);
    CHECK(contact_law_kind(name) == law->kind());
    const double lambdas[] = {0.0, law->linear_stiffness() > 0 ? 2e6 : 0.0};  // a multiplier only where the law takes one
    for (const double lambda : lambdas) {
      for (const double gap : {-3e-6, -1e-6, -2e-7, 1e-7, 5e-6}) {
        INFO("gap " << gap << ", multiplier " << lambda);
        const double p = law->pressure(gap, lambda);
        CHECK(p >= 0);
        // presses exactly where its effective gap is negative
        CHECK((p > 0) == (law->effective_gap(gap, lambda) < 0));
        if (p == 0) {
          CHECK(law->energy(gap, lambda) == 0);
          CHECK(law->stiffness(gap, lambda) == 0);
          continue;
        }
        // central differences of step h: errors O(h^2) relative to the curvature's scale |g|
        const double h = 1e-4 * std::abs(law->effective_gap(gap, lambda));
        const double dE = (law->energy(gap - h, lambda) - law->energy(gap + h, lambda)) / (2 * h);
        const double dp = (law->pressure(gap - h, lambda) - law->pressure(gap + h, lambda)) / (2 * h);
        CHECK(dE == Approx(p).epsilon(1e-6));
        CHECK(dp == Approx(law->stiffness(gap, lambda)).epsilon(1e-6));
      }
    }
  }
}

TEST_CASE("contact laws: the penalty law and Hertz's law against their closed forms", "[runtime][unit][contact]") {
  const auto penalty = make_contact_law("penalty", {4e15});
  REQUIRE(penalty);
  CHECK(penalty->kind() == ContactLaw::Kind::Pressure);
  CHECK(penalty->linear_stiffness() == 4e15);
  CHECK(penalty->pressure(-2e-9) == Approx(8e6));
  CHECK(penalty->energy(-2e-9) == Approx(0.5 * 4e15 * 4e-18));
  // augmented Lagrangian: lambda - c_p g, pressing at a small positive gap
  CHECK(penalty->pressure(1e-9, 1e7) == Approx(6e6));
  CHECK(penalty->effective_gap(1e-9, 1e7) == Approx(1e-9 - 2.5e-9));

  const auto hertz = make_contact_law("hertz", {2e10});
  REQUIRE(hertz);
  CHECK(hertz->kind() == ContactLaw::Kind::Point);
  CHECK(hertz->linear_stiffness() == 0);  // no exact contact, no gap space
  const double delta = 4e-6;
  CHECK(hertz->pressure(-delta) == Approx(2e10 * std::pow(delta, 1.5)));
  CHECK(hertz->stiffness(-delta) == Approx(1.5 * 2e10 * std::sqrt(delta)));
  CHECK(hertz->energy(-delta) == Approx(0.4 * 2e10 * std::pow(delta, 2.5)));
  CHECK(hertz->effective_gap(-delta, 0) == -delta);
}

TEST_CASE("contact laws: the table knows its names and kinds, and nothing else", "[runtime][unit][contact][bad-input]") {
  CHECK(make_contact_law("coulomb", {1.0}) == nullptr);
  CHECK_FALSE(contact_law_kind("coulomb").has_value());
  CHECK(contact_law_kind("penalty") == ContactLaw::Kind::Pressure);
  CHECK(contact_law_kind("hertz") == ContactLaw::Kind::Point);
  const auto pressure = contact_law_names(ContactLaw::Kind::Pressure);
  CHECK(std::find(pressure.begin(), pressure.end(), "penalty") != pressure.end());
  CHECK(std::find(pressure.begin(), pressure.end(), "hertz") == pressure.end());
}
