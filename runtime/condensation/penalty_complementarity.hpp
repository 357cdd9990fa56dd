// The penalty contact problem of points whose gaps respond linearly to their forces: with the
// compliance C between the points (g = g_free + C f) and each point's penalty stiffness k_i,
// the forces f_i = k_i max(0, -g_i). It is the linear complementarity problem
//   f >= 0,  w = g_free + (C + K^-1) f >= 0,  f^T w = 0,
// whose matrix is positive definite: one solution, the minimum of 1/2 f^T (C + K^-1) f +
// g_free^T f over f >= 0. Gap space (gap_space_solve.hpp) solves it at every static solve.
#pragma once
#include "condensation/subset_cholesky.hpp"

#include <Eigen/Dense>

#include <vector>

namespace isosid::run {

class PenaltyComplementarity {
public:
  enum class Outcome { Solved, NotPositiveDefinite, NoActiveSet, NotFinite };

  PenaltyComplementarity() = default;
  // its factor reads this object's compliance and flexibilities in place
  PenaltyComplementarity(const PenaltyComplementarity&) = delete;
  PenaltyComplementarity& operator=(const PenaltyComplementarity&) = delete;

  /// The points' compliance (symmetric, positive semidefinite) and penalty stiffness k_i > 0;
  /// forgets the last active set.
  void set(Eigen::MatrixXd compliance, Eigen::VectorXd stiffness);
  Eigen::Index size() const { return stiffness_.size(); }

  /// The forces at these free gaps (the gaps without force), from the last solve's active
  /// set; `iterations` counts both methods' iterations. NotFinite: a free gap is not finite.
  Outcome solve(const Eigen::VectorXd& free_gaps, int& iterations);
  /// The last solution: every point's force, the pressed points, and whether Newton cycled and
  /// the active-set method found it.
  const Eigen::VectorXd& forces() const { return forces_; }
  const std::vector<Eigen::Index>& pressed() const { return pressed_; }
  /// Every point's gap g_free + C f at the last solution (a pressed point's: -f / k).
  const Eigen::VectorXd& gaps() const { return gaps_; }
  bool by_active_set() const { return by_active_set_; }

private:
  /// Semismooth Newton on the active set: the pressed points' forces solve
  /// (C + K^-1)_PP f_P = -g_free,P; a point leaves where its force would pull, enters where its
  /// gap closes. Fast from the last solve's active set, but it can cycle where many points
  /// close together under a compliance of low rank (a flat face on a plane). False then.
  bool newton(const Eigen::VectorXd& free_gaps, int& iterations, Outcome& outcome);
  /// The primal active-set method (as Lawson and Hanson's for NNLS), from no force: it keeps f
  /// feasible and lowers the energy whenever it presses a point (in exact arithmetic it ends;
  /// its iterations are capped against round-off).
  bool active_set(const Eigen::VectorXd& free_gaps, int& iterations, Outcome& outcome);
  /// The forces of the points in pressed_ with the others' zero, into `forces`; false if their
  /// matrix is not positive definite.
  bool pressed_forces(const Eigen::VectorXd& free_gaps, Eigen::VectorXd& forces);
  /// gaps_ = g_free + C f for forces_.
  void update_gaps(const Eigen::VectorXd& free_gaps);
  /// The same for the open points, which is all Newton reads; a pressed point's gap is
  /// -f / k (its penalty law, which the forces solve), in whichever way costs less.
  void update_open_gaps(const Eigen::VectorXd& free_gaps);
  void list_pressed();

  Eigen::MatrixXd compliance_;
  Eigen::VectorXd stiffness_;
  std::vector<char> is_pressed_, left_out_;  ///< per point; left_out_: the active-set method's guard
  std::vector<Eigen::Index> pressed_;
  Eigen::VectorXd forces_, trial_forces_, gaps_;
  Eigen::VectorXd flexibility_;    ///< per point, 1 / k_i
  SubsetCholesky pressed_block_;   ///< the pressed points' block of C + K^-1, factored as they change
  bool by_active_set_ = false;
};

}  // namespace isosid::run
