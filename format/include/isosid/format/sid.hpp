// The SID data model: everything isosid-prep hands to isosid-run for one reduced
// flexible body (classic FFRF standard input data plus contact, stress and transfer data).
// Conventions: SI units; body-frame vectors of the classic SID terms and of nodes are 3D
// (2D bodies lie in the x-y plane, axisymmetric bodies have x radial and y on the axis);
// contact, master-patch and stress-point data use the analysis dimension `dim` (2 or 3).
#pragma once
#include "isosid/format/analysis_type.hpp"
#include "isosid/format/reduction_method.hpp"
#include "isosid/format/taylor.hpp"

#include <Eigen/Dense>
#include <optional>
#include <string>
#include <utility>
#include <vector>

namespace isosid::format {

struct Material {
  double youngs_modulus = 0;  ///< Pa
  double poisson_ratio = 0;   ///< -
  double density = 0;         ///< kg/m^3
};

/// Reference model data (SID "refmod") and how the elastic coordinates were made.
struct RefMod {
  double mass = 0;                       ///< kg
  std::vector<std::string> mode_names;   ///< nq names
  Eigen::VectorXd frequencies_hz;        ///< nq natural frequencies of the reduced body
  int n_low = 0;                         ///< leading normal (low-frequency) modes; the rest are high
  std::string reduction_method;          ///< a name of reduction_method.hpp's table (or another SID writer's)
  std::string interface_description;     ///< e.g. the contact surface and interval of the constraint modes
  /// nq x 3 (empty: not recorded): share of each coordinate's kinetic energy carried by the
  /// mean translation of cross-sections across `long_axis`, per body-frame axis
  Eigen::MatrixXd section_translation;
  Eigen::Vector3d long_axis = Eigen::Vector3d::Zero();
  Eigen::Index nq() const { return frequencies_hz.size(); }
  int n_high() const { return static_cast<int>(nq()) - n_low; }
  /// Massless-boundary SIDs (MacNeal and the massless Craig-Bampton variant): the high
  /// coordinates are the displacements of the boundary's DOFs (no mass: their rows of Me are
  /// zero, their frequency is listed as 0).
  bool massless_boundary() const {
    const std::optional<ReductionMethod> method = reduction_method_named(reduction_method);
    return method && traits(*method).massless_boundary;
  }
  int n_massless() const { return massless_boundary() ? n_high() : 0; }
};

/// Rayleigh damping De = alpha1 Me + alpha2 Ke from (kappa, f1, f2) ([R1] eq. 26-28,
/// docs/references.md).
struct Damping {
  double kappa = 0, f1_hz = 0, f2_hz = 0;
  double alpha1 = 0;  ///< 1/s, mass-proportional
  double alpha2 = 0;  ///< s, stiffness-proportional
};

/// A node where joints, loads or monitors attach (SID "frame/node").
struct Node {
  std::string name;
  Taylor origin;  ///< 3x1, order 1: M0 = reference position c_k, M1[j] = phi(:, j)
  Eigen::MatrixXd phi;  ///< 3 x nq translational mode shapes
  Eigen::MatrixXd psi;  ///< 3 x nq rotational mode shapes (small rotations of the node frame)
  Taylor AP;     ///< 3x3, order 1: node frame orientation
};

/// Gauss points of a contact boundary: where the runtime evaluates penalty contact.
struct ContactSurface {
  std::string name;
  std::string patch;           ///< the body's patch it lies on (empty: a body of one patch; several: space-separated)
  std::string side;            ///< the patch side it lies on, e.g. "zeta0"
  std::string master_patch;    ///< the MasterPatch describing the same boundary
  Eigen::MatrixXd parameter;   ///< npts x param_dim, patch parameters of each point
  Eigen::VectorXi element;     ///< npts, element index (in the body's element list)
  Eigen::MatrixXd position;    ///< npts x dim, reference position in the body frame, m
  Eigen::MatrixXd normal;      ///< npts x dim, outward unit normal
  Eigen::VectorXd weight;      ///< npts, quadrature weight: area (2*pi*r*length, thickness*length), m^2
  Eigen::MatrixXd Psi;         ///< (npts*dim) x nq, row g*dim+a: displacement a of point g per q
  /// Craig-Bampton SIDs: 1 where the point moves with interface control points only, so that
  /// the reduction holds its static flexibility; 0 where the normal modes alone move it (a
  /// load there meets a stiff surface). Empty for other reductions.
  Eigen::VectorXi in_interface;
  Eigen::Index points() const { return weight.size(); }
};

/// A boundary NURBS (curve in 2D, surface in 3D) for closest-point projection on a deformed body.
struct MasterPatch {
  std::string name;
  std::vector<int> degrees;              ///< one per parametric direction
  std::vector<Eigen::VectorXd> knots;    ///< one open knot vector per direction
  Eigen::VectorXd weights;               ///< ncp NURBS weights (first direction fastest)
  Eigen::MatrixXd control_points;        ///< ncp x dim reference control points, m
  Eigen::MatrixXd Phi;                   ///< (ncp*dim) x nq displacement rows of the control points
};

/// Points where stresses are recovered as sigma = S q (linear elasticity).
struct StressRecovery {
  std::string name;
  std::string patch;                     ///< the body's patch it lies in (empty: a body of one patch)
  std::vector<std::string> components;   ///< e.g. xx yy zz xy (2D) or xx yy zz xy yz xz (3D)
  Eigen::MatrixXd position;              ///< npts x dim, m
  Eigen::MatrixXd S;                     ///< (npts*ncomp) x nq, Pa per unit q
};

/// One patch of a body of several: its material and where it meets the others.
struct PatchInfo {
  std::string name;
  Material material;
  std::vector<std::string> interfaces;   ///< "side other.side", e.g. "xi1 beam_free.xi0"
};

/// Maps elastic coordinates between a coarse model and this (refined) model of one body.
struct TransferOperator {
  std::string coarse_model_sha256;
  Eigen::MatrixXd coarse_to_fine;        ///< nq x nq_coarse
  Eigen::MatrixXd fine_to_coarse;        ///< nq_coarse x nq
};

/// A tessellation of the whole body for viewing (isosid-run's ParaView output): the corners
/// of every element's parametric grid, cells between them, and the rows that displace and
/// stress them, so a viewer draws the deformed body and its stress field from q alone.
struct VisualMesh {
  int corners_per_cell = 4;            ///< 4: quadrilaterals, 8: hexahedra (VTK corner order)
  Eigen::MatrixXd position;            ///< npts x dim, reference positions in the body frame, m
  Eigen::VectorXi cells;               ///< ncells * corners_per_cell point indices (0-based)
  Eigen::MatrixXd Phi;                 ///< (npts*dim) x nq displacement rows, row p*dim + a
  std::vector<std::string> stress_components;  ///< as StressRecovery's; empty: no stress rows
  Eigen::MatrixXd S;                   ///< (npts*ncomp) x nq stress rows, Pa per unit q (empty: none)
  Eigen::Index points() const { return position.rows(); }
  Eigen::Index cell_count() const { return corners_per_cell > 0 ? cells.size() / corners_per_cell : 0; }
};

/// The isogeometric mesh the body was reduced from (informational; isosid-info reports it).
struct Discretization {
  Eigen::VectorXi elements_per_level;    ///< one entry per hierarchical level (one for a tensor mesh)
  Eigen::VectorXi functions_per_level;
  int free_dofs = 0;
  double contact_radius = 0;   ///< m: the expected contact radius its contact elements were sized for (0: sized by hand)
};

struct Provenance {
  std::string model_file, model_sha256, program_version, created_utc;
  std::string command_line;  ///< the isosid-prep command that wrote the file (empty in older files)
  std::vector<std::pair<std::string, double>> timings_s;
};

struct Sid {
  std::string body_name;
  AnalysisType analysis = AnalysisType::Solid;
  Material material;
  double thickness = 1.0;  ///< m, for plane strain / plane stress bodies
  RefMod refmod;
  Damping damping;

  // Classic SID body terms (Wallrapp; docs/references.md [R8]).
  Taylor mdCM;    ///< 3x1, o1: first moment of mass, kg m
  Taylor J;       ///< 3x3, o1: inertia tensor about the frame origin, kg m^2
  Taylor Ct;      ///< nq x 3, o1
  Taylor Cr;      ///< nq x 3, o1
  Taylor Me;      ///< nq x nq, o0
  Taylor Gr;      ///< 3 x 3nq, o0
  Taylor Ge;      ///< nq x 3nq, o0
  Taylor Oe;      ///< nq x 6, o1, columns pair with [wx^2, wy^2, wz^2, wx wy, wy wz, wz wx]
  Taylor ksigma;  ///< nq x 1, o0
  Taylor Ke;      ///< nq x nq, o0
  Taylor De;      ///< nq x nq, o0

  std::vector<Node> nodes;
  std::vector<ContactSurface> contact_surfaces;
  std::vector<MasterPatch> master_patches;
  std::vector<StressRecovery> stress_recovery;
  std::vector<PatchInfo> patches;  ///< bodies of several patches only; `material` is then one of theirs
  std::optional<TransferOperator> transfer;
  std::optional<Discretization> discretization;
  std::optional<VisualMesh> visual;
  Provenance provenance;

  Eigen::Index nq() const { return refmod.nq(); }
  int dim() const { return spatial_dim(analysis); }
};

/// The material of the body's patch `patch` (a contact surface's or stress line's), or the
/// body's material for a body of one patch.
inline const Material& material_of(const Sid& sid, const std::string& patch) {
  const std::string first = patch.substr(0, patch.find(' '));  // a surface over several patches: its first
  for (const PatchInfo& p : sid.patches)
    if (p.name == first) return p.material;
  return sid.material;
}

/// The master patch called `name`, or nullptr (how a contact surface finds its boundary NURBS).
inline const MasterPatch* find_master_patch(const Sid& sid, const std::string& name) {
  for (const MasterPatch& m : sid.master_patches)
    if (m.name == name) return &m;
  return nullptr;
}

}  // namespace isosid::format
