// What the contacts contribute to the quasistatic sub-problem ([R2], docs/references.md): every
// candidate contact point of the quasistatic modes z of all bodies (stacked; each body's block
// starts at its quasistatic_offset()) with its gap linearized in z, g(z) ~ g + v^T (z - z0). A
// point carries its contact law's normal pressure p(g, lambda) over its weight w (lambda:
// exact contact's multiplier, else 0), and its generalized force on z is p w (v + t), t the
// friction direction per unit normal force. The Jacobian -df/dz of the pressed points is a sum
// of rank-one terms k w (v + t) v^T (k the law's stiffness), whose low rank keeps the Newton
// solve cheap with hundreds of modes; the recorded free points let the solve find the active
// set on the linear model (contact_model).
#pragma once
#include "contact/contact_law.hpp"

#include <Eigen/Dense>

#include <cmath>
#include <vector>

namespace isosid::run {

struct QuasistaticTerms {
  Eigen::MatrixXd V;           ///< n x capacity: d gap / dz of each recorded point
  Eigen::MatrixXd T;           ///< n x capacity: friction direction per unit normal force (if friction)
  Eigen::VectorXd gap;         ///< m, at the z of the recording
  Eigen::VectorXd multiplier;  ///< Pa: exact contact's lambda (0: penalty)
  std::vector<const ContactLaw*> law;  ///< each point's contact law (its contact's)
  Eigen::VectorXd weight;      ///< m^2
  Eigen::Index count = 0;      ///< recorded points
  bool friction = false;       ///< some point has a friction direction (T in use)
  /// Free points are recorded too where their law's effective gap is below
  /// window + reach |Psi_h|_F, the most a change of z by `reach` (modal units) can close
  /// (against targets with quasistatic modes: below the window): the active set of the linear
  /// model can only grow by points it knows. Points beyond cost the outer Newton an iteration
  /// when they close after all.
  double window = INFINITY;  ///< m
  double reach = 0;          ///< modal units
  /// Some contact's broad phase found its surface clear and recorded nothing of it: its points
  /// are not bounded by the reach.
  bool unseen = false;
  /// Penalty points pressed here that the recording before did not hold: the model a step
  /// was made from did not know them.
  Eigen::Index newly_pressed = 0;
  /// The round-off of the pressed points' gaps, m: differences of positions that are far
  /// larger than the gaps (a few eps of their distance from the world's and bodies' origins).
  double gap_resolution = 0;

  void reset(Eigen::Index n) {
    if (V.rows() != n) V.resize(n, 0), T.resize(n, 0);
    count = 0;
    friction = false;
    unseen = false;
    newly_pressed = 0;
    gap_resolution = 0;
  }
  /// Appends a point with zeroed v and t; fill V.col(k) (and T.col(k)) for the returned k.
  Eigen::Index add_point(double gap_m, double lambda, const ContactLaw& contact_law, double w) {
    if (count == V.cols()) {  // grows geometrically, so steady state is allocation-free
      const Eigen::Index capacity = std::max<Eigen::Index>(16, 2 * V.cols());
      V.conservativeResize(Eigen::NoChange, capacity);
      T.conservativeResize(Eigen::NoChange, capacity);
      gap.conservativeResize(capacity);
      multiplier.conservativeResize(capacity);
      law.resize(std::size_t(capacity));
      weight.conservativeResize(capacity);
    }
    V.col(count).setZero();
    T.col(count).setZero();
    gap(count) = gap_m, multiplier(count) = lambda, law[std::size_t(count)] = &contact_law, weight(count) = w;
    return count++;
  }
  /// Pressure of point k at gap g, Pa.
  double pressure(Eigen::Index k, double g) const { return law[std::size_t(k)]->pressure(g, multiplier(k)); }
  /// Its stiffness -dp/dg there, Pa/m.
  double stiffness(Eigen::Index k, double g) const { return law[std::size_t(k)]->stiffness(g, multiplier(k)); }
  /// The energy it stores there per unit weight, J/m^2.
  double energy(Eigen::Index k, double g) const { return law[std::size_t(k)]->energy(g, multiplier(k)); }
  /// How far the generalized contact force at the recorded gaps is known: the gap round-off
  /// moves a pressed point's force by k w |v| per metre (k its law's stiffness).
  double force_resolution() const {
    double sum = 0;
    for (Eigen::Index k = 0; k < count; ++k)
      if (pressure(k, gap(k)) > 0) sum += stiffness(k, gap(k)) * weight(k) * V.col(k).norm();
    return gap_resolution * sum;
  }
};

}  // namespace isosid::run
