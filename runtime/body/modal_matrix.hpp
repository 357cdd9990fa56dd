// Ke or De of a SID in its normal form, applied as a diagonal beside a dense block.
#pragma once
#include <Eigen/Dense>
#include <algorithm>

namespace isosid::run {

/// Ke or De in the SID's normal form: diagonal on the leading coordinates whose rows hold
/// nothing but round-off beside the diagonal (all of a modal or Craig-Bampton SID's), dense
/// on the trailing ones. A MacNeal SID's modes couple to its boundary: its matrix is all
/// trailing block.
class ModalMatrix {
public:
  explicit ModalMatrix(const Eigen::MatrixXd& M);
  /// out -= the leading out.size() rows of M x, x of all nq entries (no allocation)
  void subtract_product(const Eigen::VectorXd& x, Eigen::Ref<Eigen::VectorXd> out) const {
    const Eigen::Index rows = out.size(), d = diagonal_.size(), head = std::min(rows, d);
    out.head(head) -= diagonal_.head(head).cwiseProduct(x.head(head));
    if (rows > d) out.tail(rows - d).noalias() -= trailing_.topRows(rows - d) * x.tail(x.size() - d);
  }
  /// true where M is diagonal throughout
  bool is_diagonal() const { return trailing_.size() == 0; }
  /// The leading coordinates whose rows are diagonal.
  Eigen::Index diagonal_rows() const { return diagonal_.size(); }
  /// x^T M x; the trailing block is skipped where x is zero on it (an interface out of
  /// contact, whose modes do not couple to it)
  double quadratic_form(const Eigen::VectorXd& x) const {
    const Eigen::Index d = diagonal_.size();
    double form = x.head(d).dot(diagonal_.cwiseProduct(x.head(d)));
    const auto tail = x.tail(x.size() - d);
    if (trailing_.size() && !tail.isZero(0.0)) {
      product_.noalias() = trailing_ * tail;
      form += tail.dot(product_);
    }
    return form;
  }

private:
  Eigen::VectorXd diagonal_;   ///< the leading coordinates' entries
  Eigen::MatrixXd trailing_;   ///< the block of the others, if they are not diagonal
  mutable Eigen::VectorXd product_;  ///< trailing block times x, kept to avoid a temporary
};

}  // namespace isosid::run
