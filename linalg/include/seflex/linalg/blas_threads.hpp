#pragma once
// The BLAS's idle threads, for the command-line front end.
//
// OpenBLAS (pthreads build, Debian's default) starts its worker threads when the library is loaded,
// before main, and each worker then waits for work by spinning on sched_yield for 2^28 TSC cycles
// (its THREAD_TIMEOUT, 0.13 s at 2.1 GHz) before it sleeps. A command that never calls the BLAS
// (`seflex run`, `info`, `version`) pays that spin in CPU time: 0.13 s of the 1.3 s of the demo's
// sync-3d run (perf: a second thread in sched_yield, 10.7 % of the samples; docs/benchmarks.md,
// "Idle BLAS threads"). Stopping the workers at start-up removes it; the first multithreaded BLAS
// call after that starts them again (OpenBLAS creates its threads when none are running), so the
// reduction keeps its threads. With another BLAS, or OpenBLAS built with OpenMP, this does nothing.

namespace seflex::linalg {

/// Stops the BLAS's worker threads if they are running and the BLAS can restart them on demand.
/// Returns true if threads were stopped.
bool release_idle_blas_threads();

}  // namespace seflex::linalg
