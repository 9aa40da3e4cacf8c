// The plugin's entry point (backend.hpp): the table of the distributed backend's functions.
#include "seflex/parallel/backend.hpp"

#include "seflex/parallel/mumps_factorization.hpp"
#include "seflex/parallel/partitioned_craig_bampton.hpp"
#include "seflex/parallel/slepc_eigensolver.hpp"

namespace seflex::parallel {
namespace {

Backend make_table() {
  Backend b;
  b.fingerprint = backend_fingerprint();
  b.open_session = [] { return std::make_unique<Session>(); };
  b.slepc_eigenproblem = [](const reduction::SparseMatrixd& K, const reduction::SparseMatrixd& M,
                            const reduction::EigenOptions& options) { return slepc_eigenproblem(K, M, options); };
  b.make_mumps_factorization = [] { return make_mumps_factorization(); };
  b.partition_refusal = [](const fem::Model& model, std::optional<int> mpc_set) { return partition_refusal(model, mpc_set); };
  b.solve_normal_modes_partitioned = [](fem::Model& model, const reduction::ModesOptions& options, PartitionStats* stats) {
    return solve_normal_modes_partitioned(model, options, stats);
  };
  b.assemble_partitioned = [](fem::Model& model, const fem::ConstraintOptions& options, fem::GlobalMatrices* whole) {
    return std::make_shared<PartitionedSystem>(assemble_partitioned(model, options, whole));
  };
  b.craig_bampton_partitioned = [](const PartitionedSystem& system, const std::vector<Eigen::Index>& boundary,
                                   const reduction::CraigBamptonOptions& options) {
    return craig_bampton_partitioned(system, boundary, options);
  };
  return b;
}

}  // namespace
}  // namespace seflex::parallel

extern "C" __attribute__((visibility("default"))) const seflex::parallel::Backend* seflex_parallel_backend() {
  static const seflex::parallel::Backend table = seflex::parallel::make_table();
  return &table;
}
