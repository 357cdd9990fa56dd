// Test support: a consistent SID computed from first principles for a cloud of point masses
// and a mass-orthonormal mode basis (lumped-mass body integrals, independent of isosid-prep).
#pragma once
#include "isosid/format/sid.hpp"

#include <Eigen/Dense>

namespace isosid::test {

struct LumpedBody {
  Eigen::MatrixXd points;   ///< n x 3 positions in the body frame
  Eigen::VectorXd masses;   ///< n point masses
  Eigen::MatrixXd Phi;      ///< 3n x nq displacement modes (row 3i+a: point i, direction a)
  Eigen::VectorXd omega;    ///< nq angular frequencies (Ke = Q^T diag(omega^2) Q for a rotated basis)
  Eigen::MatrixXd Ke;       ///< nq x nq modal stiffness in the basis Phi
};

/// A body of `n` random points with `nq` modes; modes 1 and 2 share one frequency so that
/// their basis is arbitrary up to a rotation. Deterministic for a given seed.
LumpedBody random_lumped_body(int n, int nq, unsigned seed);

/// The same body with its modes replaced by Phi Q (Q orthogonal): the same physics.
LumpedBody rotate_modes(const LumpedBody& body, const Eigen::MatrixXd& Q);

/// Builds every SID term, a node, a contact surface with its master patch, stress rows and
/// a transfer operator from the lumped body (3D solid analysis).
format::Sid lumped_sid(const LumpedBody& body);

}  // namespace isosid::test
