// Dense linear algebra after assembly runs on one thread, except inside the large BLAS-3 work of
// a sparse factorization and its block solves.
// - The BLAS under CHOLMOD (Debian's OpenBLAS, pthread build): its worker threads busy-wait
//   between calls and, next to the OpenMP assembly threads on two cores, took most of
//   isosid-prep's time (the rod: 118 s wall under load against 7.7 s with one BLAS thread;
//   bench/RESULTS.md). Other BLAS builds are left as they are.
// - Eigen's OpenMP products: each opens a parallel region whose idle worker then spins in
//   libgomp until the next; in the rod's reduction that spinning was a quarter of all CPU
//   samples, and the parallel products saved 3 % of its wall time.
// - A factorization of a 3D body's stiffness is one long stretch of large BLAS-3 calls after the
//   assembly's threads are done: the free beam at a/4 (4.7e11 flops) factors in 24.5 s on two
//   threads against about 38 s on one. ParallelBlas gives such work the cores for its duration.
// The assembly's own parallel loop is not affected.
#pragma once

namespace isosid::prep {

/// Sets OpenBLAS (if it is the BLAS loaded; looked up at run time, the BLAS is a Debian
/// alternative) and Eigen's products to one thread. Idempotent and cheap after the first call.
void use_single_threaded_blas();

/// While alive, OpenBLAS runs on the cores this process may use (OPENBLAS_NUM_THREADS, if set,
/// instead); back to one thread after. For work of at least `flops` floating-point operations
/// only: below kParallelBlasFlops it changes nothing, so small models and the tests' bodies
/// keep one thread (and no idle worker spins next to another process).
class ParallelBlas {
public:
  explicit ParallelBlas(double flops);
  ~ParallelBlas();
  ParallelBlas(const ParallelBlas&) = delete;
  ParallelBlas& operator=(const ParallelBlas&) = delete;

private:
  bool active_ = false;
};

/// About a second of one core's BLAS-3.
inline constexpr double kParallelBlasFlops = 1e10;

}  // namespace isosid::prep
