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

}  // namespace seflex::scene
