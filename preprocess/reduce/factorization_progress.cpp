// The factorization's BLAS calls counted on their way to the BLAS library; see
// factorization_progress.hpp.
#include "reduce/factorization_progress.hpp"

#include "isosid/common/progress_line.hpp"

#include <algorithm>
#include <atomic>
#include <cstdio>
#include <cstdlib>
#include <dlfcn.h>
#include <string>

namespace isosid::prep {
namespace {

/// The meter's state: armed while a FactorizationProgress lives (one at a time: factorizations
/// run one after another). The calls come from the thread that factors; the counts are atomic
/// so that a call from any other thread is counted safely too.
std::atomic<bool> g_meter_armed{false};
std::atomic<double> g_counted_flops{0};
double g_expected_flops = 0;
std::atomic<int> g_tenths_shown{0};
std::string g_base_step;

void count_blas_work(double flops) {
  if (!g_meter_armed.load(std::memory_order_relaxed)) return;
  const double counted = g_counted_flops.fetch_add(flops, std::memory_order_relaxed) + flops;
  // the calls' count and the analysis's differ in terms of lower order (about 10 %): the
  // fraction stays below 1 until the factorization is done
  const double fraction = std::min(0.99, counted / g_expected_flops);
  common::set_work_fraction(fraction);
  const int tenths = int(10 * fraction);
  int shown = g_tenths_shown.load(std::memory_order_relaxed);
  if (tenths > shown && g_tenths_shown.compare_exchange_strong(shown, tenths)) {
    char text[64];
    std::snprintf(text, sizeof text, ", %d %% of its %.2g flops", 10 * tenths, g_expected_flops);
    common::set_work_step(g_base_step + text);
  }
}

/// The next definition of `name` after this program's: the BLAS library's.
template <typename Function>
Function next_definition(const char* name) {
  void* f = dlsym(RTLD_NEXT, name);
  if (!f) {
    std::fprintf(stderr, "isosid: the BLAS function %s was not found in the libraries this program loaded\n", name);
    std::abort();
  }
  return reinterpret_cast<Function>(f);
}

}  // namespace

FactorizationProgress::FactorizationProgress(double expected_flops, std::string step) {
  g_base_step = std::move(step);
  g_expected_flops = std::max(expected_flops, 1.0);
  g_counted_flops.store(0);
  g_tenths_shown.store(0);
  common::set_work_fraction(0);
  g_meter_armed.store(true);
}

FactorizationProgress::~FactorizationProgress() {
  g_meter_armed.store(false);
  common::set_work_fraction(-1);
  if (g_tenths_shown.load() > 0) common::set_work_step(g_base_step);  // no share left standing for the work after
}

double FactorizationProgress::counted_flops() const { return g_counted_flops.load(); }

}  // namespace isosid::prep

// The four calls of CHOLMOD's supernodal factorization, as CHOLMOD declares them (cholmod_blas.h,
// 32-bit BLAS integers; character arguments without hidden lengths). Each counts its work, then
// calls the BLAS library's own. Visible to the dynamic linker whatever the build's default.
extern "C" {

__attribute__((visibility("default"))) void dpotrf_(const char* uplo, const int* n, double* a, const int* lda, int* info) {
  using Call = void (*)(const char*, const int*, double*, const int*, int*);
  static const Call call = isosid::prep::next_definition<Call>("dpotrf_");
  isosid::prep::count_blas_work(double(*n) * *n * *n / 3);
  call(uplo, n, a, lda, info);
}

__attribute__((visibility("default"))) void dtrsm_(const char* side, const char* uplo, const char* transa, const char* diag, const int* m, const int* n,
            const double* alpha, const double* a, const int* lda, double* b, const int* ldb) {
  using Call = void (*)(const char*, const char*, const char*, const char*, const int*, const int*, const double*,
                        const double*, const int*, double*, const int*);
  static const Call call = isosid::prep::next_definition<Call>("dtrsm_");
  // the triangle's side times the other dimension
  isosid::prep::count_blas_work((*side == 'L' || *side == 'l') ? double(*m) * *m * *n : double(*m) * *n * *n);
  call(side, uplo, transa, diag, m, n, alpha, a, lda, b, ldb);
}

__attribute__((visibility("default"))) void dsyrk_(const char* uplo, const char* trans, const int* n, const int* k, const double* alpha, const double* a,
            const int* lda, const double* beta, double* c, const int* ldc) {
  using Call = void (*)(const char*, const char*, const int*, const int*, const double*, const double*, const int*,
                        const double*, double*, const int*);
  static const Call call = isosid::prep::next_definition<Call>("dsyrk_");
  isosid::prep::count_blas_work(double(*n) * (*n + 1) * *k);
  call(uplo, trans, n, k, alpha, a, lda, beta, c, ldc);
}

__attribute__((visibility("default"))) void dgemm_(const char* transa, const char* transb, const int* m, const int* n, const int* k, const double* alpha,
            const double* a, const int* lda, const double* b, const int* ldb, const double* beta, double* c, const int* ldc) {
  using Call = void (*)(const char*, const char*, const int*, const int*, const int*, const double*, const double*,
                        const int*, const double*, const int*, const double*, double*, const int*);
  static const Call call = isosid::prep::next_definition<Call>("dgemm_");
  isosid::prep::count_blas_work(2.0 * *m * *n * *k);
  call(transa, transb, m, n, k, alpha, a, lda, b, ldb, beta, c, ldc);
}

}  // extern "C"
