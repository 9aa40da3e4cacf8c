// METIS nested dissection on the supervariable-compressed graph of a symmetric sparse matrix.
#include "metis_ordering.hpp"

#include <metis.h>

#include <algorithm>
#include <future>
#include <numeric>
#include <string>
#include <thread>

namespace seflex::linalg {
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

/// Components this small are ordered as they come (METIS is for the large ones).
constexpr idx_t kSmallComponent = 8;

/// METIS_NodeND of one graph (CSR xadj/adjncy, vertex weights): order[k] = vertex eliminated k-th.
std::vector<idx_t> metis_order(std::vector<idx_t>& xadj, std::vector<idx_t>& adjncy, std::vector<idx_t>& vwgt) {
  idx_t nv = static_cast<idx_t>(vwgt.size());
  std::vector<idx_t> order(static_cast<std::size_t>(nv)), inverse(static_cast<std::size_t>(nv));
  if (nv < kSmallComponent || adjncy.empty()) {
    std::iota(order.begin(), order.end(), 0);
    return order;
  }
  idx_t options[METIS_NOPTIONS];
  METIS_SetDefaultOptions(options);
  const int status = METIS_NodeND(&nv, xadj.data(), adjncy.data(), vwgt.data(), options, order.data(), inverse.data());
  if (status == METIS_ERROR_MEMORY) throw std::bad_alloc();
  SEFLEX_DEMAND(status == METIS_OK, "METIS_NodeND failed (status " + std::to_string(status) + ")");
  return order;
}

/// Nested dissection of a graph that may fall into independent parts (a flat shell's membrane and
/// bending dofs, disconnected bodies): each connected component is ordered on its own and they are
/// eliminated one after another (the factor is block diagonal), the large ones on two threads at
/// once. The result does not depend on the threads: each component keeps its place in the order.
std::vector<idx_t> component_order(const std::vector<idx_t>& cx, const std::vector<idx_t>& cadj, const std::vector<idx_t>& vwgt) {
  const auto nv = static_cast<idx_t>(vwgt.size());
  std::vector<idx_t> component(static_cast<std::size_t>(nv), -1), stack;
  std::vector<std::vector<idx_t>> members;  // vertices of each component, ascending
  for (idx_t v0 = 0; v0 < nv; ++v0) {
    if (component[static_cast<std::size_t>(v0)] >= 0) continue;
    const auto c = static_cast<idx_t>(members.size());
    members.emplace_back();
    component[static_cast<std::size_t>(v0)] = c;
    stack.assign(1, v0);
    while (!stack.empty()) {
      const idx_t v = stack.back();
      stack.pop_back();
      members.back().push_back(v);
      for (idx_t k = cx[static_cast<std::size_t>(v)]; k < cx[static_cast<std::size_t>(v) + 1]; ++k) {
        const idx_t w = cadj[static_cast<std::size_t>(k)];
        if (component[static_cast<std::size_t>(w)] < 0) {
          component[static_cast<std::size_t>(w)] = c;
          stack.push_back(w);
        }
      }
    }
    std::sort(members.back().begin(), members.back().end());
  }
  std::vector<idx_t> local(static_cast<std::size_t>(nv));  // index of each vertex within its component
  for (const auto& m : members)
    for (std::size_t i = 0; i < m.size(); ++i) local[static_cast<std::size_t>(m[i])] = static_cast<idx_t>(i);

  // Order component c: its subgraph in local numbering, then METIS; returns global vertices.
  auto order_component = [&](std::size_t c) {
    const std::vector<idx_t>& m = members[c];
    std::vector<idx_t> x(m.size() + 1, 0), adj, w(m.size());
    for (std::size_t i = 0; i < m.size(); ++i) {
      const auto v = static_cast<std::size_t>(m[i]);
      w[i] = vwgt[v];
      for (idx_t k = cx[v]; k < cx[v + 1]; ++k) adj.push_back(local[static_cast<std::size_t>(cadj[static_cast<std::size_t>(k)])]);
      x[i + 1] = static_cast<idx_t>(adj.size());
    }
    std::vector<idx_t> order = metis_order(x, adj, w);
    for (idx_t& v : order) v = m[static_cast<std::size_t>(v)];
    return order;
  };
  std::vector<std::vector<idx_t>> orders(members.size());
  // Components by size, largest first; the large ones alternate between this thread and a helper.
  std::vector<std::size_t> by_size(members.size());
  std::iota(by_size.begin(), by_size.end(), 0);
  std::stable_sort(by_size.begin(), by_size.end(), [&](std::size_t a, std::size_t b) { return members[a].size() > members[b].size(); });
  const bool two_threads = members.size() > 1 && members[by_size[1]].size() >= 1000 && std::thread::hardware_concurrency() > 1;
  if (two_threads) {
    std::size_t load_here = 0, load_there = 0;
    std::vector<std::size_t> there;
    for (std::size_t c : by_size) {
      if (load_there < load_here) {
        there.push_back(c);
        load_there += members[c].size();
      } else {
        load_here += members[c].size();
      }
    }
    auto helper = std::async(std::launch::async, [&] {
      for (std::size_t c : there) orders[c] = order_component(c);
    });
    std::vector<char> is_there(members.size(), 0);
    for (std::size_t c : there) is_there[c] = 1;
    for (std::size_t c : by_size)
      if (!is_there[c]) orders[c] = order_component(c);
    helper.get();
  } else {
    for (std::size_t c = 0; c < members.size(); ++c) orders[c] = order_component(c);
  }
  std::vector<idx_t> order;
  order.reserve(static_cast<std::size_t>(nv));
  for (const auto& o : orders) order.insert(order.end(), o.begin(), o.end());
  return order;
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
  // Nearly identical neighbours: on a regular mesh some couplings are exact zeros (pruned), so the
  // dofs of one node differ in a few entries and the exact test above leaves two or three vertices
  // per node where one would do. Adjacent columns close in the numbering (the dofs of one grid) whose
  // closed neighbourhoods share at least kSimilar of their union are merged as well; neighbouring
  // nodes of a mesh share about half, and decoupled dof sets (a flat shell's membrane and bending
  // dofs) are not adjacent, so neither is merged. A merged vertex is eliminated as one block, which
  // the supernodal factor does anyway.
  constexpr std::size_t kWindow = 8;
  constexpr double kSimilar = 0.75;
  auto root = [&](std::size_t j) {
    while (rep[j] != j) j = rep[j] = rep[rep[j]];
    return j;
  };
  auto similar = [&](std::size_t a, std::size_t b) {  // b in adj(a)
    std::size_t ia = static_cast<std::size_t>(xadj[a]), ib = static_cast<std::size_t>(xadj[b]), common = 2;
    const auto ea = static_cast<std::size_t>(xadj[a + 1]), eb = static_cast<std::size_t>(xadj[b + 1]);
    while (ia < ea && ib < eb) {
      if (adjncy[ia] < adjncy[ib]) ++ia;
      else if (adjncy[ib] < adjncy[ia]) ++ib;
      else ++common, ++ia, ++ib;
    }
    const std::size_t all = static_cast<std::size_t>(ea - xadj[a] + eb - xadj[b]) + 2 - common;
    return static_cast<double>(common) >= kSimilar * static_cast<double>(all);
  };
  for (std::size_t j = 0; j < n; ++j)
    for (auto k = xadj[j]; k < xadj[j + 1]; ++k) {
      const auto i = static_cast<std::size_t>(adjncy[static_cast<std::size_t>(k)]);
      if (i <= j || i > j + kWindow) continue;
      const std::size_t ri = root(i), rj = root(j);
      if (ri != rj && similar(j, i)) rep[std::max(ri, rj)] = std::min(ri, rj);
    }
  for (std::size_t j = 0; j < n; ++j) rep[j] = root(j);

  std::vector<idx_t> vertex(n);  // compressed vertex of each column
  idx_t nv = 0;
  for (std::size_t j = 0; j < n; ++j)
    if (rep[j] == j) vertex[j] = nv++;
  for (std::size_t j = 0; j < n; ++j) vertex[j] = vertex[rep[j]];

  // Compressed graph: the union of the adjacencies of each vertex's columns, minus itself.
  std::vector<idx_t> cx(static_cast<std::size_t>(nv) + 1, 0), cadj, vwgt(static_cast<std::size_t>(nv), 0);
  for (std::size_t j = 0; j < n; ++j) ++vwgt[static_cast<std::size_t>(vertex[j])];
  std::vector<std::size_t> first(static_cast<std::size_t>(nv) + 1, 0), members(n);  // columns by vertex
  for (std::size_t v = 0; v < static_cast<std::size_t>(nv); ++v) first[v + 1] = first[v] + static_cast<std::size_t>(vwgt[v]);
  {
    std::vector<std::size_t> fill(first.begin(), first.end() - 1);
    for (std::size_t j = 0; j < n; ++j) members[fill[static_cast<std::size_t>(vertex[j])]++] = j;
  }
  cadj.reserve(adjncy.size() / std::max<std::size_t>(1, n / static_cast<std::size_t>(nv)));
  std::vector<idx_t> mark(static_cast<std::size_t>(nv), -1);
  for (idx_t v = 0; v < nv; ++v) {
    mark[static_cast<std::size_t>(v)] = v;
    for (std::size_t m = first[static_cast<std::size_t>(v)]; m < first[static_cast<std::size_t>(v) + 1]; ++m) {
      const std::size_t j = members[m];
      for (auto k = xadj[j]; k < xadj[j + 1]; ++k) {
        const idx_t w = vertex[static_cast<std::size_t>(adjncy[static_cast<std::size_t>(k)])];
        if (mark[static_cast<std::size_t>(w)] == v) continue;
        mark[static_cast<std::size_t>(w)] = v;
        cadj.push_back(w);
      }
    }
    cx[static_cast<std::size_t>(v) + 1] = static_cast<idx_t>(cadj.size());
  }
  std::vector<idx_t>().swap(adjncy);
  std::vector<std::int64_t>().swap(xadj);

  // order[k] is the vertex eliminated k-th. Expand each vertex into its columns, kept together and
  // in their original order.
  const std::vector<idx_t> order = component_order(cx, cadj, vwgt);
  std::vector<std::int64_t> start(static_cast<std::size_t>(nv) + 1, 0);
  for (idx_t k = 0; k < nv; ++k) start[static_cast<std::size_t>(k) + 1] = start[static_cast<std::size_t>(k)] + vwgt[static_cast<std::size_t>(order[static_cast<std::size_t>(k)])];
  std::vector<std::int64_t> position_of_vertex(static_cast<std::size_t>(nv));
  for (idx_t k = 0; k < nv; ++k) position_of_vertex[static_cast<std::size_t>(order[static_cast<std::size_t>(k)])] = start[static_cast<std::size_t>(k)];
  for (std::size_t j = 0; j < n; ++j) perm[static_cast<std::size_t>(position_of_vertex[static_cast<std::size_t>(vertex[j])]++)] = static_cast<std::int64_t>(j);
  return perm;
}

}  // namespace seflex::linalg
