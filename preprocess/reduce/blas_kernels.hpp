// The BLAS kernels for this CPU. OpenBLAS picks its kernels from the CPU's model number at load
// time; a release older than the CPU (Debian 12's 0.3.21 on Intel's Sapphire and Emerald
// Rapids, models 143 and 207) does not know it and falls back to its Prescott kernels (SSE3).
// There CHOLMOD's supernodal factorization of the free beam's stiffness at a/4 (4.7e11 flops)
// took 36 s instead of 15 s with the AVX-512 kernels. OpenBLAS's documented override,
// OPENBLAS_CORETYPE, is read once at load: isosid-prep sets it and runs itself again.
#pragma once
#include <string>

namespace isosid::prep {

/// The OpenBLAS core type this CPU should use when the loaded OpenBLAS fell back to Prescott
/// although the CPU has AVX-512 ("SkylakeX") or AVX2 and FMA ("Haswell"); empty when the
/// BLAS is not OpenBLAS, chose another core, or the user set OPENBLAS_CORETYPE.
std::string better_openblas_core();

/// With such a core type, sets OPENBLAS_CORETYPE and replaces this process by the same program
/// with the same arguments (execv of /proc/self/exe). Returns when there is nothing to do or
/// the exec fails (the run then goes on with the kernels it has). Call first thing in main.
void rerun_with_better_blas_kernels(char** argv);

}  // namespace isosid::prep
