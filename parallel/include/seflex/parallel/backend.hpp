#pragma once
// The distributed backend as the seflex command reaches it: a table of entry points exported by the
// plugin libseflex_parallel.so (the `parallel` module built as a shared module with PETSc, SLEPc, MUMPS
// and MPI inside), which the command loads only when a run asks for it (`--backend slepc`). The
// command itself links none of those libraries, so every other command starts without loading the
// 90 shared libraries they pull in (docs/distributed.md, "The plugin").
//
// Both sides are compiled from the same sources; kBackendAbi (bumped when this table or a type that
// crosses it changes) and backend_fingerprint() (the sizes of those types) let the loader refuse a
// plugin from another build instead of crashing. The objects that cross (Session, PartitionedSystem,
// the factorisation) are created in the plugin and destroyed through their virtual destructors or
// the deleter the plugin put in the shared_ptr, so the command never needs their out-of-line code.
#include <cstddef>
#include <cstdint>
#include <memory>
#include <optional>
#include <string>
#include <vector>

#include "seflex/common/plugin.hpp"
#include "seflex/fem/constraints.hpp"
#include "seflex/fem/model.hpp"
#include "seflex/parallel/partitioned_modes.hpp"
#include "seflex/parallel/partitioned_system.hpp"
#include "seflex/parallel/session.hpp"
#include "seflex/reduction/craig_bampton.hpp"
#include "seflex/linalg/eigensolver.hpp"
#include "seflex/solutions/normal_modes.hpp"
#include "seflex/linalg/sparse_factorization.hpp"

namespace seflex::parallel {

inline constexpr int kBackendAbi = 2;

/// Name of the plugin's entry point: extern "C" const Backend* seflex_parallel_backend().
inline constexpr const char* kBackendEntry = "seflex_parallel_backend";

struct Backend {
  int abi = kBackendAbi;
  std::uint64_t fingerprint = 0;
  /// Initialises MPI, PETSc and SLEPc (Session's constructor); throws InvariantError if that fails.
  std::unique_ptr<Session> (*open_session)() = nullptr;
  linalg::EigenSolution (*slepc_eigenproblem)(const linalg::SparseMatrixd& K, const linalg::SparseMatrixd& M,
                                                 const linalg::EigenOptions& options) = nullptr;
  std::unique_ptr<linalg::SparseFactorization> (*make_mumps_factorization)() = nullptr;
  std::optional<std::string> (*partition_refusal)(const fem::Model& model, std::optional<int> mpc_set) = nullptr;
  solutions::NormalModes (*solve_normal_modes_partitioned)(fem::Model& model, const solutions::ModesOptions& options,
                                                           PartitionStats* stats) = nullptr;
  /// The command reads the result's data members only; the plugin's deleter destroys it.
  std::shared_ptr<PartitionedSystem> (*assemble_partitioned)(fem::Model& model, const fem::ConstraintOptions& options,
                                                             fem::GlobalMatrices* whole) = nullptr;
  reduction::CraigBamptonBasis (*craig_bampton_partitioned)(const PartitionedSystem& system,
                                                            const std::vector<Eigen::Index>& boundary,
                                                            const reduction::CraigBamptonOptions& options) = nullptr;
  void (*sum_over_ranks)(const std::vector<double*>& arrays, std::size_t count, bool failed_here) = nullptr;
};

/// The sizes of the types that cross the table, combined: equal on both sides of one build.
inline std::uint64_t backend_fingerprint() {
  return size_fingerprint({sizeof(Backend), sizeof(Session), sizeof(PartitionStats), sizeof(PartitionedSystem),
                           sizeof(fem::Model), sizeof(fem::ConstraintOptions), sizeof(fem::GlobalMatrices),
                           sizeof(linalg::EigenOptions), sizeof(linalg::EigenSolution), sizeof(solutions::ModesOptions),
                           sizeof(solutions::NormalModes), sizeof(reduction::CraigBamptonOptions),
                           sizeof(reduction::CraigBamptonBasis), sizeof(std::string), sizeof(Eigen::Index)});
}

}  // namespace seflex::parallel
