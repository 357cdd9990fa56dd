// The SID layout table's terms, its ordered item list and its markdown form; see sid_layout.hpp.
#include "isosid/format/sid_layout.hpp"

namespace isosid::format::layout {
namespace {

constexpr Extent k3{3};
constexpr Extent k3Nq{3, Size::Nq};

std::string_view size_name(Size s) {
  switch (s) {
    case Size::One: return "";
    case Size::Nq: return "nq";
    case Size::Dim: return "dim";
    case Size::Points: return "npts";
    case Size::ControlPoints: return "ncp";
    case Size::Components: return "ncomp";
    case Size::CoarseNq: return "nc";
    case Size::ParamDim: return "param_dim";
    case Size::Knots: return "nknots";
    case Size::Levels: return "levels";
    case Size::Timings: return "ntimings";
    case Size::Interfaces: return "ninterfaces";
    case Size::Cells: return "ncells";
    case Size::Corners: return "ncorners";
    case Size::Count: break;
  }
  return "?";
}

std::string extent_text(const Extent& e) {
  std::string symbols(size_name(e.a));
  if (e.b != Size::One) symbols += "·" + std::string(size_name(e.b));
  if (symbols.empty()) return std::to_string(e.factor);
  return e.factor == 1 ? symbols : std::to_string(e.factor) + symbols;
}

std::string shape_text(const Shape& s) {
  if (s.rank == 0) return "scalar";
  if (s.rank == 1) return extent_text(s.rows);
  return extent_text(s.rows) + " × " + extent_text(s.cols);
}

std::string_view kind_text(Kind k) {
  switch (k) {
    case Kind::Group: return "group";
    case Kind::Float64: return "float64";
    case Kind::Int64: return "int64";
    case Kind::Int32: return "int32";
    case Kind::String: return "string";
    case Kind::StringAttribute: return "string attribute";
    case Kind::TaylorOrder0: return "Taylor, order 0";
    case Kind::TaylorOrder1: return "Taylor, order 0 or 1";
  }
  return "?";
}

std::string row(const Item& item) {
  std::string path = "`" + std::string(item.path) + "`";
  if (!item.attribute.empty()) path += " attribute `" + std::string(item.attribute) + "`";
  std::string shape = item.kind == Kind::Group ? "" : shape_text(item.shape);
  if (item.kind == Kind::TaylorOrder0) shape = "M0 " + shape;
  if (item.kind == Kind::TaylorOrder1) shape = "M0 " + shape + ", M1 nq × " + shape;
  return "| " + path + " | " + std::string(kind_text(item.kind)) + " | " + shape + " | " + std::string(item.units) +
         " | " + (item.presence == Presence::Required ? "required" : "optional") + " | " + std::string(item.meaning) +
         " |\n";
}

}  // namespace

std::string Item::at(std::string_view name, std::string_view direction) const {
  std::string p(path);
  for (auto [placeholder, value] : {std::pair{std::string_view("<name>"), name}, {std::string_view("<d>"), direction}})
    if (const auto at = p.find(placeholder); at != std::string::npos) p.replace(at, placeholder.size(), value);
  return p;
}

Sizes::Sizes(Eigen::Index nq, Eigen::Index dim) {
  values_.fill(0);
  set(Size::One, 1).set(Size::Nq, nq).set(Size::Dim, dim);
}

Sizes& Sizes::set(Size size, Eigen::Index value) {
  values_[std::size_t(size)] = value;
  return *this;
}

Eigen::Index Sizes::operator()(const Extent& e) const {
  return e.factor * values_[std::size_t(e.a)] * values_[std::size_t(e.b)];
}

const std::vector<Term>& terms() {
  using enum Kind;
  constexpr auto R = Presence::Required;
  static const std::vector<Term> table = {
      {{"/terms/mdCM", {}, TaylorOrder1, matrix(k3, {1}), "kg*m", R, "first moment of mass"}, &Sid::mdCM},
      {{"/terms/J", {}, TaylorOrder1, matrix(k3, k3), "kg*m^2", R, "inertia about the frame origin (symmetric)"}, &Sid::J},
      {{"/terms/Ct", {}, TaylorOrder1, matrix(kNq, k3), "kg*m/[q]", R, "translational coupling"}, &Sid::Ct},
      {{"/terms/Cr", {}, TaylorOrder1, matrix(kNq, k3), "kg*m^2/[q]", R, "rotational coupling"}, &Sid::Cr},
      {{"/terms/Me", {}, TaylorOrder0, matrix(kNq, kNq), "kg*m^2/[q]^2", R,
        "modal mass (symmetric, positive diagonal)"}, &Sid::Me},
      {{"/terms/Gr", {}, TaylorOrder1, matrix(k3, k3Nq), "kg*m^2/[q]", R, "block k: 2∫c̃ᵀΦ̃ₖ dm"}, &Sid::Gr},
      {{"/terms/Ge", {}, TaylorOrder0, matrix(kNq, k3Nq), "kg*m^2/[q]^2", R, "block j, row a: 2∫(Φⱼ×Φₐ)ᵀ dm"}, &Sid::Ge},
      {{"/terms/Oe", {}, TaylorOrder1, matrix(kNq, {6}), "kg*m^2/[q]", R,
        "columns pair with [ωx², ωy², ωz², ωxωy, ωyωz, ωzωx]"}, &Sid::Oe},
      {{"/terms/ksigma", {}, TaylorOrder1, matrix(kNq, {1}), "N*m/[q]", R,
        "prestress modal force (zero unless prestressed)"}, &Sid::ksigma},
      {{"/terms/Ke", {}, TaylorOrder0, matrix(kNq, kNq), "N*m^2/[q]^2", R, "modal stiffness (symmetric)"}, &Sid::Ke},
      {{"/terms/De", {}, TaylorOrder0, matrix(kNq, kNq), "N*s*m^2/[q]^2", R, "modal damping (symmetric)"}, &Sid::De},
  };
  return table;
}

const std::vector<const Item*>& items() {
  static const std::vector<const Item*> all = [] {
    std::vector<const Item*> v = {
        &header::group, &header::version, &header::program_version,
        &body::group, &body::name, &body::analysis_type, &body::youngs_modulus, &body::poisson_ratio, &body::density,
        &body::thickness,
        &refmod::group, &refmod::q_units, &refmod::mass, &refmod::nq, &refmod::mode_names, &refmod::frequencies_hz,
        &refmod::n_low, &refmod::n_high, &refmod::reduction_method, &refmod::interface,
        &refmod::section_translation, &refmod::long_axis,
        &damping::group, &damping::kappa, &damping::f1_hz, &damping::f2_hz, &damping::alpha1, &damping::alpha2,
        &terms_group};
    for (const Term& t : terms()) v.push_back(&t.item);
    v.insert(v.end(), {
        &node::list, &node::group, &node::origin, &node::phi, &node::psi, &node::AP,
        &master::list, &master::group, &master::degrees, &master::knots, &master::weights, &master::control_points,
        &master::Phi,
        &contact::list, &contact::group, &contact::patch, &contact::side, &contact::master_patch, &contact::parameter, &contact::element,
        &contact::position, &contact::normal, &contact::weight, &contact::Psi, &contact::in_interface,
        &stress::list, &stress::group, &stress::patch, &stress::components, &stress::position, &stress::S,
        &patches::list, &patches::group, &patches::youngs_modulus, &patches::poisson_ratio, &patches::density,
        &patches::interfaces,
        &transfer::group, &transfer::coarse_model_sha256, &transfer::coarse_to_fine, &transfer::fine_to_coarse,
        &discretization::group, &discretization::elements_per_level, &discretization::functions_per_level,
        &discretization::free_dofs, &discretization::contact_radius,
        &visual::group, &visual::corners_per_cell, &visual::position, &visual::cells, &visual::Phi,
        &visual::stress_components, &visual::S,
        &provenance::group, &provenance::model_file, &provenance::model_sha256, &provenance::program_version,
        &provenance::created_utc, &provenance::command_line, &provenance::timing_names, &provenance::timings_s});
    return v;
  }();
  return all;
}

std::string markdown_table() {
  std::string out = "| path | type | shape | units | presence | meaning |\n|---|---|---|---|---|---|\n";
  for (const Item* item : items()) out += row(*item);
  return out;
}

}  // namespace isosid::format::layout
