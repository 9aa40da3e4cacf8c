// The BLAS's idle threads (seflex/linalg/blas_threads.hpp).
#include "seflex/linalg/blas_threads.hpp"

#include "blas_threads.hpp"

namespace seflex::linalg {

bool release_idle_blas_threads() {
  if (blas_thread_shutdown_ == nullptr) return false;
  return blas_thread_shutdown_() == 0;
}

}  // namespace seflex::linalg
