// Compares two SIDs of the same body up to the arbitrariness of their mode bases:
// signs and rotations within groups of repeated frequencies are factored out by
// principal angles and an orthogonal (Procrustes) alignment before terms are compared.
#pragma once
#include "isosid/format/sid.hpp"

#include <string>
#include <vector>

namespace isosid::format {

struct Difference {
  std::string what;        ///< e.g. "/terms/Ct/M0" or "frequency of mode 3"
  double difference = 0;   ///< ||a - b|| (after alignment)
  double tolerance = 0;    ///< what was allowed
  std::string detail;
};

struct ModeCluster {
  Eigen::Index first = 0, size = 0;   ///< modes [first, first+size) share one frequency (to tolerance)
  double max_sine = 0;                ///< sine of the largest principal angle between the two subspaces
  bool determined = true;             ///< false if the stored rows do not span the cluster
};

struct Comparison {
  std::vector<Difference> differences;
  std::vector<ModeCluster> clusters;
  std::vector<std::string> notes;
  bool equal() const { return differences.empty(); }
};

/// The smallest tolerance a comparison can honour: aligning the mode bases (principal angles,
/// an orthogonal Procrustes rotation) and rotating the reduced terms into one basis leave
/// round-off of a few hundred machine epsilons even between identical files.
constexpr double kComparisonRoundOff = 1e-13;

/// rtol: relative tolerance on every compared quantity (at least kComparisonRoundOff, so that
/// rtol 0 means "equal to round-off"); small quantities are compared against rtol times their
/// natural scale (mass, size and frequencies of the body).
Comparison compare_sids(const Sid& a, const Sid& b, double rtol);

}  // namespace isosid::format
