// Inertia invariants of a superelement (inertia_invariants.hpp, docs/inertia-invariants.md).
// Every invariant is a mass pairing a^T M b of FE-level fields that are linear in the reduced
// coordinates; node sums of cross products become GEMMs over the component rows of the fields.
#include "seflex/superelement/inertia_invariants.hpp"
#include "seflex/superelement/symmetric_basis.hpp"

#include <Eigen/Dense>
#include <algorithm>

#include "seflex/common/error.hpp"
#include "seflex/superelement/superelement.hpp"

namespace seflex::se {

namespace {

using Eigen::Index;
using Eigen::Matrix3d;
using Eigen::MatrixXd;
using Eigen::Vector3d;

Matrix3d skew(const Vector3d& v) {
  Matrix3d S;
  S << 0, -v.z(), v.y(), v.z(), 0, -v.x(), -v.y(), v.x(), 0;
  return S;
}

// Rows 6 i + t of an FE-level field (n_fe x cols).
MatrixXd component_rows(const MatrixXd& Y, int t) {
  const Index nfe = Y.rows() / 6;
  MatrixXd out(nfe, Y.cols());
  for (Index i = 0; i < nfe; ++i) out.row(i) = Y.row(6 * i + t);
  return out;
}

struct Fields {
  const MatrixXd& P;
  const Eigen::SparseMatrix<double>& M;
  std::array<MatrixXd, 3> Pt;  // translation component rows of P (n_fe x n)
  MatrixXd E0;                 // 6 n_fe x 6
  MatrixXd Xf;                 // 6 n_fe x 1

  // H_k(y)[r, c] = sum_i (P_t,i[:,k] x (M y)_t,i[:,c])_r as a (3 C) x n matrix, row r + 3 c.
  MatrixXd H(const MatrixXd& MY) const {
    std::array<MatrixXd, 3> Yt;
    for (int t = 0; t < 3; ++t) Yt[t] = component_rows(MY, t);
    const Index C = MY.cols(), n = P.cols();
    MatrixXd out(3 * C, n);
    for (int r = 0; r < 3; ++r) {
      const int s = (r + 1) % 3, t = (r + 2) % 3;
      const MatrixXd G = Yt[t].transpose() * Pt[s] - Yt[s].transpose() * Pt[t];  // C x n
      for (Index c = 0; c < C; ++c) out.row(r + 3 * c) = G.row(c);
    }
    return out;
  }
};

// The field y with translation rows multiplied by S.
MatrixXd apply_L(const Matrix3d& S, const MatrixXd& Y) {
  MatrixXd out = MatrixXd::Zero(Y.rows(), Y.cols());
  for (Index i = 0; i < Y.rows() / 6; ++i) out.middleRows<3>(6 * i).noalias() = S * Y.middleRows<3>(6 * i);
  return out;
}

// The field y with translation rows 2 e_a x y_t and rotation rows e_a x y_r.
MatrixXd apply_G(int a, const MatrixXd& Y) {
  const Matrix3d Ea = skew(Vector3d::Unit(a));
  MatrixXd out(Y.rows(), Y.cols());
  for (Index i = 0; i < Y.rows() / 6; ++i) {
    out.middleRows<3>(6 * i).noalias() = 2.0 * Ea * Y.middleRows<3>(6 * i);
    out.middleRows<3>(6 * i + 3).noalias() = Ea * Y.middleRows<3>(6 * i + 3);
  }
  return out;
}

}  // namespace

InertiaInvariants compute_inertia_invariants(const Superelement& body) {
  const Index n = body.size();
  const auto nfe = static_cast<Index>(body.p_BoI_B.cols());
  if (nfe == 0 || body.recovery.rows() != 6 * nfe || body.recovery.cols() != n)
    throw InputError("superelement '" + body.name + "': the inertia invariants need the recovery matrix (6 x " +
                     std::to_string(nfe) + " FE node rows by " + std::to_string(n) + " columns)");
  if (body.M_fe.rows() != 6 * nfe || body.M_fe.cols() != 6 * nfe)
    throw InputError("superelement '" + body.name + "': the inertia invariants need the FE mass matrix M_fe (" +
                     std::to_string(6 * nfe) + " square)");
  const MatrixXd& P = body.recovery;
  Fields f{P, body.M_fe, {}, MatrixXd::Zero(6 * nfe, 6), MatrixXd::Zero(6 * nfe, 1)};
  for (int t = 0; t < 3; ++t) f.Pt[t] = component_rows(P, t);
  for (Index i = 0; i < nfe; ++i) {
    const Vector3d X = body.p_BoI_B.col(i);
    f.E0.block<3, 3>(6 * i, 0).setIdentity();
    f.E0.block<3, 3>(6 * i, 3) = -skew(X);
    f.E0.block<3, 3>(6 * i + 3, 3).setIdentity();
    f.Xf.block<3, 1>(6 * i, 0) = X;
  }
  const auto& M = body.M_fe;

  InertiaInvariants v;
  v.n = static_cast<int>(n);
  {
    const MatrixXd MP = M * P;
    v.Mpp = P.transpose() * MP;
    v.Mpp = 0.5 * (v.Mpp + v.Mpp.transpose()).eval();
    v.HP = f.H(MP);
  }
  {
    const MatrixXd ME0 = M * f.E0;
    v.PmE0 = P.transpose() * ME0;
    v.E0mE0 = f.E0.transpose() * ME0;
    v.HE0 = f.H(ME0);
  }
  // E1_l: column c + 3 l has translation rows e_c x P_t,i[:,l] (the deformation part of the FE rigid
  // modes per unit xi_l). Built in chunks of columns l to bound memory on large meshes.
  v.HE1.resize(9 * n, n);
  const Index chunk = std::max<Index>(1, std::min<Index>(n, 8));
  for (Index l0 = 0; l0 < n; l0 += chunk) {
    const Index nl = std::min(chunk, n - l0);
    MatrixXd E1 = MatrixXd::Zero(6 * nfe, 3 * nl);
    for (Index l = 0; l < nl; ++l)
      for (int c = 0; c < 3; ++c)
        for (Index i = 0; i < nfe; ++i)
          E1.block<3, 1>(6 * i, c + 3 * l) = Vector3d::Unit(c).cross(P.block<3, 1>(6 * i, l0 + l));
    v.HE1.middleRows(9 * l0, 9 * nl) = f.H(M * E1);
  }
  // Centrifugal field L_s(X + P xi).
  v.PmLX.resize(n, 6);
  v.HLX.resize(18, n);
  for (int s = 0; s < 6; ++s) {
    const Matrix3d S = se::sym_basis(s);
    const MatrixXd MLX = M * apply_L(S, f.Xf);
    v.PmLX.col(s) = P.transpose() * MLX;
    v.E0mLX.col(s) = f.E0.transpose() * MLX;
    v.HLX.middleRows<3>(3 * s) = f.H(MLX);
    const MatrixXd MLP = M * apply_L(S, P);
    v.PmLP[s] = P.transpose() * MLP;
    v.E0mLP[s] = f.E0.transpose() * MLP;
    v.HLP[s] = f.H(MLP);
  }
  // Coriolis field G_a(P xi_dot).
  for (int a = 0; a < 3; ++a) {
    const MatrixXd MGP = M * apply_G(a, P);
    v.PmGP[a] = P.transpose() * MGP;
    v.E0mGP[a] = f.E0.transpose() * MGP;
    v.HGP[a] = f.H(MGP);
  }
  // Gyroscopic moments of the nodal rotary inertia J_i (the rotation-rotation block of M at node i).
  std::vector<Matrix3d> J(static_cast<std::size_t>(nfe), Matrix3d::Zero());
  bool any_J = false;
  for (Index c = 0; c < M.outerSize(); ++c)
    for (Eigen::SparseMatrix<double>::InnerIterator it(M, c); it; ++it) {
      const Index r = it.row();
      if (r / 6 == c / 6 && r % 6 >= 3 && c % 6 >= 3 && it.value() != 0.0) {
        J[static_cast<std::size_t>(c / 6)](r % 6 - 3, c % 6 - 3) = it.value();
        any_J = true;
      }
    }
  v.PgOO = MatrixXd::Zero(n, 9);
  for (int a = 0; a < 3; ++a) {
    v.PgOV[a] = MatrixXd::Zero(n, n);
    v.EgOV[a] = MatrixXd::Zero(3, n);
  }
  if (any_J) {
    for (int a = 0; a < 3; ++a)
      for (int b = 0; b < 3; ++b) {
        MatrixXd g = MatrixXd::Zero(6 * nfe, 1);
        Vector3d sum = Vector3d::Zero();
        for (Index i = 0; i < nfe; ++i) {
          const Vector3d m = Vector3d::Unit(a).cross(J[static_cast<std::size_t>(i)] * Vector3d::Unit(b));
          g.block<3, 1>(6 * i + 3, 0) = m;
          sum += m;
        }
        v.PgOO.col(a + 3 * b) = P.transpose() * g;
        v.EgOO.col(a + 3 * b) = sum;
      }
    for (int a = 0; a < 3; ++a) {
      const Matrix3d Ea = skew(Vector3d::Unit(a));
      MatrixXd F = MatrixXd::Zero(6 * nfe, n);
      for (Index i = 0; i < nfe; ++i) {
        const Matrix3d& Ji = J[static_cast<std::size_t>(i)];
        const Matrix3d B = Ea * Ji - skew(Ji * Vector3d::Unit(a));
        F.middleRows<3>(6 * i + 3).noalias() = B * P.middleRows<3>(6 * i + 3);
        v.EgOV[a] += F.middleRows<3>(6 * i + 3);
      }
      v.PgOV[a] = P.transpose() * F;
    }
  }
  const Index m = body.num_modes;
  v.mode_max_translation = Eigen::VectorXd::Zero(m);
  for (Index k = 0; k < m; ++k)
    for (Index i = 0; i < nfe; ++i)
      v.mode_max_translation[k] = std::max(v.mode_max_translation[k], P.block<3, 1>(6 * i, n - m + k).norm());
  return v;
}

}  // namespace seflex::se
