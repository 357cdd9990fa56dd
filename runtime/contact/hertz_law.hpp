// Hertz's law between two elastic spheres (Johnson, Contact Mechanics, eq. 4.22-4.23): an
// overlap delta = -g carries the force K delta^(3/2) and stores 2/5 K delta^(5/2). It has no
// multiplier: exact contact does not apply.
#pragma once
#include "contact/contact_law.hpp"

#include <cmath>

namespace isosid::run {

class HertzLaw final : public ContactLaw {
public:
  /// K = 4/3 E* sqrt(R*), N/m^1.5.
  explicit HertzLaw(double stiffness) : k_(stiffness) {}

  Kind kind() const override { return Kind::Point; }
  double pressure(double gap, double = 0) const override {
    const double overlap = -gap;
    return overlap > 0 ? k_ * overlap * std::sqrt(overlap) : 0.0;
  }
  double stiffness(double gap, double = 0) const override { return gap < 0 ? 1.5 * k_ * std::sqrt(-gap) : 0.0; }
  double energy(double gap, double = 0) const override { return gap < 0 ? 0.4 * pressure(gap) * -gap : 0.0; }
  double effective_gap(double gap, double) const override { return gap; }

private:
  double k_;
};

}  // namespace isosid::run
