// The quasistatic contact problem in gap space; see gap_space_solve.hpp.
#include "condensation/gap_space_solve.hpp"

#include "condensation/quasistatic_modes.hpp"
#include "isosid/format/error.hpp"

#include <Eigen/SparseCore>

namespace isosid::run {

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
    if (!pairing.paired() && c->min_gap(y) < pairing.pairing_distance()) pairing.pair(y), paired = true;
  }
  return paired;
}

bool GapSpaceSolve::evaluate_pairs(const double* y) {
  const Eigen::Index m = Eigen::Index(pairs_.size());
  free_gaps_.resize(m);
  GapPairing::Evaluation e;
  bool held = true;
  // pairs are stacked contact by contact: each contact's run of them
  for (Eigen::Index first = 0; first < m;) {
    const SurfaceContact* c = pairs_[std::size_t(first)].contact;
    GapPairing& pairing = c->gap_pairing();
    const GapPairing::Poses at = pairing.poses(y);
    double smallest = INFINITY;
    bool slid = false;
    Eigen::Index i = first;
    for (; i < m && pairs_[std::size_t(i)].contact == c; ++i) {
      const GapPairing::Pair& p = pairing.pairs()[pairs_[std::size_t(i)].k];
      pairing.evaluate(at, pairs_[std::size_t(i)].k, e);
      free_gaps_(i) = e.gap;
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
    first = i;
  }
  return held;
}

void GapSpaceSolve::throw_unsettled_pairing() const {
  throw QuasistaticDivergence("the gap-space pairing of contact '" + contacts_.front()->name() + "' slid again as soon as it was made (" +
                              std::to_string(kMaxRepairings) + " times at one state)");
}

void GapSpaceSolve::condense(const double* y) {
  pairs_.clear();
  for (const SurfaceContact* c : contacts_) {
    const GapPairing& pairing = c->gap_pairing();
    if (!pairing.paired()) continue;
    for (std::size_t k = 0; k < pairing.pairs().size(); ++k) pairs_.push_back({c, k});
  }
  const Eigen::Index m = Eigen::Index(pairs_.size()), n = stiffness_.size();
  // V column by column: each pair's gradient touches its points' control points only
  std::vector<Eigen::Triplet<double>> entries;
  Eigen::VectorXd column(n);
  for (Eigen::Index i = 0; i < m; ++i) {
    column.setZero();
    pairs_[std::size_t(i)].contact->gap_pairing().add_gradient(y, pairs_[std::size_t(i)].k, column);
    for (Eigen::Index j = 0; j < n; ++j)
      if (column(j) != 0) entries.emplace_back(j, i, column(j));
  }
  Eigen::SparseMatrix<double> V(n, m);
  V.setFromTriplets(entries.begin(), entries.end());
  stiffness_.solve_stiffness(V, W_);
  C_.noalias() = V.transpose() * W_;
  stiffness_per_point_.resize(m);
  for (Eigen::Index i = 0; i < m; ++i) {
    const StackedPair& p = pairs_[std::size_t(i)];
    stiffness_per_point_(i) = p.contact->penalty() * p.contact->surface().weight(p.contact->gap_pairing().pairs()[p.k].g);
  }
  forces_.setZero(m);
  active_.assign(std::size_t(m), 0);
}

int GapSpaceSolve::solve_forces() {
  const Eigen::Index m = Eigen::Index(pairs_.size());
  // semismooth Newton on the active set: the active points' forces solve
  // (C_AA + diag(1 / (c_p w))) f_A = -g_free,A; a point leaves where its force would pull,
  // enters where its gap closes
  for (int iteration = 1; iteration <= kMaxIterations; ++iteration) {
    active_index_.clear();
    for (Eigen::Index i = 0; i < m; ++i)
      if (active_[std::size_t(i)]) active_index_.push_back(i);
    const Eigen::Index r = Eigen::Index(active_index_.size());
    forces_.setZero();
    if (r > 0) {
      active_matrix_.resize(r, r);
      active_forces_.resize(r);
      for (Eigen::Index b = 0; b < r; ++b) {
        for (Eigen::Index a = b; a < r; ++a) active_matrix_(a, b) = C_(active_index_[std::size_t(a)], active_index_[std::size_t(b)]);
        active_matrix_(b, b) += 1.0 / stiffness_per_point_(active_index_[std::size_t(b)]);
        active_forces_(b) = -free_gaps_(active_index_[std::size_t(b)]);
      }
      Eigen::LLT<Eigen::MatrixXd, Eigen::Lower> llt(active_matrix_);
      if (llt.info() != Eigen::Success)
        throw QuasistaticDivergence("the gap-space compliance of contact '" + contacts_.front()->name() + "' is not positive definite");
      llt.solveInPlace(active_forces_);
      for (Eigen::Index b = 0; b < r; ++b) forces_(active_index_[std::size_t(b)]) = active_forces_(b);
    }
    gaps_ = free_gaps_;
    for (const Eigen::Index a : active_index_) gaps_.noalias() += forces_(a) * C_.col(a);
    bool changed = false;
    for (Eigen::Index i = 0; i < m; ++i) {
      const char now = active_[std::size_t(i)] ? forces_(i) > 0 : gaps_(i) < 0;
      changed = changed || now != active_[std::size_t(i)];
      active_[std::size_t(i)] = now;
    }
    if (!changed) return iteration;
  }
  throw QuasistaticDivergence("the gap-space contact of '" + contacts_.front()->name() + "' found no active set in " +
                              std::to_string(kMaxIterations) + " Newton iterations");
}

}  // namespace isosid::run
