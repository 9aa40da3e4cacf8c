// The assembly loop: bodies and loads put wrenches on nodes; a backward pass over the node forest
// turns them into generalised forces (Free node: its subtree wrench; hinge: a_W . subtree moment)
// and adds the geometric stiffness of the node tree. For a rotation-type dof i (a Free node's
// spatial rotation about e_i, or a hinge about a_W) with pivot o and axis w_i:
//   Q_i = w_i . sum_k [(p_k - p_o) x f_k + m_k]          (k in the subtree of o)
//   dQ_i = dw_i . M_o + w_i . sum_k (dp_k - dp_o) x f_k,  dw_i = dpi_P x w_i for a hinge
// which for a single hinge reduces to the extra term ((R_p a) x m_c)^T of formulation 4.3.
#include <Eigen/Dense>

#include "assembly/assembly_detail.hpp"
#include "seflex/common/error.hpp"

namespace seflex::mbd {

using Eigen::Vector3d;

namespace {

Vector3d dof_axis(const Model& model, const Data& data, int dof) {
  const char kind = model.dof_kind[static_cast<std::size_t>(dof)];
  if (kind == 'h') return data.hinges[static_cast<std::size_t>(model.dof_owner[static_cast<std::size_t>(dof)])].axis_W;
  const Node& n = model.nodes[static_cast<std::size_t>(model.dof_node[static_cast<std::size_t>(dof)])];
  return Vector3d::Unit(dof - n.dof - 3);
}

void tree_pass(const Model& model, Data& data, bool matrices) {
  const std::size_t nn = model.nodes.size();
  for (std::size_t k = 0; k < nn; ++k) data.nodes[k].subtree = data.nodes[k].wrench;
  for (std::size_t k = nn; k-- > 0;) {
    const Node& n = model.nodes[k];
    NodeKinematics& nk = data.nodes[k];
    if (n.kind == NodeKind::Attached) {
      NodeKinematics& P = data.nodes[static_cast<std::size_t>(n.parent.value)];
      P.subtree.head<3>() += nk.subtree.head<3>();
      P.subtree.tail<3>() += nk.subtree.tail<3>() + (nk.p - P.p).cross(nk.subtree.head<3>());
      if (n.hinge.valid()) {
        HingeKinematics& hk = data.hinges[static_cast<std::size_t>(n.hinge.value)];
        const double Q = hk.axis_W.dot(nk.subtree.tail<3>());
        hk.joint_torque = Q;
        const int dof = model.hinge(n.hinge).dof;
        if (dof >= 0) data.residual[dof] += Q;
      }
    } else if (n.kind == NodeKind::Free) {
      data.residual.segment<6>(n.dof) += nk.subtree;
    }
  }
  if (!matrices) return;
  for (std::size_t k = 0; k < nn; ++k) {
    const auto& dofs = model.node_dofs[k];
    const auto nd = dofs.size();
    if (nd == 0) continue;
    const NodeKinematics& nk = data.nodes[k];
    const auto& off = data.pattern.offsets[static_cast<std::size_t>(data.clique_of_node[k])];
    const Vector3d f = nk.wrench.head<3>();
    const bool loaded = f.squaredNorm() > 0.0;
    for (std::size_t a = 0; a < nd; ++a) {
      const char kind = model.dof_kind[static_cast<std::size_t>(dofs[a])];
      if (kind != 'r' && kind != 'h') continue;
      const Vector3d wi = dof_axis(model, data, dofs[a]);
      // Subtree-independent part: sum over loaded nodes k in the subtree of dof a.
      if (loaded) {
        const Vector3d t = f.cross(wi);
        for (std::size_t b = 0; b < nd; ++b) data.K[static_cast<std::size_t>(off[a + nd * b])] += t.dot(nk.J[b].head<3>());
      }
      // Pivot part: only at the pivot node of dof a.
      if (model.dof_node[static_cast<std::size_t>(dofs[a])] != static_cast<int>(k)) continue;
      const Vector3d t = nk.subtree.head<3>().cross(wi);
      for (std::size_t b = 0; b < nd; ++b) data.K[static_cast<std::size_t>(off[a + nd * b])] -= t.dot(nk.J[b].head<3>());
      if (kind == 'h') {
        const NodeKinematics& P = data.nodes[static_cast<std::size_t>(model.nodes[k].parent.value)];
        const Vector3d u = wi.cross(nk.subtree.tail<3>());
        for (std::size_t b = 0; b < P.J.size(); ++b) data.K[static_cast<std::size_t>(off[a + nd * b])] += u.dot(P.J[b].tail<3>());
      }
    }
  }
}

}  // namespace

namespace detail {

bool convective_map(const ElementMap& map, const std::vector<const std::vector<Vector6d>*>& G, ElementMap& out) {
  out = map;
  out.J = G;
  bool any = false;
  for (std::size_t i = 0; i < G.size(); ++i) {
    out.identity[i] = 0;
    if (!map.identity[i]) any = true;
  }
  out.extra = nullptr;
  return any;
}

namespace {

/// Y_j = X(:, block j) R_j for every node block j of the right map (a Free node's identity block: the
/// block itself).
void column_blocks(const ElementMap& R, const Eigen::MatrixXd& X, std::vector<Eigen::MatrixXd>& Y) {
  const int nb = static_cast<int>(R.J.size());
  Y.resize(static_cast<std::size_t>(nb));
  for (int j = 0; j < nb; ++j) {
    const auto& Jj = *R.J[static_cast<std::size_t>(j)];
    Eigen::MatrixXd& Yj = Y[static_cast<std::size_t>(j)];
    if (R.identity[static_cast<std::size_t>(j)]) {
      Yj = X.middleCols<6>(6 * j);
      continue;
    }
    Yj.resize(X.rows(), static_cast<Eigen::Index>(Jj.size()));
    for (std::size_t c = 0; c < Jj.size(); ++c) Yj.col(static_cast<Eigen::Index>(c)).noalias() = X.middleCols<6>(6 * j) * Jj[c];
  }
}

/// vals += L^T [Y_j]_j on the node columns (positions of R) and X's modal columns, rows and corner.
void scatter_blocks(std::vector<double>& vals, const std::vector<int>& offsets, int nc, const ElementMap& L,
                    const ElementMap& R, const Eigen::MatrixXd& X, const std::vector<Eigen::MatrixXd>& Y) {
  const int nb = static_cast<int>(L.J.size());
  const int ne = L.extra ? static_cast<int>(L.extra->size()) : 0;
  const int ner = R.extra ? static_cast<int>(R.extra->size()) : 0;
  auto put = [&](int a, int b, double v) {
    vals[static_cast<std::size_t>(offsets[static_cast<std::size_t>(a + nc * b)])] += v;
  };
  for (int i = 0; i < nb; ++i) {
    const auto& Ji = *L.J[static_cast<std::size_t>(i)];
    const auto& pi = *L.pos[static_cast<std::size_t>(i)];
    const bool idi = L.identity[static_cast<std::size_t>(i)];
    for (int j = 0; j < nb; ++j) {
      const auto& Yj = Y[static_cast<std::size_t>(j)];
      const auto& pj = *R.pos[static_cast<std::size_t>(j)];
      for (Eigen::Index b = 0; b < Yj.cols(); ++b)
        for (std::size_t a = 0; a < Ji.size(); ++a) {
          const double v = idi ? Yj(6 * i + static_cast<Eigen::Index>(a), b) : Ji[a].dot(Yj.block<6, 1>(6 * i, b));
          put(pi[a], pj[static_cast<std::size_t>(b)], v);
        }
    }
    for (int k = 0; k < ner; ++k) {  // node rows, modal columns
      const int pk = (*R.extra)[static_cast<std::size_t>(k)];
      const auto col = X.block<6, 1>(6 * i, 6 * nb + k);
      for (std::size_t a = 0; a < Ji.size(); ++a) put(pi[a], pk, idi ? col[static_cast<Eigen::Index>(a)] : Ji[a].dot(col));
    }
  }
  for (int k = 0; k < ne; ++k) {
    const int pk = (*L.extra)[static_cast<std::size_t>(k)];
    for (int j = 0; j < nb; ++j) {  // modal rows, node columns
      const auto& Yj = Y[static_cast<std::size_t>(j)];
      const auto& pj = *R.pos[static_cast<std::size_t>(j)];
      for (Eigen::Index b = 0; b < Yj.cols(); ++b) put(pk, pj[static_cast<std::size_t>(b)], Yj(6 * nb + k, b));
    }
    for (int l = 0; l < ner; ++l) put(pk, (*R.extra)[static_cast<std::size_t>(l)], X(6 * nb + k, 6 * nb + l));
  }
}

}  // namespace

void scatter_mapped(std::vector<double>& vals, const std::vector<int>& offsets, int nc, const ElementMap& map,
                    const Eigen::MatrixXd& X, std::vector<Eigen::MatrixXd>& Y, const ElementMap* right) {
  const ElementMap& R = right ? *right : map;
  column_blocks(R, X, Y);
  scatter_blocks(vals, offsets, nc, map, R, X, Y);
}

void scatter_iteration(std::vector<double>& vals, const std::vector<int>& offsets, int nc, const ElementMap& map,
                       const NodeSpaceIteration& it, std::vector<Eigen::MatrixXd>& Y) {
  const Eigen::MatrixXd& X = *it.X;
  column_blocks(map, X, Y);
  const auto nb = map.J.size();
  for (std::size_t j = 0; j < nb; ++j) {
    Eigen::MatrixXd& Yj = Y[j];
    const auto& Jj = *map.J[j];
    // K's rotation columns of a Free node r times T_r: the columns (J T_r - J) of the K share.
    if (it.T && it.K)
      for (const auto& [c0, r] : *(*it.triples)[j]) {
        const Eigen::Matrix3d D = (*it.T)[static_cast<std::size_t>(r)] - Eigen::Matrix3d::Identity();
        for (int l = 0; l < 3; ++l) {
          Vector6d dJ = Vector6d::Zero();
          for (int q = 0; q < 3; ++q) dJ += D(q, l) * Jj[static_cast<std::size_t>(c0 + q)];
          Yj.col(c0 + l).noalias() += (it.cK * it.K->middleCols<6>(6 * static_cast<Eigen::Index>(j))) * dJ;
        }
      }
    // The convective term of the node tree, M G (zero on Free nodes; a null G: zero).
    if (it.M && (*it.G)[j] && !map.identity[j]) {
      const auto& Gj = *(*it.G)[j];
      for (std::size_t c = 0; c < Gj.size(); ++c)
        Yj.col(static_cast<Eigen::Index>(c)).noalias() += (it.cC * it.M->middleCols<6>(6 * static_cast<Eigen::Index>(j))) * Gj[c];
    }
  }
  scatter_blocks(vals, offsets, nc, map, map, X, Y);
}

void add_mapped_abs(Eigen::VectorXd& out, const ElementMap& map, const Eigen::VectorXd& f) {
  const int nb = static_cast<int>(map.J.size());
  for (int i = 0; i < nb; ++i) {
    const auto& Ji = *map.J[static_cast<std::size_t>(i)];
    const auto& pi = *map.pos[static_cast<std::size_t>(i)];
    for (std::size_t a = 0; a < Ji.size(); ++a) out[pi[a]] += std::abs(Ji[a].dot(f.segment<6>(6 * i)));
  }
  if (map.extra)
    for (std::size_t k = 0; k < map.extra->size(); ++k) out[(*map.extra)[k]] += std::abs(f[6 * nb + static_cast<Eigen::Index>(k)]);
}

}  // namespace detail

void assemble(const Model& model, const State& s, Data& data, const AssemblyOptions& opt) {
  SEFLEX_DEMAND(!(opt.energies_only && opt.matrices), "assemble: energies_only evaluates no matrices");
  update_kinematics(model, s, data, opt.dynamics);
  for (auto& nk : data.nodes) nk.wrench.setZero();
  for (auto& hk : data.hinges) hk.joint_torque = 0.0;
  data.residual.setZero();
  data.scale.setZero();
  data.floor.setZero();
  if (opt.matrices) {
    std::fill(data.K.begin(), data.K.end(), 0.0);
    std::fill(data.C.begin(), data.C.end(), 0.0);
    std::fill(data.M.begin(), data.M.end(), 0.0);
  }
  data.S_flex_filled = opt.matrices && opt.iteration != nullptr;
  if (data.S_flex_filled) {
    std::fill(data.S_flex.begin(), data.S_flex.end(), 0.0);
    data.S_flex_for = *opt.iteration;
  }
  for (int b = 0; b < static_cast<int>(model.flexible_bodies.size()); ++b) detail::assemble_flexible(model, s, data, opt, b);
  for (int b = 0; b < static_cast<int>(model.rigid_bodies.size()); ++b) detail::assemble_rigid(model, data, opt, b);
  if (opt.energies_only) {  // the force elements' values and energies; no joint torques
    detail::assemble_force_elements(model, s, data, opt);
    for (auto& hk : data.hinges) hk.joint_torque = 0.0;
    return;
  }
  detail::assemble_loads(model, s, data, opt);
  tree_pass(model, data, opt.matrices);
  detail::assemble_force_elements(model, s, data, opt);
}

void combine_matrices(const Model& model, Data& data, double cK, double cC, double cM,
                      const std::vector<Eigen::Matrix3d>* rotation_jacobians, Eigen::SparseMatrix<double>& S) {
  if (S.nonZeros() != data.pattern.matrix.nonZeros()) S = data.pattern.matrix;
  double* val = S.valuePtr();
  const auto nnz = static_cast<std::size_t>(S.nonZeros());
  const std::vector<double>* Kp = &data.K;
  if (rotation_jacobians) {
    std::vector<double>& Kv = data.K_rotated;
    Kv = data.K;  // same size after the first call: no allocation
    const int* outer = S.outerIndexPtr();
    const int* inner = S.innerIndexPtr();
    SEFLEX_DEMAND(rotation_jacobians->size() == model.rotation_dof_starts.size(), "one tangent operator per free node");
    for (std::size_t r = 0; r < model.rotation_dof_starts.size(); ++r) {
      const int c0 = model.rotation_dof_starts[r];
      const int len = outer[c0 + 1] - outer[c0];
      SEFLEX_DEMAND(outer[c0 + 2] - outer[c0 + 1] == len && outer[c0 + 3] - outer[c0 + 2] == len,
                    "rotation columns of a node must share their pattern");
      const Eigen::Matrix3d& T = (*rotation_jacobians)[r];
      for (int q = 0; q < len; ++q) {
        const int i0 = outer[c0] + q, i1 = outer[c0 + 1] + q, i2 = outer[c0 + 2] + q;
        SEFLEX_DEMAND(inner[i0] == inner[i1] && inner[i0] == inner[i2], "rotation columns of a node must share their pattern");
        const Eigen::RowVector3d row(data.K[static_cast<std::size_t>(i0)], data.K[static_cast<std::size_t>(i1)],
                                     data.K[static_cast<std::size_t>(i2)]);
        const Eigen::RowVector3d out = row * T;
        Kv[static_cast<std::size_t>(i0)] = out[0];
        Kv[static_cast<std::size_t>(i1)] = out[1];
        Kv[static_cast<std::size_t>(i2)] = out[2];
      }
    }
    Kp = &Kv;
  }
  for (std::size_t i = 0; i < nnz; ++i) val[i] = cK * (*Kp)[i] + cC * data.C[i] + cM * data.M[i];
  if (data.S_flex_filled) {
    const IterationMatrix& f = data.S_flex_for;
    SEFLEX_DEMAND(f.cK == cK && f.cC == cC && f.cM == cM && f.rotation_jacobians == rotation_jacobians,
                  "combine_matrices: the coefficients of the assembly's iteration matrix (AssemblyOptions::iteration)");
    for (std::size_t i = 0; i < nnz; ++i) val[i] += data.S_flex[i];
  }
}

}  // namespace seflex::mbd
