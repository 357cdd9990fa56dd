// The points' penalty contact problem; see penalty_complementarity.hpp.
#include "condensation/penalty_complementarity.hpp"

namespace isosid::run {

void PenaltyComplementarity::set(Eigen::MatrixXd compliance, Eigen::VectorXd stiffness) {
  compliance_ = std::move(compliance);
  stiffness_ = std::move(stiffness);
  forces_.setZero(size());
  is_pressed_.assign(std::size_t(size()), 0);
  pressed_.clear();
}

PenaltyComplementarity::Outcome PenaltyComplementarity::solve(const Eigen::VectorXd& free_gaps, int& iterations) {
  iterations = 0;
  Outcome outcome = Outcome::Solved;
  by_active_set_ = false;
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
  const Eigen::Index r = Eigen::Index(pressed_.size());
  forces.setZero(size());
  if (r == 0) return true;
  pressed_matrix_.resize(r, r);
  pressed_rhs_.resize(r);
  for (Eigen::Index b = 0; b < r; ++b) {
    for (Eigen::Index a = b; a < r; ++a) pressed_matrix_(a, b) = compliance_(pressed_[std::size_t(a)], pressed_[std::size_t(b)]);
    pressed_matrix_(b, b) += 1.0 / stiffness_(pressed_[std::size_t(b)]);
    pressed_rhs_(b) = -free_gaps(pressed_[std::size_t(b)]);
  }
  Eigen::LLT<Eigen::MatrixXd, Eigen::Lower> llt(pressed_matrix_);
  if (llt.info() != Eigen::Success) return false;
  llt.solveInPlace(pressed_rhs_);
  for (Eigen::Index b = 0; b < r; ++b) forces(pressed_[std::size_t(b)]) = pressed_rhs_(b);
  return true;
}

void PenaltyComplementarity::update_gaps(const Eigen::VectorXd& free_gaps) {
  gaps_ = free_gaps;
  for (const Eigen::Index a : pressed_) gaps_.noalias() += forces_(a) * compliance_.col(a);
}

bool PenaltyComplementarity::newton(const Eigen::VectorXd& free_gaps, int& iterations, Outcome& outcome) {
  for (int iteration = 1; iteration <= kNewtonIterations; ++iteration) {
    ++iterations;
    list_pressed();
    if (!pressed_forces(free_gaps, forces_)) return outcome = Outcome::NotPositiveDefinite, false;
    update_gaps(free_gaps);
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
  // Each iteration minimizes the energy over the free points with the others held at zero
  // force. A free point whose force would pull stops the move toward that minimum and is held;
  // at a minimum whose forces all push, the held point whose gap is most closed is freed.
  forces_.setZero(size());
  is_pressed_.assign(std::size_t(size()), 0);
  for (int iteration = 1; iteration <= active_set_iterations(size()); ++iteration) {
    ++iterations;
    list_pressed();
    if (!pressed_forces(free_gaps, trial_forces_)) return outcome = Outcome::NotPositiveDefinite, false;
    double step = 1;
    Eigen::Index blocking = -1;
    for (const Eigen::Index a : pressed_) {
      if (trial_forces_(a) > 0) continue;
      const double reach = forces_(a) > 0 ? forces_(a) / (forces_(a) - trial_forces_(a)) : 0.0;
      if (reach < step) step = reach, blocking = a;
    }
    if (blocking >= 0) {
      forces_ += step * (trial_forces_ - forces_);
      forces_(blocking) = 0;  // exactly, whatever the round-off of the move
      for (const Eigen::Index a : pressed_)
        if (forces_(a) <= 0) forces_(a) = 0, is_pressed_[std::size_t(a)] = 0;
      continue;
    }
    forces_ = trial_forces_;
    update_gaps(free_gaps);
    Eigen::Index most_closed = -1;
    for (Eigen::Index i = 0; i < size(); ++i)
      if (!is_pressed_[std::size_t(i)] && gaps_(i) < 0 && (most_closed < 0 || gaps_(i) < gaps_(most_closed))) most_closed = i;
    if (most_closed < 0) return list_pressed(), true;
    is_pressed_[std::size_t(most_closed)] = 1;
  }
  return false;
}

}  // namespace isosid::run
