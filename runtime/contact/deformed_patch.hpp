// A master patch (a boundary side stored in the SID as a NURBS curve or surface with the
// modal rows of its control points) evaluated on its deformed control net X + Phi q, with
// first and second parametric derivatives, in the body frame.
#pragma once
#include "contact/span_polynomials.hpp"
#include "isosid/format/sid.hpp"

#include <Eigen/Dense>
#include <cmath>
#include <vector>

namespace isosid::run {

/// The columns of a contact surface's parameters that are its master patch's, in order: the
/// side's free directions (those along which its points' parameters vary). Empty unless the
/// surface lies on one patch and has parameter_dim of them.
std::vector<Eigen::Index> side_parameters(const format::ContactSurface& surface, int parameter_dim);

class DeformedPatch {
public:
  /// A point of the patch with derivatives and the rational basis functions that carry it.
  struct Point {
    Eigen::Vector3d C = Eigen::Vector3d::Zero();                 ///< position (body frame, dim components used)
    Eigen::Vector3d dC[2] = {Eigen::Vector3d::Zero(), Eigen::Vector3d::Zero()};  ///< d/du, d/dv
    Eigen::Vector3d ddC[3] = {Eigen::Vector3d::Zero(), Eigen::Vector3d::Zero(), Eigen::Vector3d::Zero()};  ///< uu, uv, vv
    std::vector<int> control_points;   ///< indices of the non-zero rational basis functions
    std::vector<double> R;             ///< their values
    std::vector<Eigen::Vector2d> dR;   ///< their derivatives d/du, d/dv
    /// The knot span evaluated, per direction: one polynomial piece, where Taylor's formula holds.
    Eigen::Vector2d span_lower = Eigen::Vector2d::Constant(-INFINITY), span_upper = Eigen::Vector2d::Constant(INFINITY);
    /// The point at u + s (within the span) from its Taylor expansion: position to second
    /// order, tangents and basis values to first (second derivatives stay those at u).
    void advance(const Eigen::Vector2d& s);
  };

  DeformedPatch(const format::MasterPatch& patch, int dim);

  const format::MasterPatch& patch() const { return patch_; }
  int parameter_dim() const { return int(patch_.degrees.size()); }
  double lower(int direction) const { return patch_.knots[std::size_t(direction)](0); }
  double upper(int direction) const { return patch_.knots[std::size_t(direction)](patch_.knots[std::size_t(direction)].size() - 1); }
  /// Moves the control net to X + Phi q (q: all nq elastic coordinates). A control point is
  /// moved when an evaluation first needs it: projections near a contact visit a few spans of
  /// a patch that may have hundreds of control points (the beam face of [R3] in docs/references.md:
  /// 893).
  void deform(const Eigen::VectorXd& q);
  /// A sphere (body frame) that holds the deformed patch, which lies in the convex hull of its
  /// control net: the reference net's bounding sphere grown by a bound of the control points'
  /// displacement, max_i |Phi_i|_F |q|.
  void bounding_sphere(Eigen::Vector3d& center, double& radius) const;
  /// max_i |Phi_i|_F: no point of the patch moves further than this times |q|.
  double largest_row_norm() const { return largest_row_norm_; }
  /// Evaluates the patch at parameter u (only the first parameter_dim() entries used).
  void evaluate(const Eigen::Vector2d& u, Point& out) const;
  /// Displacement rows of a point: Psi = sum R_i Phi_i (dim x nq).
  void shape_rows(const Point& point, Eigen::MatrixXd& Psi) const;
  /// Closest point of the patch to the body-frame point x: Newton's method from u (a warm
  /// start; NaN: none), else from the knot-span midpoint nearest on the undeformed patch. On
  /// success u is its parameter and `point` the point there (its second derivatives may be
  /// those of a parameter up to 3e-5 of a knot span away: evaluate at u for curvatures); on
  /// failure u is NaN.
  bool closest_point(const Eigen::Vector3d& x, Eigen::Vector2d& u, Point& point) const;

private:
  /// Newton's method for the closest point from u; false if it did not converge.
  bool newton_projection(const Eigen::Vector3d& x, Eigen::Vector2d& u, Point& point) const;

  /// Control point i of the deformed net (z = 0 in 2D), moved for the last deform() if not yet.
  Eigen::Vector3d control_point(int i) const;

  const format::MasterPatch& patch_;
  int dim_;
  mutable Eigen::MatrixXd net_;       ///< ncp x dim, rows valid where moved_ holds the current stamp
  mutable std::vector<long> moved_;   ///< per control point: the deform() stamp it was moved for
  long stamp_ = 0;
  Eigen::VectorXd q_;                 ///< the elastic coordinates of the last deform()
  SpanPolynomials basis_[2];          ///< per parametric direction
  Eigen::MatrixXd Phi_transposed_;   ///< nq x (ncp*dim): each control point's rows are contiguous columns
  mutable Eigen::MatrixXd rows_transposed_;  ///< nq x dim: shape_rows' sum
  Eigen::Vector3d reference_center_ = Eigen::Vector3d::Zero();
  double reference_radius_ = 0;
  double largest_row_norm_ = 0;       ///< max_i |Phi_i|_F
  std::vector<Eigen::Vector2d> midpoints_;  ///< knot-span midpoints: starting guesses of projections
  std::vector<Eigen::Vector3d> midpoint_positions_;  ///< their points on the undeformed patch
};

}  // namespace isosid::run
