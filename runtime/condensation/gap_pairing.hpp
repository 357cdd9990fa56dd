// A contact's slave points paired once with target points, for the contact solved in gap space
// (gap_space_solve.hpp). At pairing, every slave point is projected on the target; from then on
// its target point is the same material point of the target (its body-frame reference point and
// displacement rows), and its normal the target's normal there, turning with the target's frame.
// Each gap is then linear in both bodies' elastic coordinates, with a constant gradient over
// their quasistatic modes: what condenses a massless boundary onto the gaps. A pairing holds
// while the points do not slide along the target by more than a quarter of their spacing
// (slip()); beyond, the contact is paired again where it stands.
//
// Not every pair need take part in the condensation: the pairs within the condensation reach
// (their gap at pairing at most that much above the smallest) are condensed, those beyond are
// only checked (gap_space_solve.hpp). A reach sized from the impact keeps the dense compliance
// between the condensed points to the contact and its rim, not the whole surface.
#pragma once
#include "body/floating_body.hpp"
#include "condensation/control_net_rows.hpp"
#include "contact/contact_target.hpp"

#include <algorithm>
#include <array>
#include <cmath>
#include <vector>

namespace isosid::run {

/// The non-zero columns of dim displacement rows (a point moves with the few control points
/// whose basis functions cover it).
struct SparseRows {
  std::vector<Eigen::Index> columns;
  Eigen::Matrix<double, 3, Eigen::Dynamic> values;  ///< 3 x columns (unused rows zero)
  /// The non-zero entries of those columns, row by row (each row's in the columns' order) and
  /// where each row's begin: a massless boundary's surface point reads each control point's x,
  /// y and z in one row each, so two thirds of `values` are zeros the products skip.
  std::vector<Eigen::Index> entry_columns;
  std::vector<double> entry_values;
  std::array<std::size_t, 4> row_begin{};
  /// Adds the rows' product with q (all the body's coordinates) to out: each row's sum in the
  /// columns' order, as the product with `values` forms it (its zeros add nothing where q is
  /// finite). The entries are `from()`'s: rows filled by hand have none.
  void add_product(const Eigen::VectorXd& q, Eigen::Vector3d& out) const {
    // the three rows' sums side by side, three independent chains of additions (one row after
    // another waits on each addition's latency)
    if (entry_values.empty()) return;
    const double* v[3];
    const Eigen::Index* c[3];
    std::size_t n[3];
    for (std::size_t r = 0; r < 3; ++r)
      v[r] = entry_values.data() + row_begin[r], c[r] = entry_columns.data() + row_begin[r], n[r] = row_begin[r + 1] - row_begin[r];
    const std::size_t common = std::min({n[0], n[1], n[2]});
    double s0 = out(0), s1 = out(1), s2 = out(2);
    for (std::size_t i = 0; i < common; ++i) s0 += v[0][i] * q(c[0][i]), s1 += v[1][i] * q(c[1][i]), s2 += v[2][i] * q(c[2][i]);
    for (std::size_t i = common; i < n[0]; ++i) s0 += v[0][i] * q(c[0][i]);
    for (std::size_t i = common; i < n[1]; ++i) s1 += v[1][i] * q(c[1][i]);
    for (std::size_t i = common; i < n[2]; ++i) s2 += v[2][i] * q(c[2][i]);
    out << s0, s1, s2;
  }
  /// The entries of a dense dim x nq block above a relative threshold of its largest.
  static SparseRows from(const Eigen::Ref<const Eigen::MatrixXd>& rows);
};

/// How far a set of rows can move any point they describe: for every pair's rows S over the
/// same coordinates, |S x| is below both the rows' largest Frobenius norm times |x| (over the
/// columns they read) and the sum over columns of the largest column norm times |x_j|. The
/// second is the tight one where the columns' scales differ by orders (a Craig-Bampton body:
/// its interface modes' columns are thousands of times its normal modes').
class RowsBound {
public:
  void clear();
  void add(const SparseRows& rows);
  /// Sorts the columns once every pair's rows are added.
  void finish();
  /// The columns any pair's rows read, ascending.
  const std::vector<Eigen::Index>& columns() const { return columns_; }
  /// A bound of |S x| over the pairs' rows S.
  double of(const Eigen::VectorXd& x) const;
  /// A bound of |S (a - b)| over the pairs' rows S.
  double of_difference(const Eigen::VectorXd& a, const Eigen::VectorXd& b) const;

private:
  std::vector<std::pair<Eigen::Index, double>> added_;  ///< (column, norm) of every pair, until finish()
  std::vector<Eigen::Index> columns_;
  std::vector<double> column_norms_;  ///< the largest norm of each column over the pairs
  double frobenius_ = 0;              ///< the largest Frobenius norm of a pair's rows
};

class GapPairing {
public:
  /// One slave point and the target point it is paired with.
  struct Pair {
    Eigen::Index g = 0;                                   ///< the slave point
    Eigen::Vector3d normal = Eigen::Vector3d::UnitY();    ///< target normal: in the target body's frame, or world
    Eigen::Vector3d target_point = Eigen::Vector3d::Zero();  ///< its undeformed position, same frame
    SparseRows slave_rows, target_rows;                   ///< displacement rows (target: a flexible body's)
    double spacing = 0;                                   ///< m: the slave point's distance to its nearest neighbour
    double offset = 0;                                    ///< m: its gap at pairing less the pairing's smallest
  };
  /// Where a pair stands at a state.
  struct Evaluation {
    double gap = 0;                                         ///< m, along the target normal
    Eigen::Vector3d normal = Eigen::Vector3d::UnitY();      ///< world
    Eigen::Vector3d slave_point = Eigen::Vector3d::Zero();  ///< slave body frame, deformed
    Eigen::Vector3d target_point = Eigen::Vector3d::Zero(); ///< target body frame (world for a fixed target), deformed
    double slip = 0;                                        ///< m, the points' distance along the target
  };

  /// Both bodies' frames and coordinates at one state, for evaluations there.
  struct Poses {
    Eigen::Vector3d r_slave = Eigen::Vector3d::Zero(), r_target = Eigen::Vector3d::Zero();
    Eigen::Matrix3d A_slave = Eigen::Matrix3d::Identity(), A_target = Eigen::Matrix3d::Identity();
    const Eigen::VectorXd* q_slave = nullptr;
    const Eigen::VectorXd* q_target = nullptr;  ///< null for a fixed or rigid target
  };

  GapPairing(const FloatingBody& slave, const format::ContactSurface& surface, const ContactTarget& target);

  bool paired() const { return paired_; }
  const std::vector<Pair>& pairs() const { return pairs_; }
  /// Pairs every slave point that the target sees at y (its quasistatic coordinates as set).
  void pair(const double* y);
  /// The offset up to which pairs are condensed (see Pair::offset), m; +inf: every pair. Kept by
  /// later pairings until set again.
  void set_condensation_reach(double reach);
  /// Whether pair k is within the condensation reach.
  bool condensed(std::size_t k) const { return pairs_[k].offset <= condensation_reach_; }
  /// Doubles the condensation reach (a point beyond it would have pressed).
  void widen();
  /// Ends the pairing once the contact has left (every pair open by twice the pairing
  /// distance). Its pairs are kept to watch the bodies: while no point has slid along the target
  /// by the pairing distance, they tell the contact's gap far more cheaply than projecting.
  void release() { paired_ = false, watching_ = true, watched_.valid = false, forget_solution(); }
  bool watching() const { return watching_; }
  /// While watching: the pairs' smallest gap at y, or a lower bound of it, if it stays beyond
  /// twice the pairing distance and no point has slid by the pairing distance; otherwise
  /// watching ends here and this returns NaN (the gap must then be found by projecting). The
  /// pairs are evaluated only when the bodies' motion since their last evaluation could have
  /// brought a pair that close (or slid it that far): in free flight mostly not at all.
  double watched_gap(const double* y);
  /// Times pair() was called, and how many of them replaced a pairing (one that slid).
  long pairings() const { return pairings_; }
  long repairings() const { return repairings_; }
  /// The most pairs any pairing made, and the most of them within reach at once.
  std::size_t largest_pairing() const { return largest_; }
  std::size_t largest_condensed() const { return largest_condensed_; }
  /// Whether the slave's (the target's) pairs are evaluated through the control points that
  /// carry them (ControlNetRows), not through their own rows.
  bool slave_factored() const { return slave_net_.active(); }
  bool target_factored() const { return target_net_.active(); }
  /// Times the reach was widened.
  long widenings() const { return widenings_; }

  /// The poses at y (both bodies' coordinates as set now).
  Poses poses(const double* y) const;
  /// Pair k at the poses of some y.
  void evaluate(const Poses& at, std::size_t k, Evaluation& e) const;
  /// Every pair at the poses of some y, in the order of pairs(). Kept until the poses change:
  /// the static solve's result, the loads, the step's gaps and the recorder all ask at one
  /// state in turn.
  const std::vector<Evaluation>& evaluations(const Poses& at) const;

  /// The gap-space solve's record of the state it solved, kept for the loads and the gaps there:
  /// cleared (forget_solution), filled (add_pressed: the pairs its forces press, ascending;
  /// note_gap: every pair's gap, as the solve has them) and closed with that state's poses
  /// (solved_at). Pairs it does not list as pressed carry no force there (their gaps are open).
  void forget_solution() { pressed_pairs_.clear(), solved_at_.valid = pressed_evaluated_ = false, solved_min_gap_ = INFINITY; }
  void add_pressed(std::size_t k) { pressed_pairs_.push_back(k); }
  void note_gap(double gap) { solved_min_gap_ = std::min(solved_min_gap_, gap); }
  void solved_at(const Poses& at) { solved_at_.assign(at), pressed_evaluated_ = false; }
  /// The pairs the last solve pressed (see forget_solution()), ascending.
  const std::vector<std::size_t>& pressed_pairs() const { return pressed_pairs_; }
  /// Their evaluations, in that order, if the solve solved at these poses (evaluated at the
  /// first call there and kept); null at other poses.
  const std::vector<Evaluation>* pressed_evaluations(const Poses& at) const;
  /// The smallest gap of the pairs at y (+inf without pairs): the solve's where it solved at y.
  double min_gap(const double* y) const;
  /// d gap / d z of pair k over the stacked quasistatic coordinates (n entries; each body's
  /// block at its quasistatic_offset()), with the frames' rotations at y.
  void add_gradient(const double* y, std::size_t k, Eigen::Ref<Eigen::VectorXd> v) const;
  /// The target point of an evaluation as the loads need it: body point, normal, the target's
  /// integrated rows and, if asked for (friction), the velocity of its material point (else zero).
  void target_point(const double* y, std::size_t k, const Evaluation& e, bool with_velocity, TargetPoint& t) const;

  /// The contact is paired once its gap is below this, m: a fiftieth of the slave surface's
  /// radius (its points around their centroid; 9 um for the seed sphere's). A pairing made
  /// where the points already press is as good (they are projected where they stand), so this
  /// need not anticipate a large step; it bounds how long the pairs are evaluated.
  double pairing_distance() const { return kPairingDistancePerExtent * extent_; }
  static constexpr double kPairingDistancePerExtent = 0.02;

  /// Slip allowed, as a fraction of a point's spacing, for a point within a spacing of the
  /// target: beyond, the pairing no longer holds.
  static constexpr double kSlipPerSpacing = 0.25;

private:
  /// Poses with their coordinates copied (the bodies' coordinate vectors are overwritten for
  /// each state).
  struct PosesCopy {
    bool valid = false;
    Eigen::Vector3d r_slave, r_target;
    Eigen::Matrix3d A_slave, A_target;
    Eigen::VectorXd q_slave, q_target;
    void assign(const Poses& at);
    /// The same frames and the same coordinates where the pairs' rows read them.
    bool same(const Poses& at, const std::vector<Eigen::Index>& slave_columns, const std::vector<Eigen::Index>& target_columns) const;
  };
  /// The state at the pairs' last evaluation while watching: its poses, their smallest gap,
  /// largest slip and largest distance between paired points.
  struct WatchedState : PosesCopy {
    double gap = 0, slip = 0, separation = 0;
  };
  /// How much any pair's gap (first) and slip (second) can have changed from the watched state
  /// to `at`, m: bounds from the frames' moves and the coordinates' change, through the largest
  /// reference point and displacement rows of the pairs.
  std::pair<double, double> watched_change(const Poses& at) const;
  /// Forms the factored sides' control-point displacements at `at` (ControlNetRows), for the
  /// evaluations there.
  void deform_nets(const Poses& at) const;
  /// evaluate() once deform_nets(at) has run.
  void evaluate_deformed(const Poses& at, std::size_t k, Evaluation& e) const;
  /// The slave surface's points' carriers on its master patch (found at the first pairing whose
  /// slave rows fill most of the modes): empty where the patch's rows do not give the points'.
  const std::vector<ControlNetCarrier>& slave_carriers();

  const FloatingBody& slave_;
  const format::ContactSurface& surface_;
  const ContactTarget& target_;
  int dim_;
  Eigen::VectorXd spacing_;  ///< per slave point: the distance to its nearest neighbour, m
  double extent_ = 0;
  std::vector<Pair> pairs_;
  /// Over the pairs: the largest reference point (slave: its surface point, target: its
  /// point) from the body's frame origin, m
  double slave_reach_ = 0, target_reach_ = 0;
  /// The pairs' rows of each body: the coordinates they read (a massless boundary's, or all
  /// modes' where the rows fill them: Craig-Bampton) and how far those can move a point
  RowsBound slave_rows_, target_rows_;
  /// The pairs' rows of each body factored through its control points, where that is cheaper.
  ControlNetRows slave_net_, target_net_;
  const format::MasterPatch* slave_patch_;  ///< the slave surface's master patch (null: none)
  std::vector<ControlNetCarrier> slave_carriers_;
  bool slave_carriers_found_ = false;
  ControlNetCarrier target_carrier_;        ///< pair()'s buffer for each target point's carrier
  WatchedState watched_;
  mutable PosesCopy evaluated_at_;  ///< the poses of evaluations_
  mutable std::vector<Evaluation> evaluations_;
  std::vector<std::size_t> pressed_pairs_;  ///< see forget_solution()
  double solved_min_gap_ = INFINITY;        ///< the solve's smallest gap of the pairs
  PosesCopy solved_at_;                     ///< the poses of the solve's record
  mutable std::vector<Evaluation> pressed_evaluations_;  ///< at solved_at_, once asked for
  mutable bool pressed_evaluated_ = false;
  /// Counts the pairs within reach into largest_condensed_.
  void count_condensed();
  /// Whether `copy` holds the poses `at` where the pairs' rows read them.
  bool same_poses(const PosesCopy& copy, const Poses& at) const { return copy.same(at, slave_rows_.columns(), target_rows_.columns()); }

  bool paired_ = false, watching_ = false;
  double condensation_reach_ = INFINITY;
  long pairings_ = 0, repairings_ = 0, widenings_ = 0;
  std::size_t largest_ = 0, largest_condensed_ = 0;
};

}  // namespace isosid::run
