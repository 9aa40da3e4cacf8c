// Element results: component names, peaks and the linear map from g-set displacements
// (element_results.hpp). The per-type functions live with their elements (quad4_results in
// element_shell_quad4.cpp, tria3_results in element_shell_tria3.cpp, line elements in
// element_results_line.cpp, solids in element_results_solid.cpp); this file only gathers.
#include "seflex/fem/element_results.hpp"

#include <algorithm>
#include <cmath>
#include <map>
#include <unordered_set>

#include "model_lookup.hpp"
#include "seflex/fem/assembly.hpp"
#include "seflex/fem/dof_map.hpp"
#include "seflex/fem/element_bar.hpp"
#include "seflex/fem/element_bush.hpp"
#include "seflex/fem/element_rod.hpp"
#include "seflex/fem/element_shell_quad4.hpp"
#include "seflex/fem/element_shell_tria3.hpp"
#include "seflex/fem/element_solid.hpp"
#include "seflex/fem/element_spring.hpp"

namespace seflex::fem {

const std::vector<std::string>& element_result_components(ResultKind kind) {
  static const std::vector<std::string> names[kResultKinds] = {
      {"nx", "ny", "nxy", "mx", "my", "mxy", "qx", "qy", "sx_z1", "sy_z1", "txy_z1", "sx_z2", "sy_z2", "txy_z2"},
      {"m1_a", "m2_a", "m1_b", "m2_b", "v1", "v2", "axial", "torque"},
      {"axial", "torque", "axial_stress"},
      {"sx", "sy", "sz", "txy", "tyz", "tzx"},
      {"force"},
      {"fx", "fy", "fz", "mx", "my", "mz"}};
  return names[static_cast<int>(kind)];
}

double plane_von_mises(double sx, double sy, double txy) {
  return std::sqrt(std::max(0.0, sx * sx - sx * sy + sy * sy + 3 * txy * txy));
}

const char* element_result_peak_name(ResultKind kind) {
  switch (kind) {
    case ResultKind::Shell:
    case ResultKind::Solid: return "von_mises";
    case ResultKind::Bar: return "moment";
    case ResultKind::Rod: return "axial_stress";
    default: return "force";
  }
}

ResultPeak element_result_peak(ResultKind kind, const double* c) {
  ResultPeak p;
  switch (kind) {
    case ResultKind::Shell: {
      const double v1 = plane_von_mises(c[8], c[9], c[10]), v2 = plane_von_mises(c[11], c[12], c[13]);
      p.value = std::max(v1, v2);
      p.fibre = v2 > v1 ? 2 : 1;
      break;
    }
    case ResultKind::Solid: {
      const double a = c[0] - c[1], b = c[1] - c[2], d = c[2] - c[0];
      p.value = std::sqrt(0.5 * (a * a + b * b + d * d) + 3 * (c[3] * c[3] + c[4] * c[4] + c[5] * c[5]));
      break;
    }
    case ResultKind::Bar: p.value = std::max({std::abs(c[0]), std::abs(c[1]), std::abs(c[2]), std::abs(c[3])}); break;
    case ResultKind::Rod: p.value = std::abs(c[2]); break;
    case ResultKind::Spring: p.value = std::abs(c[0]); break;
    case ResultKind::Bush: p.value = std::max({std::abs(c[0]), std::abs(c[1]), std::abs(c[2])}); break;
  }
  return p;
}

void ElementResultMap::apply(const Eigen::Ref<const Eigen::VectorXd>& u_g, Eigen::Ref<Eigen::VectorXd> results) const {
  for (Eigen::Index r = 0; r < rows; ++r) {
    double s = 0;
    for (Eigen::Index k = ptr[static_cast<std::size_t>(r)]; k < ptr[static_cast<std::size_t>(r) + 1]; ++k)
      s += weight[static_cast<std::size_t>(k)] * u_g[dof[static_cast<std::size_t>(k)]];
    results[r] = s;
  }
}

Eigen::VectorXd ElementResultMap::apply(const Eigen::Ref<const Eigen::VectorXd>& u_g) const {
  Eigen::VectorXd r(rows);
  apply(u_g, r);
  return r;
}

Eigen::MatrixXd ElementResultMap::apply_columns(const Eigen::Ref<const Eigen::MatrixXd>& U) const {
  Eigen::MatrixXd R = Eigen::MatrixXd::Zero(rows, U.cols());
  for (Eigen::Index r = 0; r < rows; ++r)
    for (Eigen::Index k = ptr[static_cast<std::size_t>(r)]; k < ptr[static_cast<std::size_t>(r) + 1]; ++k)
      R.row(r) += weight[static_cast<std::size_t>(k)] * U.row(dof[static_cast<std::size_t>(k)]);
  return R;
}

namespace {

using Axes = std::vector<std::optional<Eigen::Matrix3d>>;

// Appends the rows of one element: f(u_basic) -> components, linear in the element's grid
// displacements (`per_grid` = 6 dofs per grid, or 3 translations for solids), sampled column by
// column and turned to the grids' CD components.
struct Builder {
  const Model& model;
  const DofMap dofs;
  const Axes axes;
  ElementResultMap& map;

  template <class F>
  void add(int id, ResultKind kind, const std::string& card, const std::vector<std::int32_t>& nodes, int per_grid, F f) {
    const int n = per_grid * static_cast<int>(nodes.size());
    const int nc = element_result_count(kind);
    Eigen::MatrixXd R(nc, n);
    Eigen::VectorXd u = Eigen::VectorXd::Zero(n);
    for (int j = 0; j < n; ++j) {
      u[j] = 1.0;
      R.col(j) = f(u);
      u[j] = 0.0;
    }
    // u_basic = A u_cd per 3-block of a grid with a CD system.
    for (std::size_t a = 0; a < nodes.size(); ++a) {
      const auto& A = axes[static_cast<std::size_t>(nodes[a])];
      if (!A) continue;
      for (int h = 0; h < per_grid / 3; ++h) {
        const int o = per_grid * static_cast<int>(a) + 3 * h;
        R.middleCols<3>(o) = R.middleCols<3>(o) * (*A);
      }
    }
    map.entries.push_back({id, kind, card, map.rows});
    for (int i = 0; i < nc; ++i) {
      for (std::size_t a = 0; a < nodes.size(); ++a)
        for (int c = 0; c < per_grid; ++c) {
          const double w = R(i, per_grid * static_cast<int>(a) + c);
          if (w == 0.0) continue;
          map.dof.push_back(dofs.grid_dof(nodes[a], c + 1));
          map.weight.push_back(w);
        }
      map.ptr.push_back(static_cast<Eigen::Index>(map.dof.size()));
    }
    map.rows += nc;
  }

  std::int32_t node(int grid, const CardRef& ref, const std::string& card, int id) const {
    return static_cast<std::int32_t>(detail::grid_index(model, grid, ref, card, id, "grid"));
  }
};

template <int N>
Eigen::Matrix<double, 6 * N, 1> fixed(const Eigen::VectorXd& u) {
  return u;
}

}  // namespace

ElementResultMap make_element_result_map(const Model& model, const std::vector<int>& ids) {
  ElementResultMap map;
  Builder b{model, make_dof_map(model), grid_cd_axes(model), map};
  std::unordered_set<int> want(ids.begin(), ids.end()), found;
  const auto selected = [&](int id) {
    if (ids.empty()) return true;
    if (!want.count(id)) return false;
    found.insert(id);
    return true;
  };
  std::map<std::string, int> missing;

  detail::ShellSectionCache sections;
  for (const Shell& s : model.shells) {
    if (!selected(s.id)) continue;
    const std::string card = shell_card(s);
    std::vector<std::int32_t> nodes;
    for (int k = 0; k < s.nnode; ++k) nodes.push_back(b.node(s.g[static_cast<std::size_t>(k)], s.ref, card, s.id));
    ShellFibres f;
    f.zoffs = s.zoffs;
    double ratio = 1.0, z1 = 0, z2 = 0;
    if (const auto it = model.shell_prop_index.find(s.pid); it != model.shell_prop_index.end()) {
      const ShellProperty& p = model.shell_props[it->second];
      ratio = p.bend_ratio;
      z1 = p.z1, z2 = p.z2;
    }
    if (s.nnode == 4) {
      const Quad4Element e = make_quad4_element(model, s, &sections.get(model, s));
      const double t = e.section.t;
      f.z1 = z1 != 0 || z2 != 0 ? z1 : -t / 2, f.z2 = z1 != 0 || z2 != 0 ? z2 : t / 2, f.I = ratio * t * t * t / 12;
      b.add(s.id, ResultKind::Shell, card, nodes, 6, [&](const Eigen::VectorXd& u) { return quad4_results(e, f, fixed<4>(u)); });
    } else {
      const Tria3Element e = make_tria3_element(model, s, &sections.get(model, s));
      const double t = e.section.t;
      f.z1 = z1 != 0 || z2 != 0 ? z1 : -t / 2, f.z2 = z1 != 0 || z2 != 0 ? z2 : t / 2, f.I = ratio * t * t * t / 12;
      b.add(s.id, ResultKind::Shell, card, nodes, 6, [&](const Eigen::VectorXd& u) { return tria3_results(e, f, fixed<3>(u)); });
    }
  }
  for (const Bar& r : model.bars) {
    if (!selected(r.id)) continue;
    const std::string card = r.is_beam ? "CBEAM" : "CBAR";
    const BarElement e = make_bar_element(model, r);
    b.add(r.id, ResultKind::Bar, card, {b.node(r.ga, r.ref, card, r.id), b.node(r.gb, r.ref, card, r.id)}, 6,
          [&](const Eigen::VectorXd& u) { return bar_results(e, fixed<2>(u)); });
  }
  for (const Rod& r : model.rods) {
    if (!selected(r.id)) continue;
    const std::string card = rod_card(r);
    const RodElement e = make_rod_element(model, r);
    b.add(r.id, ResultKind::Rod, card, {b.node(r.ga, r.ref, card, r.id), b.node(r.gb, r.ref, card, r.id)}, 6,
          [&](const Eigen::VectorXd& u) { return rod_results(e, fixed<2>(u)); });
  }
  for (const Solid& s : model.solids) {
    if (!selected(s.id)) continue;
    std::vector<std::int32_t> nodes;
    for (int k = 0; k < s.nnode; ++k) nodes.push_back(b.node(s.g[static_cast<std::size_t>(k)], s.ref, s.card(), s.id));
    const SolidElement e = make_solid_element(model, s);
    b.add(s.id, ResultKind::Solid, s.card(), nodes, 3, [&](const Eigen::VectorXd& u) { return solid_results(e, u); });
  }
  for (const Bush& r : model.bushes) {
    if (!selected(r.id)) continue;
    const BushElement e = make_bush_element(model, r);
    const std::int32_t a = b.node(r.ga, r.ref, bush_card(r), r.id);
    const std::vector<std::int32_t> nodes = r.gb ? std::vector<std::int32_t>{a, b.node(r.gb, r.ref, bush_card(r), r.id)}
                                                 : std::vector<std::int32_t>{a};
    b.add(r.id, ResultKind::Bush, bush_card(r), nodes, 6, [&](const Eigen::VectorXd& u) {
      Eigen::Matrix<double, 12, 1> v = Eigen::Matrix<double, 12, 1>::Zero();
      v.head(u.size()) = u;
      return bush_results(e, v);
    });
  }
  for (const Spring& s : model.springs) {
    if (!selected(s.id)) continue;
    const SpringElement e = make_spring_element(model, b.dofs, s);
    map.entries.push_back({s.id, ResultKind::Spring, s.scalar_points ? (s.inline_property ? "CELAS4" : "CELAS3")
                                                                     : (s.inline_property ? "CELAS2" : "CELAS1"),
                           map.rows});
    map.dof.push_back(e.dof1);
    map.weight.push_back(e.k);
    if (e.dof2 >= 0) {
      map.dof.push_back(e.dof2);
      map.weight.push_back(-e.k);
    }
    map.ptr.push_back(static_cast<Eigen::Index>(map.dof.size()));
    map.rows += 1;
  }
  // Elements without results.
  const auto none = [&](int id, const char* card) {
    if (selected(id)) ++missing[card];
  };
  for (const ShearPanel& s : model.shear_panels) none(s.id, "CSHEAR");
  for (const Bend& s : model.bends) none(s.id, "CBEND");
  for (const QuadraticShell& s : model.shells8) none(s.shell.id, quadratic_shell_card(s));
  for (const Genel& s : model.genels) none(s.id, "GENEL");
  for (const Rbe2& r : model.rbe2) none(r.id, "RBE2");
  for (const Rbar& r : model.rbars) none(r.id, "RBAR");
  for (const Rbe3& r : model.rbe3) none(r.id, "RBE3");
  static const char* rigid_cards[] = {"RBE1", "CRIGD1", "CRIGD2", "CRIGD3"};
  for (const RigidBody& r : model.rigid_bodies) none(r.id, rigid_cards[static_cast<int>(r.card)]);
  for (const RigidRod& r : model.rigid_rods) none(r.id, r.card == RigidRod::Card::Rrod ? "RROD" : "CRIGDR");
  for (const Conm2& m : model.conm2) none(m.id, "CONM2");
  for (const Conm1& m : model.conm1) none(m.id, "CONM1");
  static const char* mass_cards[2][2] = {{"CMASS1", "CMASS2"}, {"CMASS3", "CMASS4"}};
  for (const ScalarMass& m : model.scalar_masses) none(m.id, mass_cards[m.scalar_points][m.inline_property]);
  for (const int id : ids)
    if (!found.count(id)) ++missing["unknown element id " + std::to_string(id)];
  for (const auto& [card, n] : missing) map.missing.emplace_back(card, n);
  return map;
}

}  // namespace seflex::fem
