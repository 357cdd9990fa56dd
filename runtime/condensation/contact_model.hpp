// The quasistatic contact problem on its linear model: every recorded contact point's gap
// linear in the quasistatic modes z (QuasistaticTerms). Without friction the problem minimizes
//   Pi(z0 + d) = 1/2 z^T K z - z . loads + sum w E(g + v^T d)
// with E each point's contact-law energy (1/2 p^2 / c_p for the penalty law, whose forces are
// piecewise linear in z and Pi piecewise quadratic), strictly convex. Semismooth Newton on it (the active set of the
// model's gaps, an Armijo search on the model's energy whose terms cost O(points) per trial)
// ends where the active set repeats, at the model's exact solution. The outer Newton of
// QuasistaticModes then needs one pass over the real contact points per step instead of one
// per line-search trial: against a plane the model is exact and one step solves the problem.
#pragma once
#include "condensation/quasistatic_jacobian.hpp"
#include "condensation/quasistatic_terms.hpp"

#include <vector>

namespace isosid::run {

class ContactModel {
public:
  /// Semismooth Newton iterations before the model solve returns its best step.
  static constexpr int kMaxIterations = 50;

  /// The generalized contact force of the recorded points at gaps `gaps` (its friction part
  /// separately; sized n); returns the merit energy sum w E(g).
  double forces(const QuasistaticTerms& terms, const Eigen::VectorXd& gaps, Eigen::VectorXd& force, Eigen::VectorXd& friction) const;
  /// Collects the Jacobian terms of the points pressed at `gaps`: V = v and, with friction,
  /// U = k w (v + t) in the first r columns of V() and U() (k w itself, k the law's stiffness,
  /// in the first r of weights_, which stand for U = V diag(k w) without friction); returns r.
  Eigen::Index jacobian_terms(const QuasistaticTerms& terms, const Eigen::VectorXd& gaps) const;
  const Eigen::MatrixXd& U() const { return U_; }
  const Eigen::MatrixXd& V() const { return V_; }

  /// Sets the model at z0, where `terms` were recorded: its gaps, forces, residual and energy
  /// there are those of the real problem (the accessors below).
  void start(const QuasistaticJacobian& K, const QuasistaticTerms& terms, const Eigen::VectorXd& z0, const Eigen::VectorXd& loads) const;
  /// The step d from start()'s z0 that solves the linear model: K (z0 + d) - loads =
  /// f(g + V^T d). `conservative`: no friction, so the search minimizes the energy above; with
  /// friction it reduces the model residual's norm. Returns the iterations.
  int solve(const QuasistaticJacobian& K, const QuasistaticTerms& terms, const Eigen::VectorXd& loads, bool conservative,
            Eigen::VectorXd& d) const;
  /// The last solve reached the model's solution (to round-off) within kMaxIterations.
  bool solved() const { return solved_; }
  /// At start()'s z0, then at the last solve's step: the recorded points' gaps in the model
  /// (first terms.count), the generalized contact force and its friction part, the residual
  /// and the merit energy.
  const Eigen::VectorXd& gaps() const { return gaps_; }
  const Eigen::VectorXd& force() const { return force_; }
  const Eigen::VectorXd& friction() const { return friction_; }
  const Eigen::VectorXd& residual() const { return R_; }
  double energy() const { return energy_; }

private:
  /// Residual K z - loads - f at gaps_ into R_; returns the merit energy.
  double model_residual(const QuasistaticJacobian& K, const QuasistaticTerms& terms, const Eigen::VectorXd& z, const Eigen::VectorXd& loads) const;
  /// Merit energy of the recorded points at gaps_ - alpha rates_.
  double energy_along(const QuasistaticTerms& terms, double alpha) const;

  mutable Eigen::MatrixXd U_, V_;
  mutable Eigen::VectorXd weights_;  ///< k w of the Jacobian's terms (k the law's stiffness): U = V diag(weights_) without friction
  mutable Eigen::VectorXd gaps_, rates_, z_, R_, step_, force_, friction_;
  mutable std::vector<char> pressed_;
  mutable bool solved_ = false;
  mutable double energy_ = 0;
};

}  // namespace isosid::run
