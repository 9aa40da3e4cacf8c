// CBAR / CBEAM element (see element_bar.hpp for the formulation and conventions).
#include "seflex/fem/element_bar.hpp"

#include <Eigen/Cholesky>
#include <Eigen/LU>
#include <cmath>
#include <vector>

#include "model_lookup.hpp"
#include "seflex/common/error.hpp"
#include "seflex/fem/beam_section.hpp"
#include "seflex/fem/components.hpp"

namespace seflex::fem {
namespace {

using Matrix12 = NodeMatrix<2>;

// Indices of the element-axis dofs of one end: u v w (0..2), theta_x theta_y theta_z (3..5).
constexpr int kU = 0, kV = 1, kW = 2, kRx = 3, kRy = 4, kRz = 5;

// Add Gamma^T Kd Gamma for a block of tip loads whose tip deformations are rows `gamma` (n x 12).
template <int n>
void add_flexibility_block(const Eigen::Matrix<double, n, n>& C, const Eigen::Matrix<double, n, 12>& gamma,
                           Matrix12& K) {
  const Eigen::Matrix<double, n, n> Kd = C.inverse();
  K += gamma.transpose() * Kd * gamma;
}

// Deformation of end B relative to the rigid motion of end A, per element-axis component:
// translations d = u_B - u_A + (L e_x) x theta_A ... written out for each component.
Eigen::Matrix<double, 1, 12> deformation_row(int comp, double L) {
  Eigen::Matrix<double, 1, 12> g = Eigen::Matrix<double, 1, 12>::Zero();
  g(6 + comp) = 1.0;
  g(comp) = -1.0;
  if (comp == kV) g(kRz) = -L;  // v_B - v_A - L theta_z,A
  if (comp == kW) g(kRy) = L;   // w_B - w_A + L theta_y,A
  return g;
}

// 8-point Gauss-Legendre on [-1, 1].
constexpr double kGauss8X[8] = {-0.96028985649753618, -0.79666647741362673, -0.52553240991632899, -0.18343464249564978,
                                0.18343464249564978,  0.52553240991632899,  0.79666647741362673,  0.96028985649753618};
constexpr double kGauss8W[8] = {0.10122853629037669, 0.22238103445337434, 0.31370664587788705, 0.36268378337836177,
                                0.36268378337836177, 0.31370664587788705, 0.22238103445337434, 0.10122853629037669};

/// The stations of a bar: its taper, or its section at both ends (prismatic).
std::vector<BarStation> stations_of(const BarElement& e) {
  if (!e.taper.empty()) return e.taper;
  return {{0.0, e.section, e.nsi}, {1.0, e.section, e.nsi}};
}

/// A bar's section (and NSI) at x in [0, 1]: linear between its stations t.
BarStation station_at(const std::vector<BarStation>& t, double x) {
  std::size_t k = 1;
  while (k + 1 < t.size() && t[k].x < x) ++k;
  const BarStation &a = t[k - 1], &b = t[k];
  const double f = b.x > a.x ? (x - a.x) / (b.x - a.x) : 0.0, g = 1.0 - f;
  BarStation s;
  s.x = x;
  s.section = {g * a.section.A + f * b.section.A,     g * a.section.I1 + f * b.section.I1, g * a.section.I2 + f * b.section.I2,
               g * a.section.I12 + f * b.section.I12, g * a.section.J + f * b.section.J,   a.section.K1,
               a.section.K2,                           g * a.section.nsm + f * b.section.nsm};
  s.nsi = g * a.nsi + f * b.nsi;
  return s;
}

/// Calls f(s, ds, station) at the Gauss points along the bar: each interval between stations in
/// four parts of 8 points (the flexibility's integrand, 1/A and 1/I of linear A and I, is rational:
/// relative error below 1e-14 for an area tapering 4 to 1, tests/solutions/tapered_beam_test.cpp).
template <class F>
void along_taper(const BarElement& e, double L, F f) {
  const std::vector<BarStation> t = stations_of(e);
  for (std::size_t k = 1; k < t.size(); ++k)
    for (int part = 0; part < 4; ++part) {
      const double x0 = t[k - 1].x + part * 0.25 * (t[k].x - t[k - 1].x);
      const double x1 = x0 + 0.25 * (t[k].x - t[k - 1].x);
      if (!(x1 > x0)) continue;
      for (int i = 0; i < 8; ++i) {
        const double x = x0 + 0.5 * (x1 - x0) * (1.0 + kGauss8X[i]);
        f(x * L, 0.5 * (x1 - x0) * L * kGauss8W[i], station_at(t, x));
      }
    }
}

/// The neutral axis (n) or the non-structural mass (m) at x in [0, 1], element (y, z): linear between the ends.
Eigen::Vector2d between_ends(const Eigen::Vector2d& a, const Eigen::Vector2d& b, double x) { return (1.0 - x) * a + x * b; }

/// Stiffness of a tapered bar, or of one whose neutral axis is offset, in element axes: the
/// flexibility of end B (end A clamped) integrated along the bar, section resultants about the
/// reference axis (N, Vy, Vz, T, My, Mz) = B(s) (Fx, Fy, Fz, Mx, My, Mz) at B, the section compliance
/// Q^T S^-1 Q with Q the moments about the neutral axis (My - n2 N, Mz + n1 N).
/// A block whose property is zero anywhere along the bar (A, J, I1/I2) carries no stiffness, as
/// for the prismatic bar.
Matrix12 integrated_stiffness(const BarElement& e, double L) {
  const double E = e.material.E, G = e.material.G;
  bool axial = E > 0.0, torsion = G > 0.0, plane1 = E > 0.0, plane2 = E > 0.0, coupled = false;
  for (const BarStation& t : stations_of(e)) {
    axial = axial && t.section.A > 0.0;
    torsion = torsion && t.section.J > 0.0;
    plane1 = plane1 && t.section.I1 > 0.0;
    plane2 = plane2 && t.section.I2 > 0.0;
    coupled = coupled || t.section.I12 != 0.0;
  }
  if (coupled) plane1 = plane2 = plane1 && plane2;
  std::vector<int> comp;  // active tip-load components
  if (axial) comp.push_back(kU);
  if (plane1) comp.push_back(kV);
  if (plane2) comp.push_back(kW);
  if (torsion) comp.push_back(kRx);
  if (plane2) comp.push_back(kRy);
  if (plane1) comp.push_back(kRz);
  Matrix12 K = Matrix12::Zero();
  if (comp.empty()) return K;
  Eigen::Matrix<double, 6, 6> C = Eigen::Matrix<double, 6, 6>::Zero();
  along_taper(e, L, [&](double s, double ds, const BarStation& st) {
    const BarSection& x = st.section;
    Eigen::Matrix<double, 6, 6> S = Eigen::Matrix<double, 6, 6>::Zero();  // section compliance
    if (axial) S(0, 0) = 1.0 / (E * x.A);
    if (plane1 && x.K1 > 0.0 && G > 0.0) S(1, 1) = 1.0 / (G * x.K1 * x.A);
    if (plane2 && x.K2 > 0.0 && G > 0.0) S(2, 2) = 1.0 / (G * x.K2 * x.A);
    if (torsion) S(3, 3) = 1.0 / (G * x.J);
    if (plane1 || plane2) {  // curvatures of (My, Mz): inv(E [I2 -I12; -I12 I1])
      const double det = x.I1 * x.I2 - x.I12 * x.I12;
      if (coupled) {
        S(4, 4) = x.I1 / (E * det), S(5, 5) = x.I2 / (E * det);
        S(4, 5) = S(5, 4) = x.I12 / (E * det);
      } else {
        if (plane2) S(4, 4) = 1.0 / (E * x.I2);
        if (plane1) S(5, 5) = 1.0 / (E * x.I1);
      }
    }
    Eigen::Matrix<double, 6, 6> B = Eigen::Matrix<double, 6, 6>::Identity();
    B(4, 2) = -(L - s);  // My(s) = My - (L - s) Fz
    B(5, 1) = L - s;     // Mz(s) = Mz + (L - s) Fy
    const Eigen::Vector2d n = between_ends(e.n_A, e.n_B, s / L);
    B.row(4) -= n(1) * B.row(0);  // about the neutral axis: My - n2 N
    B.row(5) += n(0) * B.row(0);  //                         Mz + n1 N
    C += ds * B.transpose() * S * B;
  });
  const auto n = static_cast<Eigen::Index>(comp.size());
  Eigen::MatrixXd Ca(n, n), g(n, 12);
  for (Eigen::Index i = 0; i < n; ++i) {
    for (Eigen::Index j = 0; j < n; ++j) Ca(i, j) = C(comp[static_cast<std::size_t>(i)], comp[static_cast<std::size_t>(j)]);
    g.row(i) = deformation_row(comp[static_cast<std::size_t>(i)], L);
  }
  K = g.transpose() * Ca.ldlt().solve(g);
  return 0.5 * (K + K.transpose());
}

}  // namespace

Eigen::Matrix3d bar_axes(const BarElement& e) {
  const Eigen::Vector3d d = (e.x_B + e.w_B) - (e.x_A + e.w_A);
  const double L = d.norm();
  SEFLEX_DEMAND(L > 0.0, "bar of zero length");
  const Eigen::Vector3d ex = d / L;
  const Eigen::Vector3d zz = ex.cross(e.v);
  SEFLEX_DEMAND(zz.norm() > 1e-9 * e.v.norm(), "bar orientation vector parallel to the bar axis");
  const Eigen::Vector3d ez = zz.normalized();
  Eigen::Matrix3d R;
  R.col(0) = ex;
  R.col(1) = ez.cross(ex);
  R.col(2) = ez;
  return R;
}

double bar_length(const BarElement& e) { return ((e.x_B + e.w_B) - (e.x_A + e.w_A)).norm(); }

bool bar_has_neutral_axis_offset(const BarElement& e) { return !e.n_A.isZero(0.0) || !e.n_B.isZero(0.0); }

NodeMatrix<2> bar_stiffness_element_axes(const BarElement& e) {
  const double L = bar_length(e);
  SEFLEX_DEMAND(L > 0.0, "bar of zero length");
  if (!e.taper.empty() || bar_has_neutral_axis_offset(e)) return integrated_stiffness(e, L);
  const BarSection& s = e.section;
  const double E = e.material.E, G = e.material.G;
  Matrix12 K = Matrix12::Zero();

  // Axial and torsion: decoupled from bending (section at the centroid and shear centre).
  if (s.A > 0.0 && E > 0.0) {
    const Eigen::Matrix<double, 1, 12> g = deformation_row(kU, L);
    K += (E * s.A / L) * g.transpose() * g;
  }
  if (s.J > 0.0 && G > 0.0) {
    const Eigen::Matrix<double, 1, 12> g = deformation_row(kRx, L);
    K += (G * s.J / L) * g.transpose() * g;
  }
  // Transverse shear compliance per length (0 = rigid in shear).
  const double fy = (s.K1 > 0.0 && s.A > 0.0 && G > 0.0) ? 1.0 / (G * s.K1 * s.A) : 0.0;
  const double fz = (s.K2 > 0.0 && s.A > 0.0 && G > 0.0) ? 1.0 / (G * s.K2 * s.A) : 0.0;

  if (s.I12 == 0.0) {
    // Plane 1 (x-y): tip loads (Vy, Mz) -> (v_B, theta_z,B); resultants Vy, Mz + (L - s) Vy.
    if (s.I1 > 0.0 && E > 0.0) {
      const double EI = E * s.I1;
      Eigen::Matrix2d C;
      C << fy * L + L * L * L / (3 * EI), L * L / (2 * EI), L * L / (2 * EI), L / EI;
      Eigen::Matrix<double, 2, 12> g;
      g.row(0) = deformation_row(kV, L);
      g.row(1) = deformation_row(kRz, L);
      add_flexibility_block<2>(C, g, K);
    }
    // Plane 2 (x-z): tip loads (Vz, My) -> (w_B, theta_y,B); resultants Vz, My - (L - s) Vz.
    if (s.I2 > 0.0 && E > 0.0) {
      const double EI = E * s.I2;
      Eigen::Matrix2d C;
      C << fz * L + L * L * L / (3 * EI), -L * L / (2 * EI), -L * L / (2 * EI), L / EI;
      Eigen::Matrix<double, 2, 12> g;
      g.row(0) = deformation_row(kW, L);
      g.row(1) = deformation_row(kRy, L);
      add_flexibility_block<2>(C, g, K);
    }
  } else {
    // Coupled bending: tip loads P = (Vy, Vz, My, Mz); resultants B(s) P =
    // (Vy, Vz, My - (L-s) Vz, Mz + (L-s) Vy); curvature (ky, kz) = inv(E [I2 -I12; -I12 I1]) (My, Mz).
    const double det = s.I1 * s.I2 - s.I12 * s.I12;
    SEFLEX_DEMAND(det > 0.0 && E > 0.0, "bar section needs I1 I2 > I12^2");
    Eigen::Matrix2d Cb;  // inverse of E [I2 -I12; -I12 I1]
    Cb << s.I1, s.I12, s.I12, s.I2;
    Cb /= E * det;
    Eigen::Matrix4d Sinv = Eigen::Matrix4d::Zero();
    Sinv(0, 0) = fy;
    Sinv(1, 1) = fz;
    Sinv.block<2, 2>(2, 2) = Cb;
    Eigen::Matrix4d C = Eigen::Matrix4d::Zero();
    const double gp = 1.0 / std::sqrt(3.0);  // 2-point Gauss: exact, the integrand is quadratic in s
    for (double xi : {-gp, gp}) {
      const double a = L - 0.5 * L * (1.0 + xi);  // L - s
      Eigen::Matrix4d B = Eigen::Matrix4d::Identity();
      B(2, 1) = -a;
      B(3, 0) = a;
      C += (0.5 * L) * B.transpose() * Sinv * B;
    }
    Eigen::Matrix<double, 4, 12> g;
    g.row(0) = deformation_row(kV, L);
    g.row(1) = deformation_row(kW, L);
    g.row(2) = deformation_row(kRy, L);
    g.row(3) = deformation_row(kRz, L);
    add_flexibility_block<4>(C, g, K);
  }
  return K;
}

namespace {

// Statically condense the released dofs of K (element axes); returns false if K restricted to the
// released dofs is not positive definite (a release without stiffness, or a mechanism).
bool condense_pins(ComponentMask pin_A, ComponentMask pin_B, Matrix12& K) {
  std::vector<int> p, r;
  for (int i = 0; i < 12; ++i) {
    const ComponentMask m = i < 6 ? pin_A : pin_B;
    (has_component(m, i % 6 + 1) ? p : r).push_back(i);
  }
  if (p.empty()) return true;
  const int np = static_cast<int>(p.size()), nr = static_cast<int>(r.size());
  Eigen::MatrixXd Kpp(np, np), Kpr(np, nr), Krr(nr, nr);
  for (int i = 0; i < np; ++i) {
    for (int j = 0; j < np; ++j) Kpp(i, j) = K(p[i], p[j]);
    for (int j = 0; j < nr; ++j) Kpr(i, j) = K(p[i], r[j]);
  }
  for (int i = 0; i < nr; ++i)
    for (int j = 0; j < nr; ++j) Krr(i, j) = K(r[i], r[j]);
  Eigen::LLT<Eigen::MatrixXd> llt(Kpp);
  if (llt.info() != Eigen::Success) return false;
  const double scale = Kpp.diagonal().maxCoeff();
  const Eigen::VectorXd d = llt.matrixL().toDenseMatrix().diagonal();
  if (!(d.minCoeff() * d.minCoeff() > 1e-10 * scale)) return false;
  const Eigen::MatrixXd Kc = Krr - Kpr.transpose() * llt.solve(Kpr);
  K.setZero();
  for (int i = 0; i < nr; ++i)
    for (int j = 0; j < nr; ++j) K(r[i], r[j]) = 0.5 * (Kc(i, j) + Kc(j, i));
  return true;
}

void to_grids(const BarElement& e, const Eigen::Matrix3d& R_BE, Matrix12& K) {
  rotate_local_to_basic<2>(R_BE, K);
  apply_node_offsets<2>({e.w_A, e.w_B}, K);
}

}  // namespace

NodeMatrix<2> bar_stiffness(const BarElement& e) {
  Matrix12 K = bar_stiffness_element_axes(e);
  SEFLEX_DEMAND(condense_pins(e.pin_A, e.pin_B, K), "bar pin flags release dofs without stiffness");
  to_grids(e, bar_axes(e), K);
  return K;
}

Eigen::Matrix<double, 12, 1> bar_thermal_load(const BarElement& e, double alpha, const BarTemperatureField& t) {
  const double L = bar_length(e);
  const BarSection& s = e.section;
  // Curvature sources of the two planes: inv([I1 I12; I12 I2]) (I1 TP1, I2 TP2) at each end.
  const double det = s.I1 * s.I2 - s.I12 * s.I12;
  auto curvature = [&](double tp1, double tp2) -> Eigen::Vector2d {
    if (!(det > 0.0)) return {s.I1 > 0.0 ? tp1 : 0.0, s.I2 > 0.0 ? tp2 : 0.0};
    return {(s.I2 * s.I1 * tp1 - s.I12 * s.I2 * tp2) / det, (-s.I12 * s.I1 * tp1 + s.I1 * s.I2 * tp2) / det};
  };
  const Eigen::Vector2d kA = curvature(t.tp1a, t.tp2a), kB = curvature(t.tp1b, t.tp2b);
  Eigen::Matrix<double, 12, 1> u = Eigen::Matrix<double, 12, 1>::Zero();  // end B clamped
  // The free strain of a fibre at (y, z) from the neutral axis is alpha (dT + k1 y + k2 z): the
  // reference axis, at -n, strains alpha (dT - k . n), integrated along the bar (k and n linear).
  const double kn = kA.dot(e.n_A) / 3.0 + (kA.dot(e.n_B) + kB.dot(e.n_A)) / 6.0 + kB.dot(e.n_B) / 3.0;
  u(kU) = -alpha * L * (t.dT - kn);
  u(kV) = -alpha * L * L * (kA(0) / 6.0 + kB(0) / 3.0);
  u(kW) = -alpha * L * L * (kA(1) / 6.0 + kB(1) / 3.0);
  u(kRz) = alpha * L * 0.5 * (kA(0) + kB(0));
  u(kRy) = -alpha * L * 0.5 * (kA(1) + kB(1));
  Matrix12 K = bar_stiffness_element_axes(e);
  SEFLEX_DEMAND(condense_pins(e.pin_A, e.pin_B, K), "bar pin flags release dofs without stiffness");
  Eigen::Matrix<double, 12, 1> f = K * u;  // element axes at the bar ends
  const Eigen::Matrix3d R = bar_axes(e);
  const std::array<Eigen::Vector3d, 2> w = {e.w_A, e.w_B};
  for (int n = 0; n < 2; ++n) {
    const Eigen::Vector3d F = R * f.segment<3>(6 * n), M = R * f.segment<3>(6 * n + 3);
    f.segment<3>(6 * n) = F;
    f.segment<3>(6 * n + 3) = M + w[n].cross(F);  // the force at the offset end, moved to the grid
  }
  return f;
}

namespace {

/// The cross-product matrix of r = (0, y, z).
Eigen::Matrix3d cross_matrix(const Eigen::Vector2d& yz) {
  Eigen::Matrix3d X;
  X << 0, -yz(1), yz(0), yz(1), 0, 0, -yz(0), 0, 0;
  return X;
}

/// Rigid-body mass (6 x 6, element axes, about the reference axis) of a slice of mass m whose centre
/// is at r = (0, y, z) and whose polar inertia about its own line (parallel to x) is j.
Eigen::Matrix<double, 6, 6> slice_mass(double m, const Eigen::Vector2d& yz, double j) {
  const Eigen::Matrix3d X = cross_matrix(yz);
  Eigen::Matrix<double, 6, 6> M;
  M << m * Eigen::Matrix3d::Identity(), -m * X, m * X, -m * X * X;
  M(3, 3) += j;
  return M;
}

/// The mass of a tapered bar, or one with neutral-axis or non-structural-mass offsets (element axes
/// before offsets; see element_bar.hpp): lumped, each end the rigid-body mass of the slices weighted by
/// the linear function of its end ((1 - s/L) at A, s/L at B: the total and the first moment kept);
/// coupled, the prismatic bar's shape functions (linear axial and torsion, cubic Hermite transverse)
/// integrated with the varying mass per length, each line mass moving with u + theta x r.
Matrix12 integrated_mass(const BarElement& e, double L, MassKind kind) {
  Matrix12 M = Matrix12::Zero();
  const double rho = e.material.rho;
  along_taper(e, L, [&](double s, double ds, const BarStation& st) {
    const double x = s / L, N[2] = {1 - x, x};
    struct Line {
      double m, j;
      Eigen::Vector2d yz;
    };
    // the structure at the neutral axis (the centroid), the non-structural mass at M1/M2
    const Line lines[2] = {{rho * st.section.A * ds, rho * (st.section.I1 + st.section.I2) * ds, between_ends(e.n_A, e.n_B, x)},
                           {st.section.nsm * ds, st.nsi * ds, between_ends(e.m_A, e.m_B, x)}};
    if (kind == MassKind::Lumped) {  // a CBAR's lumped mass has no polar inertia
      for (const Line& l : lines)
        for (int n = 0; n < 2; ++n) M.block<6, 6>(6 * n, 6 * n) += N[n] * slice_mass(l.m, l.yz, e.is_beam ? l.j : 0.0);
      return;
    }
    const double H[4] = {1 - 3 * x * x + 2 * x * x * x, L * (x - 2 * x * x + x * x * x), 3 * x * x - 2 * x * x * x,
                         L * (-x * x + x * x * x)};
    const double dH[4] = {(-6 * x + 6 * x * x) / L, 1 - 4 * x + 3 * x * x, (6 * x - 6 * x * x) / L, -2 * x + 3 * x * x};
    const int p1[4] = {kV, kRz, 6 + kV, 6 + kRz};
    const int p2[4] = {kW, kRy, 6 + kW, 6 + kRy};
    const double sgn[4] = {1, -1, 1, -1};  // theta_y = -w'
    Eigen::Matrix<double, 6, 12> phi = Eigen::Matrix<double, 6, 12>::Zero();  // (u v w theta) at s
    for (int n = 0; n < 2; ++n) {
      phi(kU, 6 * n + kU) = N[n];
      phi(kRx, 6 * n + kRx) = N[n];
    }
    for (int i = 0; i < 4; ++i) {
      phi(kV, p1[i]) = H[i];
      phi(kRz, p1[i]) = dH[i];  // theta_z = v'
      phi(kW, p2[i]) = sgn[i] * H[i];
      phi(kRy, p2[i]) = -sgn[i] * dH[i];  // theta_y = -w'
    }
    for (const Line& l : lines) {
      const Eigen::Matrix<double, 3, 12> P = phi.topRows<3>() - cross_matrix(l.yz) * phi.bottomRows<3>();  // u + theta x r
      M += l.m * P.transpose() * P + l.j * phi.row(kRx).transpose() * phi.row(kRx);
    }
  });
  return M;
}

}  // namespace

NodeMatrix<2> bar_mass(const BarElement& e, MassKind kind) {
  const double L = bar_length(e);
  if (!e.taper.empty() || bar_has_neutral_axis_offset(e) || !e.m_A.isZero(0.0) || !e.m_B.isZero(0.0)) {
    Matrix12 M = integrated_mass(e, L, kind);
    to_grids(e, bar_axes(e), M);
    return M;
  }
  const BarSection& s = e.section;
  const double m = (e.material.rho * s.A + s.nsm) * L;  // total translational mass
  Matrix12 M = Matrix12::Zero();
  const double polar = (e.material.rho * (s.I1 + s.I2) + e.nsi) * L;  // about the bar axis
  if (kind == MassKind::Lumped) {
    for (int i : {0, 1, 2, 6, 7, 8}) M(i, i) = 0.5 * m;
    if (e.is_beam && polar > 0.0) {  // CBEAM: half the polar inertia about the axis at each end
      const Eigen::Vector3d x = bar_axes(e).col(0);
      M.block<3, 3>(3, 3) = M.block<3, 3>(9, 9) = 0.5 * polar * x * x.transpose();
    }
    apply_node_offsets<2>({e.w_A, e.w_B}, M);
    return M;
  }
  // Coupled mass in element axes.
  const double a = m / 6.0;  // linear axial (and torsion pattern [2 1; 1 2])
  M(kU, kU) = M(6 + kU, 6 + kU) = 2 * a;
  M(kU, 6 + kU) = M(6 + kU, kU) = a;
  const double jt = polar / 6.0;
  M(kRx, kRx) = M(6 + kRx, 6 + kRx) = 2 * jt;
  M(kRx, 6 + kRx) = M(6 + kRx, kRx) = jt;
  // Cubic Hermite, plane 1 dofs (v_A, tz_A, v_B, tz_B); plane 2 (w_A, ty_A, w_B, ty_B) with
  // theta_y = -w' (coupling terms change sign).
  Eigen::Matrix4d H;
  H << 156, 22 * L, 54, -13 * L, 22 * L, 4 * L * L, 13 * L, -3 * L * L, 54, 13 * L, 156, -22 * L, -13 * L,
      -3 * L * L, -22 * L, 4 * L * L;
  H *= m / 420.0;
  const int p1[4] = {kV, kRz, 6 + kV, 6 + kRz};
  const int p2[4] = {kW, kRy, 6 + kW, 6 + kRy};
  const double sgn[4] = {1, -1, 1, -1};
  for (int i = 0; i < 4; ++i)
    for (int j = 0; j < 4; ++j) {
      M(p1[i], p1[j]) = H(i, j);
      M(p2[i], p2[j]) = sgn[i] * sgn[j] * H(i, j);
    }
  to_grids(e, bar_axes(e), M);
  return M;
}

BarElement make_bar_element(const Model& model, const Bar& bar) {
  const std::string card = bar.is_beam ? "CBEAM" : "CBAR";
  BarElement e;
  const Grid& ga = model.grids[detail::grid_index(model, bar.ga, bar.ref, card, bar.id, "4 (GA)")];
  const Grid& gb = model.grids[detail::grid_index(model, bar.gb, bar.ref, card, bar.id, "5 (GB)")];
  e.x_A = ga.x_basic;
  e.x_B = gb.x_basic;
  const Eigen::Matrix3d A_A = detail::axes_at(model, ga.cd, ga.x_basic, ga.ref, "GRID", ga.id, "7 (CD)");
  const Eigen::Matrix3d A_B = detail::axes_at(model, gb.cd, gb.x_basic, gb.ref, "GRID", gb.id, "7 (CD)");

  const auto pit = model.bar_prop_index.find(bar.pid);
  if (pit == model.bar_prop_index.end())
    detail::fail(model, bar.ref, card, bar.id, "3 (PID)",
                 "references " + std::string(bar.is_beam ? "PBEAM" : "PBAR") + " " + std::to_string(bar.pid) +
                     ", which is not defined");
  const BarProperty& p = model.bar_props[pit->second];
  const std::string pcard = card_name(p.source);
  e.section = {p.A, p.I1, p.I2, p.I12, p.J, p.K1, p.K2, p.nsm};
  e.material = detail::material(model, p.mid, p.ref, pcard, p.id, "3 (MID)");
  e.is_beam = bar.is_beam;
  e.nsi = bar.is_beam ? p.nsi : 0.0;
  if (bar.is_beam) {
    e.n_A = {p.n_A[0], p.n_A[1]};
    e.n_B = {p.n_B[0], p.n_B[1]};
    e.m_A = {p.m_A[0], p.m_A[1]};
    e.m_B = {p.m_B[0], p.m_B[1]};
  }
  for (std::size_t k = 0; k < p.stations.size(); ++k) {  // tapered PBEAM / PBEAML
    const BarProperty::Station& s = p.stations[k];
    if (p.source != BarProperty::Source::PBEAML || k == 0) {
      e.taper.push_back({s.x, {s.A, s.I1, s.I2, s.I12, s.J, p.K1, p.K2, s.nsm}, s.nsi});
      continue;
    }
    // PBEAML: the dimensions vary linearly between stations (QRG), the section properties do not:
    // 32 sub-intervals, each section from the interpolated dimensions (linear properties between
    // them: 1.4e-4 of a tip deflection for a tube whose radius tapers 3 to 2, tests/solutions/tapered_beam_test.cpp)
    const BarProperty::Station& a = p.stations[k - 1];
    constexpr int kParts = 32;
    for (int j = 1; j <= kParts; ++j) {
      const double f = static_cast<double>(j) / kParts;
      std::vector<double> dims(s.dims.size());
      for (std::size_t d = 0; d < dims.size(); ++d) dims[d] = (1 - f) * a.dims[d] + f * s.dims[d];
      const BeamSection b = beam_section(p.section_type, dims);
      e.taper.push_back({(1 - f) * a.x + f * s.x, {b.A, b.I1, b.I2, b.I12, b.J, p.K1, p.K2, (1 - f) * a.nsm + f * s.nsm}, 0.0});
    }
  }
  if (p.I12 != 0.0 && !(p.I1 * p.I2 > p.I12 * p.I12))
    detail::fail(model, p.ref, pcard, p.id, "I12", "I1 * I2 must exceed I12^2 (I1 = " + std::to_string(p.I1) +
                                                       ", I2 = " + std::to_string(p.I2) +
                                                       ", I12 = " + std::to_string(p.I12) + ")");

  const std::string offt = bar.offt.size() == 3 ? bar.offt : std::string("GGG");
  if (bar.has_g0) {
    const Grid& g0 = model.grids[detail::grid_index(model, bar.g0, bar.ref, card, bar.id, "6 (G0)")];
    e.v = g0.x_basic - ga.x_basic;
  } else {
    e.v = offt[0] == 'B' ? bar.v : Eigen::Vector3d(A_A * bar.v);
  }
  // Offsets in GA/GB's displacement system ('G'), basic ('B') or element axes ('O'); element axes
  // for 'O' offsets are taken from the grid-to-grid line.
  Eigen::Matrix3d R0 = Eigen::Matrix3d::Identity();
  if (offt[1] == 'O' || offt[2] == 'O') {
    BarElement g = e;
    if ((g.x_B - g.x_A).norm() == 0.0 || (g.x_B - g.x_A).cross(g.v).norm() <= 1e-9 * g.v.norm() * (g.x_B - g.x_A).norm())
      detail::fail(model, bar.ref, card, bar.id, "9 (OFFT)", "element axes undefined for offsets in element axes");
    R0 = bar_axes(g);
  }
  e.w_A = offt[1] == 'G' ? Eigen::Vector3d(A_A * bar.wa) : offt[1] == 'B' ? bar.wa : Eigen::Vector3d(R0 * bar.wa);
  e.w_B = offt[2] == 'G' ? Eigen::Vector3d(A_B * bar.wb) : offt[2] == 'B' ? bar.wb : Eigen::Vector3d(R0 * bar.wb);
  e.pin_A = bar.pa;
  e.pin_B = bar.pb;

  const Eigen::Vector3d d = (e.x_B + e.w_B) - (e.x_A + e.w_A);
  if (!(d.norm() > 0.0)) detail::fail(model, bar.ref, card, bar.id, "", "has zero length between its (offset) ends");
  if (!(d.cross(e.v).norm() > 1e-9 * e.v.norm() * d.norm()))
    detail::fail(model, bar.ref, card, bar.id, bar.has_g0 ? "6 (G0)" : "6-8 (X1-X3)",
                 "orientation vector is zero or parallel to the bar axis");
  if (e.pin_A || e.pin_B) {
    Matrix12 K = bar_stiffness_element_axes(e);
    if (!condense_pins(e.pin_A, e.pin_B, K))
      detail::fail(model, bar.ref, card, bar.id, "PA/PB",
                   "pin flags PA = '" + component_string(e.pin_A) + "', PB = '" + component_string(e.pin_B) +
                       "' release degrees of freedom the bar has no stiffness for (or leave a mechanism)");
  }
  return e;
}

}  // namespace seflex::fem
