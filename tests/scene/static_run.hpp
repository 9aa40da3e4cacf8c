#pragma once
// Shared by the scene tests of stresses and interface loads: a scene solved quasi-statically (the slow-
// loading limit) with the run's output written as `seflex run` writes it.
#include <filesystem>

#include "seflex/mbd/data.hpp"
#include "seflex/mbd/solvers/statics.hpp"
#include "seflex/mbd/state.hpp"
#include "seflex/scene/run_output.hpp"

namespace seflex::test {

/// `sc` solved by mbd::solve_static (residual 1e-10, increment 1e-12) with its RunOutput in `folder`
/// (overwritten, no animation); the last sample.
inline mbd::Sample solve_static_with_output(const scene::Scene& sc, const std::filesystem::path& folder) {
  scene::RunOutput out(sc, {folder, true, false});
  struct Last : mbd::Observer {
    scene::RunOutput* out = nullptr;
    mbd::Sample last;
    void on_sample(const mbd::Model& m, const mbd::Sample& s) override {
      last = s;
      out->on_sample(m, s);
    }
  } obs;
  obs.out = &out;
  mbd::State state = mbd::initial_state(sc.model);
  mbd::Data data(sc.model);
  mbd::StaticSettings settings;
  settings.residual_tol = 1e-10;
  settings.increment_tol = 1e-12;
  mbd::solve_static(sc.model, state, data, settings, &obs);
  out.finish(scene::RunEnd{});
  return obs.last;
}

}  // namespace seflex::test
