// The formulation and integrator switch of scenes (--formulation, integrator.method).
#include "seflex/io/solve_scene.hpp"

#include <string>

#include "seflex/common/error.hpp"
#include "seflex/mbd/solvers/explicit_integrator.hpp"
#include "seflex/mbd/state.hpp"

namespace seflex::io {

const char* formulation_name(Formulation f) {
  switch (f) {
    case Formulation::Aic: return "aic";
    case Formulation::FfrfLm: return "ffrf-lm";
    case Formulation::RigidLm: return "rigid-lm";
  }
  return "?";
}

SceneRun solve_scene(const Scene& scene, const mbd::IntegratorSettings& settings, Formulation formulation,
                     mbd::Observer* observer) {
  SceneRun out;
  if (formulation == Formulation::Aic) {
    mbd::State state = mbd::initial_state(scene.model);
    mbd::Data data(scene.model);
    out.run = scene.description.method == IntegratorMethod::Rk4 ? mbd::simulate_rk4(scene.model, state, data, settings, observer)
                                                                : mbd::simulate(scene.model, state, data, settings, observer);
    return out;
  }
  if (scene.description.method != IntegratorMethod::GeneralizedAlpha)
    throw InputError(scene.description.file.string() + ": integrator.method rk4: the formulation " +
                     formulation_name(formulation) + " integrates with generalized-alpha only");
  mbd::FfrfOptions fo;
  fo.rigid = formulation == Formulation::RigidLm;
  out.ffrf = mbd::simulate_ffrf(scene.model, settings, fo, observer);
  out.run = out.ffrf->run;
  return out;
}

}  // namespace seflex::io
