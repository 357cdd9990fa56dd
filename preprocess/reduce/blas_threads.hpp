// Dense linear algebra after assembly runs on one thread.
// - The BLAS under CHOLMOD (Debian's OpenBLAS, pthread build): its worker threads busy-wait
//   between calls and, next to the OpenMP assembly threads on two cores, took most of
//   isosid-prep's time (the rod: 118 s wall under load against 7.7 s with one BLAS thread;
//   bench/RESULTS.md). Other BLAS builds are left as they are.
// - Eigen's OpenMP products: each opens a parallel region whose idle worker then spins in
//   libgomp until the next; in the rod's reduction that spinning was a quarter of all CPU
//   samples, and the parallel products saved 3 % of its wall time.
// The assembly's own parallel loop is not affected.
#pragma once

namespace isosid::prep {

/// Sets OpenBLAS (if it is the BLAS loaded; looked up at run time, the BLAS is a Debian
/// alternative) and Eigen's products to one thread. Idempotent and cheap after the first call.
void use_single_threaded_blas();

}  // namespace isosid::prep
