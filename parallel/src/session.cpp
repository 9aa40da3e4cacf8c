// MPI + PETSc + SLEPc session and the collective agreement on failures (session.hpp).
#include "seflex/parallel/session.hpp"

#include <slepcsys.h>

#include <algorithm>
#include <vector>

#include "petsc_support.hpp"
#include "seflex/common/error.hpp"

namespace seflex::parallel {

Session::Session() {
  // No PETSc signal handler or error printing: errors come back as codes and become exceptions.
  SEFLEX_PETSC(PetscOptionsSetValue(nullptr, "-no_signal_handler", "true"));
  SEFLEX_PETSC(SlepcInitialize(nullptr, nullptr, nullptr, nullptr));
  SEFLEX_PETSC(PetscPushErrorHandler(PetscReturnErrorHandler, nullptr));
  MPI_Comm_rank(PETSC_COMM_WORLD, &rank_);
  MPI_Comm_size(PETSC_COMM_WORLD, &size_);
}

Session::~Session() { (void)SlepcFinalize(); }

void sum_over_ranks(const std::vector<double*>& arrays, std::size_t count, bool failed_here) {
  int mine = failed_here ? 1 : 0, any = 0;
  SEFLEX_DEMAND(MPI_Allreduce(&mine, &any, 1, MPI_INT, MPI_MAX, PETSC_COMM_WORLD) == MPI_SUCCESS, "MPI_Allreduce failed");
  if (failed_here) return;
  if (any != 0) throw PeerFailure();
  constexpr std::size_t kChunk = std::size_t{1} << 28;  // doubles per call: counts are ints
  for (double* a : arrays)
    for (std::size_t at = 0; at < count; at += kChunk)
      SEFLEX_DEMAND(MPI_Allreduce(MPI_IN_PLACE, a + at, static_cast<int>(std::min(kChunk, count - at)), MPI_DOUBLE,
                                  MPI_SUM, PETSC_COMM_WORLD) == MPI_SUCCESS,
                    "MPI_Allreduce failed");
}

std::optional<Failure> Session::agree(const std::optional<Failure>& local) const {
  // The lowest failing rank (size_ if none) ...
  int mine = local ? rank_ : size_, first = size_;
  SEFLEX_DEMAND(MPI_Allreduce(&mine, &first, 1, MPI_INT, MPI_MIN, PETSC_COMM_WORLD) == MPI_SUCCESS,
                "MPI_Allreduce failed");
  if (first == size_) return std::nullopt;
  // ... sends its exit code and message to every rank.
  Failure f;
  int header[2] = {local ? local->exit_code : 0, local ? static_cast<int>(local->message.size()) : 0};
  MPI_Bcast(header, 2, MPI_INT, first, PETSC_COMM_WORLD);
  std::vector<char> text(static_cast<std::size_t>(header[1]));
  if (rank_ == first) text.assign(local->message.begin(), local->message.end());
  if (header[1] > 0) MPI_Bcast(text.data(), header[1], MPI_CHAR, first, PETSC_COMM_WORLD);
  f.exit_code = header[0];
  f.message.assign(text.begin(), text.end());
  f.rank = first;
  return f;
}

}  // namespace seflex::parallel
