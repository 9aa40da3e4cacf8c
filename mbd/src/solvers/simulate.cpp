// The formulation and integrator switch (scene files' integrator.method, seflex run --formulation).
#include "seflex/mbd/solvers/simulate.hpp"

#include <string>

#include "seflex/common/error.hpp"
#include "seflex/mbd/solvers/explicit_integrator.hpp"
#include "seflex/mbd/solvers/radau5.hpp"
#include "seflex/mbd/state.hpp"

namespace seflex::mbd {

const char* integrator_method_name(IntegratorMethod m) {
  switch (m) {
    case IntegratorMethod::GeneralizedAlpha: return "generalized-alpha";
    case IntegratorMethod::Radau5: return "radau5";
    case IntegratorMethod::Rk4: return "rk4";
  }
  return "?";
}

const char* formulation_name(Formulation f) {
  switch (f) {
    case Formulation::Aic: return "aic";
    case Formulation::FfrfLm: return "ffrf-lm";
    case Formulation::RigidLm: return "rigid-lm";
  }
  return "?";
}

std::string integrator_unavailable(Formulation formulation, IntegratorMethod method) {
  if (formulation == Formulation::Aic || method == IntegratorMethod::GeneralizedAlpha) return {};
  return std::string("integrator.method ") + integrator_method_name(method) + ": the formulation " +
         formulation_name(formulation) + " integrates with generalized-alpha only (docs/ffrf.md, Limits)";
}

SimulationRun simulate(const Model& model, const IntegratorSettings& settings, IntegratorMethod method,
                       Formulation formulation, Observer* observer) {
  SimulationRun out;
  if (formulation == Formulation::Aic) {
    State state = initial_state(model);
    Data data(model);
    switch (method) {
      case IntegratorMethod::Rk4: out.run = simulate_rk4(model, state, data, settings, observer); break;
      case IntegratorMethod::Radau5: out.run = simulate_radau5(model, state, data, settings, observer); break;
      case IntegratorMethod::GeneralizedAlpha: out.run = simulate(model, state, data, settings, observer); break;
    }
    return out;
  }
  if (const std::string why = integrator_unavailable(formulation, method); !why.empty()) throw InputError(why);
  FfrfOptions fo;
  fo.rigid = formulation == Formulation::RigidLm;
  out.ffrf = simulate_ffrf(model, settings, fo, observer);
  out.run = out.ffrf->run;
  return out;
}

}  // namespace seflex::mbd
