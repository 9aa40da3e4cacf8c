#include "block_pattern.hpp"

#include <algorithm>

#include "seflex/common/error.hpp"

namespace seflex::fem::detail {

BlockPattern::BlockPattern(const DofMap& dofs, const Connectivity& conn, bool self_only)
    : dofs_(dofs), self_only_(self_only) {
  const std::int64_t n = dofs.n_nodes();
  const std::int64_t n_elem = static_cast<std::int64_t>(conn.ptr.size()) - 1;
  adj_ptr_.assign(static_cast<std::size_t>(n + 1), 0);
  if (self_only) {
    adj_.resize(static_cast<std::size_t>(n));
    for (std::int64_t i = 0; i < n; ++i) {
      adj_[i] = static_cast<std::int32_t>(i);
      adj_ptr_[i + 1] = i + 1;
    }
  } else {
    // node -> elements incidence (CSR)
    std::vector<std::int64_t> inc_ptr(static_cast<std::size_t>(n + 1), 0);
    for (std::int32_t v : conn.nodes) ++inc_ptr[v + 1];
    for (std::int64_t i = 0; i < n; ++i) inc_ptr[i + 1] += inc_ptr[i];
    std::vector<std::int32_t> inc(conn.nodes.size());
    {
      std::vector<std::int64_t> fill(inc_ptr.begin(), inc_ptr.end() - 1);
      for (std::int64_t e = 0; e < n_elem; ++e)
        for (std::int64_t k = conn.ptr[e]; k < conn.ptr[e + 1]; ++k)
          inc[fill[conn.nodes[k]]++] = static_cast<std::int32_t>(e);
    }
    // neighbours: union of the nodes of the incident elements, plus the node itself
    std::vector<std::int32_t> buf;
    adj_.reserve(conn.nodes.size() * 3 + static_cast<std::size_t>(n));
    for (std::int64_t i = 0; i < n; ++i) {
      buf.clear();
      buf.push_back(static_cast<std::int32_t>(i));
      for (std::int64_t k = inc_ptr[i]; k < inc_ptr[i + 1]; ++k) {
        const std::int32_t e = inc[k];
        buf.insert(buf.end(), conn.nodes.begin() + conn.ptr[e], conn.nodes.begin() + conn.ptr[e + 1]);
      }
      std::sort(buf.begin(), buf.end());
      buf.erase(std::unique(buf.begin(), buf.end()), buf.end());
      adj_.insert(adj_.end(), buf.begin(), buf.end());
      adj_ptr_[i + 1] = static_cast<std::int64_t>(adj_.size());
    }
  }
  adj_off_.resize(adj_.size());
  for (std::int64_t i = 0; i < n; ++i) {
    std::int64_t off = 0;
    for (std::int64_t k = adj_ptr_[i]; k < adj_ptr_[i + 1]; ++k) {
      adj_off_[k] = off;
      off += dofs_.node_dof_count(adj_[k]);
    }
  }
}

void BlockPattern::make_matrix(Eigen::SparseMatrix<double>& A) const {
  const Eigen::Index n = dofs_.size();
  // column lengths: per node, the dofs of all neighbours
  std::int64_t nnz = 0;
  for (Eigen::Index i = 0; i < dofs_.n_nodes(); ++i) {
    const std::int64_t k = adj_ptr_[i + 1] - 1;
    const std::int64_t len = adj_off_[k] + dofs_.node_dof_count(adj_[k]);
    nnz += len * dofs_.node_dof_count(i);
  }
  SEFLEX_DEMAND(nnz < std::int64_t(2147483647), "sparse matrix too large for 32-bit indices");
  A.resize(n, n);
  A.resizeNonZeros(static_cast<Eigen::Index>(nnz));
  int* outer = A.outerIndexPtr();
  int* inner = A.innerIndexPtr();
  std::int64_t pos = 0;
  for (Eigen::Index i = 0; i < dofs_.n_nodes(); ++i) {
    for (int c = 0; c < dofs_.node_dof_count(i); ++c) {
      outer[dofs_.node_first_dof(i) + c] = static_cast<int>(pos);
      for (std::int64_t k = adj_ptr_[i]; k < adj_ptr_[i + 1]; ++k) {
        const Eigen::Index f = dofs_.node_first_dof(adj_[k]);
        for (int r = 0; r < dofs_.node_dof_count(adj_[k]); ++r) inner[pos++] = static_cast<int>(f + r);
      }
    }
  }
  outer[n] = static_cast<int>(pos);
  std::fill(A.valuePtr(), A.valuePtr() + nnz, 0.0);
}

std::int64_t BlockPattern::row_offset(std::int32_t J, std::int32_t I) const {
  const auto first = adj_.begin() + adj_ptr_[J], last = adj_.begin() + adj_ptr_[J + 1];
  const auto it = std::lower_bound(first, last, I);
  SEFLEX_DEMAND(it != last && *it == I, "node pair missing from the sparsity pattern");
  return adj_off_[static_cast<std::size_t>(it - adj_.begin())];
}

void add_entry(Eigen::SparseMatrix<double>& A, Eigen::Index row, Eigen::Index col, double v) {
  const int* inner = A.innerIndexPtr();
  const int b = A.outerIndexPtr()[col], e = A.outerIndexPtr()[col + 1];
  const int* it = std::lower_bound(inner + b, inner + e, static_cast<int>(row));
  SEFLEX_DEMAND(it != inner + e && *it == row, "entry missing from the sparsity pattern");
  A.valuePtr()[it - inner] += v;
}

}  // namespace seflex::fem::detail
