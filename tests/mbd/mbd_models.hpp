#pragma once
// Small models shared by the multibody tests: rigid rods, flexible pendulum chains, and an
// observer that keeps every sample.
#include <Eigen/Dense>
#include <Eigen/Eigenvalues>
#include <Eigen/Sparse>
#include <cmath>
#include <functional>
#include <string>
#include <utility>
#include <vector>

#include "beam_superelement.hpp"
#include "seflex/mbd/assembly/assembly.hpp"
#include "seflex/mbd/solvers/integrator.hpp"
#include "seflex/mbd/model.hpp"

namespace seflex::test {

/// A rigid uniform rod (no stiffness data): mass m, length L along x, interfaces at both ends,
/// frame at the centre. Only a rigid body can use it.
inline se::Superelement rod(double L, double m, const std::string& name = "rod") {
  se::Superelement s;
  s.name = name;
  for (int j = 0; j < 2; ++j) {
    se::InterfaceNode itf;
    itf.id = j + 1;
    itf.p_BoN_B = Eigen::Vector3d((j == 0 ? -0.5 : 0.5) * L, 0, 0);
    s.interfaces.push_back(itf);
  }
  s.mass = m;
  s.I_Cm_B = Eigen::Vector3d(1e-6 * m * L * L, m * L * L / 12, m * L * L / 12).asDiagonal();
  return s;
}

/// The spin-up beam of Simo and Vu-Quoc (1986): EI = 1.4e4 N m^2, EA = 2.8e7 N, rho A = 1.2 kg/m
/// (L = 10 m), as a section of the given area (the area sets only the torsion and rotary terms).
inline BeamSection spinup_section(double area) {
  const double EI = 1.4e4, EA = 2.8e7, rhoA = 1.2;
  BeamSection sec;
  sec.A = area;
  sec.E = EA / sec.A;
  sec.G = sec.E / 2.6;
  sec.Iz = sec.Iy = EI / sec.E;
  sec.J = 2 * sec.Iz;
  sec.rho = rhoA / sec.A;
  return sec;
}

/// A beam of length L along x cut into `bodies` AIC superelements `segment` (interfaces at its ends)
/// on a hub hinge about z with the prescribed motion `drive` (the spin-up tests).
inline mbd::Model spinning_beam(const se::Superelement& segment, int bodies, double L, mbd::InertiaModel inertia,
                                mbd::Drive drive) {
  using Eigen::Matrix3d;
  using Eigen::Vector3d;
  mbd::ModelBuilder mb;
  const auto sei = mb.add_superelement(segment);
  mbd::HingeOptions ho;
  ho.drive = std::move(drive);
  const auto h = mb.add_hinge("hub", mb.add_ground("hub axis", mbd::Pose{}), Vector3d::UnitZ(), ho);
  mbd::NodeIndex prev = mb.hinge_child(h);
  mbd::FlexibleBodyOptions fo;
  fo.inertia = inertia;
  for (int b = 0; b < bodies; ++b) {
    const auto n = mb.add_node("n" + std::to_string(b + 1), mbd::Pose{Matrix3d::Identity(), Vector3d((b + 1) * L / bodies, 0, 0)});
    mb.add_flexible_body("segment" + std::to_string(b + 1), sei, {prev, n},
                         mbd::Pose{Matrix3d::Identity(), Vector3d((b + 0.5) * L / bodies, 0, 0)}, fo);
    prev = n;
  }
  return mb.build();
}

/// Keeps every sample.
struct Recorder : mbd::Observer {
  std::vector<mbd::Sample> samples;
  void on_sample(const mbd::Model&, const mbd::Sample& s) override { samples.push_back(s); }
};

/// The tip of a spinning beam in the hub frame at each recorded sample (spin-up tests): the last
/// node's position rotated back by the first hinge's angle about z, less the undeformed tip (L, 0, 0):
/// v transverse, u axial.
struct HubFrameTip {
  std::vector<double> t, v, u;
};
inline HubFrameTip tip_in_hub_frame(const Recorder& rec, double L) {
  HubFrameTip out;
  for (const auto& smp : rec.samples) {
    const double th = smp.hinges[0].phi;
    const Eigen::Vector3d p = smp.nodes.back().p;
    out.t.push_back(smp.t);
    out.v.push_back(-std::sin(th) * p.x() + std::cos(th) * p.y());
    out.u.push_back(std::cos(th) * p.x() + std::sin(th) * p.y() - L);
  }
  return out;
}

struct ChainOptions {
  int bodies = 2;
  double length = 1.0;          ///< per body
  int elements = 4;             ///< FE elements per body (frame at the middle node)
  BeamSection section;
  mbd::InertiaModel inertia = mbd::InertiaModel::Simplified;
  bool rigid = false;           ///< rigid bodies of the same superelement
  Eigen::Vector3d gravity{0, -9.81, 0};
  Eigen::Vector3d axis{0, 0, 1};  ///< hinge axes (world)
  int frame_node = -1;          ///< FE node of the floating frame (-1: middle)
  int modes = 0;                ///< fixed-interface modes per body
  /// Called before build() with the hinges H1..Hn (e.g. to add force elements).
  std::function<void(mbd::ModelBuilder&, const std::vector<mbd::HingeIndex>&)> extra;
};

/// A pendulum chain hanging from a ground hinge at the origin, bodies along +x (horizontal at
/// t = 0), hinges between consecutive bodies. Returns the model; tip node = last node.
inline mbd::Model pendulum_chain(const ChainOptions& o) {
  using namespace mbd;
  auto fe = straight_beam(o.length, o.elements, o.section);
  const int f = o.frame_node >= 0 ? o.frame_node : o.elements / 2;
  const se::Superelement s = craig_bampton(fe, {0, o.elements}, f, o.modes, "link");
  ModelBuilder mb;
  const auto sei = mb.add_superelement(s);
  NodeIndex base = mb.add_ground("ground", Pose{});
  std::vector<HingeIndex> hinges;
  for (int b = 0; b < o.bodies; ++b) {
    const auto h = mb.add_hinge("H" + std::to_string(b + 1), base, o.axis);
    hinges.push_back(h);
    const Pose X{Eigen::Matrix3d::Identity(), Eigen::Vector3d(b * o.length + fe.pts[f].x(), 0, 0)};
    if (o.rigid) {
      const auto rb = mb.add_rigid_body("link" + std::to_string(b + 1), sei, mb.hinge_child(h), 0, X);
      base = mb.rigid_body(rb).nodes[1];
    } else {
      const auto tip = mb.add_node("n" + std::to_string(b + 1), Pose{Eigen::Matrix3d::Identity(), Eigen::Vector3d((b + 1) * o.length, 0, 0)});
      FlexibleBodyOptions fo;
      fo.inertia = o.inertia;
      mb.add_flexible_body("link" + std::to_string(b + 1), sei, {mb.hinge_child(h), tip}, X, fo);
      base = tip;
    }
  }
  mb.set_gravity(o.gravity);
  if (o.extra) o.extra(mb, hinges);
  return mb.build();
}

/// A rigid rod (1 m, 1 kg: J = 1/3 kg m^2 about its end) on a ground hinge about z, driven by the
/// linear torsion spring tau = tau0 + (tau1 - tau0) phi / phi_ref, with a latching lock at phi_lock of
/// stiffness k_lock (none when k_lock = 0) and damping c_lock.
inline mbd::Model spring_rotor(double tau0, double tau1, double phi_ref, double phi_lock, double k_lock, double c_lock = 0) {
  using namespace mbd;
  ModelBuilder mb;
  const auto r = mb.add_superelement(rod(1.0, 1.0));
  const auto g = mb.add_ground("ground", Pose{});
  const auto h = mb.add_hinge("H", g, Eigen::Vector3d::UnitZ());
  mb.add_rigid_body("rod", r, mb.hinge_child(h), 0, Pose{Eigen::Matrix3d::Identity(), Eigen::Vector3d(0.5, 0, 0)});
  mb.add_force_element("spring", TorsionSpring{h, tau0, tau1, phi_ref, {}, {}});
  if (k_lock > 0) mb.add_force_element("lock", HingeLock{h, phi_lock, k_lock, c_lock});
  return mb.build();
}

/// Highest frequency of the model linearised at its initial state: max sqrt(eig(K, M)).
inline double highest_frequency(const mbd::Model& model) {
  using namespace mbd;
  State s = initial_state(model);
  Data data(model);
  initial_accelerations(model, s, data);
  assemble(model, s, data, AssemblyOptions{});
  Eigen::SparseMatrix<double> K, M;
  combine_matrices(model, data, 1.0, 0.0, 0.0, nullptr, K);
  combine_matrices(model, data, 0.0, 0.0, 1.0, nullptr, M);
  const Eigen::MatrixXd Kd = Eigen::MatrixXd(K), Md = Eigen::MatrixXd(M);
  Eigen::GeneralizedSelfAdjointEigenSolver<Eigen::MatrixXd> es(0.5 * (Kd + Kd.transpose()), 0.5 * (Md + Md.transpose()));
  return std::sqrt(es.eigenvalues().maxCoeff());
}

/// The closed form of spring_rotor's motion (J = 1/3 kg m^2) from rest at phi = 0: J phi'' = tau0 - k phi,
/// phi(t) = (tau0 / k)(1 - cos w t), w = sqrt(k / J), k = (tau0 - tau1) / phi_ref, reaching phi_lock
/// at t_star = acos(1 - k phi_lock / tau0) / w with rate phidot_star; after the latch a harmonic
/// oscillation about phi_eq = (tau0 + k_lock phi_lock) / (k + k_lock) at w_l = sqrt((k + k_lock) / J).
struct SpringRotorMotion {
  double t_star, phidot_star, phi_eq, wl, phi_lock;
  SpringRotorMotion(double tau0, double tau1, double phi_ref, double phi_lock_, double k_lock) : phi_lock(phi_lock_) {
    const double J = 1.0 / 3.0, k = (tau0 - tau1) / phi_ref, w = std::sqrt(k / J);
    t_star = std::acos(1 - k * phi_lock / tau0) / w;
    phidot_star = tau0 / k * w * std::sin(w * t_star);
    phi_eq = (tau0 + k_lock * phi_lock) / (k + k_lock);
    wl = std::sqrt((k + k_lock) / J);
  }
  /// The angle at time t after the latch.
  double phi_after_latch(double t) const {
    const double tau = t - t_star;
    return phi_eq + (phi_lock - phi_eq) * std::cos(wl * tau) + phidot_star / wl * std::sin(wl * tau);
  }
};

}  // namespace seflex::test
