#pragma once
// Threads of the BLAS in a scope (private to linalg/). OpenBLAS synchronises its threads on every
// call; a supernodal triangular solve makes one call per supernode and the Lanczos basis products
// are memory-bound, so for them a second thread gains little on an idle machine and, on a machine
// shared with other jobs, loses several times over waiting for a descheduled partner (100k-dof
// plate at load 5: `seflex modes` 35 s with 2 threads, 9.6 s with 1; docs/benchmarks.md). The
// numeric factorisation (large dense kernels) keeps all threads. With another BLAS this is a no-op.
extern "C" {
void openblas_set_num_threads(int) __attribute__((weak));
int openblas_get_num_threads(void) __attribute__((weak));
int blas_thread_shutdown_(void) __attribute__((weak));
}

namespace seflex::linalg {

class BlasThreadScope {
 public:
  explicit BlasThreadScope(int threads) {
    if (openblas_set_num_threads == nullptr || openblas_get_num_threads == nullptr) return;
    previous_ = openblas_get_num_threads();
    if (previous_ > threads) openblas_set_num_threads(threads);
    else previous_ = 0;
  }
  ~BlasThreadScope() {
    if (previous_ > 0) openblas_set_num_threads(previous_);
  }
  BlasThreadScope(const BlasThreadScope&) = delete;
  BlasThreadScope& operator=(const BlasThreadScope&) = delete;

 private:
  int previous_ = 0;  // threads to restore (0: nothing changed)
};

}  // namespace seflex::linalg
