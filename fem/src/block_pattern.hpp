#pragma once
// Internal: a node-block sparsity pattern built from element connectivity, and scattering of
// element matrices into it (one pass, no triplets). Nodes follow DofMap's numbering (grids with 6
// dofs, then scalar points with 1).
#include <Eigen/SparseCore>
#include <cstdint>
#include <vector>

#include "seflex/common/error.hpp"
#include "seflex/fem/dof_map.hpp"

namespace seflex::fem::detail {

/// Element connectivity: nodes of element e are nodes[ptr[e] .. ptr[e+1]).
struct Connectivity {
  std::vector<std::int64_t> ptr{0};
  std::vector<std::int32_t> nodes;
  void add(std::initializer_list<std::int32_t> n) { add(n.begin(), n.end()); }
  template <class It>
  void add(It first, It last) {
    nodes.insert(nodes.end(), first, last);
    ptr.push_back(static_cast<std::int64_t>(nodes.size()));
  }
};

class BlockPattern {
 public:
  /// Node adjacency from the connectivity (each node is always adjacent to itself); with
  /// self_only, only each node's own block (block-diagonal pattern; scatter then ignores the
  /// off-diagonal node blocks, which must be zero, as in lumped mass matrices).
  BlockPattern(const DofMap& dofs, const Connectivity& conn, bool self_only);

  /// Make A a compressed n x n matrix with this pattern and zero values (in place: Eigen 3.4's
  /// SparseMatrix copies on assignment from a temporary).
  void make_matrix(Eigen::SparseMatrix<double>& A) const;

  /// A(dofs of node a, dofs of node b) += block, for grid nodes (6 x 6 blocks) in element order:
  /// Ke is 6N x 6N on `nodes` (N grids).
  template <int N>
  void scatter(const std::int32_t* nodes, const Eigen::Matrix<double, 6 * N, 6 * N>& Ke,
               Eigen::SparseMatrix<double>& A) const {
    const int* outer = A.outerIndexPtr();
    double* val = A.valuePtr();
    for (int b = 0; b < N; ++b) {
      const std::int32_t J = nodes[b];
      for (int a = 0; a < N; ++a) {
        if (self_only_ && a != b) {  // block-diagonal pattern: off-diagonal node blocks must be zero
          SEFLEX_DEBUG_ASSERT((Ke.template block<6, 6>(6 * a, 6 * b).isZero(0.0)), "coupling outside the pattern");
          continue;
        }
        const std::int64_t off = row_offset(J, nodes[a]);
        for (int c = 0; c < 6; ++c) {
          double* col = val + outer[6 * J + c] + off;
          for (int r = 0; r < 6; ++r) col[r] += Ke(6 * a + r, 6 * b + c);
        }
      }
    }
  }

  /// A(translations of node a, translations of node b) += 3 x 3 block, for grid nodes in element
  /// order: K3 is 3N x 3N on the translations of `nodes` (N grids; solid elements).
  void scatter_translations(const std::int32_t* nodes, int N, const Eigen::MatrixXd& K3,
                            Eigen::SparseMatrix<double>& A) const {
    const int* outer = A.outerIndexPtr();
    double* val = A.valuePtr();
    for (int b = 0; b < N; ++b) {
      const std::int32_t J = nodes[b];
      for (int a = 0; a < N; ++a) {
        if (self_only_ && a != b) {
          SEFLEX_DEBUG_ASSERT((K3.block<3, 3>(3 * a, 3 * b).isZero(0.0)), "coupling outside the pattern");
          continue;
        }
        const std::int64_t off = row_offset(J, nodes[a]);
        for (int c = 0; c < 3; ++c) {
          double* col = val + outer[6 * J + c] + off;
          for (int r = 0; r < 3; ++r) col[r] += K3(3 * a + r, 3 * b + c);
        }
      }
    }
  }

 private:
  // Offset of node I's rows within any column of node J.
  std::int64_t row_offset(std::int32_t J, std::int32_t I) const;

  DofMap dofs_;
  bool self_only_ = false;
  std::vector<std::int64_t> adj_ptr_;
  std::vector<std::int32_t> adj_;      // sorted neighbours of each node
  std::vector<std::int64_t> adj_off_;  // row offset of each neighbour within the node's columns
};

/// A(row, col) += v for an entry that exists in A's pattern (binary search in the column).
void add_entry(Eigen::SparseMatrix<double>& A, Eigen::Index row, Eigen::Index col, double v);

}  // namespace seflex::fem::detail
