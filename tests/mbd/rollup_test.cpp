// T8 of formulation.md section 6.2: static cantilever roll-up by a tip moment about z with n
// two-interface AIC beam superelements (each an FE model of 2 Euler-Bernoulli elements, frame at
// the middle node; EI = 1, L = 1, EA = 1e5 as in ../shared/reference/aic_rollup.py).
// Exact tip: x = sin(kL)/k, y = (1 - cos kL)/k, rotation kL, k = M/EI.
// Reference numbers for the half circle (aic_rollup.py, same discretisation): y_tip = 0.63925,
// 0.63727, 0.63678 for n = 10, 20, 40 (error O(n^-2)); the full circle closes (regular polygon).
#include <gtest/gtest.h>

#include <cmath>

#include "beam_superelement.hpp"
#include "seflex/common/so3.hpp"
#include "seflex/mbd/solvers/statics.hpp"

using namespace seflex;
using namespace seflex::mbd;
using Eigen::Matrix3d;
using Eigen::Vector3d;

namespace {

struct RollupResult {
  Vector3d tip;
  Matrix3d R_tip;
  int max_iterations = 0;
};

RollupResult rollup(int n, double Mfac) {
  const double L = 1.0, ell = L / n;
  test::BeamSection sec;
  sec.E = 1e7;
  sec.G = 1e7 / 2.6;
  sec.A = 1e-2;
  sec.Iy = sec.Iz = 1e-7;
  sec.J = 1e-7;
  auto fe = test::straight_beam(ell, 2, sec);
  const se::Superelement s = test::craig_bampton(fe, {0, 2}, 1, 0, "element");
  ModelBuilder mb;
  const auto sei = mb.add_superelement(s);
  std::vector<NodeIndex> nodes{mb.add_ground("root", Pose{})};
  for (int i = 1; i <= n; ++i) nodes.push_back(mb.add_node("n" + std::to_string(i), Pose{Matrix3d::Identity(), Vector3d(i * ell, 0, 0)}));
  for (int e = 0; e < n; ++e)
    mb.add_flexible_body("b" + std::to_string(e), sei, {nodes[static_cast<std::size_t>(e)], nodes[static_cast<std::size_t>(e + 1)]},
                         Pose{Matrix3d::Identity(), Vector3d((e + 0.5) * ell, 0, 0)});
  NodeLoad tip{"tip moment", nodes.back(), Vector3d::Zero(), Vector3d(0, 0, Mfac * 2 * M_PI * 1.0 / L), false, {}};
  mb.add_load(tip);
  const Model model = mb.build();
  State state = initial_state(model);
  Data data(model);
  StaticSettings st;
  st.load_steps = 40;
  st.residual_tol = 1e-9;
  const StaticStats stats = solve_static(model, state, data, st);
  RollupResult r;
  r.tip = state.p_WN.back();
  r.R_tip = state.R_WN.back();
  for (int it : stats.iterations) r.max_iterations = std::max(r.max_iterations, it);
  EXPECT_EQ(stats.cutbacks, 0);
  return r;
}

}  // namespace

TEST(Rollup, T8_HalfCircleConvergesAtSecondOrder) {
  const double ref[3] = {0.63925, 0.63727, 0.63678};  // aic_rollup.py
  const double exact_y = 2.0 / M_PI;
  double err[3];
  int k = 0;
  for (int n : {10, 20, 40}) {
    const RollupResult r = rollup(n, 0.5);
    EXPECT_NEAR(r.tip.y(), ref[k], 1e-5) << "n = " << n;
    EXPECT_NEAR(r.tip.x(), 0.0, 1e-5) << "n = " << n;
    // Tip rotation pi about z.
    EXPECT_LT((r.R_tip - so3::exp(Vector3d(0, 0, M_PI))).norm(), 1e-6) << "n = " << n;
    EXPECT_LE(r.max_iterations, 7) << "n = " << n;
    err[k++] = (r.tip - Vector3d(0, exact_y, 0)).norm();
  }
  EXPECT_LE(err[1], 7e-4);  // formulation.md: n = 20 half-circle tip error <= 7e-4 L
  EXPECT_NEAR(err[0] / err[1], 4.0, 0.4);
  EXPECT_NEAR(err[1] / err[2], 4.0, 0.4);
}

TEST(Rollup, T8_FullCircleCloses) {
  for (int n : {10, 20}) {
    const RollupResult r = rollup(n, 1.0);
    EXPECT_LT(r.tip.norm(), 1e-6) << "n = " << n;                          // back at the root
    EXPECT_LT((r.R_tip - Matrix3d::Identity()).norm(), 1e-6) << "n = " << n;  // rotated by 2 pi
    EXPECT_LE(r.max_iterations, 7) << "n = " << n;
  }
}
