#pragma once
// Simulate a built scene: its model, from its initial state, with the scene's integrator method
// (`integrator.method`) in the formulation asked for. The choice of formulation and integrator is
// mbd's (mbd/solvers/simulate.hpp); this names the scene file in the messages.
#include "seflex/mbd/solvers/simulate.hpp"
#include "seflex/scene/run_output.hpp"
#include "seflex/scene/scene.hpp"

namespace seflex::scene {

/// `settings`: the scene's own (description.integrator), possibly overridden. Throws InputError
/// naming the scene file when the scene asks for an integrator the formulation does not have
/// (mbd::integrator_unavailable), and whatever mbd::simulate throws.
mbd::SimulationRun solve_scene(const Scene& scene, const mbd::IntegratorSettings& settings,
                               mbd::Formulation formulation, mbd::Observer* observer);

/// The summary's record of a run of `scene` in `formulation` (RunOutput::finish): the formulation and
/// the scene's integrator named; record_run adds a finished run's counts (its stats; the coordinates
/// and multipliers of a multiplier formulation). The command and seflex.run (python/) both use these.
RunEnd run_end(const Scene& scene, mbd::Formulation formulation);
void record_run(const mbd::SimulationRun& run, RunEnd& end);

}  // namespace seflex::scene
