// The integrator switch of scenes (integrator.method).
#include "seflex/io/solve_scene.hpp"

#include "seflex/mbd/explicit_integrator.hpp"
#include "seflex/mbd/state.hpp"

namespace seflex::io {

mbd::RunStats solve_scene(const Scene& scene, const mbd::IntegratorSettings& settings, mbd::Observer* observer) {
  mbd::State state = mbd::initial_state(scene.model);
  mbd::Data data(scene.model);
  if (scene.description.method == IntegratorMethod::Rk4) return mbd::simulate_rk4(scene.model, state, data, settings, observer);
  return mbd::simulate(scene.model, state, data, settings, observer);
}

}  // namespace seflex::io
