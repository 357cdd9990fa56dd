// Rigid-body properties of a SID body in its reference configuration.
#pragma once
#include "isosid/format/sid.hpp"

#include <Eigen/Dense>

namespace isosid::format {

struct RigidInvariants {
  double mass = 0;
  Eigen::Vector3d center_of_mass = Eigen::Vector3d::Zero();  ///< in the body frame
  Eigen::Matrix3d inertia_origin = Eigen::Matrix3d::Zero();  ///< about the frame origin
  Eigen::Matrix3d inertia_center = Eigen::Matrix3d::Zero();  ///< about the centre of mass
};

RigidInvariants rigid_invariants(const Sid& sid);

}  // namespace isosid::format
