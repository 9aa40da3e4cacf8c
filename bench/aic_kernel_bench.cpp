// Cost of the AIC superelement's kernels per evaluation (issue 12), and of making the element once:
// frame recovery, elastic force,
// full inertia, and the elastic force with geometric stiffening when the file has its invariants, each
// without and with its tangent matrices, on a superelement file, at a random
// deformed and rotating state (the same state every repetition, so the figure is the arithmetic of
// one Newton-iteration evaluation of one body); last, the full inertia's stacked-invariant product for
// three stages, as three matrix-vector products and as one three-column product.
//
// usage: aic_kernel_bench BODY.se [REPEATS]
// prints one line per kernel: microseconds per call (best of 5 batches of REPEATS calls).
#include <Eigen/Dense>
#include <chrono>
#include <cstdio>
#include <cstdlib>
#include <functional>
#include <random>
#include <string>

#include "seflex/common/so3.hpp"
#include "seflex/io/superelement_file.hpp"
#include "seflex/mbd/bodies/aic_element.hpp"
#include "seflex/mbd/bodies/aic_workspace.hpp"

using namespace seflex;
using Eigen::Matrix3d;
using Eigen::Vector3d;
using Eigen::VectorXd;

namespace {

double best_us(int repeats, const std::function<void()>& f) {
  double best = 1e300;
  for (int batch = 0; batch < 5; ++batch) {
    const auto t0 = std::chrono::steady_clock::now();
    for (int r = 0; r < repeats; ++r) f();
    const auto t1 = std::chrono::steady_clock::now();
    best = std::min(best, std::chrono::duration<double, std::micro>(t1 - t0).count() / repeats);
  }
  return best;
}

}  // namespace

int main(int argc, char** argv) {
  if (argc < 2) {
    std::fprintf(stderr, "usage: aic_kernel_bench BODY.se [REPEATS]\n");
    return 2;
  }
  const int repeats = argc > 2 ? std::atoi(argv[2]) : 2000;
  io::LoadOptions lo;
  const se::Superelement s = io::load_superelement(argv[1], lo);
  const mbd::AicElement e = mbd::make_aic_element(s);
  std::mt19937 rng(7);
  std::uniform_real_distribution<double> u(-1.0, 1.0);
  // A rigid rotation and translation of the body plus small deformations of every interface.
  const Matrix3d R0 = so3::exp(Vector3d(0.3, -0.2, 0.5));
  const Vector3d p0(0.1, 0.2, -0.3);
  std::vector<Matrix3d> R_WI(e.N);
  std::vector<Vector3d> p_WI(e.N);
  for (int j = 0; j < e.N; ++j) {
    p_WI[j] = p0 + R0 * (e.x[j] + 1e-4 * Vector3d(u(rng), u(rng), u(rng)));
    R_WI[j] = R0 * so3::exp(1e-4 * Vector3d(u(rng), u(rng), u(rng))) * e.C[j];
  }
  VectorXd eta(e.m), v(e.n), a(e.n);
  for (int k = 0; k < e.m; ++k) eta[k] = 1e-5 * u(rng);
  for (int i = 0; i < e.n; ++i) {
    v[i] = u(rng);
    a[i] = 10.0 * u(rng);
  }
  mbd::AicKinematics kin;
  mbd::AicWorkspace ws;
  mbd::FloatingFrame warm = mbd::frame_guess(e, R_WI[0], p_WI[0]);
  mbd::recover_frame(e, R_WI, p_WI, eta, mbd::FrameRecovery::Newton6, warm, kin);
  warm = kin.frame;
  VectorXd f(e.n);
  Eigen::MatrixXd Kt;
  mbd::InertiaResult in;
  std::printf("# aic_kernel_bench %s %d   (n = %d: %d interfaces, %d modes; microseconds per call)\n", argv[1], repeats,
              e.n, e.N, e.m);
  const char* only = std::getenv("AIC_KERNEL_ONLY");  // profile one kernel: its name's first word
  auto line = [&](const char* what, const std::function<void()>& fn) {
    if (only && std::string(what).rfind(only, 0) != 0) return;
    fn();  // size the scratch
    std::printf("%-42s %10.2f\n", what, best_us(repeats, fn));
  };
  // Start-up of a body: the element from the file's superelement (the stiffening invariants' SVD
  // included, docs/geometric-stiffening.md "The rank of the invariants").
  line("make_aic_element", [&] { const mbd::AicElement made = mbd::make_aic_element(s); });
  line("recover_frame", [&] { mbd::recover_frame(e, R_WI, p_WI, eta, mbd::FrameRecovery::Newton6, warm, kin); });
  line("elastic_force (force)", [&] { mbd::elastic_force(e, kin, mbd::TangentModel::Exact, f, nullptr, ws); });
  line("elastic_force (force + tangent)", [&] { mbd::elastic_force(e, kin, mbd::TangentModel::Exact, f, &Kt, ws); });
  if (e.has_stiffening()) {
    mbd::StiffeningLoads lambda;
    mbd::stiffening_load_factors(e, kin, v, a, lambda, ws);
    // ws.Uxi_of = nullptr: every call pays for G_c xi, as at a new Newton iterate.
    line("elastic_force stiffened (force)", [&] {
      ws.Uxi_of = nullptr;
      mbd::elastic_force_stiffened(e, kin, mbd::TangentModel::Exact, lambda, f, nullptr, ws);
    });
    line("elastic_force stiffened (force + tangent)", [&] {
      ws.Uxi_of = nullptr;
      mbd::elastic_force_stiffened(e, kin, mbd::TangentModel::Exact, lambda, f, &Kt, ws);
    });
  }
  line("inertia full (force)", [&] { mbd::inertia_force(e, kin, mbd::InertiaModel::Full, v, a, false, in, ws); });
  line("inertia full (force + matrices)", [&] { mbd::inertia_force(e, kin, mbd::InertiaModel::Full, v, a, true, in, ws); });
  line("inertia full (force + M, K; no C)", [&] {
    mbd::inertia_force(e, kin, mbd::InertiaModel::Full, v, a, mbd::InertiaMatrices::NoVelocityTangent, in, ws);
  });
  line("inertia simplified (force)", [&] { mbd::inertia_force(e, kin, mbd::InertiaModel::Simplified, v, a, false, in, ws); });
  line("inertia simplified (force + matrices)",
       [&] { mbd::inertia_force(e, kin, mbd::InertiaModel::Simplified, v, a, true, in, ws); });
  // The full inertia's stacked-invariant product (the largest single cost of a residual) for the three
  // stages of a Radau IIA-5 step: three matrix-vector products, as today, or one three-column product
  // (would batching the stages pay?).
  Eigen::MatrixXd eta3 = Eigen::MatrixXd::Random(e.inv_by_xi.cols(), 3), t3(e.inv_by_xi.rows(), 3);
  line("stacked invariants x xi, 3 stages: 3 x gemv", [&] {
    for (int c = 0; c < 3; ++c) t3.col(c).noalias() = e.inv_by_xi * eta3.col(c);
  });
  line("stacked invariants x xi, 3 stages: 1 gemm", [&] { t3.noalias() = e.inv_by_xi * eta3; });
  return 0;
}
