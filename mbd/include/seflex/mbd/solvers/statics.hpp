#pragma once
// Quasi-static equilibrium with load stepping: node loads and gravity ramped by the load factor
// lambda = k / load_steps, Newton with the analytic tangent K (configuration updated on SO(3)),
// load increments halved when Newton fails. Force elements and drives act at full value.
#include <vector>

#include "seflex/mbd/data.hpp"
#include "seflex/mbd/output.hpp"

namespace seflex::mbd {

struct StaticSettings {
  int load_steps = 10;
  int max_iterations = 30;
  double residual_tol = 1e-8;    ///< |r| <= tol * |residual scale|
  double increment_tol = 1e-10;  ///< weighted increment (m / length scale, rad)
  int max_cutbacks = 10;
};

struct StaticStats {
  std::vector<int> iterations;  ///< Newton iterations of each converged load step
  int cutbacks = 0;
};

/// Solve from `state` (the starting guess; usually initial_state) to load factor 1. Sends one
/// sample per load step to `observer` (may be null). Throws ConvergenceError with a diagnosis.
StaticStats solve_static(const Model& model, State& state, Data& data, const StaticSettings& settings,
                         Observer* observer = nullptr);

}  // namespace seflex::mbd
