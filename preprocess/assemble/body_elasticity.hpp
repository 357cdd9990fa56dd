// The elasticity of each patch of a body (a single-patch body has one): an element, a Gauss
// point or a point operator takes its patch's material.
#pragma once
#include "assemble/elasticity.hpp"
#include "space/analysis_space.hpp"

#include <vector>

namespace isosid::prep {

class BodyElasticity {
public:
  /// A body of one material (implicit: single-patch code and tests pass an Elasticity).
  BodyElasticity(Elasticity single) : patches_{std::move(single)} {}  // NOLINT(google-explicit-constructor)
  /// One entry per patch, all of one analysis type.
  explicit BodyElasticity(std::vector<Elasticity> per_patch) : patches_(std::move(per_patch)) {}

  const Elasticity& of_patch(int patch) const { return patches_[std::size_t(patch)]; }
  const Elasticity& of(const Element& e) const { return of_patch(e.patch); }
  // the same for every patch: the analysis type fixes them
  format::AnalysisType type() const { return patches_.front().type(); }
  int dim() const { return patches_.front().dim(); }
  std::vector<std::string> stress_components() const { return patches_.front().stress_components(); }

private:
  std::vector<Elasticity> patches_;
};

}  // namespace isosid::prep
