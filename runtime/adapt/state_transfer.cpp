// State transfer between systems; see state_transfer.hpp.
#include "adapt/state_transfer.hpp"

#include "contact/deformed_patch.hpp"
#include "isosid/format/error.hpp"

#include <algorithm>

namespace isosid::run {

Eigen::VectorXd transfer_state(const MultibodySystem& from, const double* y_from, const MultibodySystem& to,
                               const std::vector<ElasticMap>& maps) {
  if (from.bodies().size() != to.bodies().size() || maps.size() != from.bodies().size())
    throw format::ComputationError("a state transfer needs the same bodies on both sides");
  Eigen::VectorXd y(to.size());
  for (std::size_t i = 0; i < from.bodies().size(); ++i) {
    const FloatingBody& a = *from.bodies()[i];
    const FloatingBody& b = *to.bodies()[i];
    const double* s = y_from + a.offset();
    double* t = y.data() + b.offset();
    const Eigen::Index na = a.n_dynamic(), nb = b.n_dynamic();
    std::copy(s, s + 7, t);                    // r, orientation
    std::copy(s + 7 + na, s + 13 + na, t + 7 + nb);  // v, omega
    const ElasticMap& map = maps[i];
    if (map.size() == 0) {
      if (a.nq() != b.nq() || na != nb) throw format::ComputationError("body '" + a.name() + "' changes its model without a transfer");
      Eigen::Map<Eigen::VectorXd>(t + 7, nb) = Eigen::Map<const Eigen::VectorXd>(s + 7, na);
      Eigen::Map<Eigen::VectorXd>(t + 13 + nb, nb) = Eigen::Map<const Eigen::VectorXd>(s + 13 + na, na);
      continue;
    }
    if (map.rows() != b.nq() || map.cols() != a.nq())
      throw format::ComputationError("the transfer of body '" + a.name() + "' is " + std::to_string(map.rows()) + " x " +
                                     std::to_string(map.cols()) + ", its models have " + std::to_string(b.nq()) + " and " +
                                     std::to_string(a.nq()) + " coordinates");
    Eigen::Map<Eigen::VectorXd>(t + 7, nb) = (map * a.q(y_from)).head(nb);
    Eigen::Map<Eigen::VectorXd>(t + 13 + nb, nb) = (map.leftCols(na) * Eigen::Map<const Eigen::VectorXd>(s + 13 + na, na)).head(nb);
  }
  y(to.size() - 1) = y_from[from.size() - 1];  // the dissipated energy so far
  return y;
}

double transfer_mismatch(const format::Sid& coarse, const format::Sid& fine, const std::string& surface) {
  const auto patch_of = [&](const format::Sid& sid) -> const format::MasterPatch* {
    for (const format::ContactSurface& s : sid.contact_surfaces)
      if (s.name == surface) return format::find_master_patch(sid, s.master_patch);
    return nullptr;
  };
  const format::MasterPatch *a = patch_of(coarse), *b = patch_of(fine);
  if (!a || !b) return 0;  // nothing to compare with
  const DeformedPatch pa(*a, coarse.dim()), pb(*b, fine.dim());
  DeformedPatch::Point point;
  Eigen::MatrixXd rows_a, rows_b;
  double worst = 0, scale = 0;
  constexpr int n = 7;
  for (int i = 0; i <= n; ++i)
    for (int j = 0; j <= (pa.parameter_dim() > 1 ? n : 0); ++j) {
      Eigen::Vector2d u(pa.lower(0) + (pa.upper(0) - pa.lower(0)) * i / n, 0.0);
      if (pa.parameter_dim() > 1) u(1) = pa.lower(1) + (pa.upper(1) - pa.lower(1)) * j / n;
      pa.evaluate(u, point);
      pa.shape_rows(point, rows_a);
      pb.evaluate(u, point);
      pb.shape_rows(point, rows_b);
      worst = std::max(worst, (rows_b * fine.transfer->coarse_to_fine - rows_a).cwiseAbs().maxCoeff());
      scale = std::max(scale, rows_a.cwiseAbs().maxCoeff());
    }
  return scale > 0 ? worst / scale : worst;
}

}  // namespace isosid::run
