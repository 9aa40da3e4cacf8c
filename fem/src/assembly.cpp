// Assembly of K and M (see assembly.hpp).
#include "seflex/fem/assembly.hpp"

#include "block_pattern.hpp"
#include "model_lookup.hpp"
#include "seflex/fem/finalize.hpp"
#include "seflex/common/error.hpp"
#include "seflex/fem/dmig.hpp"
#include "seflex/fem/element_bar.hpp"
#include "seflex/fem/element_bend.hpp"
#include "seflex/fem/element_bush.hpp"
#include "seflex/fem/element_conm1.hpp"
#include "seflex/fem/element_conm2.hpp"
#include "seflex/fem/element_genel.hpp"
#include "seflex/fem/element_scalar_mass.hpp"
#include "seflex/fem/element_rod.hpp"
#include "seflex/fem/element_shear_panel.hpp"
#include "seflex/fem/element_shell_quad4.hpp"
#include "seflex/fem/element_shell_quadratic.hpp"
#include "seflex/fem/element_solid.hpp"
#include "seflex/fem/element_shell_tria3.hpp"
#include "seflex/fem/element_spring.hpp"

namespace seflex::fem {

AssemblyOptions assembly_options(const Model& model) {
  AssemblyOptions o;
  o.mass = param_number(model, "COUPMASS") > 0.0 ? MassKind::Coupled : MassKind::Lumped;
  o.wtmass = param_number(model, "WTMASS");
  o.k6rot = param_number(model, "K6ROT");
  if (mystran_plate_elements(model)) {
    MystranPlate m;
    m.cb_tria = param_number(model, "CBMIN3");
    m.cb_quad = param_number(model, "CBMIN4T");
    o.mystran_plate = m;
  }
  for (const Param& p : model.params) {
    if (p.name == "WTMASS" && !(o.wtmass > 0.0))
      throw InputError(where(model, p.ref), "PARAM WTMASS: expected a positive number");
    if (p.name == "K6ROT" && !(o.k6rot >= 0.0))
      throw InputError(where(model, p.ref), "PARAM K6ROT: expected a number >= 0");
  }
  return o;
}

std::vector<std::optional<Eigen::Matrix3d>> grid_cd_axes(const Model& model) {
  std::vector<std::optional<Eigen::Matrix3d>> axes(model.grids.size());
  for (std::size_t i = 0; i < model.grids.size(); ++i) {
    const Grid& g = model.grids[i];
    if (g.cd != 0) axes[i] = detail::axes_at(model, g.cd, g.x_basic, g.ref, "GRID", g.id, "7 (CD)");
  }
  return axes;
}

namespace {

using Axes = std::vector<std::optional<Eigen::Matrix3d>>;

// Rotate the node blocks of an element matrix from basic to each grid's CD system:
// block(i, j) <- A_i^T block(i, j) A_j for the translation and rotation 3 x 3 blocks.
template <int N>
void to_cd(const std::int32_t* nodes, const Axes& axes, NodeMatrix<N>& K) {
  bool any = false;
  for (int n = 0; n < N; ++n) any = any || axes[nodes[n]].has_value();
  if (!any) return;
  for (int n = 0; n < N; ++n) {
    const auto& A = axes[nodes[n]];
    if (!A) continue;
    for (int h = 0; h < 2; ++h) {
      const int o = 6 * n + 3 * h;
      K.template middleRows<3>(o) = A->transpose() * K.template middleRows<3>(o);
      K.template middleCols<3>(o) = K.template middleCols<3>(o) * (*A);
    }
  }
}

/// The translation blocks of a 3N x 3N solid matrix from basic to each grid's CD system.
void to_cd_translations(const std::int32_t* nodes, int N, const Axes& axes, Eigen::MatrixXd& K) {
  for (int n = 0; n < N; ++n) {
    const auto& A = axes[nodes[n]];
    if (!A) continue;
    K.middleRows(3 * n, 3) = A->transpose() * K.middleRows(3 * n, 3);
    K.middleCols(3 * n, 3) = K.middleCols(3 * n, 3) * (*A);
  }
}

std::int32_t node_of_grid(const Model& model, int grid_id, const CardRef& ref, const std::string& card, int id,
                          const std::string& field) {
  return static_cast<std::int32_t>(detail::grid_index(model, grid_id, ref, card, id, field));
}

/// The resolved elements of one kind with N grids each and their nodes (N per element), for the
/// element kinds whose matrices come from a stiffness and a mass function alone.
template <int N, class E>
struct ElementGroup {
  std::vector<E> elements;
  std::vector<std::int32_t> nodes;

  template <class Card, class Make>
  void add(const Model& model, const Card& card, const char* name, const std::array<int, N>& grids, Make make,
           detail::Connectivity& conn) {
    std::int32_t n[N];
    for (int k = 0; k < N; ++k)
      n[k] = node_of_grid(model, grids[static_cast<std::size_t>(k)], card.ref, name, card.id, "G" + std::to_string(k + 1));
    conn.add(n, n + N);
    nodes.insert(nodes.end(), n, n + N);
    elements.push_back(make(model, card));
  }

  /// f(element) -> NodeMatrix<N> in basic, rotated to the grids' CD systems and scattered, times `scale`.
  template <class F>
  void scatter(const detail::BlockPattern& pattern, const Axes& axes, double scale, F f, Eigen::SparseMatrix<double>& A) const {
    for (std::size_t i = 0; i < elements.size(); ++i) {
      NodeMatrix<N> K = scale * f(elements[i]);
      to_cd<N>(&nodes[N * i], axes, K);
      pattern.scatter<N>(&nodes[N * i], K, A);
    }
  }
};

}  // namespace

GlobalMatrices assemble(const Model& model, const AssemblyOptions& options) {
  SEFLEX_DEMAND(model.finalized || model.grids.empty() || !model.grid_index.empty(),
                "assemble needs a finalized model");
  GlobalMatrices g;
  g.dofs = make_dof_map(model);
  const Axes axes = grid_cd_axes(model);

  // Resolve every element once (this also checks every reference) and collect the connectivity.
  std::vector<BarElement> bars;
  std::vector<RodElement> rods;
  std::vector<Quad4Element> quads;
  std::vector<Tria3Element> trias;
  std::vector<Conm2Element> masses;
  std::vector<SpringElement> springs;
  std::vector<SolidElement> solids;
  std::vector<std::int32_t> solid_nodes, solid_ptr{0};
  detail::Connectivity conn;
  std::vector<std::int32_t> bar_nodes, rod_nodes, quad_nodes, tria_nodes, mass_nodes;

  bars.reserve(model.bars.size());
  for (const Bar& b : model.bars) {
    bars.push_back(make_bar_element(model, b));
    const std::string card = b.is_beam ? "CBEAM" : "CBAR";
    const std::int32_t n[2] = {node_of_grid(model, b.ga, b.ref, card, b.id, "4 (GA)"),
                               node_of_grid(model, b.gb, b.ref, card, b.id, "5 (GB)")};
    conn.add(n, n + 2);
    bar_nodes.insert(bar_nodes.end(), n, n + 2);
  }
  rods.reserve(model.rods.size());
  for (const Rod& r : model.rods) {
    rods.push_back(make_rod_element(model, r));
    const std::string card = rod_card(r);
    const std::int32_t n[2] = {node_of_grid(model, r.ga, r.ref, card, r.id, "G1"),
                               node_of_grid(model, r.gb, r.ref, card, r.id, "G2")};
    conn.add(n, n + 2);
    rod_nodes.insert(rod_nodes.end(), n, n + 2);
  }
  detail::ShellSectionCache sections;
  std::size_t n_quads = 0;
  for (const Shell& s : model.shells) n_quads += s.nnode == 4;
  quads.reserve(n_quads);
  trias.reserve(model.shells.size() - n_quads);
  quad_nodes.reserve(4 * n_quads);
  tria_nodes.reserve(3 * (model.shells.size() - n_quads));
  conn.nodes.reserve(2 * (model.bars.size() + model.rods.size() + model.springs.size()) + 4 * model.shells.size() +
                     model.conm2.size());
  conn.ptr.reserve(model.bars.size() + model.rods.size() + model.shells.size() + model.springs.size() + 1);
  for (const Shell& s : model.shells) {
    const std::string card = shell_card(s);
    std::int32_t n[4];
    for (int k = 0; k < s.nnode; ++k)
      n[k] = node_of_grid(model, s.g[k], s.ref, card, s.id, std::to_string(k + 4) + " (G" + std::to_string(k + 1) + ")");
    conn.add(n, n + s.nnode);
    if (s.nnode == 4) {
      quads.push_back(make_quad4_element(model, s, &sections.get(model, s)));
      quad_nodes.insert(quad_nodes.end(), n, n + 4);
    } else {
      trias.push_back(make_tria3_element(model, s, &sections.get(model, s)));
      tria_nodes.insert(tria_nodes.end(), n, n + 3);
    }
  }
  solids.reserve(model.solids.size());
  for (const Solid& s : model.solids) {
    std::int32_t n[20];
    for (int k = 0; k < s.nnode; ++k)
      n[k] = node_of_grid(model, s.g[static_cast<std::size_t>(k)], s.ref, s.card(), s.id, "G" + std::to_string(s.grid_number(k)));
    conn.add(n, n + s.nnode);
    solids.push_back(make_solid_element(model, s));
    solid_nodes.insert(solid_nodes.end(), n, n + s.nnode);
    solid_ptr.push_back(static_cast<std::int32_t>(solid_nodes.size()));
  }
  masses.reserve(model.conm2.size());
  springs.reserve(model.springs.size());
  for (const Conm2& c : model.conm2) {
    masses.push_back(make_conm2_element(model, c));
    mass_nodes.push_back(node_of_grid(model, c.grid, c.ref, "CONM2", c.id, "3 (G)"));
  }
  std::vector<BushElement> bushes;
  std::vector<std::int32_t> bush_nodes;  // two per CBUSH (the second = the first when grounded)
  for (const Bush& b : model.bushes) {
    bushes.push_back(make_bush_element(model, b));
    const std::int32_t a = node_of_grid(model, b.ga, b.ref, bush_card(b), b.id, "4 (GA)");
    const std::int32_t n[2] = {a, b.gb ? node_of_grid(model, b.gb, b.ref, bush_card(b), b.id, "5 (GB)") : a};
    conn.add(n, n + (b.gb ? 2 : 1));
    bush_nodes.insert(bush_nodes.end(), n, n + 2);
  }
  std::vector<std::int32_t> conm1_nodes;
  for (const Conm1& c : model.conm1) conm1_nodes.push_back(node_of_grid(model, c.grid, c.ref, "CONM1", c.id, "3 (G)"));
  std::vector<ScalarMassElement> scalar_masses;
  for (const ScalarMass& s : model.scalar_masses) scalar_masses.push_back(make_scalar_mass_element(model, g.dofs, s));
  ElementGroup<4, ShearPanelElement> shear_panels;
  for (const ShearPanel& s : model.shear_panels) shear_panels.add(model, s, "CSHEAR", s.g, make_shear_panel_element, conn);
  ElementGroup<2, BendElement> bends;
  for (const Bend& b : model.bends) bends.add(model, b, "CBEND", {b.ga, b.gb}, make_bend_element, conn);
  ElementGroup<8, QuadraticShellElement> shells8;
  for (const QuadraticShell& q : model.shells8) {
    const Shell& s = q.shell;
    std::array<int, 8> grids;  // absent mid-side grids: the first corner (their blocks are zero)
    for (int k = 0; k < 8; ++k) grids[static_cast<std::size_t>(k)] = s.g[0];
    for (int k = 0; k < s.nnode; ++k) {
      grids[static_cast<std::size_t>(k)] = s.g[static_cast<std::size_t>(k)];
      if (q.mid[static_cast<std::size_t>(k)]) grids[static_cast<std::size_t>(s.nnode + k)] = q.mid[static_cast<std::size_t>(k)];
    }
    shells8.add(model, s, quadratic_shell_card(q), grids,
                [&](const Model& m, const Shell&) { return make_quadratic_shell_element(m, q, &sections.get(m, s)); }, conn);
  }
  std::vector<GenelElement> genels;
  for (const Genel& ge : model.genels) {
    genels.push_back(make_genel_element(model, g.dofs, ge));
    std::vector<std::int32_t> n;
    for (const Eigen::Index d : genels.back().dofs) n.push_back(static_cast<std::int32_t>(g.dofs.node_of_dof(d)));
    conn.add(n.data(), n.data() + n.size());
  }
  for (const Spring& s : model.springs) {
    springs.push_back(make_spring_element(model, g.dofs, s));
    const SpringElement& e = springs.back();
    if (e.dof2 < 0)
      conn.add({static_cast<std::int32_t>(g.dofs.node_of_dof(e.dof1))});
    else
      conn.add({static_cast<std::int32_t>(g.dofs.node_of_dof(e.dof1)),
                static_cast<std::int32_t>(g.dofs.node_of_dof(e.dof2))});
  }

  // A CBUSH's (CBUSH1D's) 12 x 12 matrix on its grids; grounded: its GA block alone.
  auto scatter_bush = [&](const detail::BlockPattern& pattern, std::size_t i, NodeMatrix<2> A, auto& target) {
    if (bushes[i].grounded) {
      NodeMatrix<1> A1 = A.topLeftCorner<6, 6>();
      to_cd<1>(&bush_nodes[2 * i], axes, A1);
      pattern.scatter<1>(&bush_nodes[2 * i], A1, target);
    } else {
      to_cd<2>(&bush_nodes[2 * i], axes, A);
      pattern.scatter<2>(&bush_nodes[2 * i], A, target);
    }
  };

  // Stiffness.
  {
    const MystranPlate* mystran = options.mystran_plate ? &*options.mystran_plate : nullptr;
    const detail::BlockPattern pattern(g.dofs, conn, false);
    pattern.make_matrix(g.K);
    for (std::size_t i = 0; i < bars.size(); ++i) {
      NodeMatrix<2> K = bar_stiffness(bars[i]);
      to_cd<2>(&bar_nodes[2 * i], axes, K);
      pattern.scatter<2>(&bar_nodes[2 * i], K, g.K);
    }
    for (std::size_t i = 0; i < rods.size(); ++i) {
      NodeMatrix<2> K = rod_stiffness(rods[i]);
      to_cd<2>(&rod_nodes[2 * i], axes, K);
      pattern.scatter<2>(&rod_nodes[2 * i], K, g.K);
    }
    for (std::size_t i = 0; i < quads.size(); ++i) {
      NodeMatrix<4> K = quad4_stiffness(quads[i], options.k6rot, mystran);
      to_cd<4>(&quad_nodes[4 * i], axes, K);
      pattern.scatter<4>(&quad_nodes[4 * i], K, g.K);
    }
    for (std::size_t i = 0; i < trias.size(); ++i) {
      NodeMatrix<3> K = tria3_stiffness(trias[i], options.k6rot, mystran);
      to_cd<3>(&tria_nodes[3 * i], axes, K);
      pattern.scatter<3>(&tria_nodes[3 * i], K, g.K);
    }
    for (std::size_t i = 0; i < bushes.size(); ++i) scatter_bush(pattern, i, bush_stiffness(bushes[i]), g.K);
    for (std::size_t i = 0; i < solids.size(); ++i) {
      Eigen::MatrixXd K = solid_stiffness(solids[i]);
      to_cd_translations(&solid_nodes[solid_ptr[i]], solids[i].nnode, axes, K);
      pattern.scatter_translations(&solid_nodes[solid_ptr[i]], solids[i].nnode, K, g.K);
    }
    shear_panels.scatter(pattern, axes, 1.0, shear_panel_stiffness, g.K);
    bends.scatter(pattern, axes, 1.0, bend_stiffness, g.K);
    shells8.scatter(pattern, axes, 1.0, [&](const QuadraticShellElement& e) { return quadratic_shell_stiffness(e, options.k6rot); }, g.K);
    for (const GenelElement& e : genels)
      for (std::size_t j = 0; j < e.dofs.size(); ++j)
        for (std::size_t i = 0; i < e.dofs.size(); ++i)
          detail::add_entry(g.K, e.dofs[i], e.dofs[j], e.K(static_cast<Eigen::Index>(i), static_cast<Eigen::Index>(j)));
    for (const SpringElement& s : springs) {
      detail::add_entry(g.K, s.dof1, s.dof1, s.k);
      if (s.dof2 >= 0) {
        detail::add_entry(g.K, s.dof2, s.dof2, s.k);
        detail::add_entry(g.K, s.dof1, s.dof2, -s.k);
        detail::add_entry(g.K, s.dof2, s.dof1, -s.k);
      }
    }
  }

  // Mass: lumped mass only couples dofs of the same node.
  {
    const detail::BlockPattern pattern(g.dofs, conn, options.mass == MassKind::Lumped);
    pattern.make_matrix(g.M);
    const double w = options.wtmass;
    for (std::size_t i = 0; i < bars.size(); ++i) {
      NodeMatrix<2> M = w * bar_mass(bars[i], options.mass);
      to_cd<2>(&bar_nodes[2 * i], axes, M);
      pattern.scatter<2>(&bar_nodes[2 * i], M, g.M);
    }
    for (std::size_t i = 0; i < rods.size(); ++i) {
      NodeMatrix<2> M = w * rod_mass(rods[i], options.mass);
      to_cd<2>(&rod_nodes[2 * i], axes, M);
      pattern.scatter<2>(&rod_nodes[2 * i], M, g.M);
    }
    for (std::size_t i = 0; i < quads.size(); ++i) {
      NodeMatrix<4> M = w * quad4_mass(quads[i], options.mass);
      to_cd<4>(&quad_nodes[4 * i], axes, M);
      pattern.scatter<4>(&quad_nodes[4 * i], M, g.M);
    }
    for (std::size_t i = 0; i < trias.size(); ++i) {
      NodeMatrix<3> M = w * tria3_mass(trias[i], options.mass);
      to_cd<3>(&tria_nodes[3 * i], axes, M);
      pattern.scatter<3>(&tria_nodes[3 * i], M, g.M);
    }
    for (std::size_t i = 0; i < solids.size(); ++i) {
      Eigen::MatrixXd M = w * solid_mass(solids[i], options.mass);
      to_cd_translations(&solid_nodes[solid_ptr[i]], solids[i].nnode, axes, M);
      pattern.scatter_translations(&solid_nodes[solid_ptr[i]], solids[i].nnode, M, g.M);
    }
    shear_panels.scatter(pattern, axes, w, shear_panel_mass, g.M);
    bends.scatter(pattern, axes, w, bend_mass, g.M);
    shells8.scatter(pattern, axes, w, [&](const QuadraticShellElement& e) { return quadratic_shell_mass(e, options.mass); }, g.M);
    for (std::size_t i = 0; i < bushes.size(); ++i)
      if (bushes[i].mass != 0.0) scatter_bush(pattern, i, w * bush_mass(bushes[i]), g.M);
    for (std::size_t i = 0; i < masses.size(); ++i) {
      NodeMatrix<1> M = w * conm2_mass(masses[i]);
      to_cd<1>(&mass_nodes[i], axes, M);
      pattern.scatter<1>(&mass_nodes[i], M, g.M);
    }
  }
  for (std::size_t i = 0; i < model.conm1.size(); ++i) {
    NodeMatrix<1> M = options.wtmass * conm1_mass(model, model.conm1[i]);
    to_cd<1>(&conm1_nodes[i], axes, M);
    for (int c = 0; c < 6; ++c)
      for (int r = 0; r < 6; ++r) detail::add_entry(g.M, 6 * conm1_nodes[i] + r, 6 * conm1_nodes[i] + c, M(r, c));
  }
  if (!scalar_masses.empty()) {  // CMASS may couple two nodes: outside the lumped (block-diagonal) pattern
    std::vector<Eigen::Triplet<double>> t;
    for (const ScalarMassElement& s : scalar_masses) {
      const double m = options.wtmass * s.m;
      t.emplace_back(s.dof1, s.dof1, m);
      if (s.dof2 >= 0) {
        t.emplace_back(s.dof2, s.dof2, m);
        t.emplace_back(s.dof1, s.dof2, -m);
        t.emplace_back(s.dof2, s.dof1, -m);
      }
    }
    Eigen::SparseMatrix<double> Ms(g.M.rows(), g.M.cols());
    Ms.setFromTriplets(t.begin(), t.end());
    g.M = (g.M + Ms).eval();
    g.M.makeCompressed();
  }
  add_direct_matrices(model, g.dofs, g.K, g.M, &g.M_bulk);  // K2GG / M2GG, external superelements (dmig.hpp)
  if (options.prune_zeros) {
    g.K.prune(0.0, 0.0);
    g.M.prune(0.0, 0.0);
    g.M_bulk.prune(0.0, 0.0);
  }
  return g;
}

}  // namespace seflex::fem
