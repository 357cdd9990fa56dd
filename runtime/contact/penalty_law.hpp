// The linear penalty law of Gauss-point contact ([R1] eq. 22, docs/references.md): a point
// inside the target by |g| carries the pressure c_p |g|. Under exact contact (augmented
// Lagrangian) its multiplier lambda shifts it to max(0, lambda - c_p g), and the penalty becomes
// the augmentation.
#pragma once
#include "contact/contact_law.hpp"

#include <algorithm>

namespace isosid::run {

class PenaltyLaw final : public ContactLaw {
public:
  /// c_p > 0, N/m^3.
  explicit PenaltyLaw(double penalty) : c_(penalty) {}

  Kind kind() const override { return Kind::Pressure; }
  double pressure(double gap, double multiplier = 0) const override { return std::max(0.0, multiplier - c_ * gap); }
  double stiffness(double gap, double multiplier = 0) const override { return pressure(gap, multiplier) > 0 ? c_ : 0.0; }
  /// p^2 / (2 c_p): 1/2 c_p g^2 without a multiplier.
  double energy(double gap, double multiplier = 0) const override {
    const double p = pressure(gap, multiplier);
    return 0.5 * p * p / c_;
  }
  double effective_gap(double gap, double multiplier) const override { return gap - multiplier / c_; }
  double linear_stiffness() const override { return c_; }

private:
  double c_;
};

}  // namespace isosid::run
