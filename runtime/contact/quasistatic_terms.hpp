// What the contacts contribute to the quasistatic sub-problem (seed 001): the generalized
// contact forces f(z) on the quasistatic modes z of all bodies (stacked; each body's block
// starts at its quasistatic_offset()) and the Jacobian -df/dz as a sum of rank-one terms
// u v^T, one per active contact point (v = d gap/dz, u = -df/d gap). The low rank is what
// makes the Newton solve cheap even with hundreds of quasistatic modes.
#pragma once
#include <Eigen/Dense>

namespace isosid::run {

struct QuasistaticTerms {
  Eigen::VectorXd force;
  Eigen::VectorXd friction;  ///< the friction part of `force` (its work on z is dissipated)
  Eigen::MatrixXd U, V;    ///< n x capacity; the first `rank` columns are in use
  Eigen::Index rank = 0;

  void reset(Eigen::Index n) {
    force.setZero(n);
    friction.setZero(n);
    if (U.rows() != n) U.resize(n, 0), V.resize(n, 0);
    rank = 0;
  }
  /// Appends a zeroed term; fill U.col(k) and V.col(k) for the returned k.
  Eigen::Index add_term() {
    if (rank == U.cols()) {  // grows geometrically, so steady state is allocation-free
      const Eigen::Index capacity = std::max<Eigen::Index>(16, 2 * U.cols());
      U.conservativeResize(Eigen::NoChange, capacity);
      V.conservativeResize(Eigen::NoChange, capacity);
    }
    U.col(rank).setZero();
    V.col(rank).setZero();
    return rank++;
  }
};

}  // namespace isosid::run
