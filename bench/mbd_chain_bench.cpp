// Benchmark: a chain of N flexible AIC superelement bodies (aluminium beams of 0.1 m, 2 FE elements
// each, hinged end to end, the first to ground) released horizontally under gravity and swinging for
// T seconds with a constant step. Prints wall time, Newton iterations and factorisations per step,
// and the cost per step and per body, for N = 2 ... 200. With the sparse (clique) assembly and
// sparse LU the cost per step should grow linearly in N.
//
//   build/bench/mbd_chain_bench [--t-end 10] [--step 2e-3] [--repeat 3] [--full] [--sizes 2,5,10,...]
//                               [--formulation aic|ffrf-lm|rigid-lm]
// --formulation ffrf-lm runs the same model with the classic floating frame and Lagrange
// multipliers (mbd/ffrf.hpp; all frame-clamped modes, full FE nodal inertia), rigid-lm with rigid
// bodies and multipliers; "dofs" is then coordinates + multipliers.
#include <algorithm>
#include <chrono>
#include <cstdio>
#include <cstdlib>
#include <cstring>
#include <sstream>
#include <string>
#include <vector>

#include "../tests/support/beam_superelement.hpp"  // test-only beam Craig-Bampton builder (until reduction/ has one)
#include "seflex/mbd/ffrf/ffrf.hpp"
#include "seflex/mbd/solvers/integrator.hpp"

using namespace seflex;
using namespace seflex::mbd;

namespace {

Model chain(int n, InertiaModel inertia) {
  test::BeamSection sec;  // aluminium, A = 1e-4, Iz = 2e-9
  const double L = 0.1;
  auto fe = test::straight_beam(L, 2, sec);
  const se::Superelement s = test::craig_bampton(fe, {0, 2}, 1, 0, "link");
  ModelBuilder mb;
  const auto sei = mb.add_superelement(s);
  NodeIndex base = mb.add_ground("pivot", Pose{});
  FlexibleBodyOptions fo;
  fo.inertia = inertia;
  for (int b = 0; b < n; ++b) {
    const auto h = mb.add_hinge("H" + std::to_string(b + 1), base, Eigen::Vector3d::UnitZ());
    const auto tip = mb.add_node("n" + std::to_string(b + 1), Pose{Eigen::Matrix3d::Identity(), Eigen::Vector3d((b + 1) * L, 0, 0)});
    mb.add_flexible_body("link" + std::to_string(b + 1), sei, {mb.hinge_child(h), tip},
                         Pose{Eigen::Matrix3d::Identity(), Eigen::Vector3d((b + 0.5) * L, 0, 0)}, fo);
    base = tip;
  }
  mb.set_gravity(Eigen::Vector3d(0, -9.81, 0));
  return mb.build();
}

/// Keeps the last sample.
struct LastSample : Observer {
  Sample sample;
  void on_sample(const Model&, const Sample& s) override { sample = s; }
};

}  // namespace

int main(int argc, char** argv) {
  double t_end = 10.0, step = 2e-3;
  int repeat = 3;
  bool full = false;
  std::string formulation = "aic";
  std::vector<int> sizes{2, 5, 10, 20, 50, 100, 200};
  std::string cmd = argv[0];
  for (int i = 1; i < argc; ++i) {
    cmd += std::string(" ") + argv[i];
    const std::string a = argv[i];
    auto next = [&]() -> std::string { return i + 1 < argc ? (cmd += std::string(" ") + argv[i + 1], argv[++i]) : ""; };
    if (a == "--t-end") t_end = std::atof(next().c_str());
    else if (a == "--step") step = std::atof(next().c_str());
    else if (a == "--repeat") repeat = std::atoi(next().c_str());
    else if (a == "--full") full = true;
    else if (a == "--formulation") formulation = next();
    else if (a == "--sizes") {
      sizes.clear();
      std::stringstream ss(next());
      std::string tok;
      while (std::getline(ss, tok, ',')) sizes.push_back(std::atoi(tok.c_str()));
    } else {
      std::fprintf(stderr, "usage: %s [--t-end T] [--step h] [--repeat k] [--full] [--sizes 2,5,...] [--formulation aic|ffrf-lm|rigid-lm]\n", argv[0]);
      return 2;
    }
  }
  if (formulation != "aic" && formulation != "ffrf-lm" && formulation != "rigid-lm") {
    std::fprintf(stderr, "--formulation expects aic, ffrf-lm or rigid-lm\n");
    return 2;
  }
  std::printf("# %s\n", cmd.c_str());
  std::printf("# chain of N flexible beams (0.1 m, 2 FE elements each), formulation %s, %s inertia, %.3g s at constant h = %.3g s, "
              "generalized-alpha rho_inf 0.8, median of %d runs\n",
              formulation.c_str(), formulation != "aic" ? "FE nodal" : full ? "full" : "simplified", t_end, step, repeat);
  std::printf("%6s %6s %7s %9s %9s %10s %10s %12s %12s\n", "N", "dofs", "steps", "its/step", "LU/step", "wall [s]", "ms/step",
              "us/step/body", "tip y [m]");
  double base_per_body = 0;
  for (int n : sizes) {
    const Model model = chain(n, full ? InertiaModel::Full : InertiaModel::Simplified);
    std::vector<double> walls;
    RunStats stats;
    double tip_y = 0;
    int dofs = model.num_dofs;
    for (int r = 0; r < repeat; ++r) {
      IntegratorSettings st;
      st.t_end = t_end;
      st.h_initial = step;
      st.adaptive = false;
      st.rho_inf = 0.8;
      if (formulation == "aic") {
        State s = initial_state(model);
        Data data(model);
        const auto t0 = std::chrono::steady_clock::now();
        stats = simulate(model, s, data, st);
        walls.push_back(std::chrono::duration<double>(std::chrono::steady_clock::now() - t0).count());
        tip_y = s.p_WN.back().y();
      } else {
        st.output_interval = t_end;  // samples at the start and the end only
        LastSample last;
        FfrfOptions fo;
        fo.rigid = formulation == "rigid-lm";
        const auto t0 = std::chrono::steady_clock::now();
        const FfrfStats fs = simulate_ffrf(model, st, fo, &last);
        walls.push_back(std::chrono::duration<double>(std::chrono::steady_clock::now() - t0).count());
        stats = fs.run;
        dofs = fs.coordinates + fs.constraints;
        tip_y = last.sample.nodes.back().p.y();
      }
    }
    std::sort(walls.begin(), walls.end());
    const double wall = walls[walls.size() / 2];
    const double per_step = 1e3 * wall / static_cast<double>(stats.steps);
    const double per_body = 1e3 * per_step / n;
    if (base_per_body == 0) base_per_body = per_body;
    std::printf("%6d %6d %7ld %9.2f %9.2f %10.3f %10.3f %12.1f %12.4f\n", n, dofs, stats.steps,
                static_cast<double>(stats.newton_iterations) / static_cast<double>(stats.steps),
                static_cast<double>(stats.factorizations) / static_cast<double>(stats.steps), wall, per_step, per_body, tip_y);
    std::fflush(stdout);
  }
  return 0;
}
