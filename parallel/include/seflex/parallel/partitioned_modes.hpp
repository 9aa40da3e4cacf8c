#pragma once
// Normal modes (solutions::solve_normal_modes: same case-control selections, EIGRL/EIGR fields,
// normalisation and result) with K and M assembled by element partition (partitioned_system.hpp) and
// solved by the distributed SLEPc backend (slepc_eigensolver.hpp): no rank holds the whole K or M.
// The mode shapes are gathered on every rank (g-set x m), as the replicated path does.
//
// Collective on PETSC_COMM_WORLD; needs a parallel::Session. Preconditions: check_card_usage found
// nothing Refused and partition_refusal(model, selection's MPC) is nullopt (else InvariantError).
// Throws as solve_normal_modes (InputError for a missing METHOD, an EIGRL that bounds nothing, a
// mechanism: K - sigma M not positive definite, the dof unnamed), and PeerFailure (session.hpp).
#include <cstddef>

#include "seflex/fem/model.hpp"
#include "seflex/solutions/normal_modes.hpp"

namespace seflex::parallel {

/// What the partitioned assembly did on this rank (for the summary and the benchmark).
struct PartitionStats {
  std::size_t local_elements = 0, total_elements = 0;
  long local_rows = 0, total_rows = 0;
  double seconds_assembly = 0;  ///< partition, element matrices, constraints, PETSc assembly
};

solutions::NormalModes solve_normal_modes_partitioned(fem::Model& model, const solutions::ModesOptions& options,
                                                      PartitionStats* stats = nullptr);

}  // namespace seflex::parallel
