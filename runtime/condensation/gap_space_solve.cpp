// The quasistatic contact problem in gap space; see gap_space_solve.hpp.
#include "condensation/gap_space_solve.hpp"

#include "condensation/quasistatic_modes.hpp"
#include "contact/impact_estimate.hpp"
#include "isosid/format/error.hpp"

#include <Eigen/SparseCore>

#include <optional>

namespace isosid::run {

namespace {
/// C = V^T W between the points: each of V's nonzeros adds one row of W, read from W's
/// transpose as a contiguous column (the sparse product V^T W gathers every term from a
/// column of W, a strided read). The sums and their order are the sparse product's, so C is
/// bitwise the same.
Eigen::MatrixXd compliance(const Eigen::SparseMatrix<double>& V, const Eigen::MatrixXd& W) {
  const Eigen::MatrixXd Wt = W.transpose();
  Eigen::MatrixXd Ct = Eigen::MatrixXd::Zero(W.cols(), V.cols());  // column j: row j of C
  for (Eigen::Index j = 0; j < V.outerSize(); ++j)
    for (Eigen::SparseMatrix<double>::InnerIterator it(V, j); it; ++it) Ct.col(j).noalias() += it.value() * Wt.col(it.index());
  return Ct.transpose();
}
}  // namespace

GapSpaceSolve::GapSpaceSolve(const std::vector<const SurfaceContact*>& contacts, const QuasistaticJacobian& stiffness)
    : contacts_(contacts), stiffness_(stiffness) {
  if (!stiffness_.stiffness_solvable())
    throw format::InputError(contacts_.front()->name(), "formulation",
                             "gap-space contact condenses the quasistatic modes' stiffness, which is not positive definite here");
}

bool GapSpaceSolve::pair_approaching(const double* y) {
  bool paired = false;
  for (const SurfaceContact* c : contacts_) {
    GapPairing& pairing = c->gap_pairing();
    // an unpaired contact's gap: watched from its last pairing while clearly apart, else projected
    if (pairing.paired() || !(c->min_gap(y) < pairing.pairing_distance())) continue;
    const std::optional<ImpactEstimate> estimate = estimate_impact(*c, y);
    pairing.set_condensation_reach(estimate && estimate->approach > 0 ? kReachPerApproach * estimate->approach : INFINITY);
    pairing.pair(y);
    paired = true;
  }
  return paired;
}

bool GapSpaceSolve::evaluate_pairs(const double* y) {
  bool held = true;
  for (const SurfaceContact* c : contacts_) {
    GapPairing& pairing = c->gap_pairing();
    if (!pairing.paired()) continue;
    const std::vector<GapPairing::Evaluation>& evaluations = pairing.evaluations(pairing.poses(y));
    double smallest = INFINITY;
    bool slid = false;
    for (std::size_t k = 0; k < evaluations.size(); ++k) {
      const GapPairing::Pair& p = pairing.pairs()[k];
      const GapPairing::Evaluation& e = evaluations[k];
      smallest = std::min(smallest, e.gap);
      // a point far from the target may slide without harm: it counts from a spacing's distance on
      slid = slid || (e.gap < p.spacing && e.slip > GapPairing::kSlipPerSpacing * p.spacing);
    }
    if (slid) {
      pairing.pair(y);
      held = false;
    } else if (smallest > 2 * pairing.pairing_distance()) {
      pairing.release();
      held = false;
    }
  }
  if (!held) return false;
  // the stacked pairs run contact by contact: each run's evaluations fetched once
  const auto free_gaps = [&](const std::vector<StackedPair>& stacked, Eigen::VectorXd& gaps) {
    gaps.resize(Eigen::Index(stacked.size()));
    const std::vector<GapPairing::Evaluation>* evaluations = nullptr;
    for (std::size_t i = 0; i < stacked.size(); ++i) {
      const GapPairing& pairing = stacked[i].contact->gap_pairing();
      if (i == 0 || stacked[i].contact != stacked[i - 1].contact) evaluations = &pairing.evaluations(pairing.poses(y));
      gaps(Eigen::Index(i)) = (*evaluations)[stacked[i].k].gap;
    }
  };
  free_gaps(pairs_, free_gaps_);
  free_gaps(beyond_, free_gaps_beyond_);
  return true;
}

void GapSpaceSolve::throw_unsettled_pairing() const {
  throw QuasistaticDivergence("the gap-space pairing of contact '" + contacts_.front()->name() + "' slid again as soon as it was made (" +
                              std::to_string(kMaxRepairings) + " times at one state)");
}

Eigen::SparseMatrix<double> GapSpaceSolve::gradients(const double* y, const std::vector<StackedPair>& stacked) const {
  const Eigen::Index m = Eigen::Index(stacked.size()), n = stiffness_.size();
  // column by column: each pair's gradient touches its points' control points only
  std::vector<Eigen::Triplet<double>> entries;
  Eigen::VectorXd column(n);
  for (Eigen::Index i = 0; i < m; ++i) {
    column.setZero();
    stacked[std::size_t(i)].contact->gap_pairing().add_gradient(y, stacked[std::size_t(i)].k, column);
    for (Eigen::Index j = 0; j < n; ++j)
      if (column(j) != 0) entries.emplace_back(j, i, column(j));
  }
  Eigen::SparseMatrix<double> V(n, m);
  V.setFromTriplets(entries.begin(), entries.end());
  return V;
}

void GapSpaceSolve::condense(const double* y) {
  pairs_.clear(), beyond_.clear();
  for (const SurfaceContact* c : contacts_) {
    const GapPairing& pairing = c->gap_pairing();
    if (!pairing.paired()) continue;
    for (std::size_t k = 0; k < pairing.pairs().size(); ++k) (pairing.condensed(k) ? pairs_ : beyond_).push_back({c, k});
  }
  const Eigen::Index m = Eigen::Index(pairs_.size());
  const Eigen::SparseMatrix<double> V = gradients(y, pairs_);
  V_beyond_ = gradients(y, beyond_);
  stiffness_.solve_stiffness(V, W_);
  Eigen::VectorXd penalty_stiffness(m);
  for (Eigen::Index i = 0; i < m; ++i) {
    const StackedPair& p = pairs_[std::size_t(i)];
    penalty_stiffness(i) = p.contact->law().linear_stiffness() * p.contact->surface().weight(p.contact->gap_pairing().pairs()[p.k].g);
  }
  points_.set(compliance(V, W_), std::move(penalty_stiffness));
}

int GapSpaceSolve::solve_forces() {
  int iterations = 0;
  switch (points_.solve(free_gaps_, iterations)) {
    case PenaltyComplementarity::Outcome::Solved:
      response_.setZero(stiffness_.size());
      for (const Eigen::Index a : points_.pressed()) response_.noalias() += points_.forces()(a) * W_.col(a);
      return iterations;
    case PenaltyComplementarity::Outcome::NotPositiveDefinite:
      throw QuasistaticDivergence("the gap-space compliance of contact '" + contacts_.front()->name() + "' is not positive definite");
    case PenaltyComplementarity::Outcome::NotFinite:
      throw QuasistaticDivergence("the gap-space contact of '" + contacts_.front()->name() + "' has gaps that are not finite numbers");
    case PenaltyComplementarity::Outcome::NoActiveSet:
      break;
  }
  throw QuasistaticDivergence("the gap-space contact of '" + contacts_.front()->name() + "' found no active set in " +
                              std::to_string(iterations) + " iterations");
}

void GapSpaceSolve::record_solution(const double* y) {
  // points_.pressed() ascends, and pairs_ runs contact by contact with each contact's pairs
  // ascending: every contact's list ascends, the order in which its loads sum
  for (const Eigen::Index a : points_.pressed()) pairs_[std::size_t(a)].contact->gap_pairing().add_pressed(pairs_[std::size_t(a)].k);
  for (std::size_t a = 0; a < pairs_.size(); ++a) pairs_[a].contact->gap_pairing().note_gap(points_.gaps()(Eigen::Index(a)));
  for (std::size_t i = 0; i < beyond_.size(); ++i) beyond_[i].contact->gap_pairing().note_gap(gaps_beyond_(Eigen::Index(i)));
  for (const SurfaceContact* c : contacts_) {
    GapPairing& pairing = c->gap_pairing();
    if (pairing.paired()) pairing.solved_at(pairing.poses(y));
  }
}

bool GapSpaceSolve::widen_outgrown() {
  // the pairs beyond run contact by contact: a contact widens once however many of them press
  bool widened = false;
  const SurfaceContact* last_widened = nullptr;
  gaps_beyond_.resize(V_beyond_.outerSize());
  for (Eigen::Index i = 0; i < V_beyond_.outerSize(); ++i) {
    const SurfaceContact* c = beyond_[std::size_t(i)].contact;
    double gap = free_gaps_beyond_(i);
    for (Eigen::SparseMatrix<double>::InnerIterator it(V_beyond_, i); it; ++it) gap += it.value() * response_(it.index());
    gaps_beyond_(i) = gap;
    if (gap < 0 && c != last_widened) c->gap_pairing().widen(), last_widened = c, widened = true;
  }
  return widened;
}

}  // namespace isosid::run
