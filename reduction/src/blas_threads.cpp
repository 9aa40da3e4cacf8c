// The BLAS's idle threads (seflex/reduction/blas_threads.hpp).
#include "seflex/reduction/blas_threads.hpp"

#include "blas_threads.hpp"

namespace seflex::reduction {

bool release_idle_blas_threads() {
  if (blas_thread_shutdown_ == nullptr) return false;
  return blas_thread_shutdown_() == 0;
}

}  // namespace seflex::reduction
