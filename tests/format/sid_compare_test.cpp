// isosid-diff's comparison: the same physics in a sign-flipped or rotated mode basis is equal;
// a perturbed frequency, inertia or mode shape is not. The rotated SIDs are recomputed from
// scratch (lumped body integrals), so the alignment rules are checked independently.
#include "isosid/format/sid_compare.hpp"
#include "support/lumped_sid.hpp"

#include <catch2/catch.hpp>
#include <random>

using namespace isosid;
using Eigen::MatrixXd;

namespace {
const double kRtol = 1e-8;  // the recomputed SIDs differ from the originals only by round-off (~1e-14)

std::string listing(const format::Comparison& c) {
  std::string s;
  for (const auto& d : c.differences) s += d.what + ": " + d.detail + "\n";
  return s;
}
}  // namespace

TEST_CASE("identical SIDs compare equal", "[format][diff]") {
  const auto body = test::random_lumped_body(12, 5, 21);
  const auto c = format::compare_sids(test::lumped_sid(body), test::lumped_sid(body), kRtol);
  INFO(listing(c));
  CHECK(c.equal());
}

TEST_CASE("a sign-flipped mode is the same body", "[format][diff]") {
  const auto body = test::random_lumped_body(12, 5, 21);
  MatrixXd Q = MatrixXd::Identity(5, 5);
  Q(3, 3) = -1;
  Q(0, 0) = -1;
  const auto c = format::compare_sids(test::lumped_sid(body), test::lumped_sid(test::rotate_modes(body, Q)), kRtol);
  INFO(listing(c));
  CHECK(c.equal());
}

TEST_CASE("a rotated pair of repeated-frequency modes is the same body", "[format][diff]") {
  const auto body = test::random_lumped_body(12, 5, 21);  // modes 1 and 2 share a frequency
  MatrixXd Q = MatrixXd::Identity(5, 5);
  const double t = 0.7;
  Q.block(1, 1, 2, 2) << std::cos(t), -std::sin(t), std::sin(t), std::cos(t);
  Q(4, 4) = -1;
  const auto c = format::compare_sids(test::lumped_sid(body), test::lumped_sid(test::rotate_modes(body, Q)), kRtol);
  INFO(listing(c));
  CHECK(c.equal());
  REQUIRE(c.clusters.size() == 4);
  CHECK(c.clusters[1].size == 2);
  CHECK(c.clusters[1].max_sine < 1e-10);
}

TEST_CASE("a rotation that mixes modes of different frequency is a different body", "[format][diff]") {
  const auto body = test::random_lumped_body(12, 5, 21);
  MatrixXd Q = MatrixXd::Identity(5, 5);
  const double t = 0.3;
  Q.block(3, 3, 2, 2) << std::cos(t), -std::sin(t), std::sin(t), std::cos(t);  // modes 3, 4: 4 and 5 kHz
  const auto c = format::compare_sids(test::lumped_sid(body), test::lumped_sid(test::rotate_modes(body, Q)), kRtol);
  CHECK_FALSE(c.equal());
}

TEST_CASE("a perturbed frequency is reported", "[format][diff]") {
  const auto body = test::random_lumped_body(12, 5, 21);
  auto a = test::lumped_sid(body), b = a;
  b.refmod.frequencies_hz(3) *= 1 + 1e-5;
  const auto c = format::compare_sids(a, b, 1e-6);
  REQUIRE_FALSE(c.equal());
  CHECK(c.differences[0].what == "frequency of mode 3");
}

TEST_CASE("section shares: equal within a cluster whatever its rotation, a changed share reported", "[format][diff]") {
  const auto body = test::random_lumped_body(12, 5, 21);  // modes 1 and 2 share a frequency
  auto a = test::lumped_sid(body), b = a;
  a.refmod.section_translation = MatrixXd::Constant(5, 3, 0.1);
  a.refmod.long_axis = Eigen::Vector3d::UnitX();
  b.refmod.section_translation = a.refmod.section_translation;
  b.refmod.long_axis = -a.refmod.long_axis;  // the axis' sign is arbitrary
  // a rotation within the cluster moves its shares between its modes and keeps their sum
  b.refmod.section_translation.row(1) << 0.15, 0.0, 0.1;
  b.refmod.section_translation.row(2) << 0.05, 0.2, 0.1;
  auto c = format::compare_sids(a, b, 1e-6);
  INFO(listing(c));
  CHECK(c.equal());
  b.refmod.section_translation(4, 2) = 0.3;  // a mode of its own frequency
  c = format::compare_sids(a, b, 1e-6);
  REQUIRE_FALSE(c.equal());
  CHECK(c.differences[0].what == "/refmod/section_translation of mode 4");
  b.refmod.section_translation.resize(0, 3);  // one file without shares
  CHECK_FALSE(format::compare_sids(a, b, 1e-6).equal());
}

TEST_CASE("a perturbed inertia is reported", "[format][diff]") {
  const auto body = test::random_lumped_body(12, 5, 21);
  auto a = test::lumped_sid(body), b = a;
  b.J.M0(1, 1) *= 1 + 1e-4;
  const auto c = format::compare_sids(a, b, 1e-6);
  REQUIRE_FALSE(c.equal());
  bool inertia = false;
  for (const auto& d : c.differences) inertia = inertia || d.what == "inertia tensor";
  CHECK(inertia);
}

TEST_CASE("a perturbed contact mode shape is reported as a subspace difference", "[format][diff]") {
  const auto body = test::random_lumped_body(12, 5, 21);
  auto a = test::lumped_sid(body), b = a;
  b.contact_surfaces[0].Psi(2, 0) += 1e-3 * b.contact_surfaces[0].Psi.norm();
  const auto c = format::compare_sids(a, b, 1e-6);
  INFO(listing(c));
  CHECK_FALSE(c.equal());
}

TEST_CASE("SIDs of different structure are reported without comparing terms", "[format][diff]") {
  const auto a = test::lumped_sid(test::random_lumped_body(12, 5, 21));
  const auto b = test::lumped_sid(test::random_lumped_body(12, 4, 21));
  const auto c = format::compare_sids(a, b, 1e-6);
  REQUIRE_FALSE(c.equal());
  CHECK(c.notes.back().find("structure differs") != std::string::npos);
}

TEST_CASE("terms that vanish up to round-off (Buckens Ct, Cr) do not disturb the alignment", "[format][diff]") {
  // Real SIDs are in a Buckens frame: Ct and Cr are round-off noise that differs between two
  // runs. Normalizing such a block by its own norm would turn the noise into O(1) "mode rows".
  const auto body = test::random_lumped_body(12, 5, 21);
  auto a = test::lumped_sid(body), b = a;
  std::mt19937 gen(7);
  std::normal_distribution<double> noise(0.0, 1e-18);
  for (auto* s : {&a, &b}) {
    for (Eigen::Index i = 0; i < s->Ct.M0.size(); ++i) s->Ct.M0.data()[i] = noise(gen);
    for (Eigen::Index i = 0; i < s->Cr.M0.size(); ++i) s->Cr.M0.data()[i] = noise(gen);
  }
  const auto c = format::compare_sids(a, b, 1e-8);
  INFO(listing(c));
  CHECK(c.equal());
}
