// Linear model of the quasistatic contact problem; see contact_model.hpp.
#include "condensation/contact_model.hpp"

#include <cmath>

namespace isosid::run {

double ContactModel::forces(const QuasistaticTerms& terms, const Eigen::VectorXd& gaps, Eigen::VectorXd& force,
                            Eigen::VectorXd& friction) const {
  force.setZero(terms.V.rows());
  friction.setZero(terms.V.rows());
  double energy = 0;
  for (Eigen::Index k = 0; k < terms.count; ++k) {
    const double p = terms.pressure(k, gaps(k));
    if (p <= 0) continue;
    const double fn = p * terms.weight(k);
    energy += terms.energy(k, gaps(k)) * terms.weight(k);
    force.noalias() += fn * terms.V.col(k);
    if (terms.friction) friction.noalias() += fn * terms.T.col(k);
  }
  if (terms.friction) force += friction;
  return energy;
}

Eigen::Index ContactModel::jacobian_terms(const QuasistaticTerms& terms, const Eigen::VectorXd& gaps) const {
  if (U_.rows() != terms.V.rows() || U_.cols() < terms.V.cols())
    U_.resize(terms.V.rows(), terms.V.cols()), V_.resize(terms.V.rows(), terms.V.cols()), weights_.resize(terms.V.cols());
  Eigen::Index r = 0;
  for (Eigen::Index k = 0; k < terms.count; ++k) {
    if (terms.pressure(k, gaps(k)) <= 0) continue;
    const double stiffness = terms.stiffness(k, gaps(k)) * terms.weight(k);
    weights_(r) = stiffness;
    V_.col(r) = terms.V.col(k);
    // without friction the weights stand for U (QuasistaticJacobian::solve)
    if (terms.friction) U_.col(r).noalias() = stiffness * (terms.V.col(k) + terms.T.col(k));
    ++r;
  }
  return r;
}

double ContactModel::model_residual(const QuasistaticJacobian& K, const QuasistaticTerms& terms, const Eigen::VectorXd& z,
                                    const Eigen::VectorXd& loads) const {
  const double energy = forces(terms, gaps_, force_, friction_);
  K.multiply(z, R_);
  R_ -= force_;
  R_ -= loads;
  return energy;
}

double ContactModel::energy_along(const QuasistaticTerms& terms, double alpha) const {
  double energy = 0;
  for (Eigen::Index k = 0; k < terms.count; ++k) {
    energy += terms.energy(k, gaps_(k) - alpha * rates_(k)) * terms.weight(k);
  }
  return energy;
}

void ContactModel::start(const QuasistaticJacobian& K, const QuasistaticTerms& terms, const Eigen::VectorXd& z0,
                         const Eigen::VectorXd& loads) const {
  if (gaps_.size() < terms.gap.size()) gaps_.resize(terms.gap.size()), rates_.resize(terms.gap.size()), pressed_.resize(std::size_t(terms.gap.size()));
  gaps_.head(terms.count) = terms.gap.head(terms.count);
  z_ = z0;
  energy_ = model_residual(K, terms, z_, loads);
}

int ContactModel::solve(const QuasistaticJacobian& K, const QuasistaticTerms& terms, const Eigen::VectorXd& loads, bool conservative,
                        Eigen::VectorXd& d) const {
  const Eigen::Index m = terms.count;
  d.setZero(z_.size());
  double& energy = energy_;
  for (int iteration = 1; iteration <= kMaxIterations; ++iteration) {
    const Eigen::Index r = jacobian_terms(terms, gaps_);
    for (Eigen::Index k = 0; k < m; ++k) pressed_[std::size_t(k)] = terms.pressure(k, gaps_(k)) > 0;
    // the Newton move is -step_; without friction U = V diag(k w), and K can use the symmetry
    K.solve(U_, V_, r, R_, step_, terms.friction ? nullptr : &weights_);
    rates_.head(m).noalias() = terms.V.leftCols(m).transpose() * step_;
    double alpha = 1;
    if (conservative) {
      // Pi along z - alpha step: the stiffness part is a parabola in alpha (its coefficients
      // from R + f = K z - loads), the contact part a sum over the recorded points
      const double slope = -R_.dot(step_), linear = step_.dot(R_ + force_), curvature = K.product(step_, step_);
      if (slope >= 0) return solved_ = true, iteration;  // no descent left: the model is solved to round-off
      for (int halving = 0; halving < 40; ++halving) {
        const double change = energy_along(terms, alpha) - energy - alpha * linear + 0.5 * alpha * alpha * curvature;
        if (change <= 1e-4 * alpha * slope) break;
        alpha *= 0.5;
      }
    }
    z_ -= alpha * step_;
    d -= alpha * step_;
    gaps_.head(m) -= alpha * rates_.head(m);
    const double residual_before = R_.norm();
    energy = model_residual(K, terms, z_, loads);
    if (!conservative && R_.norm() > residual_before) {
      // friction: the model's residual is not a gradient; halve back along the step until it falls
      for (int halving = 0; halving < 40 && R_.norm() > residual_before; ++halving) {
        alpha *= 0.5;
        z_ += alpha * step_;
        d += alpha * step_;
        gaps_.head(m) += alpha * rates_.head(m);
        energy = model_residual(K, terms, z_, loads);
      }
    }
    // a full step that kept the active set lands on the model's solution (it is linear there)
    bool same_set = alpha == 1;
    for (Eigen::Index k = 0; same_set && k < m; ++k) same_set = (terms.pressure(k, gaps_(k)) > 0) == bool(pressed_[std::size_t(k)]);
    if (same_set || alpha * step_.norm() <= 1e-14 * z_.norm()) return solved_ = true, iteration;
  }
  solved_ = false;
  return kMaxIterations;
}

}  // namespace isosid::run
