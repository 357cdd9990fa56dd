// Progress of a sparse factorization, measured. CHOLMOD has no progress hook, but its supernodal
// factorization is a sequence of LAPACK and BLAS calls, a few per supernode: dpotrf on the
// diagonal block, dtrsm below it, dsyrk and dgemm for the updates of later supernodes. The
// program defines those four symbols itself; each counts its call's floating-point work and
// passes the call on to the BLAS library the process loaded (the next definition, dlsym
// RTLD_NEXT). The counted work against the analysis's count of the factorization's flops is the
// fraction done; a log sees it in the work step every tenth.
#pragma once
#include <string>

namespace isosid::prep {

class FactorizationProgress {
public:
  /// While alive, the BLAS calls' work counts toward `expected_flops` (CHOLMOD's analysis
  /// count): the work fraction follows it (capped below 1) and the work step `step` gains
  /// ", N % of its F flops". Afterwards the fraction is unknown again (-1) and the step is
  /// `step` again.
  FactorizationProgress(double expected_flops, std::string step);
  ~FactorizationProgress();
  FactorizationProgress(const FactorizationProgress&) = delete;
  FactorizationProgress& operator=(const FactorizationProgress&) = delete;

  /// The work the four calls counted since this meter started, in flops.
  double counted_flops() const;
};

}  // namespace isosid::prep
