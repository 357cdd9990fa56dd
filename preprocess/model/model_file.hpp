// Model files (*.model.toml): body, analysis type, material, geometry, refinement, boundary
// conditions. Parsed strictly; see models/README.md for the keys.
#pragma once
#include "geometry/nurbs_patch.hpp"
#include "isosid/format/sid.hpp"
#include "model/placement.hpp"
#include "refine/graded_knots.hpp"
#include "thb/hierarchical_mesh.hpp"

#include <array>
#include <optional>
#include <string>
#include <vector>

namespace isosid::prep {

struct FixedComponents {
  std::string side;                 ///< canonical or primitive side name of the patch
  std::vector<int> components;      ///< 0 = x, 1 = y, 2 = z
  int patch = 0;                    ///< index in ModelSpec::patches
};

/// Most [[node]] tables a model may have, and most stress points over all its stress lines:
/// each adds dense rows per mode to the SID and the runtime's output.
constexpr std::size_t kMaxNodes = 10000;
constexpr long long kMaxStressPoints = 100000;
/// Most control points a refined patch may have (3D: 6 million DOFs, beyond any eigen solve
/// this machine class takes in memory).
constexpr double kMaxControlPoints = 2e6;
/// Highest polynomial degree of a patch direction.
constexpr int kMaxDegree = 8;
/// Most [[patch]] tables of a body (interfaces are found by comparing every pair of sides).
constexpr std::size_t kMaxPatches = 200;

struct RefinementSpec {
  std::vector<int> degrees;         ///< target degree per direction (elevation first)
  std::vector<int> subdivisions;    ///< uniform split of every span per direction
  std::vector<GradingRequest> graded;
  std::optional<HierarchicalRequest> hierarchical;  ///< THB refinement on top of the above
};

/// How the body is reduced (the [reduction] table).
struct ReductionSpec {
  format::ReductionMethod method = format::ReductionMethod::Modal;
  int normal_modes = 10;
  std::string interface_surface;         ///< contact surface whose side holds the interface nodes
  std::string boundary_surface;          ///< massless-boundary methods: the contact surface whose control points are the boundary
  int interface_points = 0;              ///< that many side nodes nearest to the point at interface_center
  double interface_radius = 0;           ///< m, > 0: also every side node within this distance of it (isosid-prep --refine-at)
  Eigen::VectorXd interface_center;      ///< tangential parameter(s) on that side
  std::optional<Eigen::VectorXd> interface_point;  ///< or the centre in metres (meshed bodies)
};

struct DampingSpec {
  double kappa = 1e-3;                   ///< the value of [R1] (docs/references.md)
  double f1_hz = -1, f2_hz = -1;         ///< band; negative: the normal modes' lowest and highest
};

struct ContactSurfaceSpec {
  std::string name;
  std::string side;                             ///< side of the patch
  std::vector<std::array<double, 2>> interval;  ///< per tangential direction; empty: the whole side
  int points_per_direction = 0;                 ///< Gauss points per element and direction (0: p+1)
  int patch = 0;                                ///< index in ModelSpec::patches
  /// further (patch, side) the surface continues over, in order along one tangential direction
  /// (`side = ["a.zeta1", "b.zeta1", ...]`); its points and master patch are joined
  std::vector<std::pair<int, std::string>> continued;
};

struct NodeSpec {
  std::string name;
  GivenPoint at;                         ///< `parameter` or `point` (placed on the body by prep::place)
  int patch = 0;                         ///< the patch it lies in (index in ModelSpec::patches)
};

struct StressLineSpec {
  std::string name;
  GivenPoint from, to;                   ///< the line's ends, both parameters or both physical points
  int points = 10;
  int patch = 0;                         ///< the patch it runs in (index in ModelSpec::patches)
};

/// [visual]: a viewing mesh in the SID (ParaView output): each element cut into
/// `subdivisions` cells per direction, with stress rows unless `stress = false`.
struct VisualSpec {
  int subdivisions = 1;
  bool stress = true;
};

/// [contact_resolution]: contact elements sized from the expected contact radius a (Hertz),
/// for refinements that say smallest = "contact". isosid-run passes its estimate for the
/// scene (isosid-prep --contact-radius), so a changed body or speed gets elements of a/8.
struct ContactResolutionSpec {
  double contact_radius = 0;           ///< m
  double elements_per_radius = 8;      ///< smallest contact element = contact_radius / this
  /// the refinement.graded entries sized by it: (patch, entry)
  std::vector<std::pair<std::size_t, std::size_t>> graded;
  bool hierarchical = false;           ///< refinement.hierarchical (of the one patch that has it) sized by it
  double element_size() const { return contact_radius / elements_per_radius; }
};

/// [mesh]: an isoparametric comparison body meshed by gmsh (OpenCASCADE geometry of a
/// primitive, quadratic quadrilaterals graded toward the contact point). Its elements become
/// the body's patches, each its 9-node Lagrange element written in Bezier form (the same
/// space), so the one element loop assembles it and the one pipeline reduces it.
struct MeshSpec {
  std::string primitive;              ///< half_disk | rod_with_spherical_end (2D sections)
  double radius = 0, length = 0;      ///< m
  double element_size = 0;            ///< m, far from the contact point
  double contact_element_size = 0;    ///< m, at the contact point
  double growth = 1.3;                ///< size ratio of neighbouring elements away from it
  Eigen::Vector2d contact_point = Eigen::Vector2d::Zero();  ///< m: the primitive's pole
};

/// One patch of a body: its exact geometry, material and refinement.
struct PatchSpec {
  std::string name;                 ///< empty for a body of one patch ([geometry] form)
  format::Material material;
  NurbsPatch patch;                 ///< the coarse, exact geometry
  RefinementSpec refinement;
};

struct ModelSpec {
  std::string file;                 ///< path of the model file
  std::string body_name;
  format::AnalysisType analysis = format::AnalysisType::Solid;
  double thickness = 1.0;
  std::vector<PatchSpec> patches;   ///< one ([geometry]) or several ([[patch]]), conforming where they meet
  std::optional<ContactResolutionSpec> contact_resolution;
  std::vector<FixedComponents> fixed;
  int extra_quadrature_points = 0;
  ReductionSpec reduction;
  DampingSpec damping;
  std::vector<ContactSurfaceSpec> contact_surfaces;
  std::vector<NodeSpec> nodes;
  std::vector<StressLineSpec> stress_lines;
  std::optional<VisualSpec> visual;
  std::optional<MeshSpec> mesh;     ///< a meshed (isoparametric) body: patches are its elements
};

/// The material of the highest wave speed sqrt(E / rho): it sets the body's eigenvalue scale.
const format::Material& fastest_material(const ModelSpec& spec);

/// Reads and validates a model file; throws InputError(file, field, problem).
ModelSpec read_model_file(const std::string& path);

/// Sets the expected contact radius (m) of a model with [contact_resolution], and the sizes of
/// the refinements derived from it. Throws InputError(model file, `source`) if it has none.
void set_contact_radius(ModelSpec& model, double radius, const std::string& source);

/// Centres the model's hierarchical refinement on a point of a contact surface ([R2]
/// Sect. 4.3: the runtime asks for a fine model where an impact happens): the refined region
/// becomes `width` (m) wide around the surface's tangential parameter(s) `at`, and a
/// Craig-Bampton interface moves to that surface, centred there too. Throws InputError(model file,
/// `source`) for a model without [refinement.hierarchical] on the surface's patch, an unknown
/// or multi-patch surface, or a parameter outside the side.
void set_refinement_point(ModelSpec& model, const std::string& surface, const std::vector<double>& at, double width,
                          const std::string& source);

}  // namespace isosid::prep
