// The BLAS under CHOLMOD (Debian's OpenBLAS, pthread build) runs single-threaded: its worker
// threads busy-wait between calls and, next to the OpenMP assembly threads on two cores,
// took most of isosid-prep's time (the rod: 118 s wall under load against 7.7 s with one
// BLAS thread; bench/RESULTS.md). Other BLAS builds are left as they are.
#pragma once

namespace isosid::prep {

/// Sets OpenBLAS to one thread if it is the BLAS loaded (looked up at run time: the BLAS is a
/// Debian alternative). Idempotent and cheap after the first call.
void use_single_threaded_blas();

}  // namespace isosid::prep
