// Mass, centre of mass and inertia of the undeformed body from the SID terms.
#include "isosid/format/rigid_invariants.hpp"

namespace isosid::format {

RigidInvariants rigid_invariants(const Sid& sid) {
  RigidInvariants r;
  r.mass = sid.refmod.mass;
  if (sid.mdCM.M0.size() == 3 && r.mass > 0) r.center_of_mass = sid.mdCM.M0.col(0) / r.mass;
  if (sid.J.M0.rows() == 3 && sid.J.M0.cols() == 3) r.inertia_origin = sid.J.M0;
  const Eigen::Vector3d& c = r.center_of_mass;
  // parallel-axis theorem: J_O = J_C + m (|c|^2 I - c c^T)
  r.inertia_center = r.inertia_origin - r.mass * (c.squaredNorm() * Eigen::Matrix3d::Identity() - c * c.transpose());
  return r;
}

}  // namespace isosid::format
