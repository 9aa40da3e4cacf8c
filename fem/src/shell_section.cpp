// Shell sections: PSHELL and PCOMP/PCOMPG resolved to A, B, D, S (see section.hpp).
#include <Eigen/Dense>
#include <cmath>

#include "model_lookup.hpp"
#include "seflex/fem/section.hpp"

namespace seflex::fem {
namespace {

constexpr double kPi = 3.14159265358979323846;
using Lam = CompositeProperty::Lam;

/// The Kirchhoff penalty of a section without transverse shear flexibility: 1000 x the shear
/// stiffness `Sg` of the homogeneous plate with its bending stiffness.
constexpr double kKirchhoffPenalty = 1000.0;

/// Transverse shear of a laminate (section.hpp): S = H^-1, H = int F^T C F dz; false when no ply is
/// compliant in transverse shear (H = 0).
bool laminate_shear(const std::vector<Ply>& plies, double z_bottom, const Eigen::Matrix3d& A, const Eigen::Matrix3d& B,
                    const Eigen::Matrix3d& D, double penalty_compliance, Eigen::Matrix2d& S) {
  Eigen::Matrix<double, 6, 6> ABD;
  ABD << A, B, B, D;
  const Eigen::FullPivLU<Eigen::Matrix<double, 6, 6>> lu(ABD);
  if (!lu.isInvertible()) return false;
  // Mid-plane strains and curvatures of the unit moments M_x and M_y (N = 0, M_xy = 0).
  Eigen::Matrix<double, 6, 2> rhs = Eigen::Matrix<double, 6, 2>::Zero();
  rhs(3, 0) = 1.0;
  rhs(4, 1) = 1.0;
  const Eigen::Matrix<double, 6, 2> ek = lu.solve(rhs);
  const Eigen::Matrix<double, 3, 2> E0 = ek.topRows<3>(), K = ek.bottomRows<3>();
  // g(z) = [sigma_x(Mx) tau_xy(My); tau_xy(Mx) sigma_y(My)]: the in-plane stress derivatives that
  // equilibrium balances with d tau / dz under Q_x = M_x,x and Q_y = M_y,y.
  auto select = [](const Eigen::Matrix<double, 3, 2>& sig) {
    Eigen::Matrix2d g;
    g << sig(0, 0), sig(2, 1), sig(2, 0), sig(1, 1);
    return g;
  };
  static const double gp[3] = {-std::sqrt(0.6), 0.0, std::sqrt(0.6)};
  static const double gw[3] = {5.0 / 9.0, 8.0 / 9.0, 5.0 / 9.0};
  Eigen::Matrix2d H = Eigen::Matrix2d::Zero(), F_bottom = Eigen::Matrix2d::Zero();
  double zb = z_bottom;
  bool compliant = false;
  for (const Ply& p : plies) {
    const double zt = zb + p.t;
    const Eigen::Matrix3d Qb = rotate_plane_matrix(p.material.Q, p.theta);
    const Eigen::Matrix2d Cb = rotate_shear_matrix(p.material.Ct, p.theta);  // compliance rotates as stiffness
    const Eigen::Matrix2d gP = select(Qb * E0), gR = select(Qb * K);         // g(z) = gP + z gR
    auto F = [&](double z) { return Eigen::Matrix2d(-(F_bottom + gP * (z - zb) + gR * (0.5 * (z * z - zb * zb)))); };
    if (Cb.cwiseAbs().maxCoeff() > 0.0) {
      compliant = true;
      for (int q = 0; q < 3; ++q) {  // F^T C F is a quartic in z: three Gauss points are exact
        const double z = 0.5 * (zb + zt) + 0.5 * p.t * gp[q];
        const Eigen::Matrix2d f = F(z);
        H.noalias() += (0.5 * p.t * gw[q]) * f.transpose() * Cb * f;
      }
    }
    F_bottom += gP * (zt - zb) + gR * (0.5 * (zt * zt - zb * zb));
    zb = zt;
  }
  if (!compliant) return false;
  H = 0.5 * (H + H.transpose()).eval();
  // A direction in which every ply is rigid (e.g. MAT8 plies with only G2Z, all at 0 degrees): the
  // Kirchhoff penalty there.
  if (!(H.determinant() > 1e-12 * H.trace() * H.trace())) H += penalty_compliance * Eigen::Matrix2d::Identity();
  S = H.inverse();
  S = 0.5 * (S + S.transpose()).eval();
  return true;
}

/// Plies of LAM = SMCORE: the face plies (all but the last) smeared into one layer of their total
/// thickness (stiffness, compliance, density and G averaged by thickness in laminate axes), half of
/// it below the core and half above.
std::vector<Ply> smcore_plies(const std::vector<Ply>& plies) {
  const Ply& core = plies.back();
  ShellMaterial face;
  face.kind = ShellMaterial::Kind::Mat2;
  double tf = 0.0;
  Eigen::Vector3d Qalpha = Eigen::Vector3d::Zero();  // int Qbar alpha dz of the faces
  for (std::size_t k = 0; k + 1 < plies.size(); ++k) {
    const Ply& p = plies[k];
    face.Q += p.t * rotate_plane_matrix(p.material.Q, p.theta);
    face.Ct += p.t * rotate_shear_matrix(p.material.Ct, p.theta);
    face.G_iso += p.t * p.material.G_iso;
    face.rho += p.t * p.material.rho;
    Qalpha += p.t * (strain_rotation(p.theta).transpose() * (p.material.Q * p.material.alpha));
    tf += p.t;
  }
  face.Q /= tf;
  face.Ct /= tf;
  face.G_iso /= tf;
  face.rho /= tf;
  face.alpha = face.Q.fullPivLu().solve(Qalpha / tf);  // the smeared face's expansion: same N_T
  Ply half{face, 0.5 * tf, 0.0};
  return {half, core, half};
}

}  // namespace

ShellMaterial shell_material(const Mat1& m) {
  ShellMaterial s;
  s.id = m.id;
  s.kind = ShellMaterial::Kind::Mat1;
  s.Q = plane_stress(IsotropicMaterial{m.id, m.E, m.G, m.nu, m.rho});
  s.Gt = m.G * Eigen::Matrix2d::Identity();
  s.has_Gt = true;
  if (m.G > 0.0) s.Ct = Eigen::Matrix2d::Identity() / m.G;
  s.G_iso = m.G;
  s.rho = m.rho;
  s.alpha << m.alpha, m.alpha, 0.0;
  s.tref = m.tref;
  return s;
}

ShellMaterial shell_material(const Mat2& m) {
  ShellMaterial s;
  s.id = m.id;
  s.kind = ShellMaterial::Kind::Mat2;
  s.Q << m.G11, m.G12, m.G13, m.G12, m.G22, m.G23, m.G13, m.G23, m.G33;
  s.Gt << m.G11, m.G12, m.G12, m.G22;
  s.has_Gt = true;
  s.G_iso = orientation_average_shear(s.Q);
  s.rho = m.rho;
  s.alpha << m.a1, m.a2, m.a3;
  s.tref = m.tref;
  return s;
}

ShellMaterial shell_material(const Mat8& m) {
  ShellMaterial s;
  s.id = m.id;
  s.kind = ShellMaterial::Kind::Mat8;
  const double nu21 = m.nu12 * m.E2 / m.E1, den = 1.0 - m.nu12 * nu21;
  s.Q << m.E1 / den, m.nu12 * m.E2 / den, 0.0, m.nu12 * m.E2 / den, m.E2 / den, 0.0, 0.0, 0.0, m.G12;
  s.has_Gt = m.G1z > 0.0 && m.G2z > 0.0;
  if (s.has_Gt) s.Gt << m.G1z, 0.0, 0.0, m.G2z;
  s.Ct << (m.G1z > 0.0 ? 1.0 / m.G1z : 0.0), 0.0, 0.0, (m.G2z > 0.0 ? 1.0 / m.G2z : 0.0);
  s.G_iso = orientation_average_shear(s.Q);
  s.rho = m.rho;
  s.alpha << m.a1, m.a2, 0.0;
  s.tref = m.tref;
  return s;
}

ShellSection pshell_section(const PshellInput& in) {
  ShellSection s;
  const double t = in.t;
  s.t = t;
  s.isotropic = in.mid4 == nullptr;
  for (const ShellMaterial* m : {in.mid1, in.mid2, in.mid3, in.mid4})
    if (m && m->kind != ShellMaterial::Kind::Mat1) s.isotropic = false;
  if (in.mid1) {
    s.has_membrane = true;
    s.A = t * in.mid1->Q;
    s.drill_Gt = in.mid1->G_iso * t;
    s.NT = t * (in.mid1->Q * in.mid1->alpha);
    s.tref = in.mid1->tref;
  } else if (in.mid2) {
    s.tref = in.mid2->tref;
  }
  double G2 = 0.0;
  if (in.mid2) {
    s.has_bending = true;
    G2 = in.mid2->G_iso;
    s.D = in.bend_ratio * t * t * t / 12.0 * in.mid2->Q;
  }
  if (in.mid4) s.B = t * t * in.mid4->Q;
  // Transverse shear: G3 TS; MID3 blank: Kirchhoff (penalty 1000 x (5/6) G2 t_b, t_b = (12 I)^(1/3)
  // the thickness of the homogeneous plate with the section's bending stiffness).
  double Sg = 0.0;
  if (in.mid3) {
    s.shear_flexible = true;
    s.S = in.mid3->Gt * in.ts_t * t;
    Sg = 0.5 * s.S.trace();
  } else if (in.mid2) {
    Sg = (5.0 / 6.0) * G2 * std::cbrt(in.bend_ratio) * t;
    s.S = (kKirchhoffPenalty * Sg) * Eigen::Matrix2d::Identity();
  }
  s.ts2 = (!in.mid2 || !(Sg > 0.0)) ? t * t : (5.0 / 6.0) * G2 * in.bend_ratio * t * t * t / Sg;
  const double rho = in.mid1 ? in.mid1->rho : in.mid2 ? in.mid2->rho : 0.0;
  s.mass_per_area_value = rho * t + in.nsm;
  return s;
}

ShellSection laminate_section(std::vector<Ply> plies, std::optional<double> z0, double nsm, Lam lam) {
  if (lam == Lam::Sym) {
    const std::size_t n = plies.size();
    plies.reserve(2 * n);  // no reallocation while plies[k] is copied
    for (std::size_t k = n; k-- > 0;) plies.push_back(plies[k]);
  }
  if (lam == Lam::SmCore && plies.size() >= 2) plies = smcore_plies(plies);
  ShellSection s;
  double T = 0.0, mass = 0.0, drill = 0.0, gt = 0.0, gtz = 0.0;
  bool all_mat1 = true;
  for (const Ply& p : plies) T += p.t;
  const double z_bottom = (z0 && lam != Lam::Smear) ? *z0 : -0.5 * T;
  double zb = z_bottom;
  for (const Ply& p : plies) {
    const double zt = zb + p.t;
    const Eigen::Matrix3d Qb = rotate_plane_matrix(p.material.Q, p.theta);
    // Qbar alphabar = T^T Q T T^-1 alpha = T^T Q alpha (alpha rotates as a strain)
    const Eigen::Vector3d Qa = strain_rotation(p.theta).transpose() * (p.material.Q * p.material.alpha);
    s.NT += Qa * (zt - zb);
    s.MT += Qa * (0.5 * (zt * zt - zb * zb));
    s.A += Qb * (zt - zb);
    s.B += Qb * (0.5 * (zt * zt - zb * zb));
    s.D += Qb * ((zt * zt * zt - zb * zb * zb) / 3.0);
    mass += p.material.rho * p.t;
    drill += p.material.G_iso * p.t;
    gt += p.material.G_iso * p.t;
    gtz += p.material.G_iso * p.t * 0.5 * (zb + zt);
    all_mat1 = all_mat1 && p.material.kind == ShellMaterial::Kind::Mat1;
    zb = zt;
  }
  // Bending stiffness as one number about the G-weighted centroid (ShellSection::ts2).
  const double zc = gt > 0.0 ? gtz / gt : 0.0;
  double Dg = 0.0;
  zb = z_bottom;
  for (const Ply& p : plies) {
    const double zt = zb + p.t, a = zt - zc, b = zb - zc;
    Dg += p.material.G_iso * ((a * a * a - b * b * b) / 3.0);
    zb = zt;
  }
  s.t = T;
  s.drill_Gt = drill;
  s.mass_per_area_value = mass + nsm;
  s.has_membrane = true;
  s.has_bending = lam != Lam::Mem;
  if (lam == Lam::Mem) {
    s.B.setZero();
    s.D.setZero();
    s.MT.setZero();
    s.ts2 = T * T;
    return s;
  }
  if (lam == Lam::Smear) {  // stacking ignored: a homogeneous plate of the average stiffness
    s.B.setZero();
    s.MT.setZero();
    s.D = s.A * (T * T / 12.0);
    Dg = drill * T * T / 12.0;
  }
  s.isotropic = all_mat1 && s.B.isZero(0.0);
  const double Sg_kirchhoff = T > 0.0 ? 10.0 * Dg / (T * T) : 0.0;  // (5/6) G T of the equivalent homogeneous plate
  Eigen::Matrix2d S;
  const double penalty_compliance = Sg_kirchhoff > 0.0 ? 1.0 / (kKirchhoffPenalty * Sg_kirchhoff) : 0.0;
  if (lam != Lam::Smear && laminate_shear(plies, z_bottom, s.A, s.B, s.D, penalty_compliance, S)) {
    s.shear_flexible = true;
    s.S = S;
    const double Sg = 0.5 * S.trace();
    s.ts2 = Sg > 0.0 && Dg > 0.0 ? 10.0 * Dg / Sg : T * T;
  } else {
    s.S = (kKirchhoffPenalty * Sg_kirchhoff) * Eigen::Matrix2d::Identity();
    s.ts2 = T * T;
  }
  return s;
}

ShellSection make_shell_section(const Model& model, const Shell& shell) {
  const std::string card = shell_card(shell);
  if (const auto it = model.shell_prop_index.find(shell.pid); it != model.shell_prop_index.end()) {
    const ShellProperty& p = model.shell_props[it->second];
    ShellMaterial m[4];
    PshellInput in;
    if (p.mid1 > 0) in.mid1 = &(m[0] = detail::shell_material(model, p.mid1, p.ref, "PSHELL", p.id, "3 (MID1)"));
    if (p.mid2 > 0) in.mid2 = &(m[1] = detail::shell_material(model, p.mid2, p.ref, "PSHELL", p.id, "5 (MID2)"));
    if (p.mid3 > 0) {
      in.mid3 = &(m[2] = detail::shell_material(model, p.mid3, p.ref, "PSHELL", p.id, "7 (MID3)"));
      if (!m[2].has_Gt)
        detail::fail(model, p.ref, "PSHELL", p.id, "7 (MID3)",
                     "references MAT8 " + std::to_string(p.mid3) +
                         " whose G1Z or G2Z is blank (infinite); expected both transverse shear moduli, or MID3 blank for a section rigid in transverse shear");
    }
    if (p.mid4 > 0) {
      in.mid4 = &(m[3] = detail::shell_material(model, p.mid4, p.ref, "PSHELL", p.id, "4 of continuation 1 (MID4)"));
      if (p.mid1 <= 0 || p.mid2 <= 0)
        detail::fail(model, p.ref, "PSHELL", p.id, "4 of continuation 1 (MID4)",
                     "membrane-bending coupling without MID1 and MID2; expected MID4 blank unless both are given (QRG PSHELL)");
      if (p.mid4 == p.mid1 || p.mid4 == p.mid2)
        detail::fail(model, p.ref, "PSHELL", p.id, "4 of continuation 1 (MID4)",
                     "MID4 = " + std::to_string(p.mid4) + " is also MID1 or MID2; expected a coupling material of its own (QRG PSHELL)");
    }
    if (!in.mid1 && !in.mid2)
      detail::fail(model, p.ref, "PSHELL", p.id, "3, 5 (MID1, MID2)", "expected a membrane or bending material");
    double sum = 0.0;
    for (int k = 0; k < shell.nnode; ++k) {
      const double tk = shell.t[k];
      sum += tk == 0.0 ? p.t : (shell.tflag == 1 ? tk * p.t : tk);
    }
    in.t = sum / shell.nnode;
    if (!(in.t > 0.0))
      detail::fail(model, shell.ref, card, shell.id, "T1-T4",
                   "has no positive thickness (PSHELL " + std::to_string(p.id) + " field 4 T, or the corner thicknesses)");
    in.bend_ratio = p.bend_ratio;
    in.ts_t = p.ts_t;
    in.nsm = p.nsm;
    return pshell_section(in);
  }
  const auto it = model.composite_prop_index.find(shell.pid);
  if (it == model.composite_prop_index.end())
    detail::fail(model, shell.ref, card, shell.id, "3 (PID)",
                 "references property " + std::to_string(shell.pid) + ", which is not defined; expected a PSHELL, PCOMP or PCOMPG");
  const CompositeProperty& p = model.composite_props[it->second];
  const char* pcard = p.global ? "PCOMPG" : "PCOMP";
  for (int k = 0; k < shell.nnode; ++k)
    if (shell.t[k] != 0.0)
      detail::fail(model, shell.ref, card, shell.id, "T1-T4",
                   "corner thicknesses with " + std::string(pcard) + " " + std::to_string(p.id) +
                       "; expected them blank (the plies define the thickness)");
  if (p.lam == Lam::Bend)
    detail::fail(model, p.ref, pcard, p.id, "9 (LAM)",
                 "BEND is not supported; expected blank, SYM, MEM, SMEAR or SMCORE");
  if (p.lam == Lam::SmCore && p.plies.size() < 2)
    detail::fail(model, p.ref, pcard, p.id, "9 (LAM)", "SMCORE with one ply; expected face-sheet plies and the core ply last");
  std::vector<Ply> plies;
  plies.reserve(p.plies.size());
  for (std::size_t k = 0; k < p.plies.size(); ++k) {
    const CompositeProperty::Ply& cp = p.plies[k];
    const std::string field = "MID" + std::to_string(k + 1) + (p.global ? " (GPLYID " + std::to_string(cp.gplyid) + ")" : "");
    Ply ply;
    ply.material = detail::shell_material(model, cp.mid, p.ref, pcard, p.id, field);
    if (ply.material.kind == ShellMaterial::Kind::Mat1 && !(ply.material.G_iso > 0.0))
      detail::fail(model, p.ref, pcard, p.id, field,
                   "references MAT1 " + std::to_string(cp.mid) + " with G = 0; expected a ply material with a shear modulus");
    ply.t = cp.t;
    ply.theta = cp.theta_deg * kPi / 180.0;
    plies.push_back(ply);
  }
  std::optional<double> z0;
  if (p.has_z0) z0 = p.z0;
  ShellSection s = laminate_section(std::move(plies), z0, p.nsm, p.lam);
  s.tref = p.tref;  // QRG PCOMP: the plies' materials' TREF are not used
  return s;
}

}  // namespace seflex::fem
