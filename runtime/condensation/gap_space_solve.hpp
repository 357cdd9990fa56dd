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
//
// Only the pairs within their pairing's reach are condensed: at a contact's first pairing the
// reach is kReachPerApproach times the Hertz estimate's approach there (a sphere on a plane:
// the points within 1.22 a of the first touch; the contact itself spans a). The pairs beyond
// are checked after each solve, their gaps g_free + V^T (W f) at the forces found: if one would
// press, its contact's reach doubles and the solve is repeated, so the forces are those of every
// pair condensed (those beyond carry none: open gaps under the penalty law).
#pragma once
#include "condensation/penalty_complementarity.hpp"
#include "condensation/quasistatic_jacobian.hpp"
#include "contact/surface_contact.hpp"

#include <Eigen/SparseCore>

#include <vector>

namespace isosid::run {

class GapSpaceSolve {
public:
  /// Pairings made again at one state before the solve fails.
  static constexpr int kMaxRepairings = 3;
  /// A first pairing's reach per Hertz approach (contacts without a Hertz estimate: every pair).
  /// A point of a sphere on a plane at radius r from the first touch is offset by r^2 / 2R, and
  /// the Hertz approach is a^2 / R: the contact's points lie within half an approach, this reach
  /// within 1.22 a.
  static constexpr double kReachPerApproach = 0.75;

  /// `contacts`: every contact on the quasistatic modes, each solved in gap space
  /// (penalty, frictionless); `stiffness`: K of the stacked quasistatic modes.
  GapSpaceSolve(const std::vector<const SurfaceContact*>& contacts, const QuasistaticJacobian& stiffness);

  /// The quasistatic coordinates z at y, given in z their response to the loads that do not
  /// depend on them, z_h = K^-1 h; `scatter` sets them on the bodies. Pairs the contacts that
  /// come near, pairs again those that slid, releases those that left. Returns the points'
  /// problem's iterations.
  template <class Scatter>
  int solve(const double* y, Eigen::VectorXd& z, Scatter&& scatter) {
    for (const SurfaceContact* c : contacts_) c->gap_pairing().forget_solution();
    scatter(z);
    if (pair_approaching(y)) condense(y);
    // the pairs at z_h: their free gaps, and whether each pairing still holds (a pairing made
    // here holds here: its points were just projected)
    for (int pass = 0; !pairs_.empty() && !evaluate_pairs(y); ++pass) {
      if (pass == kMaxRepairings) throw_unsettled_pairing();
      condense(y);
    }
    if (pairs_.empty()) return 0;
    int iterations = solve_forces();
    while (widen_outgrown()) {
      condense(y);
      evaluate_pairs(y);  // the same pairs, stacked anew: it holds
      iterations += solve_forces();
    }
    z.noalias() += response_;
    scatter(z);
    record_solution(y);
    return iterations;
  }

private:
  /// One stacked pair: its contact and its index there.
  struct StackedPair {
    const SurfaceContact* contact = nullptr;
    std::size_t k = 0;
  };
  /// Pairs the unpaired contacts that came within their pairing distance at y (z = z_h set),
  /// each with its reach; true if any was.
  bool pair_approaching(const double* y);
  /// V, W and C of the current pairs within reach, their penalty stiffness c_p w, and the
  /// gradients of the pairs beyond.
  void condense(const double* y);
  /// The pairs' free gaps at y (z = z_h set), in one pass that also checks each pairing: one
  /// that slid is paired again, one whose pairs are all open by twice the pairing distance
  /// released. False if a pairing changed (the pairs must then be condensed again).
  bool evaluate_pairs(const double* y);
  /// The points' forces at the free gaps, and their response W f; returns the iterations.
  int solve_forces();
  /// The gaps of the pairs beyond reach at the forces found (gaps_beyond_), and the reach widened
  /// of every contact with such a pair that would press; true if any was.
  bool widen_outgrown();
  /// Tells each paired contact which of its pairs the last solve pressed and its pairs' smallest
  /// gap, at y's poses with the solution set: its loads there evaluate those pairs alone, and its
  /// gap there needs no evaluation.
  void record_solution(const double* y);
  /// The gaps' gradients of stacked pairs at y, a column each.
  Eigen::SparseMatrix<double> gradients(const double* y, const std::vector<StackedPair>& stacked) const;
  /// Throws QuasistaticDivergence: the pairings at one state did not hold after kMaxRepairings.
  [[noreturn]] void throw_unsettled_pairing() const;

  std::vector<const SurfaceContact*> contacts_;
  const QuasistaticJacobian& stiffness_;
  std::vector<StackedPair> pairs_;   ///< within reach: condensed
  std::vector<StackedPair> beyond_;  ///< paired beyond reach: checked
  Eigen::MatrixXd W_;
  Eigen::SparseMatrix<double> V_beyond_;  ///< the gaps' gradients of the pairs beyond reach
  Eigen::VectorXd free_gaps_, free_gaps_beyond_, gaps_beyond_;
  Eigen::VectorXd response_;  ///< W f of the last solve
  PenaltyComplementarity points_;  ///< the compliance C = V^T W and the penalty law on the points
};

}  // namespace isosid::run
