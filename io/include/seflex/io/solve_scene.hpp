#pragma once
// One entry point for simulating a built scene with the integrator its description names
// (`integrator.method` of the scene file): every front end (seflex run, seflex advise) calls this,
// so a method added here is reachable from all of them.
#include "seflex/io/scene.hpp"
#include "seflex/mbd/integrator.hpp"
#include "seflex/mbd/output.hpp"

namespace seflex::io {

/// Simulate `scene` from its initial state with `settings` (the scene's own settings, possibly
/// overridden) and the method of scene.description.method. Throws ConvergenceError on failure
/// after delivering the last good sample to `observer`.
mbd::RunStats solve_scene(const Scene& scene, const mbd::IntegratorSettings& settings, mbd::Observer* observer);

}  // namespace seflex::io
