// The volume integrals recovered from SID terms against their definitions on a lumped-mass
// body (test support builds its SID terms from first principles): m = sum m_i, int c dm =
// sum m_i c_i, ..., int Phi_a^T Phi_b dm = sum m_i Phi_i(a,:)^T Phi_i(b,:). Sums and
// differences of terms of size ~1 leave round-off only: 1e-12 of each integral's largest entry.
#include "isosid/format/body_integrals.hpp"
#include "isosid/format/error.hpp"
#include "isosid/format/sid_export.hpp"
#include "support/lumped_sid.hpp"

#include <catch2/catch.hpp>

using namespace isosid;
using Catch::Matchers::Contains;

namespace {
double relative(const Eigen::MatrixXd& a, const Eigen::MatrixXd& b) { return (a - b).cwiseAbs().maxCoeff() / b.cwiseAbs().maxCoeff(); }
}  // namespace

TEST_CASE("body integrals recovered from SID terms equal their lumped-mass definitions", "[format][export]") {
  const test::LumpedBody body = test::random_lumped_body(12, 5, 11);
  const format::BodyIntegrals b = format::body_integrals(test::lumped_sid(body));
  const Eigen::Index n = body.points.rows(), nq = body.Phi.cols();
  double m = 0;
  Eigen::Vector3d rdm = Eigen::Vector3d::Zero();
  Eigen::Matrix3d rrdm = Eigen::Matrix3d::Zero();
  Eigen::MatrixXd Pdm = Eigen::MatrixXd::Zero(3, nq);
  std::array<Eigen::MatrixXd, 3> rPdm;
  std::array<std::array<Eigen::MatrixXd, 3>, 3> PPdm;
  for (int a = 0; a < 3; ++a) {
    rPdm[std::size_t(a)] = Eigen::MatrixXd::Zero(3, nq);
    for (int c = 0; c < 3; ++c) PPdm[std::size_t(a)][std::size_t(c)] = Eigen::MatrixXd::Zero(nq, nq);
  }
  for (Eigen::Index i = 0; i < n; ++i) {
    const double mi = body.masses(i);
    const Eigen::Vector3d c = body.points.row(i).transpose();
    const Eigen::MatrixXd Phi_i = body.Phi.middleRows(3 * i, 3);
    m += mi;
    rdm += mi * c;
    rrdm += mi * c * c.transpose();
    Pdm += mi * Phi_i;
    for (int a = 0; a < 3; ++a) {
      rPdm[std::size_t(a)] += mi * c(a) * Phi_i;
      for (int d = 0; d < 3; ++d) PPdm[std::size_t(a)][std::size_t(d)] += mi * Phi_i.row(a).transpose() * Phi_i.row(d);
    }
  }
  CHECK(b.m == Approx(m).epsilon(1e-14));
  CHECK(relative(b.rdm, rdm) < 1e-12);
  CHECK(relative(b.rrdm, rrdm) < 1e-12);
  CHECK(relative(b.Pdm, Pdm) < 1e-12);
  for (int a = 0; a < 3; ++a) {
    INFO("a = " << a);
    CHECK(relative(b.rPdm[std::size_t(a)], rPdm[std::size_t(a)]) < 1e-12);
    for (int d = 0; d < 3; ++d) {
      INFO("b = " << d);
      CHECK(relative(b.PPdm[std::size_t(a)][std::size_t(d)], PPdm[std::size_t(a)][std::size_t(d)]) < 1e-12);
    }
  }
}

TEST_CASE("SIDs the export formats cannot hold are refused, naming the SID and the dataset", "[format][export]") {
  using format::ExportFormat;
  format::Sid sid = test::lumped_sid(test::random_lumped_body(8, 3, 2));
  CHECK_NOTHROW(format::check_exportable(sid, "a.sid.h5", ExportFormat::MbsimH5));
  format::Sid massless = sid;
  massless.refmod.reduction_method = "macneal";
  for (ExportFormat f : {ExportFormat::SidFem, ExportFormat::MbsimH5})
    CHECK_THROWS_WITH(format::check_exportable(massless, "a.sid.h5", f), Contains("a.sid.h5") && Contains("/refmod/reduction_method"));
  // without Oe's order-1 part the integrals of Phi^T Phi cannot be recovered: MBSim would get Me = 0
  format::Sid order0 = sid;
  order0.Oe.M1.clear();
  CHECK_NOTHROW(format::check_exportable(order0, "a.sid.h5", ExportFormat::SidFem));
  CHECK_THROWS_WITH(format::check_exportable(order0, "a.sid.h5", ExportFormat::MbsimH5), Contains("/terms/Oe"));
}
