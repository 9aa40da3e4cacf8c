#pragma once
// One entry point for simulating a model from its initial state: the formulation (the AIC
// superelements of seflex, or the classic floating frame / rigid bodies with Lagrange multipliers as
// baselines, docs/ffrf.md) and, for AIC, the integrator method. Every front end (seflex run, seflex
// advise, through scene::solve_scene) calls this, so a method added here is reachable from all of them.
#include <optional>
#include <string>

#include "seflex/mbd/ffrf/ffrf.hpp"
#include "seflex/mbd/solvers/integrator.hpp"
#include "seflex/mbd/output.hpp"

namespace seflex::mbd {

/// The time integrator (scene files' `integrator.method`): the implicit Lie-group generalized-alpha
/// (solvers/integrator.hpp), the implicit Radau IIA of order 5 (solvers/radau5.hpp) or the explicit
/// Runge-Kutta-Munthe-Kaas 4 with a constant step (solvers/explicit_integrator.hpp).
enum class IntegratorMethod { GeneralizedAlpha, Radau5, Rk4 };

/// "generalized-alpha", "radau5", "rk4" (the spelling of a scene file's `integrator.method`).
const char* integrator_method_name(IntegratorMethod m);

enum class Formulation {
  Aic,     ///< absolute interface coordinates (any IntegratorMethod)
  FfrfLm,  ///< floating frame + frame-clamped modes, joints by Lagrange multipliers
  RigidLm, ///< every body rigid, joints by Lagrange multipliers
};

/// "aic", "ffrf-lm", "rigid-lm" (the spelling of `seflex run --formulation`).
const char* formulation_name(Formulation f);

/// Empty when `formulation` integrates with `method`; otherwise why not (FFRF-LM and rigid-LM:
/// generalized-alpha only, docs/ffrf.md), as "integrator.method rk4: the formulation ffrf-lm integrates with ...".
std::string integrator_unavailable(Formulation formulation, IntegratorMethod method);

struct SimulationRun {
  RunStats run;
  std::optional<FfrfStats> ffrf;  ///< FfrfLm / RigidLm: coordinates, multipliers, constraint drift
};

/// Simulate `model` from its initial state with `settings` in `formulation` with `method`. Throws
/// InputError when the formulation does not have the method (integrator_unavailable) or the model
/// cannot be expressed in it, and ConvergenceError on failure after delivering the last good sample
/// to `observer`.
SimulationRun simulate(const Model& model, const IntegratorSettings& settings, IntegratorMethod method,
                       Formulation formulation, Observer* observer);

}  // namespace seflex::mbd
