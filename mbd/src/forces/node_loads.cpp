// Node loads: world-fixed or follower force and moment, times the load's time history and the
// assembly's load factor. A follower load F_W = R_WN F_N adds the load stiffness [F_W~] on the
// node's rotation columns (residual = ... - F_W).
#include "assembly/assembly_detail.hpp"
#include "seflex/common/so3.hpp"

namespace seflex::mbd::detail {

void assemble_loads(const Model& model, const State& s, Data& data, const AssemblyOptions& opt) {
  for (const NodeLoad& load : model.loads) {
    const double factor = opt.load_factor * (load.scale ? load.scale(s.t) : 1.0);
    NodeKinematics& nk = data.nodes[static_cast<std::size_t>(load.node.value)];
    Vector6d F;
    F.head<3>() = factor * (load.follower ? Eigen::Vector3d(nk.R * load.force) : load.force);
    F.tail<3>() = factor * (load.follower ? Eigen::Vector3d(nk.R * load.moment) : load.moment);
    nk.wrench -= F;
    const int ci = data.clique_of_node[static_cast<std::size_t>(load.node.value)];
    const auto& cdofs = data.pattern.dofs[static_cast<std::size_t>(ci)];
    const int nc = static_cast<int>(cdofs.size());
    if (nc == 0) continue;
    const auto& J = nk.J;  // columns of the node's Jacobian, one per clique dof
    for (int k = 0; k < nc; ++k) data.scale[cdofs[static_cast<std::size_t>(k)]] += std::abs(J[static_cast<std::size_t>(k)].dot(F));
    if (opt.matrices && load.follower) {
      Eigen::Matrix<double, 6, 6> K6 = Eigen::Matrix<double, 6, 6>::Zero();
      K6.block<3, 3>(0, 3) = so3::skew(F.head<3>());
      K6.block<3, 3>(3, 3) = so3::skew(F.tail<3>());
      const auto& off = data.pattern.offsets[static_cast<std::size_t>(ci)];
      for (int b = 0; b < nc; ++b) {  // J^T K6 J, entry by entry (no temporaries)
        const Vector6d KJb = K6 * J[static_cast<std::size_t>(b)];
        for (int a = 0; a < nc; ++a)
          data.K[static_cast<std::size_t>(off[static_cast<std::size_t>(a + nc * b)])] += J[static_cast<std::size_t>(a)].dot(KJb);
      }
    }
  }
}

void assemble_force_elements(const Model& model, const State& s, Data& data, const AssemblyOptions& opt) {
  Eigen::VectorXd& phi = data.hinge_phi;
  Eigen::VectorXd& phidot = data.hinge_phidot;
  phi.resize(static_cast<Eigen::Index>(model.hinges.size()));
  phidot.resize(phi.size());
  for (std::size_t h = 0; h < model.hinges.size(); ++h) {
    phi[static_cast<Eigen::Index>(h)] = data.hinges[h].phi;
    phidot[static_cast<Eigen::Index>(h)] = data.hinges[h].phidot;
  }
  const HingeValues hv{phi, phidot};
  for (std::size_t i = 0; i < model.force_elements.size(); ++i) {
    const bool latched = i < s.locks.size() && s.locks[i].latched;
    HingeForceResult& r = data.forces[i];
    evaluate(model.force_elements[i].element, hv, latched, r);
    const int ci = data.clique_of_force[i];
    const auto& cdofs = data.pattern.dofs[static_cast<std::size_t>(ci)];
    const auto& off = data.pattern.offsets[static_cast<std::size_t>(ci)];
    const auto nc = cdofs.size();
    const int nh = static_cast<int>(r.hinges.size());
    std::vector<int>& pos = data.force_pos;
    pos.assign(static_cast<std::size_t>(nh), -1);
    for (int a = 0; a < nh; ++a) {
      const Hinge& hg = model.hinge(r.hinges[static_cast<std::size_t>(a)]);
      data.hinges[static_cast<std::size_t>(r.hinges[static_cast<std::size_t>(a)].value)].joint_torque -= r.tau[a];
      if (hg.dof < 0) continue;
      data.residual[hg.dof] -= r.tau[a];
      data.scale[hg.dof] += std::abs(r.tau[a]);
      pos[static_cast<std::size_t>(a)] = static_cast<int>(std::lower_bound(cdofs.begin(), cdofs.end(), hg.dof) - cdofs.begin());
    }
    if (!opt.matrices) continue;
    for (int a = 0; a < nh; ++a)
      for (int b = 0; b < nh; ++b) {
        const int pa = pos[static_cast<std::size_t>(a)], pb = pos[static_cast<std::size_t>(b)];
        if (pa < 0 || pb < 0) continue;
        const auto idx = static_cast<std::size_t>(off[static_cast<std::size_t>(pa) + nc * static_cast<std::size_t>(pb)]);
        data.K[idx] -= r.dtau_dphi(a, b);
        if (opt.dynamics) data.C[idx] -= r.dtau_dphidot(a, b);
      }
  }
}

}  // namespace seflex::mbd::detail
