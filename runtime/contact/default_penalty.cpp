// The default penalty rule; see default_penalty.hpp.
#include "contact/default_penalty.hpp"

#include "isosid/format/error.hpp"

#include <algorithm>
#include <cmath>
#include <map>
#include <numbers>
#include <vector>

namespace isosid::run {

std::map<int, double> contact_element_lengths(const format::ContactSurface& surface, const format::Sid& sid) {
  // the weights are the element's measure times the analysis' factor: 2 pi r (axisymmetric),
  // the thickness (planar) or 1 (an area, 3D)
  std::map<int, double> measure;
  for (Eigen::Index g = 0; g < surface.points(); ++g) {
    double factor = 1;
    if (sid.analysis == format::AnalysisType::Axisymmetric) factor = 2 * std::numbers::pi * std::abs(surface.position(g, 0));
    else if (sid.dim() == 2) factor = sid.thickness;
    if (factor > 0) measure[surface.element(g)] += surface.weight(g) / factor;
  }
  std::map<int, double> length;
  for (const auto& [element, m] : measure)
    if (m > 0) length[element] = sid.dim() == 3 ? std::sqrt(m) : m;
  return length;
}

double contact_element_size(const format::ContactSurface& surface, const format::Sid& sid) {
  std::vector<double> lengths;
  for (const auto& [element, length] : contact_element_lengths(surface, sid)) lengths.push_back(length);
  if (lengths.empty()) return INFINITY;
  // the lower quartile: the finest elements, but not a sliver that grading left behind (a
  // sphere graded toward its pole can end with one element a tenth of its neighbours)
  const auto quartile = lengths.begin() + std::ptrdiff_t((lengths.size() - 1) / 4);
  std::nth_element(lengths.begin(), quartile, lengths.end());
  return *quartile;
}

double combined_modulus(const FloatingBody& slave, const FloatingBody* master, const std::string& slave_patch,
                        const std::string& master_patch) {
  auto compliance = [](const FloatingBody& b, const std::string& patch) {
    const format::Material& m = format::material_of(b.sid(), patch);
    return b.nq() == 0 || m.youngs_modulus <= 0 ? 0.0 : (1 - m.poisson_ratio * m.poisson_ratio) / m.youngs_modulus;
  };
  return 1 / (compliance(slave, slave_patch) + (master ? compliance(*master, master_patch) : 0.0));
}

double default_penalty(const FloatingBody& slave, const format::ContactSurface& slave_surface, const FloatingBody* master,
                       const format::ContactSurface* master_surface, double contact_radius) {
  double h = contact_element_size(slave_surface, slave.sid());
  if (master && master_surface) h = std::min(h, contact_element_size(*master_surface, master->sid()));
  const double modulus = combined_modulus(slave, master, slave_surface.patch, master_surface ? master_surface->patch : "");
  if (!std::isfinite(h) || !std::isfinite(modulus))
    throw format::InputError(slave.name(), "penalty",
                             "cannot be derived (no contact element size or no elastic material): give it in the scene");
  return kPenaltyStiffnessRatio * modulus / std::max(h, contact_radius);
}

}  // namespace isosid::run
