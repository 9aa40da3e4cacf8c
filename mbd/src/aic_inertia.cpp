// Inertia of an AIC flexible body: the simplified mass Rhat M Rhat^T (formulation 2.3) and the full
// inertia with quadratic-velocity terms (2.4, 2.5) evaluated from the inertia invariants
// (docs/inertia-invariants.md), at a cost set by the reduced size n, never by the FE mesh.
//
// With N = P T + E(xi) Z (T = Tx, Z = Zx, E = E0 + E1(P xi) the FE rigid modes at the deformed
// positions), every FE-level quantity enters through two projections of an FE "load" y:
// pm = P^T y (n) and em = E^T y (6), and N^T y = T^T pm + Z^T em. The invariants give, for the mass
// pairing, PmE = P^T M E (n x 6) and EmE = E^T M E (6 x 6) at the current xi; for the field of the
// velocity-dependent accelerations c_FE (centrifugal L(W)(X + P xi), Coriolis G(Om)(P xi_dot)) and
// the nodal gyroscopic moments, pm and em as linear maps of W = Om~ Om~ (6 symmetric components)
// and Om. Then
//   f_w = N^T M N (a_b - c) + N^T (M c_FE + gyro),   M_w = N^T M N,
//   C_w = d/dw [N^T (M c_FE + gyro)] - M_w dc/dw,     K_w = rotation of the inertia force with B.
#include <Eigen/Dense>

#include "aic_inertia_detail.hpp"
#include "seflex/common/error.hpp"
#include "seflex/common/so3.hpp"
#include "seflex/mbd/aic_element.hpp"

namespace seflex::mbd {

using Eigen::Matrix3d;
using Eigen::MatrixXd;
using Eigen::Vector3d;
using Eigen::VectorXd;
using so3::skew;
using Matrix6d = Eigen::Matrix<double, 6, 6>;
using Vector6d = Eigen::Matrix<double, 6, 1>;
using Matrix36d = Eigen::Matrix<double, 3, 6>;
using Vector9d = Eigen::Matrix<double, 9, 1>;

namespace {

void simplified(const AicElement& e, const AicKinematics& kin, const VectorXd& w, const VectorXd& ab, bool want,
                MatrixXd& Mw, MatrixXd& Cw, MatrixXd& Kw, VectorXd& fw, double& kinetic) {
  fw.noalias() = e.M * ab;
  kinetic = 0.5 * w.dot(e.M * w);
  if (!want) return;
  Mw = e.M;
  Cw = MatrixXd::Zero(e.n, e.n);
  Kw = (e.M * detail::stacked_skew(e, ab) - detail::stacked_skew(e, fw)) * kin.ZxL.middleRows<3>(3);
}

// Symmetric components (xx, yy, zz, xy, xz, yz) of a symmetric 3x3 W = sum_s w_s S_s.
Vector6d sym_components(const Matrix3d& W) {
  Vector6d v;
  v << W(0, 0), W(1, 1), W(2, 2), W(0, 1), W(0, 2), W(1, 2);
  return v;
}

// (3 x cols) view of the product of a stored tensor (3 cols) x n with xi.
MatrixXd contract(const MatrixXd& T, const VectorXd& xi, Eigen::Index cols) {
  const VectorXd t = T * xi;
  return Eigen::Map<const MatrixXd>(t.data(), 3, cols);
}

void full(const AicElement& e, const AicKinematics& kin, const VectorXd& w, const VectorXd& ab, bool want,
          MatrixXd& Mw, MatrixXd& Cw, MatrixXd& Kw, VectorXd& fw, double& kinetic) {
  const se::InertiaInvariants& I = e.inv;
  const Eigen::Index n = e.n;
  const MatrixXd& Z = kin.Zx;
  const VectorXd& xi = kin.xi;
  const Vector3d Om = Z.middleRows<3>(3) * w;
  VectorXd xid = w;  // Tx w = w - R6 (Zx w)
  xid.head(6 * e.N).noalias() -= kin.Phi_rig * (Z * w);

  // Mass pairing at xi.
  MatrixXd PmE = I.PmE0;
  PmE.rightCols<3>() += contract(I.HP, xi, n).transpose();
  Matrix6d EmE = I.E0mE0;
  {
    const Matrix36d B = contract(I.HE0, xi, 6);
    EmE.bottomRows<3>() += B;
    EmE.rightCols<3>() += B.transpose();
    const VectorXd q = I.HE1 * xi;
    Matrix3d Q = Matrix3d::Zero();
    for (Eigen::Index l = 0; l < n; ++l) Q += xi[l] * Eigen::Map<const Matrix3d>(q.data() + 9 * l);
    EmE.bottomRightCorner<3, 3>() += Q;
  }
  // Centrifugal field: pm = CLp s(W), em = CLe s(W) + [0; CLh s(W)].
  MatrixXd CLp = I.PmLX;
  Matrix6d CLe = I.E0mLX;
  Matrix36d CLh = contract(I.HLX, xi, 6);
  for (int s = 0; s < 6; ++s) {
    CLp.col(s) += I.PmLP[s] * xi;
    CLe.col(s) += I.E0mLP[s] * xi;
    CLh.col(s) += contract(I.HLP[s], xi, n) * xi;
  }
  // Coriolis field and gyroscopic moments, linear in Om at fixed xi_dot: columns a.
  MatrixXd GPp(n, 3), GVp(n, 3);
  Eigen::Matrix<double, 6, 3> GPe;
  Matrix3d GPh, GVe;
  std::array<MatrixXd, 3> HGPxi;
  for (int a = 0; a < 3; ++a) {
    HGPxi[a] = contract(I.HGP[a], xi, n);
    GPp.col(a) = I.PmGP[a] * xid;
    GPe.col(a) = I.E0mGP[a] * xid;
    GPh.col(a) = HGPxi[a] * xid;
    GVp.col(a) = I.PgOV[a] * xid;
    GVe.col(a) = I.EgOV[a] * xid;
  }
  Vector9d OO;
  for (int b = 0; b < 3; ++b)
    for (int a = 0; a < 3; ++a) OO[a + 3 * b] = Om[a] * Om[b];
  const Matrix3d Wc = skew(Om) * skew(Om);
  const Vector6d sW = sym_components(Wc);
  const VectorXd pm = CLp * sW + GPp * Om + I.PgOO * OO + GVp * Om;
  Vector6d em = CLe * sW + GPe * Om;
  em.tail<3>() += CLh * sW + GPh * Om + I.EgOO * OO + GVe * Om;

  // N = P T + E Z = P + D Z with D = E - P R6, R6 = [Phi_rig; 0] (T = I - R6 Z has rank-6 defect):
  // N^T M N = Mpp + Q Z + Z^T Q^T + Z^T S Z, Q = P^T M D, S = D^T M D; N^T y = pm + Z^T (em - R6^T pm).
  const auto nb = 6 * e.N;
  const auto& Phi = kin.Phi_rig;  // the non-zero rows of R6
  const Eigen::Matrix<double, Eigen::Dynamic, 6> MR = I.Mpp.leftCols(nb) * Phi;  // Mpp R6
  const Eigen::Matrix<double, Eigen::Dynamic, 6> Q = PmE - MR;
  const Matrix6d PhiPmE = Phi.transpose() * PmE.topRows(nb);
  const Matrix6d S = EmE - PhiPmE - PhiPmE.transpose() + Phi.transpose() * MR.topRows(nb);
  auto project = [&](const VectorXd& p, const Vector6d& q) -> VectorXd {  // N^T y from P^T y, E^T y
    return p + Z.transpose() * (q - Phi.transpose() * p.head(nb));
  };
  auto mass_times = [&](const VectorXd& v) -> VectorXd {
    const Vector6d z = Z * v;
    return I.Mpp * v + Q * z + Z.transpose() * (Q.transpose() * v + S * z);
  };
  VectorXd c;
  detail::interface_velocity_accelerations(e, xi, Om, xid, c);
  fw = mass_times(ab - c) + project(pm, em);
  kinetic = 0.5 * w.dot(mass_times(w));
  if (!want) return;

  const MatrixXd QZ = Q * Z;
  Mw = I.Mpp + QZ + QZ.transpose();
  Mw.noalias() += Z.transpose() * (S * Z);
  // d/dOm_a of the velocity-dependent loads (n x 3 and 6 x 3), then d/dxi_dot (n x n and 6 x n).
  MatrixXd DOp(n, 3);
  Eigen::Matrix<double, 6, 3> DOe;
  for (int a = 0; a < 3; ++a) {
    const Matrix3d Ea = skew(Vector3d::Unit(a));
    const Vector6d sWa = sym_components(Ea * skew(Om) + skew(Om) * Ea);
    Vector9d dOO = Vector9d::Zero();
    for (int b = 0; b < 3; ++b) {
      dOO[a + 3 * b] += Om[b];
      dOO[b + 3 * a] += Om[b];
    }
    DOp.col(a) = CLp * sWa + GPp.col(a) + I.PgOO * dOO + GVp.col(a);
    DOe.col(a) = CLe * sWa + GPe.col(a);
    DOe.col(a).tail<3>() += CLh * sWa + GPh.col(a) + I.EgOO * dOO + GVe.col(a);
  }
  MatrixXd Ap = Om[0] * (I.PmGP[0] + I.PgOV[0]);
  for (int a = 1; a < 3; ++a) Ap += Om[a] * (I.PmGP[a] + I.PgOV[a]);
  MatrixXd Ae = Om[0] * I.E0mGP[0];
  for (int a = 1; a < 3; ++a) Ae += Om[a] * I.E0mGP[a];
  for (int a = 0; a < 3; ++a) Ae.bottomRows<3>() += Om[a] * (HGPxi[a] + I.EgOV[a]);
  // Xp = dpm/dw = DOp Zr + Ap T, Xe = dem/dw; C_w = Xp + Z^T (Xe - R6^T Xp) - M_w dc/dw.
  const auto Zr = Z.middleRows<3>(3);
  MatrixXd Xp = Ap;
  Xp.noalias() += DOp * Zr;
  Xp.noalias() -= (Ap.leftCols(nb) * Phi) * Z;
  MatrixXd Xe = Ae;
  Xe.noalias() += DOe * Zr;
  Xe.noalias() -= (Ae.leftCols(nb) * Phi) * Z;
  Xe.noalias() -= Phi.transpose() * Xp.topRows(nb);
  Cw = Xp;
  Cw.noalias() += Z.transpose() * Xe;
  Cw -= detail::times_velocity_accelerations_tangent(e, kin, Om, xid, Mw);
  Kw = (Mw * detail::stacked_skew(e, ab) - detail::stacked_skew(e, fw)) * kin.ZxL.middleRows<3>(3);
}

}  // namespace

void inertia_force(const AicElement& e, const AicKinematics& kin, InertiaModel model, const Eigen::Ref<const VectorXd>& v,
                   const Eigen::Ref<const VectorXd>& a, bool want_matrices, InertiaResult& out) {
  if (model == InertiaModel::Full) {
    SEFLEX_DEMAND(e.inv.present(), "full inertia needs the inertia invariants of superelement " + e.name);
  }
  detail::inertia_in_world(e, kin, v, a, want_matrices, out,
                           [&](const VectorXd& w, const VectorXd& ab, bool want, MatrixXd& Mw, MatrixXd& Cw, MatrixXd& Kw,
                               VectorXd& fw, double& kinetic) {
                             if (model == InertiaModel::Full)
                               full(e, kin, w, ab, want, Mw, Cw, Kw, fw, kinetic);
                             else
                               simplified(e, kin, w, ab, want, Mw, Cw, Kw, fw, kinetic);
                           });
}

}  // namespace seflex::mbd
