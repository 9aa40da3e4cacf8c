// Differential (geometric) stiffness K_sigma: element checks (symmetry; the derivative of the
// pre-stressed element's internal force under a rigid rotation; the Hessian of the Green-Lagrange
// stress term by central finite differences) and linear buckling against closed-form solutions:
// Euler columns (Timoshenko & Gere, Theory of Elastic Stability, 2nd ed. 1961, sec. 2.1-2.3:
// P_cr = pi^2 EI / (K L)^2 with K = 1 pinned-pinned, 2 cantilever, 1/2 clamped-clamped) and the simply
// supported square plate in uniaxial compression (ibid. sec. 9.2: N_cr = k pi^2 D / b^2, k = 4).
// The eigenproblems are solved densely here (-K_sigma x = (1/lambda) K x); `seflex buckling` with the
// production eigensolver is checked in tests/solutions/cli_buckling_test.cpp.
#include "seflex/fem/geometric_stiffness.hpp"

#include <gtest/gtest.h>

#include <cmath>

#include "fem_test_util.hpp"
#include "seflex/fem/assembly.hpp"
#include "seflex/fem/constraints.hpp"
#include "seflex/fem/element_bar.hpp"
#include "seflex/fem/element_rod.hpp"
#include "seflex/fem/element_shell_quad4.hpp"
#include "seflex/fem/element_shell_tria3.hpp"
#include "seflex/fem/loads.hpp"
#include "shell_mesh.hpp"

namespace seflex::fem {
namespace {

const double kPi = std::acos(-1.0);

Eigen::Matrix3d rotation(const Eigen::Vector3d& axis_angle) {
  return Eigen::AngleAxisd(axis_angle.norm(), axis_angle.normalized()).toRotationMatrix();
}

// Rigid rotation omega of N nodes at x (translations omega x x_n, rotations omega).
template <int N>
Eigen::Matrix<double, 6 * N, 1> rigid_rotation(const std::array<Eigen::Vector3d, N>& x, const Eigen::Vector3d& w) {
  Eigen::Matrix<double, 6 * N, 1> d;
  for (int n = 0; n < N; ++n) {
    d.template segment<3>(6 * n) = w.cross(x[n]);
    d.template segment<3>(6 * n + 3) = w;
  }
  return d;
}

// A pre-stressed element turned rigidly by omega carries its nodal forces turned with it:
// d f = K_sigma d u must equal omega x f_n on the translations (and 0 on the rotations, as the
// preloads below have no nodal moments).
template <int N>
void expect_rotates_forces(const NodeMatrix<N>& Kg, const Eigen::Matrix<double, 6 * N, 1>& f0,
                           const std::array<Eigen::Vector3d, N>& x, const char* what) {
  const Eigen::Vector3d w(0.3, -0.7, 0.5);
  const Eigen::Matrix<double, 6 * N, 1> df = Kg * rigid_rotation<N>(x, w);
  for (int n = 0; n < N; ++n) {
    ASSERT_LE(f0.template segment<3>(6 * n + 3).norm(), 1e-9 * f0.norm()) << what;
    const Eigen::Vector3d expected = w.cross(f0.template segment<3>(6 * n));
    EXPECT_LE((df.template segment<3>(6 * n) - expected).norm(), 1e-9 * f0.norm()) << what << " node " << n;
    EXPECT_LE(df.template segment<3>(6 * n + 3).norm(), 1e-9 * f0.norm()) << what << " node " << n;
  }
}

// Central-difference Hessian of a scalar function of the translations of N nodes.
template <int N, class F>
NodeMatrix<N> fd_hessian(const F& W, bool rotations = false) {
  NodeMatrix<N> H = NodeMatrix<N>::Zero();
  const double h = 1e-3;
  Eigen::Matrix<double, 6 * N, 1> u = Eigen::Matrix<double, 6 * N, 1>::Zero();
  for (int i = 0; i < 6 * N; ++i)
    for (int j = 0; j < 6 * N; ++j) {
      if (!rotations && (i % 6 >= 3 || j % 6 >= 3)) continue;  // the shells' and rods' stress term has no rotations
      auto at = [&](double a, double b) {
        Eigen::Matrix<double, 6 * N, 1> v = u;
        v(i) += a;
        v(j) += b;
        return W(v);
      };
      H(i, j) = (at(h, h) - at(h, -h) - at(-h, h) + at(-h, -h)) / (4 * h * h);
    }
  return H;
}

// ---------------------------------------------------------------------------------------------
// Elements

TEST(GeometricStiffness, RodRotatesItsAxialForceAndIsTheHessianOfTheGreenStrainTerm) {
  RodElement e;
  e.x_A = {0.2, -0.1, 0.4};
  e.x_B = {1.4, 0.7, -0.3};
  e.A = 3e-4;
  e.material = {1, 7e10, 2.6e10, 0.3, 2700};
  Eigen::Matrix<double, 12, 1> u0 = Eigen::Matrix<double, 12, 1>::Zero();
  u0.segment<3>(6) = 1e-3 * (e.x_B - e.x_A);  // stretch: tension
  const double N = rod_axial_force(e, u0);
  const double L = (e.x_B - e.x_A).norm();
  EXPECT_NEAR(N, e.material.E * e.A * 1e-3, 1e-9 * std::abs(N));
  const NodeMatrix<2> Kg = rod_geometric_stiffness(e, N);
  EXPECT_LE((Kg - Kg.transpose()).norm(), 1e-14 * Kg.norm());
  expect_rotates_forces<2>(Kg, rod_stiffness(e) * u0, {e.x_A, e.x_B}, "CROD");
  // N L E_GL with E_GL = (l^2 - L^2) / (2 L^2), l the deformed length.
  const NodeMatrix<2> H = fd_hessian<2>([&](const Eigen::Matrix<double, 12, 1>& u) {
    const double l2 = ((e.x_B + u.segment<3>(6)) - (e.x_A + u.segment<3>(0))).squaredNorm();
    return N * L * (l2 - L * L) / (2 * L * L);
  });
  EXPECT_LE((H - Kg).norm(), 1e-6 * Kg.norm());
}

TEST(GeometricStiffness, BarRotatesItsAxialForceInAnyOrientation) {
  BarElement e;
  e.x_A = {0.3, -0.2, 0.5};
  e.x_B = {2.1, 0.9, -0.4};
  e.v = {0.2, -0.5, 1.0};
  e.section = {2e-3, 3e-6, 1.5e-6, 0.0, 2.5e-6, 0.0, 0.0, 0.0};
  e.material = {1, 7e10, 7e10 / 2.6, 0.3, 2700};
  Eigen::Matrix<double, 12, 1> u0 = Eigen::Matrix<double, 12, 1>::Zero();
  u0.segment<3>(0) = 2e-4 * (e.x_B - e.x_A);  // shortening: compression
  const double N = bar_axial_force(e, u0);
  EXPECT_NEAR(N, -e.material.E * e.section.A * 2e-4, 1e-9 * std::abs(N));
  const NodeMatrix<2> Kg = bar_geometric_stiffness(e, N);
  EXPECT_LE((Kg - Kg.transpose()).norm(), 1e-14 * Kg.norm());
  expect_rotates_forces<2>(Kg, bar_stiffness(e) * u0, {e.x_A, e.x_B}, "CBAR");
  // rigid translations carry no force
  const auto D = rigid_body_modes<2>({e.x_A, e.x_B});
  EXPECT_LE((Kg * D.leftCols<3>()).norm(), 1e-12 * Kg.norm());
  // a pin releasing the axial force of end B: no axial force, no geometric stiffness
  e.pin_B = test::mask("1");
  EXPECT_NEAR(bar_axial_force(e, u0), 0.0, 1e-9 * std::abs(N));
}

// The bar's K_sigma against the Hessian of N int (1/2)(u'^2 + v'^2 + w'^2 + (I1 + I2)/A theta_x'^2) ds,
// evaluated by 4-point Gauss quadrature of the interpolated fields (linear u and theta_x, cubic
// Hermite v with v' = theta_z and w with w' = -theta_y), on a bar along basic x (element axes = basic).
TEST(GeometricStiffness, BarIsTheHessianOfTheAxialForceWork) {
  BarElement e;
  const double L = 1.7;
  e.x_B = {L, 0, 0};
  e.v = {0, 1, 0};
  e.section = {2e-3, 3e-6, 1.5e-6, 0.0, 2.5e-6, 0.0, 0.0, 0.0};
  e.material = {1, 7e10, 7e10 / 2.6, 0.3, 2700};
  const double N = -1234.5;
  const NodeMatrix<2> Kg = bar_geometric_stiffness(e, N);
  const double gp[4] = {-0.8611363115940526, -0.3399810435848563, 0.3399810435848563, 0.8611363115940526};
  const double gw[4] = {0.3478548451374538, 0.6521451548625461, 0.6521451548625461, 0.3478548451374538};
  const double ip = (e.section.I1 + e.section.I2) / e.section.A;
  const NodeMatrix<2> H = fd_hessian<2>(
      [&](const Eigen::Matrix<double, 12, 1>& q) {
        double W = 0;
        for (int k = 0; k < 4; ++k) {
          const double x = 0.5 * (1 + gp[k]);  // s / L
          // derivatives d/ds of the Hermite functions H1 (v_A), H2 (theta_A), H3 (v_B), H4 (theta_B)
          const double d1 = (-6 * x + 6 * x * x) / L, d2 = 1 - 4 * x + 3 * x * x, d3 = (6 * x - 6 * x * x) / L,
                       d4 = -2 * x + 3 * x * x;
          const double du = (q(6) - q(0)) / L, dtx = (q(9) - q(3)) / L;
          const double dv = d1 * q(1) + d2 * q(5) + d3 * q(7) + d4 * q(11);
          const double dw = d1 * q(2) - d2 * q(4) + d3 * q(8) - d4 * q(10);
          W += 0.5 * L * gw[k] * 0.5 * N * (du * du + dv * dv + dw * dw + ip * dtx * dtx);
        }
        return W;
      },
      true);
  EXPECT_LE((H - Kg).norm(), 1e-6 * Kg.norm());
}

// Membrane state of uniform strain eps (element plane spanned by R's first two columns, basic).
template <int N>
Eigen::Matrix<double, 6 * N, 1> uniform_strain(const std::array<Eigen::Vector3d, N>& x, const Eigen::Matrix3d& R,
                                               const Eigen::Matrix2d& eps) {
  Eigen::Matrix3d E3 = Eigen::Matrix3d::Zero();
  E3.topLeftCorner<2, 2>() = eps;
  const Eigen::Matrix3d E = R * E3 * R.transpose();
  Eigen::Matrix<double, 6 * N, 1> u = Eigen::Matrix<double, 6 * N, 1>::Zero();
  for (int n = 0; n < N; ++n) u.template segment<3>(6 * n) = E * x[n];
  return u;
}

ShellSection isotropic_section(double E, double nu, double t) {
  ShellSection s;
  const double c = E * t / (1 - nu * nu);
  s.A << c, c * nu, 0, c * nu, c, 0, 0, 0, c * (1 - nu) / 2;
  s.D = s.A * (t * t / 12.0);
  s.S = Eigen::Matrix2d::Identity() * (5.0 / 6.0) * E / (2 * (1 + nu)) * t;
  s.has_membrane = s.has_bending = s.shear_flexible = s.isotropic = true;
  s.t = t;
  s.ts2 = t * t;
  s.drill_Gt = E / (2 * (1 + nu)) * t;
  return s;
}

// Green-Lagrange stress term of a membrane: sum over the Gauss points of N_ab E_ab with the in-plane
// metric of the deformed bilinear (quad) or linear (tria) surface, E_ab = (g_a . g_b - G_a . G_b)/2,
// g_a = dX/dx_a + du/dx_a (x_a the element's plane coordinates).
template <int N>
double green_stress_term(const std::array<Eigen::Vector3d, N>& x, const Eigen::Matrix3d& R,
                         const std::array<Eigen::Vector3d, (N == 4 ? 4 : 1)>& Ngauss,
                         const Eigen::Matrix<double, 6 * N, 1>& u) {
  const double g = 1.0 / std::sqrt(3.0);
  const double pts[4][2] = {{-g, -g}, {g, -g}, {g, g}, {-g, g}};
  const double kx[4] = {-1, 1, 1, -1}, ke[4] = {-1, -1, 1, 1};
  double W = 0;
  for (int k = 0; k < (N == 4 ? 4 : 1); ++k) {
    Eigen::Matrix<double, 2, N> dnat;  // natural derivatives of the shape functions
    if constexpr (N == 4) {
      for (int i = 0; i < 4; ++i) {
        dnat(0, i) = 0.25 * kx[i] * (1 + pts[k][1] * ke[i]);
        dnat(1, i) = 0.25 * ke[i] * (1 + pts[k][0] * kx[i]);
      }
    } else {
      dnat << -1, 1, 0, -1, 0, 1;
    }
    Eigen::Matrix<double, 3, 2> X_nat = Eigen::Matrix<double, 3, 2>::Zero(), u_nat = X_nat;
    for (int i = 0; i < N; ++i) {
      X_nat += x[i] * dnat.col(i).transpose();
      u_nat += u.template segment<3>(6 * i) * dnat.col(i).transpose();
    }
    // plane coordinates: J = d(x1, x2)/d(xi, eta)
    const Eigen::Matrix2d J = (R.leftCols<2>().transpose() * X_nat).transpose();
    const Eigen::Matrix2d Jinv = J.inverse();
    const Eigen::Matrix<double, 3, 2> G = X_nat * Jinv.transpose(), gdef = (X_nat + u_nat) * Jinv.transpose();
    const Eigen::Matrix2d E = 0.5 * (gdef.transpose() * gdef - G.transpose() * G);
    const double w = (N == 4 ? 1.0 : 0.5) * J.determinant();
    const Eigen::Vector3d& n = Ngauss[k];
    W += w * (n(0) * E(0, 0) + n(1) * E(1, 1) + 2 * n(2) * E(0, 1));
  }
  return W;
}

TEST(GeometricStiffness, Quad4MembraneStressRotatesAndIsTheHessianOfTheGreenStrainTerm) {
  const Eigen::Matrix3d R = rotation({0.4, -0.3, 0.8});
  Quad4Element e;
  const Eigen::Vector2d p[4] = {{0, 0}, {1.2, 0.1}, {1.0, 0.9}, {-0.1, 0.7}};  // general convex quad
  for (int i = 0; i < 4; ++i) e.x[i] = R * Eigen::Vector3d(p[i].x(), p[i].y(), 0) + Eigen::Vector3d(0.5, -1, 2);
  e.section = isotropic_section(7e10, 0.3, 0.01);
  Eigen::Matrix2d eps;
  eps << -3e-4, 1e-4, 1e-4, 2e-4;
  const Eigen::Matrix<double, 24, 1> u0 = uniform_strain<4>(e.x, R, eps);
  const auto Ng = quad4_membrane_resultants(e, u0);
  // uniform strain -> uniform resultants A eps (element axes e1 along the projected G1-G2 edge)
  const Eigen::Vector2d e1 = Eigen::Vector2d(1.2, 0.1).normalized();
  Eigen::Matrix2d Rl;
  Rl << e1.x(), -e1.y(), e1.y(), e1.x();
  const Eigen::Matrix2d el = Rl.transpose() * eps * Rl;
  const Eigen::Vector3d Nexp = e.section.A * Eigen::Vector3d(el(0, 0), el(1, 1), 2 * el(0, 1));
  for (const auto& n : Ng) EXPECT_LE((n - Nexp).norm(), 1e-8 * Nexp.norm());
  const NodeMatrix<4> Kg = quad4_geometric_stiffness(e, Ng);
  EXPECT_LE((Kg - Kg.transpose()).norm(), 1e-14 * Kg.norm());
  expect_rotates_forces<4>(Kg, quad4_stiffness(e, 100.0) * u0, e.x, "CQUAD4");
  // Hessian of the Green-Lagrange term, with the element-axis R of the quad (e1 along G1-G2)
  Eigen::Matrix3d Re = R;
  Re.col(0) = R * Eigen::Vector3d(e1.x(), e1.y(), 0);
  Re.col(1) = R.col(2).cross(Re.col(0));
  const NodeMatrix<4> H =
      fd_hessian<4>([&](const Eigen::Matrix<double, 24, 1>& u) { return green_stress_term<4>(e.x, Re, Ng, u); });
  EXPECT_LE((H - Kg).norm(), 1e-6 * Kg.norm());
}

TEST(GeometricStiffness, Tria3MembraneStressRotatesAndIsTheHessianOfTheGreenStrainTerm) {
  const Eigen::Matrix3d R = rotation({-0.6, 0.2, 0.5});
  Tria3Element e;
  const Eigen::Vector2d p[3] = {{0, 0}, {1.1, 0}, {0.3, 0.8}};  // G1->G2 along the plane's first axis
  for (int i = 0; i < 3; ++i) e.x[i] = R * Eigen::Vector3d(p[i].x(), p[i].y(), 0) + Eigen::Vector3d(1, 2, -0.5);
  e.section = isotropic_section(2e11, 0.25, 0.02);
  Eigen::Matrix2d eps;
  eps << 2e-4, -1.5e-4, -1.5e-4, -4e-4;
  const Eigen::Matrix<double, 18, 1> u0 = uniform_strain<3>(e.x, R, eps);
  const Eigen::Vector3d N = tria3_membrane_resultants(e, u0);
  const Eigen::Vector3d Nexp = e.section.A * Eigen::Vector3d(eps(0, 0), eps(1, 1), 2 * eps(0, 1));
  EXPECT_LE((N - Nexp).norm(), 1e-9 * Nexp.norm());
  const NodeMatrix<3> Kg = tria3_geometric_stiffness(e, N);
  EXPECT_LE((Kg - Kg.transpose()).norm(), 1e-14 * Kg.norm());
  expect_rotates_forces<3>(Kg, tria3_stiffness(e, 100.0) * u0, e.x, "CTRIA3");
  const NodeMatrix<3> H =
      fd_hessian<3>([&](const Eigen::Matrix<double, 18, 1>& u) { return green_stress_term<3>(e.x, R, {N}, u); });
  EXPECT_LE((H - Kg).norm(), 1e-6 * Kg.norm());
}

// ---------------------------------------------------------------------------------------------
// Linear buckling of models (dense): preload statics, K_sigma, lowest positive load factors.

std::vector<double> buckling_factors(const Model& m, int spc, int load) {
  const GlobalMatrices g = assemble(m, assembly_options(m));
  const ConstrainedSystem c = apply_constraints(m, g, spc);
  const Eigen::VectorXd p = reduce_load(c, g, load_vector(m, g.dofs, load));
  const Eigen::MatrixXd Kff = test::dense(c.K_ff);
  const Eigen::VectorXd u = expand(c, Eigen::LLT<Eigen::MatrixXd>(Kff).solve(p));
  const Eigen::SparseMatrix<double> Kg = assemble_geometric_stiffness(m, g.dofs, u);
  const Eigen::SparseMatrix<double> Tt = c.T.transpose();
  const Eigen::MatrixXd Kg_ff = test::dense(Eigen::SparseMatrix<double>(Tt * Kg * c.T));
  return test::dense_eigenvalues(Kff, -Kg_ff);  // -K_sigma x = (1/lambda) K x, lambda > 0 ascending
}

enum class Ends { PinnedPinned, Cantilever, ClampedClamped };

// Column along x, n CBARs (or CBEAMs as CBAR: same stiffness), compressive tip load P = 1 along -x.
// I1 (plane x-y) < I2, so the first mode bends in the x-y plane.
std::vector<double> column(Ends ends, int n) {
  Model m;
  test::add_mat1(m, 1, 2e11, 0.3, 7850);
  test::add_pbar(m, 1, 1, 1e-3, 2e-7, 8e-7, 5e-7);
  const double L = 3.0;
  for (int i = 0; i <= n; ++i) test::add_grid(m, i + 1, L * i / n, 0, 0);
  for (int i = 0; i < n; ++i) test::add_cbar(m, i + 1, 1, i + 1, i + 2, {0, 1, 0});
  const int tip = n + 1;
  switch (ends) {
    case Ends::PinnedPinned:
      test::add_spc(m, 1, 1, "1234");
      test::add_spc(m, 1, tip, "23");
      break;
    case Ends::Cantilever:
      test::add_spc(m, 1, 1, "123456");
      break;
    case Ends::ClampedClamped:
      test::add_spc(m, 1, 1, "123456");
      test::add_spc(m, 1, tip, "23456");
      break;
  }
  test::add_force(m, 2, tip, {-1, 0, 0});
  test::finalize_for_test(m);
  return buckling_factors(m, 1, 2);
}

TEST(Buckling, EulerColumnsWithCbarConvergeAtFourthOrder) {
  const double EI = 2e11 * 2e-7, L = 3.0;
  struct Case {
    Ends ends;
    double K;  // effective length factor
  };
  for (const Case& c : {Case{Ends::PinnedPinned, 1.0}, Case{Ends::Cantilever, 2.0}, Case{Ends::ClampedClamped, 0.5}}) {
    const double P = kPi * kPi * EI / (c.K * L * c.K * L);
    double err[3];
    int k = 0;
    for (int n : {4, 8, 16}) err[k++] = (column(c.ends, n).at(0) - P) / P;
    SCOPED_TRACE(static_cast<int>(c.ends));
    EXPECT_LT(err[2], 1e-4);
    // cubic Hermite bending with the consistent geometric stiffness: error O(h^4) (upper bound)
    EXPECT_GT(std::log2(err[0] / err[1]), 3.5);
    EXPECT_GT(std::log2(err[1] / err[2]), 3.5);
  }
}

// The published verification table of another beam code (Tekla Structural Designer 2020, "2nd order
// buckling - Euler strut buckling": support.tekla.com/doc/tekla-structural-designer/2020/
// ref_2ndorderbucklingeulerstrutbuckling): simply supported strut, L = 10, EI/L^2 = 1, P = 1, with
// 0..5 internal nodes: load factors 12.000, 9.944, 9.885, 9.875, 9.872, 9.871 (3 decimals), the
// values of cubic Hermite elements with the consistent geometric stiffness (1 element: 12 EI / L^2).
TEST(Buckling, SimplySupportedStrutMatchesAPublishedTable) {
  const double table[6] = {12.000, 9.944, 9.885, 9.875, 9.872, 9.871};
  for (int n = 1; n <= 6; ++n) {
    Model m;
    test::add_mat1(m, 1, 1e4, 0.3, 1.0);
    test::add_pbar(m, 1, 1, 1.0, 1e-2, 1e-2, 1e-2);  // EI = 100 = L^2
    for (int i = 0; i <= n; ++i) test::add_grid(m, i + 1, 10.0 * i / n, 0, 0);
    for (int i = 0; i < n; ++i) test::add_cbar(m, i + 1, 1, i + 1, i + 2, {0, 1, 0});
    test::add_spc(m, 1, 1, "1234");
    test::add_spc(m, 1, n + 1, "23");
    test::add_force(m, 2, n + 1, {-1, 0, 0});
    test::finalize_for_test(m);
    const std::vector<double> lam = buckling_factors(m, 1, 2);
    EXPECT_NEAR(lam.at(0), table[n - 1], 5e-4) << n << " elements";
  }
}

// Chain of n CONRODs along x (pinned ends, load P along -x at the tip), each inner node held laterally
// (T2) by a spring k: lateral equilibrium k y_i = (P / h)(y_{i-1} - 2 y_i + y_{i+1}) has the exact
// critical loads P_m = k h / (2 - 2 cos(m pi / n)), m = 1 .. n-1; the lowest is m = n - 1,
// P = k h / (2 + 2 cos(pi / n)). The rods carry the whole load; their K_sigma alone destabilises.
TEST(Buckling, RodChainOnSpringsMatchesTheDiscreteClosedForm) {
  const int n = 6;
  const double L = 2.0, h = L / n, k = 5e3;
  Model m;
  test::add_mat1(m, 1, 2e11, 0.3, 7850);
  for (int i = 0; i <= n; ++i) test::add_grid(m, i + 1, h * i, 0, 0);
  for (int i = 0; i < n; ++i) test::add_conrod(m, i + 1, i + 1, i + 2, 1, 1e-4);
  for (int i = 1; i < n; ++i) test::add_celas2(m, 100 + i, i + 1, 2, k);
  for (int i = 0; i <= n; ++i) test::add_spc(m, 1, i + 1, i == 0 ? "13456" : "3456");
  test::add_spc(m, 1, n + 1, "2");
  test::add_force(m, 2, n + 1, {-1, 0, 0});
  test::finalize_for_test(m);
  const std::vector<double> lam = buckling_factors(m, 1, 2);
  // (the rods' axial K_sigma adds "modes" at lambda = EA / |N| = 2e7, a strain of 1, far above)
  ASSERT_GE(lam.size(), static_cast<std::size_t>(n - 1));
  EXPECT_GT(lam[n - 1], 1e6);
  for (int j = 0; j < n - 1; ++j) {
    const int mode = n - 1 - j;  // ascending load = descending wave number
    const double P = k * h / (2 - 2 * std::cos(mode * kPi / n));
    EXPECT_NEAR(lam[j], P, 1e-9 * P) << "mode " << mode;
  }
}

// Simply supported square plate (a = b = 1 m, t = 10 mm, aluminium) under a uniform compression
// N_x = 1 N/m on the edges x = 0 and x = a: N_cr = 4 pi^2 D / b^2 (Timoshenko & Gere, sec. 9.2).
// Edges: w = 0 on all four; u = 0 on x = 0, v = 0 at one corner (the plate contracts freely in y, so
// N_y = 0); the "hard" simple support of a Mindlin plate: the rotation about the edge normal (the slope
// along the edge) is held, as w = 0 along the edge implies in Kirchhoff's plate. With only w = 0 (the
// "soft" support) the Mindlin plate has edge boundary layers and converges 0.5 % low at t/a = 0.01
// (measured: 0.9948 at 32 x 32), not to Kirchhoff's k = 4. The Mindlin shear of the exact plate lowers
// N_cr by 1 / (1 + 2 pi^2 D / (kappa G t a^2)) = 0.99944 here: negligible at this tolerance.
// The edge load is the consistent one of a uniform traction.
// shear = false: PSHELL MID3 blank (Kirchhoff's plate: CTRIA3's DKT, CQUAD4's MITC4 with the penalty).
double plate_first_factor(int nel, bool triangles, bool shear = true) {
  const double a = 1.0, t = 0.01, E = 7e10, nu = 0.3;
  Model m;
  test::add_mat1(m, 1, E, nu, 2700);
  test::add_pshell(m, 1, 1, t, shear);
  const test::ShellMesh mesh = test::add_shell_mesh(
      m, nel, nel, [&](double x, double y) { return Eigen::Vector3d(a * x, a * y, 0); }, triangles);
  for (int j = 0; j <= nel; ++j)
    for (int i = 0; i <= nel; ++i) {
      const bool edge = i == 0 || j == 0 || i == nel || j == nel;
      if (!edge) continue;
      std::string c = "3";
      if (i == 0) c += "1";
      if (i == 0 && j == 0) c += "2";
      if (i == 0 || i == nel) c += "4";  // hard simple support: no slope along the edge (theta_x on x = const)
      if (j == 0 || j == nel) c += "5";  // (theta_y on y = const)
      test::add_spc(m, 1, mesh.id(i, j), c);
      if (i == nel) test::add_force(m, 2, mesh.id(i, j), {-(j == 0 || j == nel ? 0.5 : 1.0) * a / nel, 0, 0});
    }
  test::finalize_for_test(m);
  return buckling_factors(m, 1, 2).at(0);
}

TEST(Buckling, SimplySupportedSquarePlateInUniaxialCompression) {
  const double t = 0.01, E = 7e10, nu = 0.3;
  const double D = E * t * t * t / (12 * (1 - nu * nu));
  const double Ncr = 4 * kPi * kPi * D;
  const double q8 = plate_first_factor(8, false), q12 = plate_first_factor(12, false);
  const double t12 = plate_first_factor(12, true);
  std::printf("plate buckling N_cr / exact: CQUAD4 8x8 %.5f, 12x12 %.5f; CTRIA3 12x12 (x2) %.5f\n", q8 / Ncr, q12 / Ncr,
              t12 / Ncr);
  EXPECT_NEAR(q12 / Ncr, 1.0, 0.01);
  EXPECT_NEAR(q8 / Ncr, 1.0, 0.02);
  EXPECT_LT(std::abs(q12 / Ncr - 1.0), 0.6 * std::abs(q8 / Ncr - 1.0));  // converging (about O(h^2): (8/12)^2 = 0.44)
  EXPECT_NEAR(t12 / Ncr, 1.0, 0.02);
  // MID3 blank: the same differential stiffness on Kirchhoff bending. Measured 2026-12-06: CTRIA3 (DKT)
  // 0.99933 at 8 x 8 (x2) and 0.99971 at 16 x 16 (x2, not run here: 20 s of dense eigenvalues), CQUAD4
  // 1.00964 at 12 x 12; tolerances 0.2 % and 1.5 %
  const double k8 = plate_first_factor(8, true, false), kq12 = plate_first_factor(12, false, false);
  std::printf("MID3 blank: CTRIA3 (DKT) 8x8 (x2) %.5f; CQUAD4 12x12 %.5f\n", k8 / Ncr, kq12 / Ncr);
  EXPECT_NEAR(k8 / Ncr, 1.0, 0.002);
  EXPECT_NEAR(kq12 / Ncr, 1.0, 0.015);
}

}  // namespace
}  // namespace seflex::fem
