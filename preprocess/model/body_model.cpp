// Building a refined, constrained body; see body_model.hpp.
#include "model/body_model.hpp"

#include "assemble/boundary_quadrature.hpp"
#include "refine/patch_refinement.hpp"
#include "isosid/format/error.hpp"

#include <algorithm>
#include <cstdio>
#include <set>

namespace isosid::prep {

namespace {
/// Refuses a refinement that would give more control points than isosid-prep can reduce, before
/// the knots go in (1000 subdivisions in each direction of a solid are 10^9 points).
void check_refined_size(const NurbsPatch& p, const std::vector<double>& added, const std::string& file,
                        const std::string& field) {
  const std::vector<int> counts = p.counts();
  double total = 1;
  for (std::size_t d = 0; d < counts.size(); ++d) total *= double(counts[d]) + added[d];
  if (total > kMaxControlPoints) {
    char text[256];
    std::snprintf(text, sizeof text, "gives %.3g control points, more than the %.0f isosid-prep reduces (a finer mesh "
                  "than any eigen solve here can take): refine less or only near the contact", total, kMaxControlPoints);
    throw format::InputError(file, field, text);
  }
}

/// A THB refinement that reaches into the last coarse element row along an interface side
/// would refine or truncate functions on that side, which the other patch does not share:
/// refused, naming the patch and the side.
void refuse_refined_interfaces(const ModelSpec& spec, const std::vector<PatchInterface>& interfaces, int patch,
                               const NurbsPatch& refined, const HierarchicalMesh& mesh) {
  if (mesh.domains.size() < 2) return;
  const ParameterBox& box = mesh.domains[1];  // the largest refined region (they are nested)
  for (const PatchInterface& i : interfaces) {
    if (i.a != patch && i.b != patch) continue;
    const PatchSide side = i.a == patch ? i.side_a : i.side_b;
    const auto d = std::size_t(side.direction);
    const std::vector<double> u = unique_knots(refined.knots[d]);
    // the coarse functions nonzero on the side live on the outermost span only
    const bool clear = side.end ? box.hi[d] <= u[u.size() - 2] + 1e-12 * (u.back() - u.front())
                                : box.lo[d] >= u[1] - 1e-12 * (u.back() - u.front());
    if (!clear)
      throw format::InputError(spec.file, "patch " + spec.patches[std::size_t(patch)].name + ".refinement.hierarchical",
                               "the refined region reaches the elements along side " + side_name(side) +
                                   ", an interface with another patch: keep it at least one element inside the patch");
  }
}

/// The THB prolongation and level counts of one patch, widened to the whole body: the other
/// patches' functions carry over unchanged (identity blocks) and count as level 0.
void widen_to_body(Hierarchy& h, std::size_t thb_patch, const std::vector<AnalysisSpace>& spaces, const std::vector<NurbsPatch>& refined) {
  std::vector<Eigen::Triplet<double>> t;
  int row = 0, col = 0;
  for (std::size_t k = 0; k < spaces.size(); ++k) {
    if (k == thb_patch) {
      for (int o = 0; o < h.prolongation.outerSize(); ++o)
        for (Eigen::SparseMatrix<double>::InnerIterator it(h.prolongation, o); it; ++it)
          t.emplace_back(row + int(it.row()), col + int(it.col()), it.value());
    } else {
      for (int i = 0; i < spaces[k].n_functions(); ++i) t.emplace_back(row + i, col + i, 1.0);
      h.functions_per_level[0] += spaces[k].n_functions();
      h.elements_per_level[0] += int(spaces[k].elements.size());
    }
    row += spaces[k].n_functions();
    col += refined[k].count();
  }
  h.prolongation.resize(row, col);
  h.prolongation.setFromTriplets(t.begin(), t.end());
}

}  // namespace

NurbsPatch refine_patch(const NurbsPatch& coarse, const RefinementSpec& r, const std::string& file) {
  NurbsPatch p = coarse;
  for (std::size_t d = 0; d < r.degrees.size(); ++d) elevate_degree(p, int(d), r.degrees[d]);
  std::vector<double> added(std::size_t(p.param_dim()), 0.0);
  // subdivide_uniformly splits each non-empty span: (parts - 1) new knots per span
  for (std::size_t d = 0; d < r.subdivisions.size(); ++d)
    added[d] = double(r.subdivisions[d] - 1) * double(unique_knots(p.knots[d]).size() - 1);
  check_refined_size(p, added, file, "refinement.subdivisions");
  for (std::size_t d = 0; d < r.subdivisions.size(); ++d) subdivide_uniformly(p, int(d), r.subdivisions[d]);
  // all graded requests are sized on the geometry before grading, then inserted together
  std::vector<std::vector<double>> knots(std::size_t(p.param_dim()));
  // each request's knots counted before any is marched (a tiny smallest with a growth near 1
  // would march hundreds of millions of them)
  for (std::size_t i = 0; i < r.graded.size(); ++i) {
    std::fill(added.begin(), added.end(), 0.0);
    added[std::size_t(r.graded[i].direction)] = graded_knot_count_bound(p, r.graded[i]);
    check_refined_size(p, added, file, "refinement.graded[" + std::to_string(i) + "]");
  }
  for (const GradingRequest& g : r.graded) {
    const auto k = graded_knots(p, g);
    knots[std::size_t(g.direction)].insert(knots[std::size_t(g.direction)].end(), k.begin(), k.end());
  }
  for (auto& k : knots) {
    std::sort(k.begin(), k.end());
    k.erase(std::unique(k.begin(), k.end(), [](double a, double b) { return std::abs(a - b) < 1e-13; }), k.end());
  }
  for (std::size_t d = 0; d < knots.size(); ++d) added[d] = double(knots[d].size());
  check_refined_size(p, added, file, "refinement.graded");
  for (std::size_t d = 0; d < knots.size(); ++d) insert_knots(p, int(d), knots[d]);
  return p;
}

double patch_size(const NurbsPatch& patch) {
  return (patch.points.colwise().maxCoeff() - patch.points.colwise().minCoeff()).norm();
}

double patches_size(const std::vector<NurbsPatch>& patches) {
  Eigen::VectorXd lo = patches.front().points.colwise().minCoeff(), hi = patches.front().points.colwise().maxCoeff();
  for (const NurbsPatch& p : patches) {
    lo = lo.cwiseMin(p.points.colwise().minCoeff().transpose());
    hi = hi.cwiseMax(p.points.colwise().maxCoeff().transpose());
  }
  return (hi - lo).norm();
}

std::vector<int> side_nodes(const BodyModel& body, int patch, PatchSide side) {
  std::set<int> nodes;
  for (const BoundaryPoint& bp : boundary_points(body.space, body.elasticity, patch, side)) {
    const Element& e = body.space.elements[std::size_t(bp.element)];
    for (std::size_t k = 0; k < e.functions.size(); ++k)
      if (std::abs(bp.R(Eigen::Index(k))) > 1e-12) nodes.insert(body.dofs.node_of(e.functions[k]));
  }
  return {nodes.begin(), nodes.end()};
}

ModelSpec coarse_model_spec(const ModelSpec& spec) {
  ModelSpec coarse = spec;
  for (PatchSpec& p : coarse.patches) p.refinement.hierarchical.reset();
  coarse.reduction.method = format::ReductionMethod::Modal;
  return coarse;
}

BodyModel build_body(const ModelSpec& spec) {
  // a mesher's elements conform by construction and are too many for the pairwise search
  std::vector<PatchInterface> interfaces = spec.mesh ? find_mesh_interfaces(spec.patches) : find_interfaces(spec.patches, spec.file);
  std::vector<NurbsPatch> refined;
  for (const PatchSpec& p : spec.patches) refined.push_back(refine_patch(p.patch, p.refinement, spec.file));
  make_conforming(refined, interfaces);
  // one patch at most is refined hierarchically (the model file says so); the others are tensor spaces
  std::vector<AnalysisSpace> spaces;
  std::optional<Hierarchy> hierarchy;
  std::size_t thb_patch = 0;
  for (std::size_t k = 0; k < refined.size(); ++k) {
    const RefinementSpec& r = spec.patches[k].refinement;
    if (!r.hierarchical) {
      spaces.push_back(tensor_space(refined[k]));
      continue;
    }
    Hierarchy h{hierarchical_mesh(refined[k], *r.hierarchical, spec.file), {}, {}, {}};
    refuse_refined_interfaces(spec, interfaces, int(k), refined[k], h.mesh);
    HierarchicalSpace thb = hierarchical_space(refined[k], h.mesh);
    spaces.push_back(std::move(thb.space));
    h.functions_per_level = std::move(thb.functions_per_level);
    h.elements_per_level = std::move(thb.elements_per_level);
    h.prolongation = std::move(thb.prolongation);
    hierarchy = std::move(h);
    thb_patch = k;
  }
  if (hierarchy && refined.size() > 1) widen_to_body(*hierarchy, thb_patch, spaces, refined);
  AnalysisSpace space = join_spaces(std::move(spaces));
  const double size = patches_size(refined);
  const int dim = format::spatial_dim(spec.analysis);
  std::vector<std::pair<int, PatchSide>> point_sides;
  for (int k = 0; k < int(refined.size()); ++k) {
    const NurbsPatch& p = refined[std::size_t(k)];
    for (int d = 0; d < p.param_dim(); ++d)
      for (int end = 0; end < 2; ++end)
        if (int(p.collapsed_directions({d, end}).size()) == p.param_dim() - 1) point_sides.push_back({k, {d, end}});
  }
  DofMap dofs(space, dim, 1e-10 * size, point_sides);
  std::vector<Elasticity> materials;
  for (const PatchSpec& p : spec.patches) materials.emplace_back(spec.analysis, p.material, spec.thickness);
  BodyModel body{spec, std::move(refined), std::move(interfaces), std::move(space), std::move(hierarchy),
                 BodyElasticity(std::move(materials)), std::move(dofs)};
  if (spec.analysis == format::AnalysisType::Axisymmetric)  // radial displacement vanishes on the axis
    for (int n = 0; n < body.dofs.node_count(); ++n)
      if (std::abs(body.dofs.node_points()(n, 0)) <= 1e-10 * size) body.dofs.fix(n, 0);
  for (const FixedComponents& f : spec.fixed)
    for (int node : side_nodes(body, f.patch, *body.refined[std::size_t(f.patch)].side(f.side)))
      for (int a : f.components) body.dofs.fix(node, a);
  return body;
}

}  // namespace isosid::prep
