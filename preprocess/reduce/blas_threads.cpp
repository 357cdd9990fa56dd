// One thread for dense algebra; see blas_threads.hpp.
#include "reduce/blas_threads.hpp"

#include <Eigen/Core>
#include <dlfcn.h>
#include <mutex>

namespace isosid::prep {

void use_single_threaded_blas() {
  static std::once_flag once;
  std::call_once(once, [] {
    using SetThreads = void (*)(int);
    Eigen::setNbThreads(1);
    if (auto set = reinterpret_cast<SetThreads>(dlsym(RTLD_DEFAULT, "openblas_set_num_threads"))) set(1);
  });
}

}  // namespace isosid::prep
