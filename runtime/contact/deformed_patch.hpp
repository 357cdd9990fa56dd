// A master patch (a boundary side stored in the SID as a NURBS curve or surface with the
// modal rows of its control points) evaluated on its deformed control net X + Phi q, with
// first and second parametric derivatives, in the body frame.
#pragma once
#include "isosid/format/sid.hpp"

#include <Eigen/Dense>
#include <vector>

namespace isosid::run {

class DeformedPatch {
public:
  /// A point of the patch with derivatives and the rational basis functions that carry it.
  struct Point {
    Eigen::Vector3d C = Eigen::Vector3d::Zero();                 ///< position (body frame, dim components used)
    Eigen::Vector3d dC[2] = {Eigen::Vector3d::Zero(), Eigen::Vector3d::Zero()};  ///< d/du, d/dv
    Eigen::Vector3d ddC[3] = {Eigen::Vector3d::Zero(), Eigen::Vector3d::Zero(), Eigen::Vector3d::Zero()};  ///< uu, uv, vv
    std::vector<int> control_points;   ///< indices of the non-zero rational basis functions
    std::vector<double> R;             ///< their values
  };

  DeformedPatch(const format::MasterPatch& patch, int dim);

  int parameter_dim() const { return int(patch_.degrees.size()); }
  double lower(int direction) const { return patch_.knots[std::size_t(direction)](0); }
  double upper(int direction) const { return patch_.knots[std::size_t(direction)](patch_.knots[std::size_t(direction)].size() - 1); }
  /// Moves the control net to X + Phi q (q: all nq elastic coordinates).
  void deform(const Eigen::VectorXd& q);
  /// The deformed control net, ncp x dim.
  const Eigen::MatrixXd& net() const { return net_; }
  /// Evaluates the patch at parameter u (only the first parameter_dim() entries used).
  void evaluate(const Eigen::Vector2d& u, Point& out) const;
  /// Displacement rows of a point: Psi = sum R_i Phi_i (dim x nq).
  void shape_rows(const Point& point, Eigen::MatrixXd& Psi) const;
  /// Closest point of the patch to the body-frame point x: Newton's method from u (a warm
  /// start; NaN: none), else from the nearest span midpoint. On success u is its parameter
  /// and `point` the evaluated point; on failure u is NaN.
  bool closest_point(const Eigen::Vector3d& x, Eigen::Vector2d& u, Point& point) const;

private:
  /// Newton's method for the closest point from u; false if it did not converge.
  bool newton_projection(const Eigen::Vector3d& x, Eigen::Vector2d& u, Point& point) const;

  const format::MasterPatch& patch_;
  int dim_;
  Eigen::MatrixXd net_;
  Eigen::MatrixXd Phi_transposed_;   ///< nq x (ncp*dim)
  Eigen::VectorXd displacement_;     ///< Phi q
  std::vector<Eigen::Vector2d> midpoints_;  ///< knot-span midpoints: starting guesses of projections
};

}  // namespace isosid::run
