// SID of a rigid body; see rigid_body_sid.hpp.
#include "body/rigid_body_sid.hpp"

namespace isosid::run {

format::Sid rigid_body_sid(const BodySpec& body, Dimension dimension) {
  const RigidShape& shape = *body.rigid;
  format::Sid sid;
  sid.body_name = body.name;
  // the analysis type only tells the runtime how the body may move in this scene
  sid.analysis = dimension == Dimension::Axisymmetric ? format::AnalysisType::Axisymmetric
                 : dimension == Dimension::Planar     ? format::AnalysisType::PlaneStress
                                                      : format::AnalysisType::Solid;
  sid.refmod.mass = shape.mass;
  sid.refmod.reduction_method = "rigid";
  sid.mdCM.M0 = Eigen::Vector3d::Zero();
  sid.J.M0 = shape.principal_inertia.asDiagonal();
  sid.Ct.M0.resize(0, 3);
  sid.Cr.M0.resize(0, 3);
  sid.Me.M0.resize(0, 0);
  sid.Gr.M0.resize(3, 0);
  sid.Ge.M0.resize(0, 0);
  sid.Oe.M0.resize(0, 6);
  sid.ksigma.M0.resize(0, 1);
  sid.Ke.M0.resize(0, 0);
  sid.De.M0.resize(0, 0);
  return sid;
}

}  // namespace isosid::run
