// The viewing mesh of a SID ([visual] in the model file): every element's parametric box cut
// into `subdivisions` cells per direction, corner points shared between neighbours of the
// same patch, with displacement rows u = N Phi and stress rows sigma = D B Phi at each point
// (a shared point takes its stress from the first element that reaches it: one-sided where
// the stress jumps, across C0 knots).
// The points lie on the exact geometry; between them ParaView draws straight-edged cells, so
// the finer the contact elements, the finer the picture where contact happens.
#pragma once
#include "model/body_model.hpp"
#include "isosid/format/sid.hpp"

namespace isosid::prep {

format::VisualMesh visual_mesh(const BodyModel& body, const VisualSpec& spec, const Eigen::MatrixXd& Phi_nodal);

}  // namespace isosid::prep
