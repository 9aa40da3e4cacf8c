#pragma once
// Fill-reducing ordering shared by the factorisation backends (the only user of metis.h in linalg/).
#include <cstdint>
#include <vector>

#include "seflex/linalg/sparse_factorization.hpp"

namespace seflex::linalg {

/// METIS nested-dissection ordering of the symmetric pattern of A (lower triangle read, diagonal
/// ignored). Columns with identical closed adjacency (the dofs of one FE node) are merged into one
/// weighted vertex first, so METIS orders the node graph, not the six-times larger dof graph.
/// Returns perm with perm[k] = the column of A eliminated k-th.
std::vector<std::int64_t> nested_dissection_ordering(const SparseMatrixd& A);

}  // namespace seflex::linalg
