// Patch tests of CQUAD4 and CTRIA3 on the distorted MacNeal-Harder patch (MacNeal & Harder 1985,
// fig. 1): boundary nodes get the exact displacements of a constant-strain (membrane) or
// constant-curvature (bending) state; the interior nodes must reproduce it exactly, and the strain
// energy must equal the analytic one.
#include <gtest/gtest.h>

#include <Eigen/SparseCholesky>
#include <cmath>
#include <functional>
#include <string>

#include "fem_test_util.hpp"
#include "seflex/fem/assembly.hpp"
#include "seflex/fem/constraints.hpp"

namespace seflex::fem {
namespace {

// Rectangle 0.24 x 0.12 with four interior nodes; 5 quads, or 10 triangles.
Model patch_model(bool triangles, double t, bool shear) {
  Model m;
  const double xy[8][2] = {{0, 0},       {0.24, 0},    {0.24, 0.12}, {0, 0.12},
                           {0.04, 0.02}, {0.18, 0.03}, {0.16, 0.08}, {0.08, 0.08}};
  for (int i = 0; i < 8; ++i) test::add_grid(m, i + 1, xy[i][0], xy[i][1], 0);
  test::add_mat1(m, 1, 1e6, 0.25, 0);
  test::add_pshell(m, 2, 1, t, shear);
  const int quads[5][4] = {{1, 2, 6, 5}, {2, 3, 7, 6}, {3, 4, 8, 7}, {4, 1, 5, 8}, {5, 6, 7, 8}};
  int id = 1;
  for (const auto& q : quads) {
    if (triangles) {
      test::add_shell(m, id++, 2, {q[0], q[1], q[2]});
      test::add_shell(m, id++, 2, {q[0], q[2], q[3]});
    } else {
      test::add_shell(m, id++, 2, {q[0], q[1], q[2], q[3]});
    }
  }
  return m;
}

using Field = std::function<Eigen::Matrix<double, 6, 1>(double, double)>;

// Prescribe `exact` on the boundary nodes 1-4 (SPC with enforced values), solve, and return the
// largest error at the interior nodes relative to the largest exact value, and the strain energy.
std::pair<double, double> run_patch(bool triangles, const Field& exact, bool shear = true) {
  Model m = patch_model(triangles, 0.001, shear);
  for (int n = 1; n <= 4; ++n) {
    const Grid& g = m.grids[n - 1];
    const auto u = exact(g.x.x(), g.x.y());
    for (int c = 1; c <= 6; ++c) {
      SpcEntry e;
      e.sid = 1;
      e.grid = n;
      e.c = static_cast<ComponentMask>(1u << (c - 1));
      e.d = u[c - 1];
      m.spcs.push_back(e);
    }
  }
  test::finalize_for_test(m);
  const GlobalMatrices g = assemble(m, AssemblyOptions{});
  ConstraintOptions o;
  o.spc_set = 1;
  const ConstrainedSystem c = apply_constraints(m, g, o);
  Eigen::SimplicialLDLT<Eigen::SparseMatrix<double>> ldlt(c.K_ff);
  const Eigen::VectorXd u = expand(c, ldlt.solve(reduce_load(c, g, Eigen::VectorXd::Zero(g.dofs.size()))));
  double err = 0, scale = 0;
  for (int n = 5; n <= 8; ++n) {
    const Grid& gr = m.grids[n - 1];
    const auto ue = exact(gr.x.x(), gr.x.y());
    err = std::max(err, (u.segment<6>(6 * (n - 1)) - ue).cwiseAbs().maxCoeff());
    scale = std::max(scale, ue.cwiseAbs().maxCoeff());
  }
  return {err / scale, 0.5 * u.dot(g.K * u)};
}

// Membrane: u = 1e-3 (x + y/2), v = 1e-3 (y + x/2); the in-plane rotation (v,x - u,y)/2 = 0.
// Energy: 0.5 * area * eps^T (t D) eps, eps = 1e-3 (1, 1, 1).
TEST(ShellPatch, MembraneConstantStrain) {
  const Field exact = [](double x, double y) {
    Eigen::Matrix<double, 6, 1> u = Eigen::Matrix<double, 6, 1>::Zero();
    u[0] = 1e-3 * (x + y / 2);
    u[1] = 1e-3 * (y + x / 2);
    return u;
  };
  const double E = 1e6, nu = 0.25, t = 0.001, area = 0.24 * 0.12;
  Eigen::Matrix3d D;
  D << 1, nu, 0, nu, 1, 0, 0, 0, (1 - nu) / 2;
  D *= E * t / (1 - nu * nu);
  const Eigen::Vector3d eps(1e-3, 1e-3, 1e-3);
  const double energy = 0.5 * area * eps.dot(D * eps);
  for (bool tri : {false, true}) {
    const auto [err, U] = run_patch(tri, exact);
    EXPECT_LT(err, 1e-10) << (tri ? "CTRIA3" : "CQUAD4");
    EXPECT_NEAR(U / energy, 1.0, 1e-10) << (tri ? "CTRIA3" : "CQUAD4");
  }
}

// Bending: w = 1e-3 (x^2 + x y + y^2) / 2, theta_x = dw/dy, theta_y = -dw/dx (Kirchhoff, no shear
// strain). Curvatures (theta_y,x, -theta_x,y, theta_y,y - theta_x,x) = -1e-3 (1, 1, 1). With MID3 and
// without (MID3 blank: CTRIA3's DKT, CQUAD4's MITC4 with the Kirchhoff penalty).
TEST(ShellPatch, BendingConstantCurvature) {
  const Field exact = [](double x, double y) {
    Eigen::Matrix<double, 6, 1> u = Eigen::Matrix<double, 6, 1>::Zero();
    u[2] = 1e-3 * (x * x + x * y + y * y) / 2;
    u[3] = 1e-3 * (y + x / 2);
    u[4] = -1e-3 * (x + y / 2);
    return u;
  };
  const double E = 1e6, nu = 0.25, t = 0.001, area = 0.24 * 0.12;
  Eigen::Matrix3d D;
  D << 1, nu, 0, nu, 1, 0, 0, 0, (1 - nu) / 2;
  D *= E * t * t * t / (12 * (1 - nu * nu));
  const Eigen::Vector3d kappa(-1e-3, -1e-3, -1e-3);
  const double energy = 0.5 * area * kappa.dot(D * kappa);
  for (bool shear : {true, false})
    for (bool tri : {false, true}) {
      const auto [err, U] = run_patch(tri, exact, shear);
      const std::string what = std::string(tri ? "CTRIA3" : "CQUAD4") + (shear ? "" : " MID3 blank");
      EXPECT_LT(err, 1e-9) << what;
      EXPECT_NEAR(U / energy, 1.0, 1e-9) << what;
    }
}

}  // namespace
}  // namespace seflex::fem
