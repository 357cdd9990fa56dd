// SID nodes at named points of the body (monitors, joints, loads): reference position,
// translational modes phi and rotational modes psi (the infinitesimal rotation, half the curl
// of the displacement), in the 3D body frame.
#pragma once
#include "model/body_model.hpp"
#include "isosid/format/sid.hpp"

namespace isosid::prep {

format::Node node_at(const BodyModel& body, const NodeSpec& spec, const Eigen::MatrixXd& Phi_nodal);

}  // namespace isosid::prep
