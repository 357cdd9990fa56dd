// The SID file layout as one table: every group, dataset and attribute with its type, shape
// rule, units, presence and meaning. The writer, reader and validator take their paths, units
// and shapes from it, and format/README.md's layout section is generated from it.
#pragma once
#include "isosid/format/sid.hpp"

#include <Eigen/Core>
#include <array>
#include <string>
#include <string_view>
#include <vector>

namespace isosid::format::layout {

/// The sizes shape rules are written in.
enum class Size { One, Nq, Dim, Points, ControlPoints, Components, CoarseNq, ParamDim, Knots, Levels, Timings, Interfaces, Cells, Corners, Count };

/// factor * a * b, e.g. 3nq = {3, Nq}, npts·dim = {1, Points, Dim}.
struct Extent {
  Eigen::Index factor = 1;
  Size a = Size::One;
  Size b = Size::One;
};

/// Rank 0 (scalar), 1 (rows entries) or 2 (rows x cols).
struct Shape {
  int rank = 0;
  Extent rows{}, cols{};
};
inline constexpr Shape kScalar{};
constexpr Shape vector_of(Extent n) { return {1, n, {}}; }
constexpr Shape matrix(Extent rows, Extent cols) { return {2, rows, cols}; }

/// How an item is stored. Taylor groups hold M0 with the item's shape and, for order 1, M1 (nq slices).
enum class Kind { Group, Float64, Int64, Int32, String, StringAttribute, TaylorOrder0, TaylorOrder1 };
enum class Presence { Required, Optional };

struct Item {
  std::string_view path;  ///< "<name>" stands for a list member's name, "<d>" for a parametric direction
  std::string_view attribute;  ///< for Kind::StringAttribute: the attribute's name on `path`
  Kind kind;
  Shape shape;
  std::string_view units;  ///< the dataset's `units` attribute ("1": dimensionless); empty: none
  Presence presence;
  std::string_view meaning;

  /// The concrete path, with `name` and `direction` put in for "<name>" and "<d>".
  std::string at(std::string_view name = {}, std::string_view direction = {}) const;
  std::string units_text() const { return std::string(units); }
};

/// The values of the sizes for one object being checked; Size::One is 1.
class Sizes {
public:
  Sizes(Eigen::Index nq, Eigen::Index dim);
  Sizes& set(Size size, Eigen::Index value);
  Eigen::Index operator()(const Extent& e) const;

private:
  std::array<Eigen::Index, std::size_t(Size::Count)> values_{};
};

// ---------------------------------------------------------------- the table
// Required/Optional says whether a reader needs the item; items of an optional group are
// marked optional and come with their group.

inline constexpr Extent kNq{1, Size::Nq};

namespace header {
inline constexpr Item group{"/isosid", {}, Kind::Group, kScalar, "", Presence::Required, "identifies an isosid SID file"};
inline constexpr Item version{"/isosid/version", {}, Kind::Int64, kScalar, "", Presence::Required,
                              "schema version; readers refuse any other"};
inline constexpr Item program_version{"/isosid/program_version", {}, Kind::String, kScalar, "", Presence::Required,
                                      "version of the program that wrote the file"};
}  // namespace header

namespace body {
inline constexpr Item group{"/body", {}, Kind::Group, kScalar, "", Presence::Required, "the body and its material"};
inline constexpr Item name{"/body/name", {}, Kind::String, kScalar, "", Presence::Required, "body name, not empty"};
inline constexpr Item analysis_type{"/body/analysis_type", {}, Kind::String, kScalar, "", Presence::Required,
                                    "`plane_strain`, `plane_stress`, `axisymmetric` or `solid`"};
inline constexpr Item youngs_modulus{"/body/youngs_modulus", {}, Kind::Float64, kScalar, "Pa", Presence::Required,
                                     "Young's modulus, > 0"};
inline constexpr Item poisson_ratio{"/body/poisson_ratio", {}, Kind::Float64, kScalar, "1", Presence::Required,
                                    "Poisson's ratio, in (-1, 0.5)"};
inline constexpr Item density{"/body/density", {}, Kind::Float64, kScalar, "kg/m^3", Presence::Required, "density, > 0"};
inline constexpr Item thickness{"/body/thickness", {}, Kind::Float64, kScalar, "m", Presence::Required,
                                "thickness of plane strain / plane stress bodies, > 0"};
}  // namespace body

namespace refmod {
inline constexpr Item group{"/refmod", {}, Kind::Group, kScalar, "", Presence::Required,
                            "reference model: mass and the elastic coordinates q"};
inline constexpr Item q_units{"/refmod", "q_units", Kind::StringAttribute, kScalar, "", Presence::Required,
                              "the unit [q] of an elastic coordinate"};
inline constexpr Item mass{"/refmod/mass", {}, Kind::Float64, kScalar, "kg", Presence::Required, "mass, > 0"};
inline constexpr Item nq{"/refmod/nq", {}, Kind::Int64, kScalar, "", Presence::Required, "number of elastic coordinates"};
inline constexpr Item mode_names{"/refmod/mode_names", {}, Kind::String, vector_of(kNq), "", Presence::Required,
                                 "one name per elastic coordinate"};
inline constexpr Item frequencies_hz{"/refmod/frequencies_hz", {}, Kind::Float64, vector_of(kNq), "Hz", Presence::Required,
                                     "natural frequencies of the reduced body, >= 0 (0 for a massless boundary coordinate)"};
inline constexpr Item n_low{"/refmod/n_low", {}, Kind::Int64, kScalar, "", Presence::Required,
                            "leading normal (low-frequency) modes, in [0, nq]"};
inline constexpr Item n_high{"/refmod/n_high", {}, Kind::Int64, kScalar, "", Presence::Required,
                             "the rest, nq - n_low (constraint / attachment modes; massless-boundary methods: the boundary DOFs)"};
inline constexpr Item reduction_method{"/refmod/reduction_method", {}, Kind::String, kScalar, "", Presence::Required,
                                       "`modal`, `craig-bampton`, `full`, `macneal` or `craig-bampton-massless`"};
inline constexpr Item interface{"/refmod/interface", {}, Kind::String, kScalar, "", Presence::Required,
                                "the interface of the constraint modes or the massless boundary, e.g. contact surface and interval"};
inline constexpr Item section_translation{
    "/refmod/section_translation", {}, Kind::Float64, matrix(kNq, {3}), "1", Presence::Optional,
    "per coordinate and body-frame axis: the share of its kinetic energy carried by the mean translation of the body's "
    "cross-sections (slabs across `long_axis`); a beam's bending modes in direction d have most of theirs along d "
    "(0 for massless coordinates)"};
inline constexpr Item long_axis{"/refmod/long_axis", {}, Kind::Float64, vector_of({3}), "1", Presence::Optional,
                                "unit vector, body frame: the principal axis of the body's mass with the largest second moment"};
}  // namespace refmod

namespace damping {
inline constexpr Item group{"/damping", {}, Kind::Group, kScalar, "", Presence::Required,
                            "Rayleigh damping De = α1 Me + α2 Ke from (κ, f1, f2) ([R1] eq. 26–28); all >= 0"};
inline constexpr Item kappa{"/damping/kappa", {}, Kind::Float64, kScalar, "1", Presence::Required, "damping ratio κ"};
inline constexpr Item f1_hz{"/damping/f1_hz", {}, Kind::Float64, kScalar, "Hz", Presence::Required, "lower band frequency"};
inline constexpr Item f2_hz{"/damping/f2_hz", {}, Kind::Float64, kScalar, "Hz", Presence::Required, "upper band frequency"};
inline constexpr Item alpha1{"/damping/alpha1", {}, Kind::Float64, kScalar, "1/s", Presence::Required,
                             "mass-proportional coefficient"};
inline constexpr Item alpha2{"/damping/alpha2", {}, Kind::Float64, kScalar, "s", Presence::Required,
                             "stiffness-proportional coefficient"};
}  // namespace damping

/// A classic SID body term and the Sid member that holds it.
struct Term {
  Item item;
  Taylor Sid::*member;
};
inline constexpr Item terms_group{"/terms", {}, Kind::Group, kScalar, "", Presence::Required,
                                  "the classic SID body terms (Wallrapp), one Taylor group each"};
/// The eleven classic SID body terms in the order of the SID standard.
const std::vector<Term>& terms();

namespace node {
inline constexpr Item list{"/nodes", {}, Kind::Group, kScalar, "", Presence::Required,
                           "nodes where joints, loads or monitors attach, in the order written"};
inline constexpr Item group{"/nodes/<name>", {}, Kind::Group, kScalar, "", Presence::Optional, "one node"};
inline constexpr Item origin{"/nodes/<name>/origin", {}, Kind::TaylorOrder1, matrix({3}, {1}), "m", Presence::Required,
                             "position; M1[j] = φ(:, j)"};
inline constexpr Item phi{"/nodes/<name>/phi", {}, Kind::Float64, matrix({3}, kNq), "m/[q]", Presence::Required,
                          "translational mode shapes"};
inline constexpr Item psi{"/nodes/<name>/psi", {}, Kind::Float64, matrix({3}, kNq), "rad/[q]", Presence::Required,
                          "rotational mode shapes (small rotations of the node frame)"};
inline constexpr Item AP{"/nodes/<name>/AP", {}, Kind::TaylorOrder1, matrix({3}, {3}), "1", Presence::Required,
                         "node-frame orientation"};
}  // namespace node

namespace master {
inline constexpr Item list{"/master", {}, Kind::Group, kScalar, "", Presence::Required,
                           "boundary NURBS (curves in 2D, surfaces in 3D) for closest-point projection"};
inline constexpr Item group{"/master/<name>", {}, Kind::Group, kScalar, "", Presence::Optional, "one master patch"};
inline constexpr Item degrees{"/master/<name>/degrees", {}, Kind::Int32, vector_of({1, Size::ParamDim}), "",
                              Presence::Required, "degree per parametric direction, 1 to 3 directions"};
inline constexpr Item knots{"/master/<name>/knots_<d>", {}, Kind::Float64, vector_of({1, Size::Knots}), "1",
                            Presence::Required, "open, non-decreasing knot vector of direction d"};
inline constexpr Item weights{"/master/<name>/weights", {}, Kind::Float64, vector_of({1, Size::ControlPoints}), "1",
                              Presence::Required, "NURBS weights, > 0 (first direction fastest)"};
inline constexpr Item control_points{"/master/<name>/control_points", {}, Kind::Float64,
                                     matrix({1, Size::ControlPoints}, {1, Size::Dim}), "m", Presence::Required,
                                     "reference control points (first direction fastest)"};
inline constexpr Item Phi{"/master/<name>/Phi", {}, Kind::Float64, matrix({1, Size::ControlPoints, Size::Dim}, kNq),
                          "m/[q]", Presence::Required, "control-point displacements per q, row c·dim + a"};
}  // namespace master

namespace contact {
inline constexpr Item list{"/contact", {}, Kind::Group, kScalar, "", Presence::Required,
                           "Gauss points of contact boundaries, where the runtime evaluates penalty contact"};
inline constexpr Item group{"/contact/<name>", {}, Kind::Group, kScalar, "", Presence::Optional, "one contact surface"};
inline constexpr Item side{"/contact/<name>", "side", Kind::StringAttribute, kScalar, "", Presence::Required,
                           "the patch side its points lie on: xi0, xi1, eta0, eta1, zeta0 or zeta1 (direction and end)"};
inline constexpr Item patch{"/contact/<name>", "patch", Kind::StringAttribute, kScalar, "", Presence::Optional,
                            "the patch (in /patches) of a body of several patches it lies on; several, space-separated, "
                            "for a surface over several patch sides (its points and master patch joined end to end)"};
inline constexpr Item master_patch{"/contact/<name>", "master_patch", Kind::StringAttribute, kScalar, "",
                                   Presence::Required, "the master patch of the same boundary (in /master), or empty"};
inline constexpr Item parameter{"/contact/<name>/parameter", {}, Kind::Float64,
                                matrix({1, Size::Points}, {1, Size::ParamDim}), "1", Presence::Required,
                                "patch parameters of each Gauss point"};
inline constexpr Item element{"/contact/<name>/element", {}, Kind::Int32, vector_of({1, Size::Points}), "",
                              Presence::Required, "element index of each point, >= 0"};
inline constexpr Item position{"/contact/<name>/position", {}, Kind::Float64, matrix({1, Size::Points}, {1, Size::Dim}),
                               "m", Presence::Required, "reference position in the body frame"};
inline constexpr Item normal{"/contact/<name>/normal", {}, Kind::Float64, matrix({1, Size::Points}, {1, Size::Dim}),
                             "1", Presence::Required, "outward unit normal"};
inline constexpr Item weight{"/contact/<name>/weight", {}, Kind::Float64, vector_of({1, Size::Points}), "m^2",
                             Presence::Required, "quadrature weight incl. 2πr or thickness, > 0"};
inline constexpr Item Psi{"/contact/<name>/Psi", {}, Kind::Float64, matrix({1, Size::Points, Size::Dim}, kNq), "m/[q]",
                          Presence::Required, "reduced shape rows Ψ = N Φ, row g·dim + a"};
inline constexpr Item in_interface{"/contact/<name>/in_interface", {}, Kind::Int32, vector_of({1, Size::Points}), "",
                                   Presence::Optional,
                                   "Craig-Bampton: 1 where the point moves with interface control points only (the reduction "
                                   "holds its static flexibility), 0 where only normal modes move it"};
}  // namespace contact

namespace stress {
inline constexpr Item list{"/stress", {}, Kind::Group, kScalar, "", Presence::Required,
                           "stress recovery point sets, σ = S q"};
inline constexpr Item group{"/stress/<name>", {}, Kind::Group, kScalar, "", Presence::Optional, "one point set"};
inline constexpr Item patch{"/stress/<name>", "patch", Kind::StringAttribute, kScalar, "", Presence::Optional,
                            "the patch (in /patches) of a body of several patches the points lie in"};
inline constexpr Item components{"/stress/<name>/components", {}, Kind::String, vector_of({1, Size::Components}), "",
                                 Presence::Required, "e.g. xx yy zz xy (2D) or xx yy zz xy yz xz (3D)"};
inline constexpr Item position{"/stress/<name>/position", {}, Kind::Float64, matrix({1, Size::Points}, {1, Size::Dim}),
                               "m", Presence::Required, "point positions"};
inline constexpr Item S{"/stress/<name>/S", {}, Kind::Float64, matrix({1, Size::Points, Size::Components}, kNq), "Pa/[q]",
                        Presence::Required, "stress rows, row p·ncomp + c"};
}  // namespace stress

namespace patches {
inline constexpr Item list{"/patches", {}, Kind::Group, kScalar, "", Presence::Optional,
                           "the patches of a body of several (absent for one patch; /body then holds the material of "
                           "the first contact surface's patch, else the one of highest wave speed)"};
inline constexpr Item group{"/patches/<name>", {}, Kind::Group, kScalar, "", Presence::Optional, "one patch"};
inline constexpr Item youngs_modulus{"/patches/<name>/youngs_modulus", {}, Kind::Float64, kScalar, "Pa", Presence::Optional,
                                     "its Young's modulus, > 0"};
inline constexpr Item poisson_ratio{"/patches/<name>/poisson_ratio", {}, Kind::Float64, kScalar, "1", Presence::Optional,
                                    "its Poisson's ratio, in (-1, 0.5)"};
inline constexpr Item density{"/patches/<name>/density", {}, Kind::Float64, kScalar, "kg/m^3", Presence::Optional,
                              "its density, > 0"};
inline constexpr Item interfaces{"/patches/<name>/interfaces", {}, Kind::String, vector_of({1, Size::Interfaces}), "",
                                 Presence::Optional, "where it meets another patch: `side other.side`, e.g. `xi1 beam.xi0`"};
}  // namespace patches

namespace transfer {
inline constexpr Item group{"/transfer", {}, Kind::Group, kScalar, "", Presence::Optional,
                            "maps q between a coarse model and this refined model: q_fine = T q_coarse and back"};
inline constexpr Item coarse_model_sha256{"/transfer/coarse_model_sha256", {}, Kind::String, kScalar, "",
                                          Presence::Optional,
                                          "`model_sha256` of the coarse SID (the same model file without its "
                                          "hierarchical refinement, `isosid-prep --coarse`)"};
inline constexpr Item coarse_to_fine{"/transfer/coarse_to_fine", {}, Kind::Float64, matrix(kNq, {1, Size::CoarseNq}), "1",
                                     Presence::Optional, "T"};
inline constexpr Item fine_to_coarse{"/transfer/fine_to_coarse", {}, Kind::Float64, matrix({1, Size::CoarseNq}, kNq), "1",
                                     Presence::Optional, "the way back"};
}  // namespace transfer

namespace discretization {
inline constexpr Item group{"/discretization", {}, Kind::Group, kScalar, "", Presence::Optional,
                            "the isogeometric mesh the body was reduced from (informational)"};
inline constexpr Item elements_per_level{"/discretization/elements_per_level", {}, Kind::Int32, vector_of({1, Size::Levels}),
                                         "", Presence::Optional, "one entry per hierarchical level (one for a tensor mesh)"};
inline constexpr Item functions_per_level{"/discretization/functions_per_level", {}, Kind::Int32, vector_of({1, Size::Levels}),
                                          "", Presence::Optional, "basis functions per level"};
inline constexpr Item free_dofs{"/discretization/free_dofs", {}, Kind::Int64, kScalar, "", Presence::Optional,
                                "free degrees of freedom"};
inline constexpr Item contact_radius{"/discretization/contact_radius_m", {}, Kind::Float64, kScalar, "m", Presence::Optional,
                                     "the expected contact radius the contact elements were sized for ([contact_resolution]); absent: sized by hand"};
}  // namespace discretization

namespace visual {
inline constexpr Item group{"/visual", {}, Kind::Group, kScalar, "", Presence::Optional,
                            "a tessellation of the whole body for viewing (ParaView output of isosid-run and isosid-info): "
                            "the corners of every element's parametric grid; present when the model file has [visual]"};
inline constexpr Item corners_per_cell{"/visual/corners_per_cell", {}, Kind::Int64, kScalar, "", Presence::Optional,
                                       "4: quadrilaterals, 8: hexahedra (3D only), corners in VTK's order"};
inline constexpr Item position{"/visual/position", {}, Kind::Float64, matrix({1, Size::Points}, {1, Size::Dim}), "m",
                               Presence::Optional, "reference positions of the points in the body frame"};
inline constexpr Item cells{"/visual/cells", {}, Kind::Int32, vector_of({1, Size::Cells, Size::Corners}), "",
                            Presence::Optional, "the points of each cell (0-based), cell after cell"};
inline constexpr Item Phi{"/visual/Phi", {}, Kind::Float64, matrix({1, Size::Points, Size::Dim}, kNq), "m/[q]",
                          Presence::Optional, "displacement rows, row p·dim + a"};
inline constexpr Item stress_components{"/visual/stress_components", {}, Kind::String, vector_of({1, Size::Components}), "",
                                        Presence::Optional, "as /stress/<name>/components; absent: no stress rows"};
inline constexpr Item S{"/visual/S", {}, Kind::Float64, matrix({1, Size::Points, Size::Components}, kNq), "Pa/[q]",
                        Presence::Optional, "stress rows, row p·ncomp + c"};
}  // namespace visual

namespace provenance {
inline constexpr Item group{"/provenance", {}, Kind::Group, kScalar, "", Presence::Required, "how the file was made"};
inline constexpr Item model_file{"/provenance/model_file", {}, Kind::String, kScalar, "", Presence::Required,
                                 "the model file"};
inline constexpr Item model_sha256{"/provenance/model_sha256", {}, Kind::String, kScalar, "", Presence::Required,
                                   "SHA-256 of the model file"};
inline constexpr Item program_version{"/provenance/program_version", {}, Kind::String, kScalar, "", Presence::Required,
                                      "version of isosid-prep"};
inline constexpr Item created_utc{"/provenance/created_utc", {}, Kind::String, kScalar, "", Presence::Required,
                                  "creation time (UTC)"};
inline constexpr Item command_line{"/provenance/command_line", {}, Kind::String, kScalar, "", Presence::Optional,
                                   "the isosid-prep command that made the file; absent in files made before it was recorded"};
inline constexpr Item timing_names{"/provenance/timing_names", {}, Kind::String, vector_of({1, Size::Timings}), "",
                                   Presence::Required, "preprocessor stages"};
inline constexpr Item timings_s{"/provenance/timings_s", {}, Kind::Float64, vector_of({1, Size::Timings}), "s",
                                Presence::Required, "time per stage"};
}  // namespace provenance

/// Every item in file order, the terms included.
const std::vector<const Item*>& items();

/// The table as markdown (path, type, shape, units, presence, meaning), as in format/README.md.
std::string markdown_table();

}  // namespace isosid::format::layout
