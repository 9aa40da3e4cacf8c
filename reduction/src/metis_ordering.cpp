// METIS nested dissection on the supervariable-compressed graph of a symmetric sparse matrix.
#include "metis_ordering.hpp"

#include <metis.h>

#include <algorithm>
#include <numeric>
#include <string>

namespace seflex::reduction {
namespace {

/// Symmetric adjacency (CSR, no diagonal) of the lower triangle of A; every list comes out sorted
/// because columns are swept in increasing order.
void symmetric_adjacency(const SparseMatrixd& A, std::vector<std::int64_t>& xadj, std::vector<idx_t>& adjncy) {
  const Eigen::Index n = A.cols();
  xadj.assign(static_cast<std::size_t>(n) + 1, 0);
  for (Eigen::Index j = 0; j < n; ++j)
    for (SparseMatrixd::InnerIterator it(A, j); it; ++it)
      if (it.row() > j) {
        ++xadj[static_cast<std::size_t>(j) + 1];
        ++xadj[static_cast<std::size_t>(it.row()) + 1];
      }
  std::partial_sum(xadj.begin(), xadj.end(), xadj.begin());
  adjncy.resize(static_cast<std::size_t>(xadj.back()));
  std::vector<std::int64_t> fill(xadj.begin(), xadj.end() - 1);
  for (Eigen::Index j = 0; j < n; ++j)
    for (SparseMatrixd::InnerIterator it(A, j); it; ++it)
      if (it.row() > j) {
        adjncy[static_cast<std::size_t>(fill[static_cast<std::size_t>(j)]++)] = static_cast<idx_t>(it.row());
        adjncy[static_cast<std::size_t>(fill[static_cast<std::size_t>(it.row())]++)] = static_cast<idx_t>(j);
      }
}

}  // namespace

std::vector<std::int64_t> nested_dissection_ordering(const SparseMatrixd& A) {
  SEFLEX_DEMAND(A.rows() == A.cols(), "ordering: matrix must be square");
  const auto n = static_cast<std::size_t>(A.cols());
  std::vector<std::int64_t> perm(n);
  std::iota(perm.begin(), perm.end(), 0);
  if (n < 2) return perm;

  std::vector<std::int64_t> xadj;
  std::vector<idx_t> adjncy;
  symmetric_adjacency(A, xadj, adjncy);

  // Supervariables: columns whose closed neighbourhoods (adjacency plus self) are identical.
  auto closed_hash = [&](std::size_t j) {
    std::uint64_t h = j;
    for (auto k = xadj[j]; k < xadj[j + 1]; ++k) h += static_cast<std::uint64_t>(adjncy[static_cast<std::size_t>(k)]);
    return h * 1000003u + static_cast<std::uint64_t>(xadj[j + 1] - xadj[j]);
  };
  auto same_closed = [&](std::size_t a, std::size_t b) {
    if (xadj[a + 1] - xadj[a] != xadj[b + 1] - xadj[b]) return false;
    // closed(a) == closed(b)  <=>  adj(a) \ {b} == adj(b) \ {a} with b in adj(a)
    std::size_t ia = static_cast<std::size_t>(xadj[a]), ib = static_cast<std::size_t>(xadj[b]);
    const auto ea = static_cast<std::size_t>(xadj[a + 1]), eb = static_cast<std::size_t>(xadj[b + 1]);
    bool b_in_a = false;
    while (ia < ea || ib < eb) {
      if (ia < ea && static_cast<std::size_t>(adjncy[ia]) == b) { b_in_a = true; ++ia; continue; }
      if (ib < eb && static_cast<std::size_t>(adjncy[ib]) == a) { ++ib; continue; }
      if (ia >= ea || ib >= eb || adjncy[ia] != adjncy[ib]) return false;
      ++ia, ++ib;
    }
    return b_in_a;
  };
  std::vector<std::uint64_t> hash(n);
  for (std::size_t j = 0; j < n; ++j) hash[j] = closed_hash(j);
  std::vector<std::size_t> by_hash(n);
  std::iota(by_hash.begin(), by_hash.end(), 0);
  std::sort(by_hash.begin(), by_hash.end(), [&](std::size_t a, std::size_t b) { return hash[a] != hash[b] ? hash[a] < hash[b] : a < b; });
  constexpr std::size_t kNone = static_cast<std::size_t>(-1);
  std::vector<std::size_t> rep(n, kNone);  // representative column of each column's supervariable
  for (std::size_t s = 0; s < n;) {
    std::size_t e = s;
    while (e < n && hash[by_hash[e]] == hash[by_hash[s]]) ++e;
    for (std::size_t a = s; a < e; ++a) {
      const std::size_t ja = by_hash[a];
      if (rep[ja] != kNone) continue;
      rep[ja] = ja;
      for (std::size_t b = a + 1; b < e; ++b)
        if (rep[by_hash[b]] == kNone && same_closed(ja, by_hash[b])) rep[by_hash[b]] = ja;
    }
    s = e;
  }
  std::vector<idx_t> vertex(n);  // compressed vertex of each column
  idx_t nv = 0;
  for (std::size_t j = 0; j < n; ++j)
    if (rep[j] == j) vertex[j] = nv++;
  for (std::size_t j = 0; j < n; ++j) vertex[j] = vertex[rep[j]];

  // Compressed graph: adjacency of each representative mapped to vertices, minus itself.
  std::vector<idx_t> cx(static_cast<std::size_t>(nv) + 1, 0), cadj, vwgt(static_cast<std::size_t>(nv), 0);
  for (std::size_t j = 0; j < n; ++j) ++vwgt[static_cast<std::size_t>(vertex[j])];
  cadj.reserve(adjncy.size() / std::max<std::size_t>(1, n / static_cast<std::size_t>(nv)));
  std::vector<idx_t> mark(static_cast<std::size_t>(nv), -1);
  for (std::size_t j = 0; j < n; ++j) {
    if (rep[j] != j) continue;
    const idx_t v = vertex[j];
    mark[static_cast<std::size_t>(v)] = v;
    for (auto k = xadj[j]; k < xadj[j + 1]; ++k) {
      const idx_t w = vertex[static_cast<std::size_t>(adjncy[static_cast<std::size_t>(k)])];
      if (mark[static_cast<std::size_t>(w)] == v) continue;
      mark[static_cast<std::size_t>(w)] = v;
      cadj.push_back(w);
    }
    cx[static_cast<std::size_t>(v) + 1] = static_cast<idx_t>(cadj.size());
  }
  std::vector<idx_t>().swap(adjncy);
  std::vector<std::int64_t>().swap(xadj);

  std::vector<idx_t> mperm(static_cast<std::size_t>(nv)), miperm(static_cast<std::size_t>(nv));
  if (nv > 1) {
    idx_t options[METIS_NOPTIONS];
    METIS_SetDefaultOptions(options);
    const int status = METIS_NodeND(&nv, cx.data(), cadj.empty() ? nullptr : cadj.data(), vwgt.data(), options,
                                    mperm.data(), miperm.data());
    if (status == METIS_ERROR_MEMORY) throw std::bad_alloc();
    SEFLEX_DEMAND(status == METIS_OK, "METIS_NodeND failed (status " + std::to_string(status) + ")");
  } else {
    mperm[0] = miperm[0] = 0;
  }
  // METIS_NodeND: mperm[k] is the vertex eliminated k-th (miperm is its inverse). Expand each
  // vertex into its columns, kept together and in their original order.
  const std::vector<idx_t>& order = mperm;
  std::vector<std::int64_t> start(static_cast<std::size_t>(nv) + 1, 0);
  for (idx_t k = 0; k < nv; ++k) start[static_cast<std::size_t>(k) + 1] = start[static_cast<std::size_t>(k)] + vwgt[static_cast<std::size_t>(order[static_cast<std::size_t>(k)])];
  std::vector<std::int64_t> position_of_vertex(static_cast<std::size_t>(nv));
  for (idx_t k = 0; k < nv; ++k) position_of_vertex[static_cast<std::size_t>(order[static_cast<std::size_t>(k)])] = start[static_cast<std::size_t>(k)];
  for (std::size_t j = 0; j < n; ++j) perm[static_cast<std::size_t>(position_of_vertex[static_cast<std::size_t>(vertex[j])]++)] = static_cast<std::int64_t>(j);
  return perm;
}

}  // namespace seflex::reduction
