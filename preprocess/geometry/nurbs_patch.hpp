// A single NURBS patch (curve, surface or volume) with exact rational evaluation, and its
// boundary sides. Control points are stored with the first parametric direction fastest.
#pragma once
#include "isosid/format/bspline_basis.hpp"
#include "isosid/format/patch_side.hpp"

#include <Eigen/Dense>
#include <map>
#include <optional>
#include <string>
#include <vector>

namespace isosid::prep {

// the B-spline basis lives in format/ (the runtime evaluates master patches with it)
using format::basis_count;
using format::basis_derivatives;
using format::basis_functions;
using format::find_span;
using format::KnotVector;
using format::unique_knots;
using format::validate_knot_vector;

/// Greville abscissa of basis function i of (U, p): the mean of its p interior knots.
inline double greville_abscissa(const KnotVector& U, int p, int i) { return U.segment(i + 1, p).sum() / p; }

/// Values of all n basis functions of (U, p) at u (length n, mostly zero).
Eigen::VectorXd basis_row(const KnotVector& U, int p, double u);

// patch sides and their names live in format/ (the SID validator checks contact points against them)
using format::direction_name;
using format::PatchSide;
using format::side_from_name;
using format::side_name;

struct NurbsPatch {
  std::vector<int> degrees;            ///< one per parametric direction
  std::vector<KnotVector> knots;       ///< one open knot vector per direction
  Eigen::MatrixXd points;              ///< ncp x ncols Cartesian control points (extra columns: fields)
  Eigen::VectorXd weights;             ///< ncp positive weights
  std::map<std::string, PatchSide> named_sides;  ///< primitive-specific aliases, e.g. "axis" -> xi0

  int param_dim() const { return int(degrees.size()); }
  int phys_dim() const { return int(points.cols()); }
  std::vector<int> counts() const;     ///< control points per direction
  int count() const { return int(weights.size()); }

  /// Position and Jacobian (phys_dim x param_dim) at parameter xi.
  void evaluate(const Eigen::VectorXd& xi, Eigen::VectorXd& x, Eigen::MatrixXd* dx_dxi = nullptr) const;
  Eigen::VectorXd point(const Eigen::VectorXd& xi) const;

  /// Parameter interval [lo, hi] of direction d.
  double lower(int d) const { return knots[std::size_t(d)](0); }
  double upper(int d) const { return knots[std::size_t(d)](knots[std::size_t(d)].size() - 1); }

  /// Resolves a canonical or primitive-specific side name.
  std::optional<PatchSide> side(const std::string& name) const;
  /// Greville abscissae of control point `i` (one parameter per direction).
  Eigen::VectorXd greville(int i) const;
  /// Flat indices of the control points on a side.
  std::vector<int> side_points(PatchSide side) const;
  /// Tangential directions along which the side's control points coincide: the side
  /// collapses along them (all of them: to a point; e.g. the axis of a revolved solid: one).
  std::vector<int> collapsed_directions(PatchSide side) const;
};

/// Flat index of the multi-index `ijk` (first direction fastest).
int flat_index(const std::vector<int>& counts, const std::vector<int>& ijk);

/// Checks degrees, knots, weights and control points; throws InputError naming `field`.
void validate_patch(const NurbsPatch& patch, const std::string& file, const std::string& field);

}  // namespace isosid::prep
