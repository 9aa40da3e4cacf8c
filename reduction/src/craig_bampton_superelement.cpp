// An FE model reduced to the absolute-interface-coordinate superelement (craig_bampton_superelement.hpp).
#include "seflex/reduction/craig_bampton_superelement.hpp"


#include <algorithm>
#include <chrono>
#include <cmath>
#include <exception>
#include <limits>
#include <map>
#include <string>
#include <unordered_set>

#include "seflex/common/error.hpp"
#include "seflex/common/so3.hpp"
#include "seflex/common/version.hpp"
#include "seflex/fem/assembly.hpp"
#include "seflex/fem/components.hpp"
#include "seflex/fem/constraints.hpp"
#include "seflex/fem/element_results.hpp"
#include "seflex/fem/element_solid.hpp"
#include "seflex/fem/finalize.hpp"
#include "seflex/solutions/card_usage.hpp"
#include "seflex/solutions/case_selection.hpp"
#include "seflex/reduction/stiffening.hpp"

namespace seflex::reduction {

namespace {

using Axes = std::vector<std::optional<Eigen::Matrix3d>>;


std::string deck_name(const fem::Model& model) { return model.files.empty() ? std::string("<model>") : model.files[0]; }

/// The constraints of the case control (first SUBCASE, else the global selections: SPC and MPC
/// sets), as the solutions use them.
fem::ConstraintOptions case_constraints(const fem::Model& model) {
  const solutions::CaseSelection sel = solutions::select_case(model);
  fem::ConstraintOptions o;
  o.spc_set = sel.spc;
  o.mpc_set = sel.mpc;
  o.autospc = fem::autospc_enabled(model);
  return o;
}

/// Why grid `gi` (index) does not have six free dofs; empty if it has.
std::string not_free_reason(const fem::Model& model, const fem::ConstrainedSystem& c, std::size_t gi) {
  const fem::Grid& grid = model.grids[gi];
  fem::ComponentMask dependent = 0, spc = 0, autospc = 0, fixed = 0;
  for (int k = 0; k < 6; ++k) {
    const auto bit = static_cast<fem::ComponentMask>(1u << k);
    switch (c.status[6 * gi + static_cast<std::size_t>(k)]) {
      case fem::DofStatus::Free:
        break;
      case fem::DofStatus::Dependent:
        dependent |= bit;
        break;
      case fem::DofStatus::Spc:
        spc |= bit;
        break;
      case fem::DofStatus::AutoSpc:
        autospc |= bit;
        break;
      case fem::DofStatus::Fixed:
        fixed |= bit;
        break;
    }
  }
  if (dependent) {
    const std::string comps = "components " + fem::component_string(dependent);
    std::int32_t card = -1;
    for (int k = 0; k < 6 && card < 0; ++k)
      if (!c.dependent_card.empty()) card = c.dependent_card[6 * gi + static_cast<std::size_t>(k)];
    if (card < 0) return comps + " are dependent";
    const fem::ConstraintCard& cc = c.constraint_cards[static_cast<std::size_t>(card)];
    const std::string name = std::string(cc.card), which = fem::describe(model, cc);
    if (name == "RBE3")
      return comps + " are the dependent reference of " + which +
             ": a weighted average of its independent grids, so a unit motion of this grid alone does not define a "
             "constraint mode (the independent grids could move in many ways); use an independent grid as the "
             "interface, or make the reference grid independent with UM on the RBE3 (listing as many components "
             "of its independent grids as REFC has)";
    if (name == "RBE2" || name == "RBAR")
      return comps + " depend on " + which + "; use its independent grid (" + (name == "RBE2" ? "GN" : "CNA/CNB") +
             ") as the interface node instead";
    return comps + " depend on " + which + " (the first dof of each MPC equation is dependent)";
  }
  if (spc) {
    if (grid.ps & spc)
      return "components " + fem::component_string(grid.ps & spc) + " are constrained by PS on its GRID card (" +
             fem::where(model, grid.ref).str() + ")";
    for (const fem::SpcEntry& e : model.spcs)
      if (e.grid == grid.id && (e.c & spc))
        return "components " + fem::component_string(spc) + " are constrained by SPC set " + std::to_string(e.sid) +
               " (" + fem::where(model, e.ref).str() + ")";
    return "components " + fem::component_string(spc) + " are constrained (SPC)";
  }
  if (autospc)
    return "components " + fem::component_string(autospc) +
           " have no stiffness (no element connects them; removed like Nastran's AUTOSPC)";
  if (fixed) return "components " + fem::component_string(fixed) + " are held fixed";
  return {};
}

/// Rigid-body modes of the g-set about point p (g x 6), each grid's rows in its CD components;
/// scalar points do not move.
Eigen::MatrixXd rigid_modes_g(const fem::Model& model, const fem::DofMap& dofs, const Axes& axes,
                              const Eigen::Vector3d& p) {
  Eigen::MatrixXd D = Eigen::MatrixXd::Zero(dofs.size(), 6);
  for (std::size_t i = 0; i < model.grids.size(); ++i) {
    Eigen::Matrix<double, 6, 6> B = Eigen::Matrix<double, 6, 6>::Identity();
    B.block<3, 3>(0, 3) = -so3::skew(model.grids[i].x_basic - p);
    if (axes[i]) {
      B.topRows<3>() = axes[i]->transpose() * B.topRows<3>();
      B.bottomRows<3>() = axes[i]->transpose() * B.bottomRows<3>();
    }
    D.middleRows<6>(static_cast<Eigen::Index>(6 * i)) = B;
  }
  return D;
}

struct RigidMass {
  double mass = 0;
  Eigen::Vector3d cg = Eigen::Vector3d::Zero();    ///< basic
  Eigen::Matrix3d I_cg = Eigen::Matrix3d::Zero();  ///< about the CG, basic axes
};

/// Mass, CG and inertia from the 6 x 6 rigid-body mass M0 about point p (basic axes):
/// M0_tr = -m skew(c - p), M0_rr = I_cg + m (|c - p|^2 I - (c - p)(c - p)^T).
RigidMass rigid_mass(const Eigen::Matrix<double, 6, 6>& M0, const Eigen::Vector3d& p) {
  RigidMass r;
  r.mass = M0.topLeftCorner<3, 3>().trace() / 3.0;
  if (!(r.mass > 0)) {
    r.cg = p;
    r.I_cg = M0.bottomRightCorner<3, 3>();
    return r;
  }
  const Eigen::Matrix3d S = -M0.block<3, 3>(0, 3) / r.mass;  // skew(c - p)
  const Eigen::Vector3d c = so3::vee(0.5 * (S - S.transpose()));
  r.cg = p + c;
  const Eigen::Matrix3d J = M0.bottomRightCorner<3, 3>();
  r.I_cg = J - r.mass * (c.squaredNorm() * Eigen::Matrix3d::Identity() - c * c.transpose());
  r.I_cg = 0.5 * (r.I_cg + r.I_cg.transpose()).eval();
  return r;
}

/// The 6 x 6 block rotation of a grid's (t, r) components from CD to basic.
Eigen::Matrix<double, 6, 6> cd_to_basic(const std::optional<Eigen::Matrix3d>& A) {
  Eigen::Matrix<double, 6, 6> B = Eigen::Matrix<double, 6, 6>::Identity();
  if (A) B.topLeftCorner<3, 3>() = B.bottomRightCorner<3, 3>() = *A;
  return B;
}

std::vector<se::MeshCell> mesh_cells(const fem::Model& model) {
  std::vector<se::MeshCell> cells;
  cells.reserve(model.bars.size() + model.rods.size() + model.shells.size());
  auto node = [&](int id) { return static_cast<std::int32_t>(model.grid_index.at(id)); };
  auto line = [&](int ga, int gb, int id) {
    se::MeshCell c;
    c.type = se::MeshCell::Type::Line;
    c.nodes = {node(ga), node(gb), -1, -1};
    c.element_id = id;
    cells.push_back(c);
  };
  for (const fem::Bar& b : model.bars) line(b.ga, b.gb, b.id);
  for (const fem::Rod& r : model.rods) line(r.ga, r.gb, r.id);
  for (const fem::Bend& b : model.bends) line(b.ga, b.gb, b.id);
  for (const fem::QuadraticShell& q : model.shells8) {  // the corners' cell
    se::MeshCell c;
    c.type = q.shell.nnode == 4 ? se::MeshCell::Type::Quad : se::MeshCell::Type::Triangle;
    for (int k = 0; k < q.shell.nnode; ++k) c.nodes[static_cast<std::size_t>(k)] = node(q.shell.g[static_cast<std::size_t>(k)]);
    c.element_id = q.shell.id;
    cells.push_back(c);
  }
  for (const fem::ShearPanel& s : model.shear_panels) {
    se::MeshCell c;
    c.type = se::MeshCell::Type::Quad;
    for (std::size_t k = 0; k < 4; ++k) c.nodes[k] = node(s.g[k]);
    c.element_id = s.id;
    cells.push_back(c);
  }
  for (const fem::Shell& s : model.shells) {
    se::MeshCell c;
    c.type = s.nnode == 4 ? se::MeshCell::Type::Quad : se::MeshCell::Type::Triangle;
    for (int k = 0; k < s.nnode; ++k) c.nodes[static_cast<std::size_t>(k)] = node(s.g[static_cast<std::size_t>(k)]);
    c.element_id = s.id;
    cells.push_back(c);
  }
  // Solids: their boundary faces (a face that two solids share is inside the body and not drawn).
  if (!model.solids.empty()) {
    std::map<std::array<std::int32_t, 4>, std::pair<se::MeshCell, int>> faces;
    std::array<std::vector<std::vector<int>>, 4> corners;
    for (const auto shape : {fem::Solid::Shape::Tetra, fem::Solid::Shape::Penta, fem::Solid::Shape::Hexa, fem::Solid::Shape::Pyram})
      corners[static_cast<std::size_t>(shape)] = fem::solid_face_corners(shape);
    for (const fem::Solid& s : model.solids)
      for (const auto& f : corners[static_cast<std::size_t>(s.shape)]) {
        se::MeshCell c;
        c.type = f.size() == 4 ? se::MeshCell::Type::Quad : se::MeshCell::Type::Triangle;
        for (std::size_t k = 0; k < f.size(); ++k) c.nodes[k] = node(s.g[static_cast<std::size_t>(f[k])]);
        c.element_id = s.id;
        std::array<std::int32_t, 4> key = c.nodes;
        std::sort(key.begin(), key.end());
        ++faces.emplace(key, std::make_pair(c, 0)).first->second.second;
      }
    for (const auto& [key, cell] : faces)
      if (cell.second == 1) cells.push_back(cell.first);
  }
  return cells;
}

/// Grid index of an interface or frame node id, or InputError naming the node and the problem.
std::size_t grid_of(const fem::Model& model, int id, const std::string& role) {
  if (const auto it = model.grid_index.find(id); it != model.grid_index.end()) return it->second;
  if (model.spoint_index.count(id))
    throw InputError(deck_name(model) + ": " + role + " " + std::to_string(id) +
                     " is a scalar point (SPOINT); expected a GRID with six dofs");
  throw InputError(deck_name(model) + ": " + role + " " + std::to_string(id) + ": there is no GRID " +
                   std::to_string(id) + " in the model; expected the id of a GRID");
}

}  // namespace

Eigen::MatrixXd interface_rigid_modes(const se::Superelement& body) {
  const int N = body.num_interfaces();
  Eigen::MatrixXd R = Eigen::MatrixXd::Zero(6 * N, 6);
  for (int j = 0; j < N; ++j) {
    R.block<6, 6>(6 * j, 0).setIdentity();
    R.block<3, 3>(6 * j, 3) = -so3::skew(body.interfaces[static_cast<std::size_t>(j)].p_BoN_B);
  }
  return R;
}

Eigen::VectorXd reduced_eigenvalues(const se::Superelement& body, int count) {
  return small_pencil_eigenvalues(body.K, body.M, count);
}

Eigen::VectorXd full_model_eigenvalues(const fem::Model& model, int count, linalg::EigenBackend backend) {
  const fem::GlobalMatrices g = fem::assemble(model, fem::assembly_options(model));
  const fem::ConstrainedSystem c = fem::apply_constraints(model, g, case_constraints(model));
  linalg::EigenOptions eo;
  eo.count = count;
  eo.backend = backend;
  return linalg::solve_eigenproblem(c.K_ff, c.M_ff, eo).eigenvalues;
}

se::Superelement reduce_to_superelement(const fem::Model& model, const SuperelementOptions& options,
                                        SuperelementInfo* info, se::StressModes* stress) {
  if (stress) *stress = {};
  SEFLEX_DEMAND(model.finalized, "reduce_to_superelement needs a finalized model");
  SuperelementInfo local;
  SuperelementInfo& inf = info ? *info : local;
  const std::string deck = deck_name(model);
  if (options.interface_ids.empty())
    throw InputError(deck + ": no interface node given; expected at least one GRID id");

  // 1. Matrices and constraints.
  const solutions::CardUsage usage = solutions::check_card_usage(
      model, solutions::Solution::CraigBampton, {solutions::select_case(model)}, options.interface_cards,
      options.ignore_unknown_cards);
  solutions::require_usable(model, usage);
  const fem::DofMap dofs = fem::make_dof_map(model);
  fem::ConstraintOptions co = case_constraints(model);
  for (const int id : options.interface_ids)  // boundary dofs: held in the interior problem, never AUTOSPC'd
    if (const auto it = model.grid_index.find(id); it != model.grid_index.end())
      for (int k = 1; k <= 6; ++k) co.no_autospc.push_back(dofs.grid_dof(it->second, k));
  const bool partitioned = options.assemble && options.basis;
  fem::GlobalMatrices g = partitioned ? options.assemble(co) : fem::assemble(model, fem::assembly_options(model));
  inf.spc_set = co.spc_set.value_or(0);
  inf.mpc_set = co.mpc_set.value_or(0);
  fem::ConstrainedSystem c = fem::apply_constraints(model, g, co);
  g.K = linalg::SparseMatrixd();  // not needed any more (memory of large models)
  for (const fem::DofStatus s : c.status) {
    inf.autospc_dofs += s == fem::DofStatus::AutoSpc;
    inf.dependent_dofs += s == fem::DofStatus::Dependent;
  }
  const Axes axes = fem::grid_cd_axes(model);

  // 2. Interface nodes.
  std::vector<std::size_t> interface_index;
  std::unordered_set<int> seen;
  for (int id : options.interface_ids) {
    const std::size_t gi = grid_of(model, id, "interface node");
    if (!seen.insert(id).second)
      throw InputError(deck + ": interface node " + std::to_string(id) + " is listed twice; expected each node once");
    if (const std::string why = not_free_reason(model, c, gi); !why.empty())
      throw InputError(deck + ": interface node " + std::to_string(id) + ": " + why +
                       "; an interface node needs all six dofs free");
    interface_index.push_back(gi);
  }

  // Mass properties of the full model (the analysis mass: WTMASS applied, DMIG M2GG included).
  Eigen::Matrix<double, 6, 6> M0;
  {
    const Eigen::MatrixXd D = rigid_modes_g(model, g.dofs, axes, Eigen::Vector3d::Zero());
    M0 = D.transpose() * (g.M * D);
  }
  const RigidMass rm = rigid_mass(M0, Eigen::Vector3d::Zero());

  // Frame node.
  std::size_t frame = 0;
  if (options.frame_node) {
    frame = grid_of(model, *options.frame_node, "frame node");
    if (seen.count(*options.frame_node))
      throw InputError(deck + ": frame node " + std::to_string(*options.frame_node) +
                       " is an interface node; expected a grid that is not on the interface");
    if (const std::string why = not_free_reason(model, c, frame); !why.empty())
      throw InputError(deck + ": frame node " + std::to_string(*options.frame_node) + ": " + why +
                       "; the frame node needs all six dofs free");
  } else {
    Eigen::Vector3d target = rm.cg;
    if (!(rm.mass > 0)) {  // no mass: the centroid of the grids
      target.setZero();
      for (const fem::Grid& gr : model.grids) target += gr.x_basic;
      target /= static_cast<double>(std::max<std::size_t>(1, model.grids.size()));
    }
    double best = std::numeric_limits<double>::infinity();
    bool found = false;
    for (std::size_t i = 0; i < model.grids.size(); ++i) {
      if (seen.count(model.grids[i].id) || !not_free_reason(model, c, i).empty()) continue;
      const double d = (model.grids[i].x_basic - target).norm();
      if (d < best || (d == best && model.grids[i].id < model.grids[frame].id)) {
        best = d;
        frame = i;
        found = true;
      }
    }
    if (!found)
      throw InputError(deck +
                       ": no grid with six free dofs besides the interface nodes; expected one to carry the "
                       "floating frame (name it with --frame)");
    inf.frame_chosen = true;
  }
  const Eigen::Vector3d X_f = model.grids[frame].x_basic;

  // 3. Craig-Bampton on the interface f-dofs.
  std::vector<Eigen::Index> boundary;
  for (std::size_t gi : interface_index)
    for (int k = 0; k < 6; ++k) boundary.push_back(c.g_to_f[6 * gi + static_cast<std::size_t>(k)]);
  // With the geometric-stiffness invariants: the inertia load cases ride on the factor of K_ii.
  const bool stiffening = options.stiffening;
  CraigBamptonOptions cbo = options.modes;
  const auto t_loads = std::chrono::steady_clock::now();
  if (stiffening) cbo.interior_loads = Eigen::MatrixXd(c.T.transpose() * inertia_load_cases(model, g.dofs, g.M, X_f));
  double seconds_stiffening = std::chrono::duration<double>(std::chrono::steady_clock::now() - t_loads).count();
  CraigBamptonBasis cb;
  try {
    cb = partitioned ? options.basis(boundary, cbo) : craig_bampton(c.K_ff, c.M_ff, boundary, cbo);
  } catch (const linalg::FactorizationError& e) {
    std::vector<char> is_b(static_cast<std::size_t>(c.n_free()), 0);
    for (Eigen::Index f : boundary) is_b[static_cast<std::size_t>(f)] = 1;
    Eigen::Index k = -1, f = 0;
    for (; f < c.n_free(); ++f)
      if (!is_b[static_cast<std::size_t>(f)] && ++k == e.column()) break;
    std::string where = "a dof";
    if (f < c.n_free()) {
      const fem::DofLabel l = fem::dof_label(model, g.dofs, c.f_to_g[static_cast<std::size_t>(f)]);
      where = l.scalar_point ? "scalar point " + std::to_string(l.point_id)
                             : "grid " + std::to_string(l.point_id) + " component " + std::to_string(l.component);
    }
    throw InputError(deck + ": with the interface nodes held, " + where +
                     " has no stiffness: part of the model is connected to no interface node, or is a mechanism; "
                     "expected every part to be held by the interface (check connectivity or add an interface node)");
  }
  inf.stats = cb.stats;
  c.K_ff = linalg::SparseMatrixd();

  // Constraint-mode columns in basic components: q_cd = blockdiag(A^T) q_basic.
  const auto nb = static_cast<Eigen::Index>(boundary.size());
  const Eigen::Index m = cb.Phi.cols(), n = nb + m;
  Eigen::MatrixXd Rb = Eigen::MatrixXd::Identity(nb, nb);
  for (std::size_t j = 0; j < interface_index.size(); ++j)
    Rb.block<6, 6>(static_cast<Eigen::Index>(6 * j), static_cast<Eigen::Index>(6 * j)) =
        cd_to_basic(axes[interface_index[j]]).transpose();
  cb.Psi = cb.Psi * Rb;
  cb.K.topLeftCorner(nb, nb) = Rb.transpose() * cb.K.topLeftCorner(nb, nb) * Rb;
  cb.M.topLeftCorner(nb, nb) = Rb.transpose() * cb.M.topLeftCorner(nb, nb) * Rb;
  if (m > 0) {
    cb.M.bottomLeftCorner(m, nb) = cb.M.bottomLeftCorner(m, nb) * Rb;
    cb.M.topRightCorner(nb, m) = cb.M.bottomLeftCorner(m, nb).transpose();
  }

  se::Superelement s;
  s.name = options.name;
  s.seflex_version = kVersion;
  for (const solutions::CardUse& u : usage.uses)  // the warnings about the deck, kept with the file
    if (u.kind != solutions::CardUse::Kind::Refused) s.source_warnings.push_back(solutions::describe(model, u));
  s.frame_node_id = model.grids[frame].id;
  s.p_OBo = X_f;
  for (std::size_t gi : interface_index) {
    se::InterfaceNode node;
    node.id = model.grids[gi].id;
    node.p_BoN_B = model.grids[gi].x_basic - X_f;
    s.interfaces.push_back(node);
  }
  s.num_modes = static_cast<int>(m);
  s.mode_frequencies_hz = cb.eigenvalues.unaryExpr([](double l) { return eigenvalue_to_hz(l); });
  s.K = cb.K;
  s.M = cb.M;
  s.mass = rm.mass;
  s.p_BoCm_B = rm.cg - X_f;
  s.I_Cm_B = rm.I_cg;
  s.truncation = truncation_report(cb, c.M_ff, interface_rigid_modes(s));
  c.M_ff = linalg::SparseMatrixd();

  if (stiffening) {
    const auto t0 = std::chrono::steady_clock::now();
    Eigen::MatrixXd B_f(cb.Psi.rows(), n);
    B_f << cb.Psi, cb.Phi;
    if (!options.sum_stiffening) {
      s.stiffening = compute_stiffening_invariants(model, g.dofs, c.T, B_f, nb, cb.static_responses);
    } else {  // this rank's share of the cases, then the sum over the ranks (collective even on failure)
      std::exception_ptr error;
      try {
        s.stiffening = compute_stiffening_invariants(model, g.dofs, c.T, B_f, nb, cb.static_responses,
                                                     options.stiffening_rank, options.stiffening_ranks);
      } catch (...) {
        error = std::current_exception();
      }
      std::vector<double*> matrices;
      if (!error) {
        for (Eigen::MatrixXd& G : s.stiffening.inertia) matrices.push_back(G.data());
        for (Eigen::MatrixXd& G : s.stiffening.interface) matrices.push_back(G.data());
      }
      options.sum_stiffening(matrices, static_cast<std::size_t>(n * n), error != nullptr);
      if (error) std::rethrow_exception(error);
    }
    seconds_stiffening += std::chrono::duration<double>(std::chrono::steady_clock::now() - t0).count();
    inf.seconds_stiffening = seconds_stiffening;
  }

  // 4. Recovery to every grid (basic components) and the frame node's rows.
  const auto ng = static_cast<Eigen::Index>(model.grids.size());
  auto to_basic_rows = [&](Eigen::MatrixXd& U, Eigen::Index first_grid) {
    for (Eigen::Index i = 0; i < U.rows() / 6; ++i)
      if (const auto& A = axes[static_cast<std::size_t>(first_grid + i)]) {
        U.middleRows<3>(6 * i) = *A * U.middleRows<3>(6 * i);
        U.middleRows<3>(6 * i + 3) = *A * U.middleRows<3>(6 * i + 3);
      }
  };
  s.recovery.resize(6 * ng, n);
  s.recovery.leftCols(nb) = Eigen::MatrixXd(c.T * cb.Psi).topRows(6 * ng);
  if (m > 0) s.recovery.rightCols(m) = Eigen::MatrixXd(c.T * cb.Phi).topRows(6 * ng);
  if (options.stress_elements && stress) {  // stress modes: element results of each basis vector (g-set, CD components)
    const fem::ElementResultMap map = fem::make_element_result_map(model, *options.stress_elements);
    inf.stress_missing = map.missing;
    if (!map.entries.empty()) {
      Eigen::MatrixXd U_g(c.T.rows(), n);
      U_g.leftCols(nb) = c.T * cb.Psi;
      if (m > 0) U_g.rightCols(m) = c.T * cb.Phi;
      stress->S = map.apply_columns(U_g);
      for (const auto& e : map.entries) {
        stress->element_ids.push_back(e.id);
        stress->kinds.push_back(static_cast<std::int32_t>(e.kind));
        stress->rows.push_back(static_cast<std::int32_t>(e.row));
      }
    }
  }
  to_basic_rows(s.recovery, 0);
  s.Phi_f = s.recovery.middleRows(6 * static_cast<Eigen::Index>(frame), 6);

  // 5. Full-mesh data.
  s.fe_node_ids.reserve(model.grids.size());
  s.p_BoI_B.resize(3, ng);
  for (Eigen::Index i = 0; i < ng; ++i) {
    s.fe_node_ids.push_back(model.grids[static_cast<std::size_t>(i)].id);
    s.p_BoI_B.col(i) = model.grids[static_cast<std::size_t>(i)].x_basic - X_f;
  }
  {
    std::vector<Eigen::Triplet<double>> t;
    t.reserve(static_cast<std::size_t>(6 * ng * 2));
    for (Eigen::Index i = 0; i < ng; ++i) {
      const Eigen::Matrix<double, 6, 6> B = cd_to_basic(axes[static_cast<std::size_t>(i)]);
      for (int r = 0; r < 6; ++r)
        for (int k = 0; k < 6; ++k)
          if (B(r, k) != 0) t.emplace_back(6 * i + r, 6 * i + k, B(r, k));
    }
    linalg::SparseMatrixd A(6 * ng, g.dofs.size());
    A.setFromTriplets(t.begin(), t.end());
    s.M_fe = A * g.M * linalg::SparseMatrixd(A.transpose());
    s.M_fe.prune(0.0, 0.0);
  }
  // 6. Inertia invariants (the full inertia without the mesh), then the mesh part if it is wanted.
  s.invariants = se::compute_inertia_invariants(s);
  if (options.full_mesh) {
    s.cells = mesh_cells(model);
  } else {
    s.recovery.resize(0, 0);
    s.M_fe.resize(0, 0);
    s.fe_node_ids.clear();
    s.p_BoI_B.resize(3, 0);
  }
  return s;
}

}  // namespace seflex::reduction
