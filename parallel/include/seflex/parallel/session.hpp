#pragma once
// The MPI + PETSc + SLEPc session of a distributed run (RAII: SlepcInitialize / SlepcFinalize), and
// the collective agreement on failures that lets one rank's error stop every rank with one message.
//
// Contract
// - At most one Session per process, made before and destroyed after every other parallel/ call.
//   PETSc's own error printing and signal handlers are switched off: a PETSc failure comes back as a
//   seflex::InvariantError (or FactorizationError / ConvergenceError) from the call that failed.
// - agree() is collective: every rank must call it the same number of times, in the same order.
#include <cstddef>
#include <optional>
#include <stdexcept>
#include <string>
#include <vector>

namespace seflex::parallel {

/// A failure as the front end reports it: its exit code and message, and the rank it came from.
struct Failure {
  int exit_code = 1;
  std::string message;
  int rank = 0;
};

/// Thrown by a collective parallel/ call on the ranks that did not fail when another rank failed
/// inside it: that rank throws its own error, and Session::agree brings its message to every rank.
struct PeerFailure : std::runtime_error {
  PeerFailure() : std::runtime_error("another rank failed") {}
};

class Session {
 public:
  /// Initialises MPI (if not yet), PETSc and SLEPc. Throws InvariantError if that fails.
  Session();
  /// Virtual, as agree(): the seflex command holds a session the plugin made (backend.hpp) and reaches
  /// its out-of-line code through the vtable only.
  virtual ~Session();
  Session(const Session&) = delete;
  Session& operator=(const Session&) = delete;

  int rank() const { return rank_; }
  int size() const { return size_; }

  /// Collective. `local`: this rank's failure, if any. Returns the failure of the lowest-numbered
  /// failing rank (its code and message, sent to every rank), or nullopt when no rank failed.
  virtual std::optional<Failure> agree(const std::optional<Failure>& local) const;

 private:
  int rank_ = 0, size_ = 1;
};

/// Collective: adds each array (`count` doubles, the same count and number of arrays on every rank)
/// up over the ranks, in place (MPI_Allreduce): every rank gets the sums. `failed_here`: this rank's
/// share of the work threw (its arrays may be missing); then nothing is summed and the ranks that did
/// not fail throw PeerFailure, while this one returns (to rethrow its own error).
void sum_over_ranks(const std::vector<double*>& arrays, std::size_t count, bool failed_here);

}  // namespace seflex::parallel
