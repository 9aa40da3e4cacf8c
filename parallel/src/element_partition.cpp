// METIS partition of the elements and node ownership (element_partition.hpp).
#include "seflex/parallel/element_partition.hpp"

#include <metis.h>

#include <string>
#include <vector>

#include "seflex/common/error.hpp"

namespace seflex::parallel {
namespace {

std::size_t owned(const std::vector<int>& v, int part) {
  std::size_t n = 0;
  for (int p : v) n += p == part;
  return n;
}

/// Element -> node lists of the mesh elements (CSR), in the order bars, rods, shells, solids, bushes,
/// shear panels, bends, CTRIA6/CQUAD8.
struct MeshConnectivity {
  std::vector<idx_t> ptr{0}, nodes;
  void add(const fem::Model& model, std::initializer_list<int> ids) { add_range(model, ids.begin(), ids.end()); }
  template <class It>
  void add_range(const fem::Model& model, It first, It last) {
    for (It it = first; it != last; ++it) {
      const auto found = model.grid_index.find(*it);
      if (found != model.grid_index.end()) nodes.push_back(static_cast<idx_t>(found->second));
    }
    ptr.push_back(static_cast<idx_t>(nodes.size()));
  }
  idx_t elements() const { return static_cast<idx_t>(ptr.size()) - 1; }
};

}  // namespace

std::size_t ElementPartition::count(int part) const {
  return owned(bars, part) + owned(rods, part) + owned(shells, part) + owned(solids, part) + owned(bushes, part) +
         owned(shear_panels, part) + owned(bends, part) + owned(shells8, part) +
         owned(conm2, part) + owned(conm1, part) + owned(springs, part) + owned(scalar_masses, part);
}

std::size_t ElementPartition::total() const {
  return bars.size() + rods.size() + shells.size() + solids.size() + bushes.size() + shear_panels.size() + bends.size() +
         shells8.size() + conm2.size() + conm1.size() +
         springs.size() + scalar_masses.size();
}

ElementPartition partition_elements(const fem::Model& model, int parts) {
  SEFLEX_DEMAND(parts >= 1, "partition_elements: parts must be at least 1");
  SEFLEX_DEMAND(model.finalized || model.grids.empty(), "partition_elements: the model must be finalized");
  ElementPartition p;
  p.parts = parts;
  MeshConnectivity mesh;
  for (const fem::Bar& b : model.bars) mesh.add(model, {b.ga, b.gb});
  for (const fem::Rod& r : model.rods) mesh.add(model, {r.ga, r.gb});
  for (const fem::Shell& s : model.shells) mesh.add_range(model, s.g.begin(), s.g.begin() + s.nnode);
  for (const fem::Solid& s : model.solids) mesh.add_range(model, s.g.begin(), s.g.begin() + s.nnode);
  for (const fem::Bush& b : model.bushes) {
    if (b.gb != 0) mesh.add(model, {b.ga, b.gb});
    else mesh.add(model, {b.ga});
  }
  for (const fem::ShearPanel& s : model.shear_panels) mesh.add_range(model, s.g.begin(), s.g.end());
  for (const fem::Bend& b : model.bends) mesh.add(model, {b.ga, b.gb});
  for (const fem::QuadraticShell& q : model.shells8) {
    std::vector<int> ids(q.shell.g.begin(), q.shell.g.begin() + q.shell.nnode);
    for (const int g : q.mid)
      if (g != 0) ids.push_back(g);
    mesh.add_range(model, ids.begin(), ids.end());
  }
  const idx_t ne = mesh.elements();
  const auto n_nodes = static_cast<idx_t>(model.grids.size() + model.spoints.size());
  std::vector<idx_t> epart(static_cast<std::size_t>(ne), 0);
  if (parts > 1 && ne > parts) {
    std::vector<idx_t> npart(static_cast<std::size_t>(n_nodes), 0);
    idx_t nparts = parts, ncommon = 1, objval = 0, nn = n_nodes, nel = ne;
    idx_t options[METIS_NOPTIONS];
    METIS_SetDefaultOptions(options);
    options[METIS_OPTION_NUMBERING] = 0;
    const int status = METIS_PartMeshDual(&nel, &nn, mesh.ptr.data(), mesh.nodes.data(), nullptr, nullptr, &ncommon,
                                          &nparts, nullptr, options, &objval, epart.data(), npart.data());
    SEFLEX_DEMAND(status == METIS_OK, "partition_elements: METIS_PartMeshDual failed (status " + std::to_string(status) + ")");
  } else if (parts > 1) {
    for (idx_t e = 0; e < ne; ++e) epart[static_cast<std::size_t>(e)] = static_cast<idx_t>(e % parts);
  }
  // Split epart back into the element kinds.
  std::size_t at = 0;
  auto take = [&](std::vector<int>& out, std::size_t n) {
    out.resize(n);
    for (std::size_t i = 0; i < n; ++i) out[i] = static_cast<int>(epart[at++]);
  };
  take(p.bars, model.bars.size());
  take(p.rods, model.rods.size());
  take(p.shells, model.shells.size());
  take(p.solids, model.solids.size());
  take(p.bushes, model.bushes.size());
  take(p.shear_panels, model.shear_panels.size());
  take(p.bends, model.bends.size());
  take(p.shells8, model.shells8.size());
  auto round_robin = [&](std::vector<int>& out, std::size_t n) {
    out.resize(n);
    for (std::size_t i = 0; i < n; ++i) out[i] = static_cast<int>(i % static_cast<std::size_t>(parts));
  };
  round_robin(p.conm2, model.conm2.size());
  round_robin(p.conm1, model.conm1.size());
  round_robin(p.springs, model.springs.size());
  round_robin(p.scalar_masses, model.scalar_masses.size());
  // Nodes: the part of the first mesh element using them, else round-robin.
  p.node_owner.assign(static_cast<std::size_t>(n_nodes), -1);
  for (idx_t e = 0; e < ne; ++e)
    for (idx_t k = mesh.ptr[static_cast<std::size_t>(e)]; k < mesh.ptr[static_cast<std::size_t>(e) + 1]; ++k) {
      int& owner = p.node_owner[static_cast<std::size_t>(mesh.nodes[static_cast<std::size_t>(k)])];
      if (owner < 0) owner = static_cast<int>(epart[static_cast<std::size_t>(e)]);
    }
  for (std::size_t n = 0; n < p.node_owner.size(); ++n)
    if (p.node_owner[n] < 0) p.node_owner[n] = static_cast<int>(n % static_cast<std::size_t>(parts));
  return p;
}

}  // namespace seflex::parallel
