// One side of a gap-space pairing (the slave points, or their target points) with its points'
// displacement rows factored through the control points that carry them. A point of a NURBS
// surface moves as sum_i R_i u_i over the few control points i whose rational basis functions
// R_i cover it, u_i = Phi_i q their displacements. Where every mode moves every control point
// (a Craig-Bampton body in normal form: its quasistatic modes are eigenvectors of the whole
// reduced model), a point's rows are dense over all nq modes, and a state's evaluation of P
// points reads 3 P nq numbers. Factored, the control points' displacements are formed once per
// state for the control points the pairs use (one dense product), and each point sums its few.
// Where the rows are sparse (a massless boundary: a point reads its control points' own
// coordinates) the rows stay the cheaper form and this stays inactive.
#pragma once
#include <Eigen/Dense>

#include <cstddef>
#include <vector>

namespace isosid::run {

/// The control points of a patch that carry one point, and their rational basis values there.
struct ControlNetCarrier {
  std::vector<int> control_points;
  std::vector<double> basis;
};

class ControlNetRows {
public:
  /// Forgets the pairs of the last pairing (inactive until finish()).
  void clear();
  /// Appends the next pair's carrier (pairs in their order): its control points and their
  /// basis values.
  void add(const std::vector<int>& control_points, const std::vector<double>& basis);
  /// Pairs added since clear().
  std::size_t added() const { return begin_.size() - 1; }
  /// Decides the form once every pair is added: factored if forming the used control points'
  /// displacements and summing the carriers reads fewer than half the `direct_entries` that
  /// the pairs' own rows hold. `Phi`: the patch's control-point rows (ncp dim x nq, row i dim + a).
  void finish(const Eigen::MatrixXd& Phi, int dim, std::size_t direct_entries);
  bool active() const { return active_; }
  /// Forms the used control points' displacements at q, unless they are q's already.
  void deform(const Eigen::VectorXd& q) const;
  /// Adds pair k's displacement at the last deform() to out (dim entries).
  void add_displacement(std::size_t k, Eigen::Vector3d& out) const;

private:
  std::vector<Eigen::Index> begin_{0};       ///< pair k's entries: [begin_[k], begin_[k + 1])
  std::vector<Eigen::Index> local_;          ///< per entry: its control point among the used ones (the patch's until finish())
  std::vector<double> basis_;                ///< per entry: its basis value
  Eigen::MatrixXd rows_;                     ///< (used dim) x nq: the used control points' rows
  int dim_ = 3;
  bool active_ = false;
  mutable bool formed_ = false;
  mutable Eigen::VectorXd q_;                ///< the q of the displacements formed
  mutable Eigen::VectorXd displacements_;   ///< rows_ q
};

}  // namespace isosid::run
