// One thread for dense algebra, more for large BLAS-3 stretches; see blas_threads.hpp.
#include "reduce/blas_threads.hpp"

#include <Eigen/Core>
#include <cstdlib>
#include <dlfcn.h>
#include <mutex>
#include <sched.h>

namespace isosid::prep {

namespace {

using SetThreads = void (*)(int);

SetThreads openblas_set_num_threads() {
  return reinterpret_cast<SetThreads>(dlsym(RTLD_DEFAULT, "openblas_set_num_threads"));
}

/// OPENBLAS_NUM_THREADS if set to a positive count, else the CPUs this process may run on.
int parallel_threads() {
  if (const char* env = std::getenv("OPENBLAS_NUM_THREADS")) {
    const int n = std::atoi(env);
    if (n > 0) return n;
  }
  cpu_set_t set;
  CPU_ZERO(&set);
  if (sched_getaffinity(0, sizeof(set), &set) == 0) return CPU_COUNT(&set);
  return 1;
}

}  // namespace

void use_single_threaded_blas() {
  static std::once_flag once;
  std::call_once(once, [] {
    Eigen::setNbThreads(1);
    if (auto set = openblas_set_num_threads()) set(1);
  });
}

ParallelBlas::ParallelBlas(double flops) {
  use_single_threaded_blas();
  const auto set = openblas_set_num_threads();
  const int threads = parallel_threads();
  if (!set || threads < 2 || !(flops >= kParallelBlasFlops)) return;
  set(threads);
  active_ = true;
}

ParallelBlas::~ParallelBlas() {
  if (active_) openblas_set_num_threads()(1);
}

}  // namespace isosid::prep
