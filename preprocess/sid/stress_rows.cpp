// Stress rows along a line of the body; see stress_rows.hpp.
#include "sid/stress_rows.hpp"

#include "assemble/point_operator.hpp"
#include "isosid/format/error.hpp"

namespace isosid::prep {

format::StressRecovery stress_rows(const BodyModel& body, const StressLineSpec& spec, const Eigen::MatrixXd& Phi_nodal) {
  const int dim = body.dofs.dim();
  const auto comps = body.elasticity.stress_components();
  const auto nc = Eigen::Index(comps.size());
  format::StressRecovery s;
  s.name = spec.name;
  s.components = comps;
  s.position.resize(spec.points, dim);
  s.S.resize(spec.points * nc, Phi_nodal.cols());
  const std::vector<BodyPoint> points = line_points(body.spec.patches[std::size_t(spec.patch)].patch, spec.from, spec.to, spec.points);
  for (int i = 0; i < spec.points; ++i) {
    const auto at = point_operator_at(body.space, body.dofs, body.elasticity, spec.patch, points[std::size_t(i)].parameter);
    if (!at) throw format::InputError(body.spec.file, "stress_line " + spec.name, "point outside the patch");
    const PointOperator& op = *at;
    const Eigen::MatrixXd local = op.gather(Phi_nodal);
    s.position.row(i) = op.x.transpose();
    s.S.middleRows(i * nc, nc) = body.elasticity.of_patch(spec.patch).D() * op.B * local;
  }
  return s;
}

}  // namespace isosid::prep
