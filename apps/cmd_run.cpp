// seflex run SCENE -o OUTDIR: simulate the mechanism of a scene file (docs/scenes.md) and write its
// time histories, events, poses, animation and summary (scene/run_output.hpp) as the run goes.
#include <unistd.h>

#include <algorithm>
#include <chrono>
#include <optional>
#include <set>
#include <cmath>
#include <cstdio>
#include <ctime>
#include <string>

#include "command.hpp"
#include "seflex/common/error.hpp"
#include "seflex/scene/run_output.hpp"
#include "seflex/scene/scene.hpp"
#include "seflex/scene/solve_scene.hpp"
#include "seflex/io/superelement_file.hpp"
#include "seflex/mbd/solvers/integrator.hpp"
#include "seflex/mbd/state.hpp"

namespace {

using seflex::app::UsageError;
namespace io = seflex::io;
namespace scene = seflex::scene;
namespace mbd = seflex::mbd;

/// Forwards to the run output and draws a progress bar on stderr (only when it is a terminal).
class Progress : public mbd::Observer {
 public:
  explicit Progress(scene::RunOutput& out) : out_(out), tty_(isatty(STDERR_FILENO) != 0) {}
  ~Progress() override { done(); }
  void on_sample(const mbd::Model& m, const mbd::Sample& s) override { out_.on_sample(m, s); }
  bool stop_requested() const override { return out_.stop_requested(); }
  void on_progress(double t, double t_end) override {
    out_.on_progress(t, t_end);
    if (!tty_) return;
    const auto now = std::chrono::steady_clock::now();
    if (drawn_ && now - last_ < std::chrono::milliseconds(200)) return;
    last_ = now;
    drawn_ = true;
    const double f = t_end > 0 ? std::clamp(t / t_end, 0.0, 1.0) : 1.0;
    const int width = 40, fill = static_cast<int>(std::lround(f * width));
    std::fprintf(stderr, "\r[%s%s] %5.1f%%  t = %.4g s", std::string(static_cast<std::size_t>(fill), '#').c_str(),
                 std::string(static_cast<std::size_t>(width - fill), ' ').c_str(), 100.0 * f, t);
    std::fflush(stderr);
  }
  void done() {
    if (drawn_) std::fprintf(stderr, "\n");
    drawn_ = false;
  }

 private:
  scene::RunOutput& out_;
  bool tty_;
  bool drawn_ = false;
  std::chrono::steady_clock::time_point last_{};
};

int run_run(seflex::app::Args& args) {
  std::optional<std::string> out = args.value("-o");
  if (!out) out = args.value("output");
  const bool force = args.flag("force");
  const auto t_end = args.value("t-end");
  const auto step = args.value("step");
  const auto inertia = args.value("inertia");
  const auto fidelity = args.value("fidelity");
  const std::string formulation_arg = args.value("formulation").value_or("aic");
  const auto method = args.value("method");
  const auto tolerance = args.value("tolerance");
  const bool no_animation = args.flag("no-animation");
  const std::string scene_path = args.positional("SCENE");
  args.finish();
  if (!out) throw UsageError("missing -o OUTDIR (the folder for the results)");
  if (inertia && *inertia != "simplified" && *inertia != "full")
    throw UsageError("option --inertia expects simplified or full, got '" + *inertia + "'");
  if (fidelity && *fidelity != "rigid" && *fidelity != "flexible")
    throw UsageError("option --fidelity expects rigid or flexible, got '" + *fidelity + "'");
  mbd::Formulation formulation = mbd::Formulation::Aic;
  if (formulation_arg == "ffrf-lm") formulation = mbd::Formulation::FfrfLm;
  else if (formulation_arg == "rigid-lm" || formulation_arg == "rigid") formulation = mbd::Formulation::RigidLm;
  else if (formulation_arg != "aic")
    throw UsageError("option --formulation expects aic, ffrf-lm or rigid-lm (also: rigid), got '" + formulation_arg + "'");
  scene::RunOutput::check_folder(*out, force);  // before the work, not after it

  scene::SceneDescription d = scene::read_scene(scene_path);
  if (method) {
    if (*method == "generalized-alpha") d.method = mbd::IntegratorMethod::GeneralizedAlpha;
    else if (*method == "radau5") d.method = mbd::IntegratorMethod::Radau5;
    else if (*method == "rk4") d.method = mbd::IntegratorMethod::Rk4;
    else throw UsageError("option --method expects generalized-alpha, radau5 or rk4, got '" + *method + "'");
  }
  if (const std::string why = mbd::integrator_unavailable(formulation, d.method); !why.empty())
    throw UsageError("option --formulation " + formulation_arg + ": " + (method ? "--method asks for " : "the scene asks for ") + why);
  if (tolerance)
    d.integrator.tol_position = d.integrator.tol_angle =
        seflex::app::positive_number("tolerance", *tolerance, "a local error tolerance > 0 (relative to the model size / rad)");
  if (t_end) d.integrator.t_end = seflex::app::positive_number("t-end", *t_end, "a time > 0 in seconds");
  if (step) {
    d.integrator.h_initial = seflex::app::positive_number("step", *step, "a time > 0 in seconds");
    d.integrator.h_min = std::min(d.integrator.h_min, d.integrator.h_initial);
  }
  for (auto& b : d.bodies) {
    if (inertia) b.inertia = *inertia == "full" ? mbd::InertiaModel::Full : mbd::InertiaModel::Simplified;
    if (fidelity) b.fidelity = *fidelity == "rigid" ? scene::Fidelity::Rigid : scene::Fidelity::Flexible;
  }
  const auto t0 = std::chrono::steady_clock::now();
  const std::clock_t c0 = std::clock();
  // The mesh part of the superelement files serves the animation and the static subcases' inertia loads
  // only; without it a run reads the dynamics (reduced matrices, inertia and stiffening invariants). The floating-frame baseline takes
  // its inertia from the invariants too (and may sum over the FE nodes of a small mesh that is read).
  scene::SceneBuildOptions bo;
  bo.keep_mesh = (!no_animation && d.output.animation_interval) || !d.output.static_subcases.empty();
  bo.full_inertia_everywhere = formulation == mbd::Formulation::FfrfLm;
  const scene::Scene scene = scene::build_scene(d, bo);
  std::uint64_t se_bytes = 0;
  bool meshless = false, with_mesh = false;
  std::set<const seflex::se::Superelement*> counted;  // bodies that share a file share its copy
  for (const auto& p : scene.superelements) {
    const auto& s = *p;
    if (counted.insert(&s).second) se_bytes += io::superelement_memory_bytes(s);
    meshless = meshless || s.fe_node_ids.empty();
    with_mesh = with_mesh || !s.fe_node_ids.empty() || s.recovery.size() != 0;
  }
  std::printf("seflex run %s -> %s\n  %s\n  %zu bodies, %zu hinges, %zu force elements, %d dofs; t_end = %g s\n",
              scene_path.c_str(), out->c_str(), d.title.c_str(), d.bodies.size(), scene.model.hinges.size(),
              scene.model.force_elements.size(), scene.model.num_dofs, d.integrator.t_end);
  std::printf("  superelements in memory: %.1f kB (%s)\n", static_cast<double>(se_bytes) / 1024.0,
              with_mesh ? "with mesh parts" : "dynamics only, mesh parts not read");
  if (!no_animation && d.output.animation_interval && meshless)
    std::printf("  note: a superelement without its mesh part (seflex reduce --no-mesh) is not drawn in the animation\n");
  for (const std::string& line : scene.redundant_hinges) std::printf("  redundant: %s\n", line.c_str());
  std::fflush(stdout);

  scene::RunOutputOptions oo;
  oo.folder = *out;
  oo.overwrite = force;
  oo.animation = !no_animation;
  scene::RunOutput output(scene, oo);
  Progress progress(output);
  scene::RunEnd end = scene::run_end(scene, formulation);
  const auto seconds = [&] { return std::chrono::duration<double>(std::chrono::steady_clock::now() - t0).count(); };
  const auto cpu_seconds = [&] { return static_cast<double>(std::clock() - c0) / CLOCKS_PER_SEC; };
  try {
    const mbd::SimulationRun r = scene::solve_scene(scene, d.integrator, formulation, &progress);
    scene::record_run(r, end);
    if (r.ffrf) {
      progress.done();
      std::printf("  %s: %d coordinates, %d multipliers; largest constraint drift %.2e m, %.2e rad (%.2e m/s)\n",
                  formulation_arg.c_str(), r.ffrf->coordinates, r.ffrf->constraints, r.ffrf->drift_position,
                  r.ffrf->drift_rotation, r.ffrf->drift_velocity);
      if (!r.ffrf->redundant.empty())
        std::printf("  %zu redundant constraint equations removed at t = 0 (their reactions are indeterminate, reported as zero): %s\n",
                    r.ffrf->redundant.size(), mbd::describe_redundant(r.ffrf->redundant).c_str());
    }
  } catch (const seflex::Error& e) {
    // Everything computed so far is on disk; say where it stopped and why.
    progress.done();
    end.ok = false;
    end.message = e.what();
    end.wall_seconds = seconds();
    end.cpu_seconds = cpu_seconds();
    output.finish(end);
    std::fprintf(stderr, "the results up to t = %g s are in %s (summary.txt, history.csv)\n", output.t_last(), out->c_str());
    if (dynamic_cast<const seflex::ConvergenceError*>(&e)) {
      std::fprintf(stderr, "error: %s\n", e.what());
      return seflex::app::kNotConverged;
    }
    throw;
  }
  progress.done();
  end.wall_seconds = seconds();
  end.cpu_seconds = cpu_seconds();
  output.finish(end);
  const mbd::RunStats& st = *end.stats;
  std::printf("done: t = %g s in %.2f s wall; %ld steps (%ld rejected), %ld Newton iterations; results in %s\n",
              output.t_last(), end.wall_seconds, st.steps, st.rejected_error + st.rejected_newton, st.newton_iterations,
              out->c_str());
  return seflex::app::kOk;
}

}  // namespace

SEFLEX_COMMAND(run,
               "SCENE -o OUTDIR [--force] [--t-end T] [--step H] [--method generalized-alpha|radau5|rk4] [--tolerance TOL] "
               "[--inertia simplified|full] [--fidelity rigid|flexible] [--formulation aic|ffrf-lm|rigid-lm] [--no-animation]",
               "simulate the mechanism of a scene file (YAML, docs/scenes.md); writes history.csv, events.csv, "
               "poses.csv, animation.pvd and summary.txt/json to OUTDIR as the run goes (options override the scene: "
               "--method = integrator.method, --tolerance = integrator.tolerance's position and angle; "
               "--formulation: the AIC superelements (default), the classic floating frame or rigid bodies with "
               "Lagrange multipliers (rigid-lm, also spelled rigid), docs/ffrf.md)",
               run_run);
