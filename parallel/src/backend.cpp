// The plugin's entry point (backend.hpp): the table of the distributed backend's functions.
#include "seflex/parallel/backend.hpp"

#include "seflex/parallel/mumps_factorization.hpp"
#include "seflex/parallel/partitioned_craig_bampton.hpp"
#include "seflex/parallel/session.hpp"
#include "seflex/parallel/slepc_eigensolver.hpp"

namespace seflex::parallel {
namespace {

Backend make_table() {
  Backend b;
  b.fingerprint = backend_fingerprint();
  b.open_session = [] { return std::make_unique<Session>(); };
  b.slepc_eigenproblem = &slepc_eigenproblem;
  b.make_mumps_factorization = &make_mumps_factorization;
  b.partition_refusal = &partition_refusal;
  b.solve_normal_modes_partitioned = &solve_normal_modes_partitioned;
  b.assemble_partitioned = [](fem::Model& model, const fem::ConstraintOptions& options, fem::GlobalMatrices* whole) {
    return std::make_shared<PartitionedSystem>(assemble_partitioned(model, options, whole));
  };
  b.craig_bampton_partitioned = &craig_bampton_partitioned;
  b.sum_over_ranks = &sum_over_ranks;
  return b;
}

}  // namespace
}  // namespace seflex::parallel

extern "C" __attribute__((visibility("default"))) const seflex::parallel::Backend* seflex_parallel_backend() {
  static const seflex::parallel::Backend table = seflex::parallel::make_table();
  return &table;
}
