#include "seflex/scene/solve_scene.hpp"

#include <string>

#include "seflex/common/error.hpp"

namespace seflex::scene {

mbd::SimulationRun solve_scene(const Scene& scene, const mbd::IntegratorSettings& settings,
                               mbd::Formulation formulation, mbd::Observer* observer) {
  if (const std::string why = mbd::integrator_unavailable(formulation, scene.description.method); !why.empty())
    throw InputError(scene.description.file.string() + ": " + why);
  return mbd::simulate(scene.model, settings, scene.description.method, formulation, observer);
}

RunEnd run_end(const Scene& scene, mbd::Formulation formulation) {
  RunEnd end;
  end.formulation = mbd::formulation_name(formulation);
  end.method = mbd::integrator_method_name(scene.description.method);
  return end;
}

void record_run(const mbd::SimulationRun& run, RunEnd& end) {
  end.stats = run.run;
  if (run.ffrf) {
    end.coordinates = run.ffrf->coordinates;
    end.multipliers = run.ffrf->constraints;
  }
}

}  // namespace seflex::scene
