// The elastic energy of a body whose held (quasistatic) coordinates couple to its integrated
// ones through a dense stiffness: a MacNeal SID's modes and massless boundary. Written through
// the held block's static condensation, the energy costs a dense form only while a load acts
// on the held coordinates (in contact), not at every output of a flight.
#pragma once
#include <Eigen/Dense>
#include <optional>

namespace isosid::run {

/// ½ qᵀ K q for K = [K_dd K_dh; K_hd K_hh] (the leading d coordinates integrated, the h others
/// held), as ½ (q_dᵀ S q_d + rᵀ K_hh r) with the Schur complement S = K_dd − K_dh K_hh⁻¹ K_hd
/// and r = q_h + K_hh⁻¹ K_hd q_d. r is how far the held coordinates depart from following the
/// integrated ones statically: only a load on them moves r from zero (a massless boundary's
/// r is round-off out of contact). The h × h form is skipped while its bound ‖K_hh‖_F |r|² lies
/// below 1e-15 of the first term, beneath the round-off of the sum itself.
class CondensedEnergy {
public:
  /// The split of K after its leading `n_dynamic` coordinates, or nothing where it does not
  /// pay or does not exist: no held or no integrated coordinates, no coupling between them,
  /// or a held block that is not positive definite.
  static std::optional<CondensedEnergy> of(const Eigen::MatrixXd& K, Eigen::Index n_dynamic);

  /// ½ qᵀ K q, q of all coordinates
  double operator()(const Eigen::VectorXd& q) const;

private:
  CondensedEnergy() = default;
  Eigen::MatrixXd schur_;       ///< S (d × d)
  Eigen::MatrixXd follow_;      ///< K_hh⁻¹ K_hd (h × d): the held coordinates' static response
  Eigen::MatrixXd held_;        ///< K_hh
  double held_norm_ = 0;        ///< ‖K_hh‖_F, bounding its spectral norm
  mutable Eigen::VectorXd modal_product_, r_, product_;  ///< kept to avoid temporaries at every output
};

}  // namespace isosid::run
