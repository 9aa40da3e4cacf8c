// PCOMP/PCOMPG, MAT8 and the general PSHELL in the CQUAD4/CTRIA3 models, against independent
// references:
//  - Navier solution of the simply supported specially orthotropic plate (cross-ply [0/90/90/0],
//    D16 = D26 = 0, B = 0) in classical lamination theory (Reddy, Mechanics of Laminated Composite
//    Plates and Shells, 2nd ed. (2004), ch. 5: for q = q0 sin(pi x/a) sin(pi y/b)
//      w_max = q0 / (pi^4 d11),  omega_mn^2 = pi^4 d_mn / (rho h),
//      d_mn = D11 (m/a)^4 + 2 (D12 + 2 D66) (m/a)^2 (n/b)^2 + D22 (n/b)^4
//    without rotary inertia, as the shell mass matrices carry none), with D from the textbook sums
//    (laminate_reference.hpp); the plate is thin (a/h = 400), so transverse shear changes it by 0.03 %.
//  - A PCOMP of one MAT1 ply is the PSHELL of that material (MID1 = MID2 = MID3, TS/T = 5/6): the
//    same K and M (1e-12).
//  - Material axes: plies rotated by -phi with THETA = phi (or MCID a system rotated by phi) give the
//    same matrices as the unrotated laminate.
//  - Membrane-bending coupling of the unsymmetric [0/90] laminate: a free plate under a uniform edge
//    tension N_x takes the constant state [eps0; kappa] = [A B; B D]^-1 [N_x 0 0 0 0 0] of
//    lamination theory (Jones, ch. 4), so its corner deflection is -(kx a^2 + ky b^2 + kxy a b)/2; the
//    PSHELL with MID4 written as Nastran's equivalent of the laminate (T, A/T, 12D/T^3, B/T^2) gives
//    the same displacements.
//  - A honeycomb sandwich written as PCOMP (face/core/face, the core a MAT8 with E ~ 0 and G1Z, G2Z)
//    and as the PSHELL of the same panel (MID1 = MID2 the face, 12I/T^3 = (h^3 - tc^3)/T^3, MID3 the
//    core with TS/T = d^2/(tc T)): the same frequencies within 1 %, and the lowest three within 1 % of
//    the Mindlin plate omega^2 = D k^4 / (m (1 + D k^2 / S)), S = G_c d^2 / tc (Mindlin 1951; Zenkert,
//    An Introduction to Sandwich Construction).
#include <gtest/gtest.h>

#include <cmath>

#include "laminate_reference.hpp"
#include "shell_mesh.hpp"
#include "seflex/fem/assembly.hpp"
#include "seflex/fem/constraints.hpp"
#include "seflex/fem/dof_map.hpp"
#include "seflex/fem/loads.hpp"
#include "seflex/fem/section.hpp"

#include <Eigen/SparseCholesky>

namespace seflex::fem {
namespace {

using namespace test::clt;

Mat8& add_mat8(Model& m, int id, const Mat8& proto) {
  Mat8 mat = proto;
  mat.id = id;
  m.mat8.push_back(mat);
  return m.mat8.back();
}

Mat2& add_mat2(Model& m, int id, const Eigen::Matrix3d& G, double rho = 0.0) {
  Mat2 mat;
  mat.id = id;
  mat.G11 = G(0, 0), mat.G12 = G(0, 1), mat.G13 = G(0, 2), mat.G22 = G(1, 1), mat.G23 = G(1, 2), mat.G33 = G(2, 2);
  mat.rho = rho;
  m.mat2.push_back(mat);
  return m.mat2.back();
}

CompositeProperty& add_pcomp(Model& m, int id, const std::vector<std::pair<int, double>>& mid_angle, double t,
                             double nsm = 0.0) {
  CompositeProperty p;
  p.id = id;
  p.nsm = nsm;
  for (const auto& [mid, angle] : mid_angle) p.plies.push_back({0, mid, t, angle, false});
  m.composite_props.push_back(p);
  return m.composite_props.back();
}

void set_mcid(Model& m, int mcid) {
  for (Shell& sh : m.shells) {
    sh.theta_is_mcid = true;
    sh.mcid = mcid;
  }
}

struct Plate {
  Model model;
  test::ShellMesh mesh;
  int n = 0;
  double a = 0, b = 0;
};

// a x b plate, n x n CQUAD4 (or CTRIA3) of property 1, hard simply supported, in-plane dofs held.
// Triangles get MCID = 0: THETA is measured from each element's G1-G2 edge, which for half of them
// is the cell's diagonal (QRG CTRIA3), so THETA = 0 would not be one material direction.
template <class AddProperty>
Plate make_plate(double a, double b, int n, AddProperty add_property, bool triangles = false, bool hold_inplane = true) {
  Plate p;
  p.n = n;
  p.a = a;
  p.b = b;
  add_property(p.model);
  p.mesh = test::add_shell_mesh(
      p.model, n, n, [&](double u, double v) { return Eigen::Vector3d(a * u, b * v, 0.0); }, triangles);
  if (triangles) set_mcid(p.model, 0);
  for (int j = 0; j <= n; ++j)
    for (int i = 0; i <= n; ++i) {
      std::string c = hold_inplane ? "126" : "";
      if (i == 0 || i == n) c += "34";
      if (j == 0 || j == n) c += "35";
      if (!c.empty()) test::add_spc(p.model, 1, p.mesh.id(i, j), c);
    }
  test::finalize_for_test(p.model);
  return p;
}

std::vector<double> frequencies_hz(const Plate& p, int count) {
  const GlobalMatrices g = assemble(p.model, assembly_options(p.model));
  const ConstrainedSystem c = apply_constraints(p.model, g, 1);
  std::vector<double> f;
  for (double lam : test::lowest_eigenvalues(c.K_ff, c.M_ff, count)) f.push_back(std::sqrt(lam) / (2 * kPi));
  return f;
}

double centre_deflection(const Plate& p, double q0) {
  const GlobalMatrices g = assemble(p.model, assembly_options(p.model));
  const ConstrainedSystem c = apply_constraints(p.model, g, 1);
  Eigen::VectorXd p_g = Eigen::VectorXd::Zero(g.K.rows());
  const double hx = p.a / p.n, hy = p.b / p.n;
  for (int j = 1; j < p.n; ++j)
    for (int i = 1; i < p.n; ++i)
      p_g[*find_dof(p.model, g.dofs, p.mesh.id(i, j), 3)] = q0 * std::sin(kPi * i / p.n) * std::sin(kPi * j / p.n) * hx * hy;
  Eigen::SimplicialLDLT<Eigen::SparseMatrix<double>> ldlt(c.K_ff);
  const Eigen::VectorXd u_g = expand(c, ldlt.solve(reduce_load(c, g, p_g)));
  return u_g[*find_dof(p.model, g.dofs, p.mesh.id(p.n / 2, p.n / 2), 3)];
}

double max_abs_difference(const Eigen::SparseMatrix<double>& X, const Eigen::SparseMatrix<double>& Y) {
  return (test::dense(X) - test::dense(Y)).cwiseAbs().maxCoeff();
}

// ---------------------------------------------------------------------------------------------
TEST(CompositePlate, CrossPlyNavierDeflectionAndFrequencies) {
  const double a = 0.2, b = 0.3, h = 4 * kPly, rho = 1600.0;
  const Plate p = make_plate(a, b, 20, [](Model& m) {
    add_mat8(m, 8, t300(5.0e9, 4.0e9, 1600.0));
    add_pcomp(m, 1, {{8, 0.0}, {8, 90.0}, {8, 90.0}, {8, 0.0}}, kPly);
  });
  const Abd abd = hand_abd({0, 90, 90, 0});
  const Eigen::Matrix3d& D = abd.D;
  auto d_mn = [&](int m, int n) {
    const double x = m / a, y = n / b;
    return D(0, 0) * std::pow(x, 4) + 2 * (D(0, 1) + 2 * D(2, 2)) * x * x * y * y + D(1, 1) * std::pow(y, 4);
  };
  const double q0 = 100.0;
  const double w_ref = q0 / (std::pow(kPi, 4) * d_mn(1, 1));
  const double w = centre_deflection(p, q0);
  std::printf("[0/90/90/0] T300/5208 %g x %g m, h = %g m, 20 x 20 CQUAD4: centre deflection %.6e m, Navier %.6e m (%+.3f %%)\n",
              a, b, h, w, w_ref, 100 * (w / w_ref - 1));
  EXPECT_NEAR(w / w_ref, 1.0, 0.01);
  // the four lowest (m, n) modes of the Navier solution
  std::vector<double> ref;
  for (int m = 1; m <= 4; ++m)
    for (int n = 1; n <= 4; ++n) ref.push_back(std::sqrt(std::pow(kPi, 4) * d_mn(m, n) / (rho * h)) / (2 * kPi));
  std::sort(ref.begin(), ref.end());
  const auto f = frequencies_hz(p, 4);
  for (int i = 0; i < 4; ++i) {
    std::printf("  mode %d: %.4f Hz, Navier %.4f Hz (%+.3f %%)\n", i + 1, f[i], ref[i], 100 * (f[i] / ref[i] - 1));
    EXPECT_NEAR(f[i] / ref[i], 1.0, 0.01) << "mode " << i + 1;
  }
}

TEST(CompositePlate, CrossPlyTrianglesWithinOnePercent) {
  const double a = 0.2, b = 0.3;
  const Plate p = make_plate(
      a, b, 20,
      [](Model& m) {
        add_mat8(m, 8, t300(5.0e9, 4.0e9));
        add_pcomp(m, 1, {{8, 0.0}, {8, 90.0}, {8, 90.0}, {8, 0.0}}, kPly);
      },
      true);
  const Eigen::Matrix3d D = hand_abd({0, 90, 90, 0}).D;
  const double x = 1 / a, y = 1 / b;
  const double d11 = D(0, 0) * std::pow(x, 4) + 2 * (D(0, 1) + 2 * D(2, 2)) * x * x * y * y + D(1, 1) * std::pow(y, 4);
  const double w_ref = 100.0 / (std::pow(kPi, 4) * d11), w = centre_deflection(p, 100.0);
  std::printf("[0/90/90/0] 20 x 20 x 2 CTRIA3: centre deflection %.6e m, Navier %.6e m (%+.3f %%)\n", w, w_ref,
              100 * (w / w_ref - 1));
  EXPECT_NEAR(w / w_ref, 1.0, 0.01);
}

TEST(CompositePlate, SingleIsotropicPlyPcompIsThePshell) {
  // a curved, distorted patch of quads and triangles: every term of the elements is exercised
  auto build = [](bool pcomp, bool triangles) {
    Model m;
    test::add_mat1(m, 1, 7.0e10, 0.33, 2700.0);
    if (pcomp) {
      add_pcomp(m, 1, {{1, 25.0}}, 2.0e-3, 0.7);  // the angle of an isotropic ply does not matter
    } else {
      ShellProperty& ps = test::add_pshell(m, 1, 1, 2.0e-3, true, 0.7);
      ps.ts_t = 5.0 / 6.0;
    }
    test::add_shell_mesh(
        m, 3, 3,
        [](double u, double v) {
          const double x = u + 0.13 * u * v, y = v + 0.07 * u * u;
          return Eigen::Vector3d(0.4 * x, 0.3 * y, 0.05 * std::sin(2 * x + y));
        },
        triangles);
    test::finalize_for_test(m);
    return m;
  };
  for (bool triangles : {false, true}) {
    const Model ps = build(false, triangles), pc = build(true, triangles);
    for (int coupled : {0, 1}) {
      AssemblyOptions o = assembly_options(ps);
      if (coupled) o.mass = MassKind::Coupled;
      const GlobalMatrices gs = assemble(ps, o), gc = assemble(pc, o);
      const double kscale = test::dense(gs.K).cwiseAbs().maxCoeff(), mscale = test::dense(gs.M).cwiseAbs().maxCoeff();
      EXPECT_LE(max_abs_difference(gs.K, gc.K), 1e-12 * kscale) << (triangles ? "CTRIA3" : "CQUAD4");
      EXPECT_LE(max_abs_difference(gs.M, gc.M), 1e-12 * mscale) << (triangles ? "CTRIA3" : "CQUAD4");
    }
  }
}

TEST(CompositePlate, ThetaAndMcidRotateTheMaterialAxes) {
  // [0/90/45] (unsymmetric, anisotropic) with its plies turned by -30 deg and the element THETA =
  // 30 deg: the same stiffness as the unturned laminate. On a distorted mesh THETA is relative to
  // each element's G1-G2 edge, so MCID is used there: a system turned by 30 deg about z against
  // MCID = 0 (basic). The plies are rigid in transverse shear (G1Z, G2Z blank): the laminate's
  // transverse shear is computed in its own axes with an approximation that depends slightly on
  // them (section.hpp), the rest is exact tensor rotation.
  const double phi = 30.0;
  auto build = [&](double turn, int mode, bool distorted) {  // mode 0: THETA, 1: MCID, 2: neither
    Model m;
    add_mat8(m, 8, t300());
    add_pcomp(m, 1, {{8, 0.0 - turn}, {8, 90.0 - turn}, {8, 45.0 - turn}}, kPly);
    test::add_shell_mesh(m, 3, 2, [&](double u, double v) {
      return distorted ? Eigen::Vector3d(0.2 * u + 0.03 * v * v, 0.1 * v + 0.02 * u, 0.0) : Eigen::Vector3d(0.2 * u, 0.1 * v, 0.0);
    });
    if (turn != 0.0 && mode == 1) {
      const double c = std::cos(turn * kPi / 180), s = std::sin(turn * kPi / 180);
      Eigen::Matrix3d R;
      R << c, -s, 0, s, c, 0, 0, 0, 1;
      test::add_rect_coord(m, 5, Eigen::Vector3d(1, 2, 3), R);
    }
    if (mode == 1) set_mcid(m, turn != 0.0 ? 5 : 0);
    if (turn != 0.0 && mode == 0)
      for (Shell& sh : m.shells) sh.theta_deg = turn;
    test::finalize_for_test(m);
    return test::dense(assemble(m, assembly_options(m)).K);
  };
  const Eigen::MatrixXd K0 = build(0.0, 0, false), Kt = build(phi, 0, false);
  EXPECT_LE((K0 - Kt).cwiseAbs().maxCoeff(), 1e-12 * K0.cwiseAbs().maxCoeff());
  const Eigen::MatrixXd D0 = build(0.0, 1, true), Dm = build(phi, 1, true);
  EXPECT_LE((D0 - Dm).cwiseAbs().maxCoeff(), 1e-12 * D0.cwiseAbs().maxCoeff());
  // and the turn matters (the test can fail): the turned plies without THETA differ
  EXPECT_GT((K0 - build(phi, 2, false)).cwiseAbs().maxCoeff(), 1e-3 * K0.cwiseAbs().maxCoeff());
}

// A free n x n plate a x b, clamped at the origin grid only, pulled by N_x on its edges x = 0 and x = a.
struct StripResult {
  double w_corner = 0, u_corner = 0;
};
template <class AddProperty>
StripResult pulled_plate(AddProperty add_property, double Nx, bool triangles, double zoffs = 0.0) {
  const double a = 0.1, b = 0.08;
  const int n = 4;
  Model m;
  add_property(m);
  const test::ShellMesh mesh = test::add_shell_mesh(
      m, n, n, [&](double u, double v) { return Eigen::Vector3d(a * u, b * v, 0.0); }, triangles);
  if (triangles) set_mcid(m, 0);  // one material direction (see make_plate)
  for (Shell& sh : m.shells) sh.zoffs = zoffs;
  test::add_spc(m, 1, mesh.id(0, 0), "123456");
  for (int j = 0; j <= n; ++j) {
    const double share = (j == 0 || j == n ? 0.5 : 1.0) * Nx * b / n;
    test::add_force(m, 2, mesh.id(n, j), Eigen::Vector3d(share, 0, 0));
    test::add_force(m, 2, mesh.id(0, j), Eigen::Vector3d(-share, 0, 0));
  }
  test::finalize_for_test(m);
  const GlobalMatrices g = assemble(m, assembly_options(m));
  const ConstrainedSystem c = apply_constraints(m, g, 1);
  const Eigen::VectorXd p = load_vector(m, g.dofs, 2);
  Eigen::SimplicialLDLT<Eigen::SparseMatrix<double>> ldlt(c.K_ff);
  const Eigen::VectorXd u = expand(c, ldlt.solve(reduce_load(c, g, p)));
  return {u[*find_dof(m, g.dofs, mesh.id(n, n), 3)], u[*find_dof(m, g.dofs, mesh.id(n, 0), 1)]};
}

TEST(CompositePlate, UnsymmetricLaminateBendsUnderTensionAsLaminationTheory) {
  const double a = 0.1, b = 0.08, Nx = 1.0e4;  // N/m
  const Abd abd = hand_abd({0, 90});
  Eigen::Matrix<double, 6, 6> ABD;
  ABD << abd.A, abd.B, abd.B, abd.D;
  Eigen::Matrix<double, 6, 1> N = Eigen::Matrix<double, 6, 1>::Zero();
  N[0] = Nx;
  const Eigen::Matrix<double, 6, 1> ek = ABD.fullPivLu().solve(N);
  const double kx = ek[3], ky = ek[4], kxy = ek[5];
  const double w_ref = -0.5 * (kx * a * a + ky * b * b + kxy * a * b), u_ref = ek[0] * a;
  auto pcomp = [](Model& m) {
    add_mat8(m, 8, t300(5.0e9, 4.0e9));
    add_pcomp(m, 1, {{8, 0.0}, {8, 90.0}}, kPly);
  };
  // Nastran's equivalent PSHELL of the laminate (section.hpp, QRG PSHELL: A = T G1, D = 12I/T^3 T^3/12 G2,
  // B = T^2 G4), its transverse shear from the laminate
  auto pshell = [&](Model& m) {
    const double T = 2 * kPly;
    const Mat8 ply = t300(5.0e9, 4.0e9);
    std::vector<Ply> plies{{shell_material(ply), kPly, 0.0}, {shell_material(ply), kPly, kPi / 2}};
    const ShellSection lam = laminate_section(plies, std::nullopt, 0.0);
    Eigen::Matrix3d G3 = Eigen::Matrix3d::Zero();
    G3.topLeftCorner<2, 2>() = lam.S / T;
    add_mat2(m, 11, hand_abd({0, 90}).A / T);
    add_mat2(m, 12, 12 * hand_abd({0, 90}).D / (T * T * T));
    add_mat2(m, 13, G3);
    add_mat2(m, 14, hand_abd({0, 90}).B / (T * T));
    ShellProperty p;
    p.id = 1;
    p.mid1 = 11;
    p.t = T;
    p.mid2 = 12;
    p.mid3 = 13;
    p.ts_t = 1.0;
    p.mid4 = 14;
    m.shell_props.push_back(p);
  };
  // the same laminate rigid in transverse shear (G1Z, G2Z blank): CTRIA3's DKT coupled to the membrane
  auto pcomp_rigid = [](Model& m) {
    add_mat8(m, 8, t300());
    add_pcomp(m, 1, {{8, 0.0}, {8, 90.0}}, kPly);
  };
  for (bool triangles : {false, true}) {
    const StripResult r = pulled_plate(pcomp, Nx, triangles), q = pulled_plate(pshell, Nx, triangles);
    const StripResult k = pulled_plate(pcomp_rigid, Nx, triangles);
    std::printf("[0/90] under N_x = %g N/m (%s): corner w %.6e m (theory %.6e), u %.6e m (theory %.6e); PSHELL+MID4 w %.6e; "
                "G1Z/G2Z blank w %.6e\n",
                Nx, triangles ? "CTRIA3" : "CQUAD4", r.w_corner, w_ref, r.u_corner, u_ref, q.w_corner, k.w_corner);
    // the uniform state is exact for the elements: measured (2026-11-28) 4.3e-12 at most, round-off;
    // tolerance 1e-9
    EXPECT_NEAR(r.w_corner / w_ref, 1.0, 1e-9);
    EXPECT_NEAR(r.u_corner / u_ref, 1.0, 1e-9);
    EXPECT_NEAR(q.w_corner / w_ref, 1.0, 1e-9);
    EXPECT_NEAR(q.u_corner / u_ref, 1.0, 1e-9);
    // rigid in shear: CTRIA3's DKT is exact to round-off as above; CQUAD4's MITC4 carries the Kirchhoff
    // penalty (1000 x the shear stiffness of the equivalent plate), whose conditioning leaves 4.1e-9
    // (measured 2026-12-06): tolerance 2e-8 there
    const double tol = triangles ? 1e-9 : 2e-8;
    EXPECT_NEAR(k.w_corner / w_ref, 1.0, tol);
    EXPECT_NEAR(k.u_corner / u_ref, 1.0, tol);
  }
  EXPECT_GT(std::abs(w_ref), 10 * std::abs(u_ref));  // the coupling dominates: the test can fail
}

// ZOFFS: an isotropic plate whose mid-surface lies e above its grids, pulled by N_x at the grids, is
// under eccentric tension: N_x and M_x = -e N_x about its mid-surface, a uniaxial stress-resultant
// state (free plate), so eps_x = N_x/(E t), kappa_x = 12 M_x/(E t^3), the y terms -nu times these
// (Timoshenko & Goodier, plane stress; Timoshenko & Woinowsky-Krieger, pure bending of plates, sec.
// 10). At the grids u = (eps_x - e kappa_x) a and w = -(kappa_x a^2 + kappa_y b^2)/2. And a PSHELL with
// ZOFFS = e is the one-ply PCOMP with Z0 = e - T/2 (K to 1e-12).
TEST(CompositePlate, ZoffsIsEccentricTension) {
  const double E = 7.0e10, nu = 0.3, t = 2.0e-3, e = 1.5e-3, Nx = 1.0e4, a = 0.1, b = 0.08;
  auto pshell = [&](Model& m) {
    test::add_mat1(m, 1, E, nu, 2700.0);
    test::add_pshell(m, 1, 1, t);
  };
  const double kx = 12 * (-e * Nx) / (E * t * t * t), ky = -nu * kx, ex = Nx / (E * t);
  const double w_ref = -0.5 * (kx * a * a + ky * b * b), u_ref = (ex - e * kx) * a;
  for (bool triangles : {false, true}) {
    const StripResult r = pulled_plate(pshell, Nx, triangles, e);
    std::printf("ZOFFS %g m, N_x %g N/m (%s): corner w %.6e m (theory %.6e), u %.6e m (theory %.6e)\n", e, Nx,
                triangles ? "CTRIA3" : "CQUAD4", r.w_corner, w_ref, r.u_corner, u_ref);
    // exact state: measured (2026-11-28) 1.3e-12 at most, round-off; tolerance 1e-9
    EXPECT_NEAR(r.w_corner / w_ref, 1.0, 1e-9);
    EXPECT_NEAR(r.u_corner / u_ref, 1.0, 1e-9);
  }
  auto stiffness = [&](bool pcomp) {
    Model m;
    test::add_mat1(m, 1, E, nu, 2700.0);
    if (pcomp) {
      CompositeProperty& p = add_pcomp(m, 1, {{1, 0.0}}, t);
      p.has_z0 = true;
      p.z0 = e - t / 2;
    } else {
      test::add_pshell(m, 1, 1, t).ts_t = 5.0 / 6.0;
    }
    test::add_shell_mesh(m, 2, 2, [](double u, double v) { return Eigen::Vector3d(0.1 * u + 0.01 * v, 0.08 * v, 0.01 * u * v); });
    if (!pcomp)
      for (Shell& sh : m.shells) sh.zoffs = e;
    test::finalize_for_test(m);
    return test::dense(assemble(m, assembly_options(m)).K);
  };
  const Eigen::MatrixXd Kp = stiffness(false), Kc = stiffness(true);
  EXPECT_LE((Kp - Kc).cwiseAbs().maxCoeff(), 1e-12 * Kp.cwiseAbs().maxCoeff());
}

TEST(CompositePlate, SandwichPcompAndPshellAgreeWithMindlinPlate) {
  const double a = 1.0, tf = 0.3e-3, tc = 20e-3, Ef = 7.0e10, nuf = 0.3, rhof = 2700, Gc = 2.0e7, rhoc = 50;
  const double h = tc + 2 * tf, d = tc + tf, T = 2 * tf;
  auto pcomp = [&](Model& m) {
    test::add_mat1(m, 1, Ef, nuf, rhof);
    Mat8 core;
    core.E1 = core.E2 = 1.0e3;  // no in-plane stiffness to speak of
    core.nu12 = 0.0;
    core.G12 = 1.0e3;
    core.G1z = core.G2z = Gc;
    core.rho = rhoc;
    add_mat8(m, 2, core);
    CompositeProperty p;
    p.id = 1;
    p.plies = {{0, 1, tf, 0.0, false}, {0, 2, tc, 0.0, false}, {0, 1, tf, 0.0, false}};
    m.composite_props.push_back(p);
  };
  auto pshell = [&](Model& m) {
    test::add_mat1(m, 1, Ef, nuf, rhof);
    Mat8 core;
    core.E1 = core.E2 = 1.0e3;
    core.nu12 = 0.0;
    core.G12 = 1.0e3;
    core.G1z = core.G2z = Gc;
    add_mat8(m, 2, core);
    ShellProperty p;
    p.id = 1;
    p.mid1 = p.mid2 = 1;
    p.t = T;
    p.bend_ratio = (h * h * h - tc * tc * tc) / (T * T * T);
    p.mid3 = 2;
    p.ts_t = d * d / (tc * T);
    p.nsm = rhoc * tc;
    m.shell_props.push_back(p);
  };
  const Plate pc = make_plate(a, a, 20, pcomp), ps = make_plate(a, a, 20, pshell);
  const auto fc = frequencies_hz(pc, 4), fs = frequencies_hz(ps, 4);
  const double D = Ef * (h * h * h - tc * tc * tc) / (12 * (1 - nuf * nuf)), S = Gc * d * d / tc, mass = rhof * T + rhoc * tc;
  const int mn[4][2] = {{1, 1}, {1, 2}, {2, 1}, {2, 2}};
  for (int i = 0; i < 4; ++i) {
    const double k2 = (mn[i][0] * mn[i][0] + mn[i][1] * mn[i][1]) * std::pow(kPi / a, 2);
    const double f_ref = std::sqrt(D * k2 * k2 / (mass * (1 + D * k2 / S))) / (2 * kPi);
    std::printf("sandwich mode %d: PCOMP %.4f Hz, PSHELL %.4f Hz (%+.3f %%), Mindlin %.4f Hz (PCOMP %+.3f %%)\n", i + 1, fc[i],
                fs[i], 100 * (fc[i] / fs[i] - 1), f_ref, 100 * (fc[i] / f_ref - 1));
    // the same sandwich as PCOMP and as PSHELL (the PCOMP core's small in-plane stiffness the only
    // difference): measured (2026-11-28) 3.3e-5 at most; tolerance 6e-5
    EXPECT_NEAR(fc[i] / fs[i], 1.0, 6e-5) << "mode " << i + 1;
    // mode (2,2) has 5 elements per half wave: -1.0 % at 20 x 20, the element's discretisation error
    if (i < 3) {
      EXPECT_NEAR(fc[i] / f_ref, 1.0, 0.01) << "mode " << i + 1;
    }
  }
  // the core's shear matters in this panel (the test sees it): D k^2 / S of mode (2,2)
  EXPECT_GT(D * 8 * std::pow(kPi / a, 2) / S, 0.05);
}

}  // namespace
}  // namespace seflex::fem
