// Meshed (isoparametric) bodies from gmsh against what they must be: the mesh's nodes become
// the body's nodes (elements joined, one rigid-body mode), the volume is the sphere's up to
// the quadratic edges' chord error, an affine field stores exactly the strain energy of its
// constant stress, and the lowest frequencies agree with the IGA sphere's (both converged
// there). Bad [mesh] input ends with exit 2 and one line.
#include "mesh/gmsh_mesh.hpp"
#include "model/model_file.hpp"
#include "pipeline/prepare.hpp"
#include "sid/node_data.hpp"
#include "preprocess/body_fixtures.hpp"
#include "support/bad_input_cases.hpp"
#include "support/run_program.hpp"
#include "support/one_line_exit.hpp"

#include <catch2/catch.hpp>
#include <cmath>
#include <algorithm>
#include <fstream>
#include <set>

using namespace isosid;
using Catch::Matchers::Contains;

namespace {
const std::string kModels = ISOSID_MODELS_DIR;
}

TEST_CASE("meshed sphere: gmsh's nodes are the body's nodes, one rigid mode, the sphere's mass and frequencies", "[mesh]") {
  const prep::ModelSpec spec = prep::read_model_file(kModels + "/sphere_axisym_gmsh.model.toml");
  REQUIRE(spec.mesh);
  const prep::QuadMesh mesh = prep::gmsh_quad_mesh(*spec.mesh, spec.file);
  std::set<int> used;
  for (const auto& q : mesh.quads) used.insert(q.begin(), q.end());
  const prep::ModalAnalysis meshed = prep::analyse_modes(spec, 8);
  // every Bezier control point merged with its neighbours': one node per gmsh node
  CHECK(meshed.body.dofs.node_count() == int(used.size()));
  CHECK(meshed.modes.rigid_body_modes == 1);  // the axial translation; separate elements would add theirs
  // the quadratic edges approximate the circle (1 mm on R = 10 mm): measured 2.7e-7 of the volume
  const double R = 0.01, rho = 2789;
  CHECK(meshed.mass == Approx(4.0 / 3.0 * M_PI * R * R * R * rho).epsilon(1e-6));

  // the IGA sphere of the same scene (graded to the same pole): their lowest modes have
  // wavelengths of the sphere's size, which 1 mm quadratic elements and the IGA's splines
  // both resolve (measured: 2e-6 to 1.1e-5 apart); 1e-4 leaves room for another gmsh mesh
  const prep::ModalAnalysis iga = prep::analyse_modes(prep::read_model_file(kModels + "/sphere_axisym.model.toml"), 8);
  const Eigen::VectorXd fm = meshed.modes.frequencies_hz(), fi = iga.modes.frequencies_hz();
  for (int k = 1; k < 8; ++k) {
    INFO("mode " << k << ": meshed " << fm(k) << " Hz, IGA " << fi(k) << " Hz");
    CHECK(std::abs(fm(k) - fi(k)) < 1e-4 * fi(k));
  }
}

TEST_CASE("a node of a meshed body lands on its point, inside an element as at a mesh vertex", "[mesh]") {
  const test::ScratchDir dir("mesh-node");
  std::ifstream in(kModels + "/sphere_axisym_gmsh.model.toml");
  std::string text((std::istreambuf_iterator<char>(in)), std::istreambuf_iterator<char>());
  text += "\n[[node]]\nname = \"inside\"\npoint = [0.0071, 0.0012]\n";
  std::ofstream(dir.path("m.model.toml")) << text;
  const prep::ModelSpec spec = prep::read_model_file(dir.path("m.model.toml"));
  const prep::BodyModel body = prep::build_body(spec);
  const Eigen::MatrixXd Phi = Eigen::MatrixXd::Zero(body.dofs.total_dofs(), 1);
  for (const auto& [name, x] : {std::pair{"centre", Eigen::Vector2d(0.0, 0.0)}, {"inside", Eigen::Vector2d(0.0071, 0.0012)}}) {
    const auto it = std::find_if(spec.nodes.begin(), spec.nodes.end(), [&](const prep::NodeSpec& n) { return n.name == name; });
    REQUIRE(it != spec.nodes.end());
    const format::Node node = prep::node_at(body, *it, Phi);
    INFO(name);
    CHECK((node.origin.M0.col(0).head(2) - x).norm() < 1e-12);  // placed exactly (1e-12 m: Newton's round-off)
  }
}

TEST_CASE("meshed sphere: an affine field stores the strain energy of its constant stress", "[mesh]") {
  const prep::ModelSpec spec = prep::read_model_file(kModels + "/sphere_axisym_gmsh.model.toml");
  const test::AssembledBody a = test::assembled(spec);
  // u_r = e r, u_z = f z: strains rr = tt = e, zz = f; admissible (u_r = 0 on the axis)
  const double e = 1e-4, f = -3e-4, E = 7.28e10, nu = 0.33;
  Eigen::VectorXd u = Eigen::VectorXd::Zero(a.sys.K.rows());
  for (int n = 0; n < a.body.dofs.node_count(); ++n)
    for (int c = 0; c < 2; ++c)
      if (const int i = a.body.dofs.free_index(n, c); i >= 0) u(i) = (c == 0 ? e : f) * a.body.dofs.node_points()(n, c);
  const double lambda = E * nu / ((1 + nu) * (1 - 2 * nu)), mu = E / (2 * (1 + nu));
  const double s_rr = lambda * (2 * e + f) + 2 * mu * e, s_zz = lambda * (2 * e + f) + 2 * mu * f;
  // the revolved volume of the mesh itself: its mass over the density
  const double mass_volume = prep::analyse_modes(spec, 2).mass / 2789.0;
  const double energy = 0.5 * u.dot(a.sys.K * u);
  // exact for the element space (affine fields lie in it): round-off of the assembled sums
  CHECK(energy == Approx(0.5 * (2 * s_rr * e + s_zz * f) * mass_volume).epsilon(1e-10));
}

TEST_CASE("bad meshed models: exit 2 with one line naming the field", "[mesh]") {
  const test::ScratchDir dir("bad-mesh");
  std::ifstream in(kModels + "/rod_axisym_gmsh.model.toml");
  const std::string base((std::istreambuf_iterator<char>(in)), std::istreambuf_iterator<char>());
  for (const auto& c : test::bad_input_cases("meshed_models.toml", {{"rod", base}}, "rod")) {
    std::ofstream(dir.path("m.model.toml")) << c.text;
    const auto r = test::run_program(std::string(ISOSID_PREP_EXE) + " -q " + dir.path("m.model.toml") + " -o " + dir.path("m.sid.h5"));
    INFO(c.label << ": " << c.expected << "\n" << r.err);
    test::check_one_line_exit(r, 2, c.expected);
  }
}
