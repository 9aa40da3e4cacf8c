// FFRF-LM on the demo's superelements (examples/solar_array/sync-3d.yaml: the 3D yoke and panel
// reductions of meshes/*.bdf, 10 modes, geometric stiffening on by default): the Newton iteration
// matrix of one step with the analytic tangents of the bodies (mbd/src/ffrf/ffrf_body_tangents.cpp),
// joints and node loads (ffrf_joint_tangents.cpp) against the one with all of them by central
// differences (FfrfOptions::fd_body_jacobians and fd_joint_jacobians, the previous paths), at states off
// the predictor with velocities, elastic deformation and nonzero multipliers; the inertia from the
// invariants and from the FE node sums. The residuals are the same; the matrices differ by the finite
// differences' error only (step 1e-6 of each coordinate's scale: ~1e-9 of the largest entry;
// tests/mbd/ffrf_body_tangents_test.cpp and ffrf_joint_tangents_test.cpp compare the tangents themselves).
#include <gtest/gtest.h>

#include <Eigen/Dense>
#include <cstdio>

#include "scene_fixture.hpp"
#include "seflex/scene/scene.hpp"
#include "seflex/mbd/ffrf/ffrf.hpp"

namespace seflex::test {
namespace {

void replace_all(std::string& s, const std::string& from, const std::string& to) {
  for (auto at = s.find(from); at != std::string::npos; at = s.find(from, at + to.size())) s.replace(at, from.size(), to);
}

TEST(FfrfDemoTangents, IterationMatrixWithAnalyticTangentsMatchesFiniteDifferences) {
  TempDir dir;
  for (const auto& [body, set] : {std::pair{"yoke", "1,3,4"}, std::pair{"panel", "1,2,3,4"}}) {
    const auto r = run_seflex("reduce " + q(source_dir() / "meshes" / (std::string(body) + ".bdf")) + " --interface " + set +
                              " --modes 10 -o " + q(dir / (std::string(body) + "-3d.se")));
    ASSERT_EQ(r.exit_code, 0) << r.err;
  }
  std::string text = read_file(source_dir() / "examples" / "solar_array" / "sync-3d.yaml");
  replace_all(text, "superelements/", "");
  // With the mesh part: the FE data of the nodal sums.
  const scene::Scene scene = scene::build_scene(scene::read_scene(dir.write("sync-3d.yaml", text)), scene::SceneBuildOptions{true});
  const mbd::Model& model = scene.model;
  for (auto inertia : {mbd::FfrfOptions::Inertia::Invariants, mbd::FfrfOptions::Inertia::Nodal}) {
    mbd::FfrfOptions fa;
    fa.inertia = inertia;
    mbd::FfrfOptions ff = fa;
    ff.fd_body_jacobians = true;
    ff.fd_joint_jacobians = true;
    const mbd::FfrfSystem sa = mbd::make_ffrf_system(model, fa), sf = mbd::make_ffrf_system(model, ff);
    ASSERT_GT(sa.num_z, 50);
    ASSERT_TRUE(sa.bodies[0].stiffening);
    for (int trial = 0; trial < 2; ++trial) {
      mbd::FfrfState s0 = mbd::ffrf_initial_state(sa);
      for (Eigen::Index i = 0; i < s0.v.size(); ++i) s0.v[i] += (0.5 + trial) * std::sin(2.0 + 3.0 * i + trial) / sa.weight[i];
      for (Eigen::Index i = 0; i < s0.z.size(); ++i) s0.z[i] = 1e-3 * std::cos(1.0 + i + trial);
      // A long step (beta h^2 omega^2 >> 1 for the modes, gamma h |C| ~ |M|), so that the stiffness and
      // velocity tangents, not the mass, carry the iteration matrix.
      const double h = 5e-2, rho = 0.9;
      const int n = sa.num_coords + sa.num_multipliers();
      Eigen::VectorXd x(n);
      x.head(sa.num_coords) = h * s0.v;
      for (int i = 0; i < sa.num_coords; ++i) x[i] += 1e-3 * std::sin(1.0 + i + trial) / sa.weight[i];
      x.tail(sa.num_multipliers()) = 0.25 * h * h * (s0.lambda + Eigen::VectorXd::Constant(s0.lambda.size(), 10.0));
      mbd::FfrfState s1;
      Eigen::VectorXd Ra, Rf;
      Eigen::SparseMatrix<double> Sa, Sf;
      mbd::ffrf_step_system(sa, s0, h, rho, x, s1, Ra, &Sa);
      mbd::ffrf_step_system(sf, s0, h, rho, x, s1, Rf, &Sf);
      EXPECT_EQ((Ra - Rf).cwiseAbs().maxCoeff(), 0.0);
      const Eigen::MatrixXd A(Sa), F(Sf);
      const double err = (A - F).cwiseAbs().maxCoeff() / F.cwiseAbs().maxCoeff();
      std::printf("sync-3d, %s, trial %d: iteration matrix %dx%d, max |S - S_fd| / max |S_fd| = %.2e\n",
                  inertia == mbd::FfrfOptions::Inertia::Nodal ? "nodal sums" : "invariants", trial, n, n, err);
      EXPECT_LT(err, 1e-7);
    }
  }
}

}  // namespace
}  // namespace seflex::test
