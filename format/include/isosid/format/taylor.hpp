// SID Taylor object: a matrix that depends linearly on the elastic coordinates,
// M(q) = M0 + sum_k M1[k] q_k (Wallrapp's SID standard, orders 0 and 1).
#pragma once
#include <Eigen/Dense>

#include <algorithm>
#include <vector>

namespace isosid::format {

struct Taylor {
  Eigen::MatrixXd M0;
  std::vector<Eigen::MatrixXd> M1;  ///< empty for order 0, else nq matrices shaped like M0

  int order() const { return M1.empty() ? 0 : 1; }
  Eigen::Index rows() const { return M0.rows(); }
  Eigen::Index cols() const { return M0.cols(); }

  /// Evaluates M(q); q must have M1.size() entries when the order is 1.
  Eigen::MatrixXd at(const Eigen::VectorXd& q) const {
    Eigen::MatrixXd M = M0;
    for (std::size_t k = 0; k < M1.size(); ++k) M += M1[k] * q(static_cast<Eigen::Index>(k));
    return M;
  }
  /// Evaluates the first `rows` rows of M(q) into `out` (fixed-size or already sized: no
  /// allocation) from the coefficients of the first `leading` coordinates: for a term known
  /// to be zero in the other rows and coefficients (a massless boundary's). Rows of `out`
  /// beyond `rows` are left alone; with leading = q.size() and rows = rows() this is M(q).
  template <class Out>
  void evaluate(const Eigen::VectorXd& q, Out&& out, Eigen::Index leading, Eigen::Index rows) const {
    out.topRows(rows) = M0.topRows(rows);
    for (Eigen::Index k = 0; k < std::min<Eigen::Index>(leading, Eigen::Index(M1.size())); ++k)
      if (q(k) != 0) out.topRows(rows) += M1[std::size_t(k)].topRows(rows) * q(k);
  }
  bool empty() const { return M0.size() == 0; }
};

}  // namespace isosid::format
