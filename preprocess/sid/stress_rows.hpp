// Stress recovery rows: points along a line (in patch parameter or physical) where the stress
// of the reduced body is sigma = S q, S = D B Phi (components as in Elasticity::stress_components()).
#pragma once
#include "model/body_model.hpp"
#include "isosid/format/sid.hpp"

namespace isosid::prep {

format::StressRecovery stress_rows(const BodyModel& body, const StressLineSpec& spec, const Eigen::MatrixXd& Phi_nodal);

}  // namespace isosid::prep
