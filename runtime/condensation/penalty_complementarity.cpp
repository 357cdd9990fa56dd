// The points' penalty contact problem; see penalty_complementarity.hpp.
#include "condensation/penalty_complementarity.hpp"

#include <algorithm>
#include <limits>

namespace isosid::run {

namespace {
/// Semismooth Newton iterations before the active-set method takes over.
constexpr int kNewtonIterations = 20;
/// The active-set method's iterations per point before the solve gives up (measured: under two
/// per pressed point on the unit test's flat faces).
constexpr int kActiveSetIterationsPerPoint = 10;
}  // namespace

void PenaltyComplementarity::set(Eigen::MatrixXd compliance, Eigen::VectorXd stiffness) {
  compliance_ = std::move(compliance);
  stiffness_ = std::move(stiffness);
  flexibility_ = stiffness_.cwiseInverse();
  forces_.setZero(size());
  trial_forces_.setZero(size());
  gaps_.setZero(size());
  is_pressed_.assign(std::size_t(size()), 0);
  left_out_.assign(std::size_t(size()), 0);
  pressed_.clear();
  pressed_.reserve(std::size_t(size()));
  pressed_block_.reset(compliance_, flexibility_);
}

PenaltyComplementarity::Outcome PenaltyComplementarity::solve(const Eigen::VectorXd& free_gaps, int& iterations) {
  iterations = 0;
  by_active_set_ = false;
  if (!free_gaps.allFinite()) return Outcome::NotFinite;
  Outcome outcome = Outcome::Solved;
  if (newton(free_gaps, iterations, outcome) || outcome != Outcome::Solved) return outcome;
  by_active_set_ = true;
  if (active_set(free_gaps, iterations, outcome) || outcome != Outcome::Solved) return outcome;
  return Outcome::NoActiveSet;
}

void PenaltyComplementarity::list_pressed() {
  pressed_.clear();
  for (Eigen::Index i = 0; i < size(); ++i)
    if (is_pressed_[std::size_t(i)]) pressed_.push_back(i);
}

bool PenaltyComplementarity::pressed_forces(const Eigen::VectorXd& free_gaps, Eigen::VectorXd& forces) {
  forces.setZero();
  if (!pressed_block_.follow(pressed_, is_pressed_)) return false;
  pressed_block_.solve(free_gaps, forces);
  for (const Eigen::Index a : pressed_) forces(a) = -forces(a);
  return true;
}

void PenaltyComplementarity::update_gaps(const Eigen::VectorXd& free_gaps) {
  gaps_ = free_gaps;
  for (const Eigen::Index a : pressed_) gaps_.noalias() += forces_(a) * compliance_.col(a);
}

void PenaltyComplementarity::update_open_gaps(const Eigen::VectorXd& free_gaps) {
  // fewer points open than pressed (about a quarter open at a sphere's peak): each open point's
  // gap as its row of C (its column: C is symmetric) against the forces, zero off the pressed
  const std::size_t open = std::size_t(size()) - pressed_.size();
  if (open >= pressed_.size()) return update_gaps(free_gaps);
  for (Eigen::Index i = 0; i < size(); ++i)
    gaps_(i) = is_pressed_[std::size_t(i)] ? -flexibility_(i) * forces_(i) : free_gaps(i) + compliance_.col(i).dot(forces_);
}

bool PenaltyComplementarity::newton(const Eigen::VectorXd& free_gaps, int& iterations, Outcome& outcome) {
  for (int iteration = 1; iteration <= kNewtonIterations; ++iteration) {
    ++iterations;
    list_pressed();
    if (!pressed_forces(free_gaps, forces_)) return outcome = Outcome::NotPositiveDefinite, false;
    update_open_gaps(free_gaps);
    bool changed = false;
    for (Eigen::Index i = 0; i < size(); ++i) {
      const char now = is_pressed_[std::size_t(i)] ? forces_(i) > 0 : gaps_(i) < 0;
      changed = changed || now != is_pressed_[std::size_t(i)];
      is_pressed_[std::size_t(i)] = now;
    }
    if (!changed) return true;
  }
  return false;
}

bool PenaltyComplementarity::active_set(const Eigen::VectorXd& free_gaps, int& iterations, Outcome& outcome) {
  // Each iteration minimizes the energy over the pressed points with the open ones at zero
  // force. A pressed point whose force would pull stops the move toward that minimum and is
  // opened; at a minimum whose forces all push, the open point whose gap is most closed is
  // pressed. A gap closed by round-off only does not count, and a point pressed whose first
  // force would pull is opened again and left out until the forces move (Lawson and Hanson's
  // guard): without both, points whose gaps are zero to round-off (a flat face's, evenly
  // pressed) would be pressed and opened in turn.
  const double eps = std::numeric_limits<double>::epsilon(), largest_free_gap = free_gaps.cwiseAbs().maxCoeff();
  forces_.setZero();
  std::fill(is_pressed_.begin(), is_pressed_.end(), 0);
  std::fill(left_out_.begin(), left_out_.end(), 0);
  Eigen::Index entered = -1;
  for (int iteration = 1; iteration <= kActiveSetIterationsPerPoint * int(size()) + 10; ++iteration) {
    ++iterations;
    list_pressed();
    if (!pressed_forces(free_gaps, trial_forces_)) return outcome = Outcome::NotPositiveDefinite, false;
    if (entered >= 0 && trial_forces_(entered) <= 0) {
      is_pressed_[std::size_t(entered)] = 0, left_out_[std::size_t(entered)] = 1, entered = -1;
    } else {
      entered = -1;
      double step = 1;
      Eigen::Index blocking = -1;
      for (const Eigen::Index a : pressed_) {
        if (trial_forces_(a) > 0) continue;
        const double reach = forces_(a) > 0 ? forces_(a) / (forces_(a) - trial_forces_(a)) : 0.0;
        if (blocking < 0 || reach < step) step = reach, blocking = a;
      }
      if (blocking >= 0) {
        forces_ += step * (trial_forces_ - forces_);
        forces_(blocking) = 0;  // exactly, whatever the round-off of the move
        for (const Eigen::Index a : pressed_)
          if (forces_(a) <= 0) forces_(a) = 0, is_pressed_[std::size_t(a)] = 0;
        if (step > 0) std::fill(left_out_.begin(), left_out_.end(), 0);
        continue;
      }
      if (forces_ != trial_forces_) std::fill(left_out_.begin(), left_out_.end(), 0);
      forces_ = trial_forces_;
    }
    list_pressed();
    update_gaps(free_gaps);
    // the gaps' resolution: round-off of g_free + C f
    const double closed = 16 * eps * (largest_free_gap + (gaps_ - free_gaps).cwiseAbs().maxCoeff());
    Eigen::Index most_closed = -1;
    for (Eigen::Index i = 0; i < size(); ++i)
      if (!is_pressed_[std::size_t(i)] && !left_out_[std::size_t(i)] && gaps_(i) < -closed &&
          (most_closed < 0 || gaps_(i) < gaps_(most_closed)))
        most_closed = i;
    if (most_closed < 0) return true;
    is_pressed_[std::size_t(most_closed)] = 1;
    entered = most_closed;
  }
  return false;
}

}  // namespace isosid::run
