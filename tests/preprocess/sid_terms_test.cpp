// SID terms: every formula against a lumped-mass computation from the body-integral
// definitions (an independent code path), invariants against closed forms, and the
// first-order inertia term against a finite difference of the deformed body's inertia.
#include "geometry/primitives.hpp"
#include "isosid/format/sid_io.hpp"
#include "reduce/body_reduction.hpp"
#include "sid/body_integrals.hpp"
#include "sid/sid_builder.hpp"
#include "sid/sid_terms.hpp"
#include "support/lumped_sid.hpp"
#include "support/run_program.hpp"
#include "preprocess/body_fixtures.hpp"

#include <catch2/catch.hpp>

using namespace isosid;
using format::AnalysisType;
using Eigen::MatrixXd;

namespace {

double rel(const MatrixXd& a, const MatrixXd& b) { return (a - b).norm() / std::max(b.norm(), 1e-300); }


struct Built {
  prep::BodyModel body;
  format::Sid sid;
  Eigen::MatrixXd Phi_nodal;
  Eigen::SparseMatrix<double> Ms;
};

Built build(prep::ModelSpec spec) {
  Built b{prep::build_body(spec), {}, {}, {}};
  const auto sys = prep::assemble_system(b.body.space, b.body.dofs, b.body.elasticity, spec.extra_quadrature_points);
  b.Ms = prep::assemble_scalar_mass(b.body.space, b.body.dofs, b.body.elasticity, spec.extra_quadrature_points);
  const auto basis = prep::reduce_body(b.body, sys);
  b.sid = prep::build_sid(b.body, sys, b.Ms, basis);
  b.Phi_nodal = prep::nodal_modes(b.body.dofs, basis.Phi);
  return b;
}

prep::ModelSpec modal_spec(prep::NurbsPatch patch, AnalysisType type, std::vector<int> degrees, std::vector<int> parts,
                           int modes, int extra = 0) {
  prep::RefinementSpec r;
  r.degrees = std::move(degrees);
  r.subdivisions = std::move(parts);
  auto s = test::spec_for(std::move(patch), type, 7.28e10, 0.33, 2789, r);
  s.reduction.method = format::ReductionMethod::Modal;
  s.reduction.normal_modes = modes;
  s.extra_quadrature_points = extra;
  return s;
}

}  // namespace

TEST_CASE("SID terms from a diagonal mass matrix equal the lumped-mass definitions", "[sid]") {
  // lumped_sid() computes every term point by point from the definitions; fill_inertia_terms()
  // computes them as quadratic forms of M_s. Both must agree to round-off (1e-12).
  const auto body = test::random_lumped_body(14, 5, 31);
  const format::Sid ref = test::lumped_sid(body);
  Eigen::SparseMatrix<double> Ms(14, 14);
  for (int i = 0; i < 14; ++i) Ms.insert(i, i) = body.masses(i);
  format::Sid s;
  s.analysis = AnalysisType::Solid;
  prep::fill_inertia_terms(s, Ms, body.points, body.Phi);
  CHECK(s.refmod.mass == Approx(ref.refmod.mass).epsilon(1e-14));
  for (const format::Taylor format::Sid::*term : {&format::Sid::mdCM, &format::Sid::J, &format::Sid::Ct, &format::Sid::Cr,
                                                  &format::Sid::Gr, &format::Sid::Ge, &format::Sid::Oe}) {
    const format::Taylor &a = s.*term, &b = ref.*term;
    CHECK(rel(a.M0, b.M0) < 1e-12);
    REQUIRE(a.M1.size() == b.M1.size());
    for (std::size_t k = 0; k < a.M1.size(); ++k) CHECK(rel(a.M1[k], b.M1[k]) < 1e-12);
  }
}

TEST_CASE("SID invariants of disk, ball and half-disk body of revolution against closed forms", "[sid]") {
  const double rho = 2789, r = 0.01;
  SECTION("disk, plane strain, thickness 1 m") {
    const auto b = build(modal_spec(prep::primitives::disk(r), AnalysisType::PlaneStrain, {4, 4}, {4, 4}, 6));
    const double m = rho * M_PI * r * r;
    CHECK(b.sid.refmod.mass == Approx(m).epsilon(1e-10));
    CHECK(b.sid.J.M0(2, 2) == Approx(0.5 * m * r * r).epsilon(1e-10));
    CHECK(b.sid.mdCM.M0.norm() < 1e-12 * m * r);
  }
  SECTION("half-disk revolved (axisymmetric sphere)") {
    const auto b = build(modal_spec(prep::primitives::half_disk(r), AnalysisType::Axisymmetric, {4, 3}, {6, 6}, 6));
    const double m = rho * 4.0 / 3.0 * M_PI * r * r * r;
    CHECK(b.sid.refmod.mass == Approx(m).epsilon(1e-10));
    CHECK((b.sid.J.M0 - 0.4 * m * r * r * Eigen::Matrix3d::Identity()).norm() < 1e-10 * 0.4 * m * r * r);
  }
  SECTION("3D ball") {
    const auto b = build(modal_spec(prep::primitives::ball(r), AnalysisType::Solid, {3, 3, 3}, {4, 4, 4}, 8, 4));
    const double m = rho * 4.0 / 3.0 * M_PI * r * r * r;
    CHECK(b.sid.refmod.mass == Approx(m).epsilon(1e-10));
    CHECK((b.sid.J.M0 - 0.4 * m * r * r * Eigen::Matrix3d::Identity()).norm() < 1e-10 * 0.4 * m * r * r);
  }
}

TEST_CASE("Me = I, Ke = diag(omega^2), De Rayleigh, and the Buckens conditions in the SID", "[sid]") {
  const auto b = build(modal_spec(prep::primitives::disk(0.1), AnalysisType::PlaneStrain, {3, 3}, {3, 3}, 6));
  const auto& s = b.sid;
  const Eigen::Index nq = s.nq();
  CHECK((s.Me.M0 - MatrixXd::Identity(nq, nq)).cwiseAbs().maxCoeff() < 1e-10);
  const Eigen::VectorXd w2 = (2 * M_PI * s.refmod.frequencies_hz).array().square();
  CHECK((s.Ke.M0 - MatrixXd(w2.asDiagonal())).cwiseAbs().maxCoeff() < 1e-10 * w2.maxCoeff());
  CHECK((s.De.M0 - s.damping.alpha1 * s.Me.M0 - s.damping.alpha2 * s.Ke.M0).norm() < 1e-12 * s.De.M0.norm());
  // [R1] eq. 26-27 (docs/references.md) with kappa = 1e-3 over the normal modes' band
  const double f1 = s.refmod.frequencies_hz(0), f2 = s.refmod.frequencies_hz(nq - 1);
  CHECK(s.damping.alpha2 == Approx(1e-3 / (M_PI * (f1 + f2))).epsilon(1e-12));
  CHECK(s.damping.alpha1 == Approx(4 * M_PI * M_PI * f1 * f2 * s.damping.alpha2).epsilon(1e-12));
  // Buckens: Ct = int Phi dm = 0 and Cr = int c x Phi dm = 0 (scales sqrt(m) and sqrt(m) L)
  const double sm = std::sqrt(s.refmod.mass), L = 0.1;
  CHECK(s.Ct.M0.cwiseAbs().maxCoeff() < 1e-10 * sm);
  CHECK(s.Cr.M0.cwiseAbs().maxCoeff() < 1e-10 * sm * L);
}

TEST_CASE("first-order inertia term equals a finite difference of the deformed body's inertia", "[sid]") {
  // J(q) = J0 + sum J1_k q_k + O(q^2); the deformed geometry is interpolated by the same
  // basis, so displacing the nodes by eps Phi_k and recomputing the inertia from M_s gives
  // J(eps e_k). A central difference is exact for the quadratic J(q): only round-off remains.
  auto check = [](const Built& b) {
    const double size = prep::body_size(b.body);
    const double eps = 1e-3 / std::sqrt(b.sid.refmod.mass) * 1e-3;  // ~1e-6 of the body size
    const int dim = b.body.dofs.dim();
    for (Eigen::Index k = 0; k < b.sid.nq(); ++k) {
      auto inertia = [&](double s) {
        MatrixXd X = b.body.dofs.node_points();
        for (Eigen::Index n = 0; n < X.rows(); ++n) X.row(n) += s * b.Phi_nodal.block(n * dim, k, dim, 1).transpose();
        return prep::rigid_integrals(b.Ms, X, b.sid.analysis).inertia();
      };
      const MatrixXd fd = (inertia(eps) - inertia(-eps)) / (2 * eps);
      // J1 of mass-normalized modes is of order sqrt(m) L; modes that leave the inertia
      // unchanged by symmetry have J1 and fd at round-off, hence the absolute floor
      const double natural = std::sqrt(b.sid.refmod.mass) * size;
      INFO("mode " << k << ": |J1| = " << b.sid.J.M1[std::size_t(k)].norm() << ", |fd| = " << fd.norm());
      CHECK((b.sid.J.M1[std::size_t(k)] - fd).norm() <= 1e-6 * fd.norm() + 1e-10 * natural);
    }
  };
  check(build(modal_spec(prep::primitives::half_disk(0.01), AnalysisType::Axisymmetric, {3, 2}, {3, 3}, 5)));
  check(build(modal_spec(prep::primitives::disk(0.01), AnalysisType::PlaneStress, {3, 3}, {2, 2}, 5)));
  check(build(modal_spec(prep::primitives::box(0.03, 0.01, 0.02), AnalysisType::Solid, {2, 2, 2}, {2, 1, 1}, 5)));
}
