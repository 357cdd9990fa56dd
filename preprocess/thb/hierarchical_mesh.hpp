// The mesh of a hierarchically refined patch: per-level knot vectors (each level splits
// every span of its parent level into an integer number of equal spans) and nested parameter
// boxes Omega^0 = patch > Omega^1 > ... where each level's functions live (THB refinement,
// [R2] Sect. 2.3 and 4.3 in docs/references.md). The boxes are built from a refinement request.
#pragma once
#include "geometry/nurbs_patch.hpp"
#include "thb/level_factors.hpp"

#include <array>
#include <string>
#include <vector>

namespace isosid::prep {

/// An axis-aligned box in parameter space (one entry per parametric direction).
struct ParameterBox {
  std::vector<double> lo, hi;
  /// True if `inner` lies inside this box (a relative tolerance absorbs knot round-off).
  bool contains(const std::vector<double>& inner_lo, const std::vector<double>& inner_hi) const;
};

/// Where and how finely to refine ([refinement.hierarchical] in a model file).
struct HierarchicalRequest {
  std::vector<std::array<double, 2>> box;  ///< one [lo, hi] per direction, or empty if `point` is used
  std::vector<double> point;               ///< patch parameter of the contact point ...
  double width = 0;                        ///< ... and the physical width of the refined region, m
  double smallest = 0;                     ///< m, element size in the box; 0: from elements_across
  int elements_across = 16;                ///< [R2]: elements across the interval per direction
  int admissibility = 2;                   ///< class m: functions of at most m levels on any element
  LevelLimits limits;
};

struct HierarchicalMesh {
  std::vector<int> degrees;
  std::vector<std::vector<KnotVector>> knots;   ///< [level][direction]
  std::vector<std::vector<int>> factors;        ///< [level][direction] span split from the parent level (1 at level 0)
  std::vector<ParameterBox> domains;            ///< [level]: Omega^level; level 0 is the whole patch
  int levels() const { return int(knots.size()); }
  int param_dim() const { return int(degrees.size()); }

  /// The patch itself as a one-level hierarchy (a tensor-product space).
  static HierarchicalMesh single_level(const NurbsPatch& patch);
};

/// Resolves the request on `base` (the globally refined coarse patch): the parameter box,
/// the level factors of each direction ([R2] Alg. 3, largest split at the coarsest level)
/// and nested domains admissible of class m (Omega^{l+m-1} grown by p level-l elements lies in
/// Omega^l, so at most m levels have functions on any element). Throws InputError(file, field, problem).
HierarchicalMesh hierarchical_mesh(const NurbsPatch& base, const HierarchicalRequest& request, const std::string& file);

}  // namespace isosid::prep
