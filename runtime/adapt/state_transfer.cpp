// State transfer between systems; see state_transfer.hpp.
#include "adapt/state_transfer.hpp"

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

}  // namespace isosid::run
