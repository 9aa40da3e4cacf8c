#pragma once
// Partition of a model's elements among P ranks (METIS on the element graph) and the nodes each
// rank owns, for the partitioned assembly (partitioned_system.hpp, docs/distributed.md).
//
// - Mesh elements (CBAR/CBEAM, CROD/CONROD, CQUAD4/CTRIA3, CHEXA/CPENTA/CTETRA, CBUSH) are split by
//   METIS_PartMeshDual (two elements are neighbours when they share a grid; minimises the grids
//   shared between parts with balanced element counts). Point elements (CONM1/CONM2, CELASi,
//   CMASSi) go round-robin by their index in the model (they add one block each).
// - Node n is owned by the part of the first mesh element (in model order) that uses it; nodes no
//   mesh element uses (scalar points, mass-only grids) go round-robin by node index.
// - Deterministic (METIS with its fixed seed; the same model gives the same partition on every
//   rank), so every rank computes it itself and nothing is communicated. parts == 1: everything 0.
// Grid ids that do not exist are skipped here (assembly reports them).
#include <cstddef>
#include <vector>

#include "seflex/fem/model.hpp"

namespace seflex::parallel {

struct ElementPartition {
  int parts = 1;
  /// Owning part of each element, indexed like the model's vectors of the same name.
  std::vector<int> bars, rods, shells, solids, bushes, shear_panels, bends, shells8, conm2, conm1, springs, scalar_masses;
  /// Owning part of each node (grid index, then scalar points: fem::DofMap's node numbering).
  std::vector<int> node_owner;

  /// Number of elements (all kinds) owned by `part`; total() over all parts.
  std::size_t count(int part) const;
  std::size_t total() const;
};

/// Throws InvariantError if parts < 1 or METIS fails; the model must be finalized.
ElementPartition partition_elements(const fem::Model& model, int parts);

}  // namespace seflex::parallel
