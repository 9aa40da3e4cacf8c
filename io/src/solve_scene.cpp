// The formulation and integrator switch of scenes (--formulation, integrator.method).
#include "seflex/io/solve_scene.hpp"

#include <string>

#include "seflex/common/error.hpp"
#include "seflex/mbd/solvers/explicit_integrator.hpp"
#include "seflex/mbd/solvers/radau5.hpp"
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

const char* method_name(IntegratorMethod m) {
  switch (m) {
    case IntegratorMethod::GeneralizedAlpha: return "generalized-alpha";
    case IntegratorMethod::Radau5: return "radau5";
    case IntegratorMethod::Rk4: return "rk4";
  }
  return "?";
}

SceneRun solve_scene(const Scene& scene, const mbd::IntegratorSettings& settings, Formulation formulation,
                     mbd::Observer* observer) {
  SceneRun out;
  if (formulation == Formulation::Aic) {
    mbd::State state = mbd::initial_state(scene.model);
    mbd::Data data(scene.model);
    switch (scene.description.method) {
      case IntegratorMethod::Rk4: out.run = mbd::simulate_rk4(scene.model, state, data, settings, observer); break;
      case IntegratorMethod::Radau5: out.run = mbd::simulate_radau5(scene.model, state, data, settings, observer); break;
      case IntegratorMethod::GeneralizedAlpha: out.run = mbd::simulate(scene.model, state, data, settings, observer); break;
    }
    return out;
  }
  if (scene.description.method != IntegratorMethod::GeneralizedAlpha)
    throw InputError(scene.description.file.string() + ": integrator.method " + method_name(scene.description.method) +
                     ": the formulation " + formulation_name(formulation) + " integrates with generalized-alpha only");
  mbd::FfrfOptions fo;
  fo.rigid = formulation == Formulation::RigidLm;
  out.ffrf = mbd::simulate_ffrf(scene.model, settings, fo, observer);
  out.run = out.ffrf->run;
  return out;
}

}  // namespace seflex::io
