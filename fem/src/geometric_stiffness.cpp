// Assembly of the differential stiffness K_sigma (see geometric_stiffness.hpp).
#include "seflex/fem/geometric_stiffness.hpp"

#include "block_pattern.hpp"
#include "model_lookup.hpp"
#include "seflex/common/error.hpp"
#include "seflex/fem/assembly.hpp"
#include "seflex/fem/element_bar.hpp"
#include "seflex/fem/element_rod.hpp"
#include "seflex/fem/element_shell_quad4.hpp"
#include "seflex/fem/element_shell_tria3.hpp"
#include "seflex/fem/finalize.hpp"

namespace seflex::fem {
namespace {

using Axes = std::vector<std::optional<Eigen::Matrix3d>>;

// Element displacements in basic from the g-set (CD components): u_basic = A u_cd per 3-block.
template <int N>
Eigen::Matrix<double, 6 * N, 1> gather_basic(const std::int32_t* nodes, const Axes& axes, const Eigen::VectorXd& u_g) {
  Eigen::Matrix<double, 6 * N, 1> u;
  for (int n = 0; n < N; ++n) {
    u.template segment<6>(6 * n) = u_g.segment<6>(6 * static_cast<Eigen::Index>(nodes[n]));
    if (const auto& A = axes[nodes[n]]) {
      u.template segment<3>(6 * n) = (*A) * u.template segment<3>(6 * n);
      u.template segment<3>(6 * n + 3) = (*A) * u.template segment<3>(6 * n + 3);
    }
  }
  return u;
}

// block(i, j) <- A_i^T block(i, j) A_j (basic -> each grid's CD system), as assembly does.
template <int N>
void to_cd(const std::int32_t* nodes, const Axes& axes, NodeMatrix<N>& K) {
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

template <int N>
void grid_nodes(const Model& model, const int* ids, const CardRef& ref, const char* card, int id, int first_field,
                std::int32_t* out) {
  for (int k = 0; k < N; ++k)
    out[k] = static_cast<std::int32_t>(detail::grid_index(
        model, ids[k], ref, card, id, std::to_string(k + first_field) + " (G" + std::to_string(k + 1) + ")"));
}

}  // namespace

Eigen::SparseMatrix<double> assemble_geometric_stiffness(const Model& model, const DofMap& dofs,
                                                         const Eigen::Ref<const Eigen::VectorXd>& u_ref) {
  SEFLEX_DEMAND(u_ref.size() == dofs.size(), "assemble_geometric_stiffness: displacement vector of the wrong size");
  // Elements whose differential stiffness seflex does not compute: refused, never left out.
  auto refuse = [&](const char* card, int id, const CardRef& ref) {
    throw InputError(where(model, ref), std::string(card) + " " + std::to_string(id) +
                                            ": seflex does not compute the differential stiffness of " + card +
                                            " elements, which buckling needs; expected CBAR, CBEAM, CROD, CONROD, CTUBE, "
                                            "CQUAD4 and CTRIA3 elements only in a buckling model");
  };
  if (!model.shear_panels.empty()) refuse("CSHEAR", model.shear_panels.front().id, model.shear_panels.front().ref);
  if (!model.bends.empty()) refuse("CBEND", model.bends.front().id, model.bends.front().ref);
  if (!model.shells8.empty())
    refuse(quadratic_shell_card(model.shells8.front()), model.shells8.front().shell.id, model.shells8.front().shell.ref);
  const Eigen::VectorXd u_g = u_ref;
  const Axes axes = grid_cd_axes(model);

  detail::Connectivity conn;
  std::vector<std::int32_t> bar_nodes, rod_nodes, shell_nodes;
  for (const Bar& b : model.bars) {
    std::int32_t n[2];
    const int ids[2] = {b.ga, b.gb};
    grid_nodes<2>(model, ids, b.ref, b.is_beam ? "CBEAM" : "CBAR", b.id, 4, n);
    conn.add(n, n + 2);
    bar_nodes.insert(bar_nodes.end(), n, n + 2);
  }
  for (const Rod& r : model.rods) {
    std::int32_t n[2];
    const int ids[2] = {r.ga, r.gb};
    grid_nodes<2>(model, ids, r.ref, rod_card(r), r.id, r.inline_property ? 3 : 4, n);
    conn.add(n, n + 2);
    rod_nodes.insert(rod_nodes.end(), n, n + 2);
  }
  for (const Shell& s : model.shells) {
    std::int32_t n[4];
    int ids[4] = {s.g[0], s.g[1], s.g[2], s.nnode == 4 ? s.g[3] : 0};
    if (s.nnode == 4)
      grid_nodes<4>(model, ids, s.ref, shell_card(s), s.id, 4, n);
    else
      grid_nodes<3>(model, ids, s.ref, shell_card(s), s.id, 4, n);
    conn.add(n, n + s.nnode);
    shell_nodes.insert(shell_nodes.end(), n, n + s.nnode);
  }

  const detail::BlockPattern pattern(dofs, conn, false);
  Eigen::SparseMatrix<double> K;
  pattern.make_matrix(K);
  for (std::size_t i = 0; i < model.bars.size(); ++i) {
    const std::int32_t* n = &bar_nodes[2 * i];
    const BarElement e = make_bar_element(model, model.bars[i]);
    NodeMatrix<2> Ke = bar_geometric_stiffness(e, bar_axial_force(e, gather_basic<2>(n, axes, u_g)));
    to_cd<2>(n, axes, Ke);
    pattern.scatter<2>(n, Ke, K);
  }
  for (std::size_t i = 0; i < model.rods.size(); ++i) {
    const std::int32_t* n = &rod_nodes[2 * i];
    const RodElement e = make_rod_element(model, model.rods[i]);
    NodeMatrix<2> Ke = rod_geometric_stiffness(e, rod_axial_force(e, gather_basic<2>(n, axes, u_g)));
    to_cd<2>(n, axes, Ke);
    pattern.scatter<2>(n, Ke, K);
  }
  detail::ShellSectionCache sections;
  std::size_t offset = 0;
  for (const Shell& s : model.shells) {
    const std::int32_t* n = &shell_nodes[offset];
    offset += s.nnode;
    if (s.nnode == 4) {
      const Quad4Element e = make_quad4_element(model, s, &sections.get(model, s));
      NodeMatrix<4> Ke = quad4_geometric_stiffness(e, quad4_membrane_resultants(e, gather_basic<4>(n, axes, u_g)));
      to_cd<4>(n, axes, Ke);
      pattern.scatter<4>(n, Ke, K);
    } else {
      const Tria3Element e = make_tria3_element(model, s, &sections.get(model, s));
      NodeMatrix<3> Ke = tria3_geometric_stiffness(e, tria3_membrane_resultants(e, gather_basic<3>(n, axes, u_g)));
      to_cd<3>(n, axes, Ke);
      pattern.scatter<3>(n, Ke, K);
    }
  }
  K.prune(0.0, 0.0);
  return K;
}

}  // namespace seflex::fem
