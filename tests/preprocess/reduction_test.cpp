// Reduced bases: M-orthonormal and K-diagonal to 1e-10 (round-off of the dense products and
// the two-pass projection), free of rigid-body content (Buckens), and Craig-Bampton's static
// exactness and eigenvalue bounds (Rayleigh-Ritz).
#include "geometry/primitives.hpp"
#include "reduce/craig_bampton.hpp"
#include "reduce/memory_budget.hpp"
#include "reduce/modal_analysis.hpp"
#include "reduce/reduction.hpp"
#include "reduce/sparse_cholesky.hpp"
#include "preprocess/body_fixtures.hpp"

#include <Eigen/Eigenvalues>
#include <SuiteSparse_config.h>
#include <catch2/catch.hpp>
#include <omp.h>
#include <random>

using namespace isosid;
using format::AnalysisType;

namespace {

using Fixture = test::AssembledBody;

std::vector<int> interface_of(const prep::BodyModel& b, const std::string& side) {
  return test::side_free_dofs(b, 0, *b.refined[0].side(side));
}

void check_basis(const Fixture& f, const prep::ReducedBasis& r) {
  const Eigen::MatrixXd G = r.Phi.transpose() * (f.sys.M * r.Phi);
  const Eigen::MatrixXd Kr = r.Phi.transpose() * (f.sys.K * r.Phi);
  const Eigen::Index nq = r.Phi.cols();
  CHECK((G - Eigen::MatrixXd::Identity(nq, nq)).cwiseAbs().maxCoeff() < 1e-10);
  const double kmax = r.omega2.cwiseAbs().maxCoeff();
  CHECK((Kr - Eigen::MatrixXd(r.omega2.asDiagonal())).cwiseAbs().maxCoeff() < 1e-10 * kmax);
  for (Eigen::Index i = 1; i < nq; ++i) CHECK(r.omega2(i) >= r.omega2(i - 1));
  // Buckens: no rigid-body content, R^T M Phi = 0 (relative to |R|_M |Phi|_M = |R|_M)
  if (f.rigid.cols() > 0) {
    const Eigen::MatrixXd MR = f.sys.M * f.rigid;
    const Eigen::VectorXd rnorm = (f.rigid.transpose() * MR).diagonal().cwiseSqrt();
    const Eigen::MatrixXd content = rnorm.cwiseInverse().asDiagonal() * (MR.transpose() * r.Phi);
    CHECK(content.cwiseAbs().maxCoeff() < 1e-10);
  }
}

}  // namespace

TEST_CASE("modal, Craig-Bampton and full bases are orthonormal, diagonal and in a Buckens frame", "[reduction]") {
  SECTION("free plane-strain disk") {
    const Fixture f = test::assembled(test::spec_for(prep::primitives::disk(0.1), AnalysisType::PlaneStrain, 2.1e11, 0.3, 7850,
                                             test::uniform({3, 3}, {3, 3})));
    REQUIRE(f.rigid.cols() == 3);
    prep::ReductionRequest modal{format::ReductionMethod::Modal, 8, {}, "", {}};
    const auto m = prep::reduce(f.sys.K, f.sys.M, f.rigid, modal, f.scale);
    CHECK(m.Phi.cols() == 8);
    check_basis(f, m);
    prep::ReductionRequest cb{format::ReductionMethod::CraigBampton, 6, interface_of(f.body, "bottom"), "", {}};
    const auto c = prep::reduce(f.sys.K, f.sys.M, f.rigid, cb, f.scale);
    CHECK(c.removed_rigid == 3);
    CHECK(c.Phi.cols() == 6 + Eigen::Index(cb.interface_dofs.size()) - 3);
    check_basis(f, c);
    const auto full = prep::reduce(f.sys.K, f.sys.M, f.rigid, {format::ReductionMethod::Full, 0, {}, "", {}}, f.scale);
    CHECK(full.Phi.cols() == f.body.dofs.free_count() - 3);
    check_basis(f, full);
    // the full basis holds the free-free elastic modes: its frequencies equal the modal ones
    for (int i = 0; i < 8; ++i) CHECK(full.omega2(i) == Approx(m.omega2(i)).epsilon(1e-9));
  }
  SECTION("axisymmetric half-disk with the radial DOF fixed on the axis") {
    const Fixture f = test::assembled(test::spec_for(prep::primitives::half_disk(0.01), AnalysisType::Axisymmetric, 7.28e10, 0.33,
                                             2789, test::uniform({3, 2}, {3, 3})));
    REQUIRE(f.rigid.cols() == 1);
    prep::ReductionRequest cb{format::ReductionMethod::CraigBampton, 4, interface_of(f.body, "lower"), "", {}};
    const auto c = prep::reduce(f.sys.K, f.sys.M, f.rigid, cb, f.scale);
    CHECK(c.removed_rigid == 1);
    check_basis(f, c);
  }
}

TEST_CASE("SparseCholesky: an analysis that CHOLMOD cannot allocate is refused, its factor never read", "[reduction]") {
  // A body beyond CHOLMOD's 32-bit indices (2^31 factor entries) or the memory leaves the
  // analysis without a factor, which must be refused with the size, not read. SuiteSparse's
  // allocator failing does the same to a small matrix.
  const Eigen::Index n = 40;
  Eigen::SparseMatrix<double> A(n, n);
  for (Eigen::Index i = 0; i < n; ++i) {
    A.insert(i, i) = 2.0;
    if (i > 0) A.insert(i, i - 1) = A.insert(i - 1, i) = -1.0;
  }
  struct FailingAllocator {
    decltype(SuiteSparse_config.malloc_func) malloc_func = SuiteSparse_config.malloc_func;
    decltype(SuiteSparse_config.calloc_func) calloc_func = SuiteSparse_config.calloc_func;
    decltype(SuiteSparse_config.realloc_func) realloc_func = SuiteSparse_config.realloc_func;
    FailingAllocator() {
      SuiteSparse_config.malloc_func = [](std::size_t) -> void* { return nullptr; };
      SuiteSparse_config.calloc_func = [](std::size_t, std::size_t) -> void* { return nullptr; };
      SuiteSparse_config.realloc_func = [](void*, std::size_t) -> void* { return nullptr; };
    }
    ~FailingAllocator() {
      SuiteSparse_config.malloc_func = malloc_func;
      SuiteSparse_config.calloc_func = calloc_func;
      SuiteSparse_config.realloc_func = realloc_func;
    }
  };
  {
    const FailingAllocator failing;
    try {
      const prep::SparseCholesky refused(A, "the test's factorization");
      FAIL("the factorization went on without a factor");
    } catch (const prep::MemoryRefusal& e) {
      CHECK(e.field() == "refinement");
      CHECK_THAT(e.what(), Catch::Matchers::Contains("the test's factorization of 40 DOFs ran out of memory in CHOLMOD's analysis"));
    }
  }
  const Eigen::VectorXd ones = Eigen::VectorXd::Ones(n);
  CHECK((A * prep::SparseCholesky(A).solve(ones) - ones).norm() < 1e-12);  // the allocator back, it factors
}

TEST_CASE("the assembly and a factorization are refused above the memory limit before they start, on their estimates", "[reduction]") {
  auto spec = test::spec_for(prep::primitives::rectangle(0.2, 0.02), AnalysisType::PlaneStress, 2.1e11, 0.3, 7850,
                             test::uniform({3, 3}, {8, 2}));
  const Fixture f = test::assembled(spec);
  // the element loop holds a value array per thread (the first is the matrix's) and the matrices'
  // row indices: a limit just below that is refused, one just above is not
  const double estimate = double(f.sys.K.nonZeros() + f.sys.M.nonZeros()) * (omp_get_max_threads() * 8.0 + 4.0);
  struct Limit {
    explicit Limit(double bytes) { prep::set_memory_limit(bytes); }
    ~Limit() { prep::set_memory_limit(0); }
  };
  {
    const Limit below(0.999 * estimate);
    try {
      (void)test::assembled(spec);
      FAIL("the assembly went on above its limit");
    } catch (const prep::MemoryRefusal& e) {
      CHECK(e.field() == "refinement");
      CHECK_THAT(e.what(), Catch::Matchers::Contains("the assembly of the stiffness and mass of " + std::to_string(f.sys.K.rows()) + " DOFs needs about"));
    }
  }
  const Limit above(1.001 * estimate);
  CHECK(test::assembled(spec).sys.K.isApprox(f.sys.K, 0.0));
  // a factorization holds K's lower triangle twice at least (CHOLMOD's copy and the factor's values):
  // more than 8 bytes per entry of K
  const Limit factor_below(double(f.sys.K.nonZeros()) * 8.0);
  try {
    const prep::SparseCholesky refused(f.sys.K, "the test's factorization");
    FAIL("the factorization went on above its limit");
  } catch (const prep::MemoryRefusal& e) {
    CHECK(e.field() == "refinement");
    CHECK_THAT(e.what(), Catch::Matchers::Contains("the test's factorization of " + std::to_string(f.sys.K.rows()) + " DOFs needs about"));
  }
}

TEST_CASE("Craig-Bampton reproduces the full static deflection under interface loads", "[reduction]") {
  auto spec = test::spec_for(prep::primitives::rectangle(0.2, 0.02), AnalysisType::PlaneStress, 2.1e11, 0.3, 7850,
                             test::uniform({3, 3}, {8, 2}));
  spec.fixed = {{"left", {0, 1}}};
  const Fixture f = test::assembled(spec);
  REQUIRE(f.rigid.cols() == 0);  // clamped: no rigid-body field is admissible
  const std::vector<int> interface = interface_of(f.body, "right");
  prep::ReductionRequest cb{format::ReductionMethod::CraigBampton, 3, interface, "", {}};
  const auto c = prep::reduce(f.sys.K, f.sys.M, f.rigid, cb, f.scale);
  std::mt19937 gen(4);
  std::normal_distribution<double> n01;
  Eigen::VectorXd load = Eigen::VectorXd::Zero(f.body.dofs.free_count());
  for (int d : interface) load(d) = 1e3 * n01(gen);
  const Eigen::VectorXd full = prep::SparseCholesky(f.sys.K).solve(load);
  const Eigen::VectorXd q = (c.Phi.transpose() * load).cwiseQuotient(c.omega2);  // Ke = diag(omega2)
  const Eigen::VectorXd reduced = c.Phi * q;
  // static condensation is exact for interface loads: only round-off (cond(K) ~ 1e8 here)
  CHECK((reduced - full).norm() < 1e-8 * full.norm());
}

TEST_CASE("Craig-Bampton eigenvalues bound the full ones from above and become exact with all interior modes",
          "[reduction]") {
  auto spec = test::spec_for(prep::primitives::rectangle(0.2, 0.02), AnalysisType::PlaneStress, 2.1e11, 0.3, 7850,
                             test::uniform({2, 2}, {6, 1}));
  spec.fixed = {{"left", {0, 1}}};
  const Fixture f = test::assembled(spec);
  const Eigen::MatrixXd Kd = f.sys.K, Md = f.sys.M;
  Eigen::GeneralizedSelfAdjointEigenSolver<Eigen::MatrixXd> dense(Kd, Md);
  const Eigen::VectorXd exact = dense.eigenvalues();
  const std::vector<int> interface = interface_of(f.body, "right");
  const int interior = f.body.dofs.free_count() - int(interface.size());
  const auto partial = prep::reduce(f.sys.K, f.sys.M, f.rigid, {format::ReductionMethod::CraigBampton, 4, interface, "", {}}, f.scale);
  for (Eigen::Index i = 0; i < partial.omega2.size(); ++i) CHECK(partial.omega2(i) >= exact(i) * (1 - 1e-10));
  CHECK(partial.omega2(0) == Approx(exact(0)).epsilon(1e-3));  // and close for the lowest
  const auto complete = prep::reduce(f.sys.K, f.sys.M, f.rigid, {format::ReductionMethod::CraigBampton, interior, interface, "", {}}, f.scale);
  CHECK(complete.Phi.cols() == f.body.dofs.free_count());
  // the basis spans the whole space: the spectrum is the full model's (relative 1e-8:
  // two dense solves whose round-off grows with the spread of the spectrum, ~1e9 here)
  for (Eigen::Index i = 0; i < complete.omega2.size(); ++i) CHECK(complete.omega2(i) == Approx(exact(i)).epsilon(1e-8));
}
