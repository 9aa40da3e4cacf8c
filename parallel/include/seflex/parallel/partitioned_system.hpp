#pragma once
// Partitioned assembly: each rank computes only its own elements' matrices (element_partition.hpp)
// and adds them into distributed PETSc matrices of the constrained f-set (docs/distributed.md).
//
//   K_pp = P^T (sum_r K_ff^(r)) P,   M_pp likewise,
// where K_ff^(r) is rank r's elements' share of K_ff (fem::assemble of the model with only those
// elements, the free dofs kept) and P renumbers the f-set so that every rank's rows are contiguous:
// the free dofs of the nodes rank r owns, in increasing g order, are rows [row_begin[r], row_begin[r+1]).
// Off-rank entries (an element on a boundary node owned by another rank) go through PETSc's stash
// (MatSetValues ADD_VALUES); the matrices are symmetric MATSBAIJ (upper triangle), K's pattern holds
// M's (K - sigma M is formed without a new pattern).
//
// Constraints: only per-dof ones (GRID PS, SPC/SPC1 of the case control, fixed dofs, AUTOSPC).
// AUTOSPC needs each grid's diagonal block of K: every rank adds its elements' blocks, the blocks are
// summed over the ranks (MPI_Allreduce, 6 x 6 per grid) and fem::apply_constraints runs on that
// block-diagonal K, which gives the same f-set as on the whole K when no dof is dependent.
// Models with dependent dofs (RBE2, RBAR, RBE3, MPC) are not partitioned (partition_refusal says
// why): their elimination T^T K T needs the whole model on one rank (the replicated path).
//
// Collective on PETSC_COMM_WORLD; needs a parallel::Session. While it assembles, `model`'s element
// vectors are swapped for the rank's own elements and restored before it returns (also on throw).
// An InputError from one rank's elements (e.g. an undefined property) is rethrown on that rank; the
// others throw PeerFailure (session.hpp), so that no rank waits for them in a collective call.
#include <Eigen/SparseCore>
#include <memory>
#include <optional>
#include <string>
#include <vector>

#include "seflex/fem/constraints.hpp"
#include "seflex/fem/model.hpp"

namespace seflex::parallel {

namespace detail {
struct PetscPencil;  // the PETSc matrices (petsc_support.hpp)
}

class PartitionedSystem {
 public:
  PartitionedSystem();
  ~PartitionedSystem();
  PartitionedSystem(PartitionedSystem&&) noexcept;
  PartitionedSystem& operator=(PartitionedSystem&&) noexcept;

  fem::DofMap dofs;
  std::vector<Eigen::Index> f_to_g;     ///< f index (serial numbering: increasing g) -> g dof
  std::vector<Eigen::Index> f_to_p;     ///< f index -> row of the distributed matrices
  std::vector<Eigen::Index> p_to_f;     ///< inverse of f_to_p
  std::vector<Eigen::Index> row_begin;  ///< P + 1 entries: rank r owns rows [row_begin[r], row_begin[r+1])
  std::size_t local_elements = 0;       ///< elements this rank assembled
  std::size_t total_elements = 0;       ///< elements of the model

  Eigen::Index n_free() const { return static_cast<Eigen::Index>(f_to_g.size()); }

  /// Collective. The whole K_ff (or M_ff) in the serial f numbering, both triangles, on every rank:
  /// for tests and small models only (it is what the partitioned assembly avoids).
  Eigen::SparseMatrix<double> gather_K_ff() const;
  Eigen::SparseMatrix<double> gather_M_ff() const;

  const detail::PetscPencil& pencil() const { return *pencil_; }
  detail::PetscPencil& pencil() { return *pencil_; }

 private:
  std::unique_ptr<detail::PetscPencil> pencil_;
};

/// Why `model` cannot be assembled by partition (the RBE2/RBAR/RBE3/MPC, ASET/OMIT or DMIG cards that
/// need the replicated path), or nullopt. `mpc_set`: the case control's MPC selection.
std::optional<std::string> partition_refusal(const fem::Model& model, std::optional<int> mpc_set);

/// Collective: the partitioned f-set matrices of `model` (finalized) under the per-dof constraints
/// of `options` (its mpc_set must select nothing). Throws InvariantError if partition_refusal
/// refuses the model, InputError from assembly or constraints (see above for the other ranks).
/// `whole` (optional, for reduce_to_superelement's mass properties and FE mass): the whole g-set M
/// gathered on every rank (the ranks' shares summed) and, as K, only each grid's summed diagonal
/// block (what apply_constraints needs without dependent dofs).
PartitionedSystem assemble_partitioned(fem::Model& model, const fem::ConstraintOptions& options,
                                       fem::GlobalMatrices* whole = nullptr);

}  // namespace seflex::parallel
