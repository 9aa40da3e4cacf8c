#pragma once
// One entry point for simulating a built scene: the formulation (the AIC superelements of seflex,
// or the classic floating frame / rigid bodies with Lagrange multipliers as baselines, docs/ffrf.md)
// and, for AIC, the integrator its description names (`integrator.method` of the scene file).
// Every front end (seflex run, seflex advise) calls this, so a method added here is reachable from
// all of them.
#include <optional>

#include "seflex/io/scene.hpp"
#include "seflex/mbd/ffrf/ffrf.hpp"
#include "seflex/mbd/solvers/integrator.hpp"
#include "seflex/mbd/output.hpp"

namespace seflex::io {

enum class Formulation {
  Aic,     ///< absolute interface coordinates (the scene's integrator.method)
  FfrfLm,  ///< floating frame + frame-clamped modes, joints by Lagrange multipliers
  RigidLm, ///< every body rigid, joints by Lagrange multipliers
};

/// "aic", "ffrf-lm", "rigid-lm" (the spelling of `seflex run --formulation`).
const char* formulation_name(Formulation f);

/// "generalized-alpha", "radau5", "rk4" (the spelling of `integrator.method`).
const char* method_name(IntegratorMethod m);

struct SceneRun {
  mbd::RunStats run;
  std::optional<mbd::FfrfStats> ffrf;  ///< FfrfLm / RigidLm: coordinates, multipliers, constraint drift
};

/// Simulate `scene` from its initial state with `settings` (the scene's own settings, possibly
/// overridden) in `formulation`. Throws InputError when the scene asks for an integrator the
/// formulation does not have (FFRF-LM and rigid-LM: generalized-alpha only) or cannot be expressed
/// in it, and ConvergenceError on failure after delivering the last good sample to `observer`.
SceneRun solve_scene(const Scene& scene, const mbd::IntegratorSettings& settings, Formulation formulation,
                     mbd::Observer* observer);

}  // namespace seflex::io
