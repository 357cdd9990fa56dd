// The static contact problem of the quasistatic modes solved in gap space ([R3]'s formulation,
// docs/design.md "Contact in gap space"). With every contact paired (gap_pairing.hpp), each
// point's gap is linear in the stacked quasistatic coordinates z with a constant gradient, the
// column k of V, and the equilibrium K z = h + V f (h the loads that do not depend on z, f >= 0
// the points' normal forces) condenses onto the gaps:
//   z = z_h + W f,  z_h = K^-1 h,  W = K^-1 V,
//   g = g(z_h) + C f,  C = V^T W   (the compliance between the points, once per pairing).
// Each solve then works on the points alone: the penalty law f = c_p w max(0, -g), a linear
// complementarity problem (penalty_complementarity.hpp), warm-started from the last active
// set. Per solve, what grows with the boundary's coordinates is the product W f and z_h's
// (the coupling response times the modes, quasistatic_modes.hpp).
#pragma once
#include "condensation/penalty_complementarity.hpp"
#include "condensation/quasistatic_jacobian.hpp"
#include "contact/surface_contact.hpp"

#include <vector>

namespace isosid::run {

class GapSpaceSolve {
public:
  /// Pairings made again at one state before the solve fails.
  static constexpr int kMaxRepairings = 3;

  /// `contacts`: every contact on the quasistatic modes, each solved in gap space
  /// (penalty, frictionless); `stiffness`: K of the stacked quasistatic modes.
  GapSpaceSolve(const std::vector<const SurfaceContact*>& contacts, const QuasistaticJacobian& stiffness);

  /// The quasistatic coordinates z at y, given in z their response to the loads that do not
  /// depend on them, z_h = K^-1 h; `scatter` sets them on the bodies. Pairs the contacts that
  /// come near, pairs again those that slid, releases those that left. Returns the points'
  /// problem's iterations.
  template <class Scatter>
  int solve(const double* y, Eigen::VectorXd& z, Scatter&& scatter) {
    scatter(z);
    if (pair_approaching(y)) condense(y);
    // the pairs at z_h: their free gaps, and whether each pairing still holds (a pairing made
    // here holds here: its points were just projected)
    for (int pass = 0; !pairs_.empty() && !evaluate_pairs(y); ++pass) {
      if (pass == kMaxRepairings) throw_unsettled_pairing();
      condense(y);
    }
    if (pairs_.empty()) return 0;
    const int iterations = solve_forces();
    for (const Eigen::Index a : points_.pressed()) z.noalias() += points_.forces()(a) * W_.col(a);
    scatter(z);
    return iterations;
  }

private:
  /// One stacked pair: its contact and its index there.
  struct StackedPair {
    const SurfaceContact* contact = nullptr;
    std::size_t k = 0;
  };
  /// Pairs the unpaired contacts that came within their pairing distance at y (z = z_h set);
  /// true if any was.
  bool pair_approaching(const double* y);
  /// V, W and C of the current pairs, and their penalty stiffness c_p w.
  void condense(const double* y);
  /// The pairs' free gaps at y (z = z_h set), in one pass that also checks each pairing: one
  /// that slid is paired again, one whose pairs are all open by twice the pairing distance
  /// released. False if a pairing changed (the pairs must then be condensed again).
  bool evaluate_pairs(const double* y);
  /// The points' forces at the free gaps; returns the iterations.
  int solve_forces();
  /// Throws QuasistaticDivergence: the pairings at one state did not hold after kMaxRepairings.
  [[noreturn]] void throw_unsettled_pairing() const;

  std::vector<const SurfaceContact*> contacts_;
  const QuasistaticJacobian& stiffness_;
  std::vector<StackedPair> pairs_;
  Eigen::MatrixXd W_;
  Eigen::VectorXd free_gaps_;
  PenaltyComplementarity points_;  ///< the compliance C = V^T W and the penalty law on the points
};

}  // namespace isosid::run
