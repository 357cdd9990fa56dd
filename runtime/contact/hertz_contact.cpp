// Hertz's law between rigid spheres; see hertz_contact.hpp.
#include "contact/hertz_contact.hpp"

#include <cmath>

namespace isosid::run {

HertzContact::HertzContact(const HertzContactSpec& spec, const FloatingBody& a, double ra, const FloatingBody& b, double rb)
    : spec_(spec), a_(a), b_(b), ra_(ra), rb_(rb) {
  const double compliance = (1 - spec.poisson_ratio[0] * spec.poisson_ratio[0]) / spec.youngs_modulus[0] +
                            (1 - spec.poisson_ratio[1] * spec.poisson_ratio[1]) / spec.youngs_modulus[1];
  const double effective_radius = ra * rb / (ra + rb);
  stiffness_ = 4.0 / 3.0 / compliance * std::sqrt(effective_radius);
  law_ = make_contact_law("hertz", {stiffness_});
}

double HertzContact::gap(const double* y) const { return (a_.r(y) - b_.r(y)).norm() - ra_ - rb_; }

double HertzContact::gap_rate(const double* y) const {
  const Eigen::Vector3d between = a_.r(y) - b_.r(y);
  const double distance = between.norm();
  return distance > 0 ? between.dot(a_.v(y) - b_.v(y)) / distance : 0.0;
}

ContactState HertzContact::apply(const double* y, GeneralizedForce& fa, GeneralizedForce& fb) const {
  ContactState state;
  const Eigen::Vector3d between = a_.r(y) - b_.r(y);
  const double distance = between.norm();
  const double overlap = ra_ + rb_ - distance;
  if (!(overlap > 0) || !(distance > 0)) return state;
  const Eigen::Vector3d normal = between / distance;  // from b to a
  const double magnitude = law_->pressure(-overlap);
  state.force = magnitude * normal;
  state.active_points = 1;
  state.max_penetration = overlap;
  state.penalty_energy = law_->energy(-overlap);
  static const Eigen::MatrixXd no_shapes(3, 0);
  // through both centres: no torque on either sphere
  a_.apply_force(state.force, Eigen::Vector3d::Zero(), no_shapes, a_.orientation(y).toRotationMatrix(), fa);
  b_.apply_force(-state.force, Eigen::Vector3d::Zero(), no_shapes, b_.orientation(y).toRotationMatrix(), fb);
  return state;
}

}  // namespace isosid::run
