#pragma once
// Model no more than a scene needs: a short study of cheaper variants of a scene (all bodies
// rigid; fewer internal modes; the simplified mass; an alternative reduction such as beam-like
// superelements for 3D ones; the classic floating frame and rigid bodies with Lagrange multipliers,
// FFRF-LM and rigid-LM, as other formulations of the finest model), each compared with the finest variant (every body flexible, full
// inertia, all internal modes of the scene as written) on the hinge angles over a short horizon
// (up to the finest variant's first lock, or a given end time). The cheapest variant (CPU time)
// whose largest hinge-angle difference stays within the tolerance is recommended; the evidence
// table lists every variant.
//
//   AdviseOptions o; o.tolerance = 0.5 * pi / 180;
//   AdviseReport r = advise(read_scene("array.yaml"), o);
#include <optional>
#include <string>
#include <vector>

#include "seflex/io/scene.hpp"

namespace seflex::io {

struct AdviseOptions {
  double tolerance = 0.0;                        ///< largest acceptable hinge-angle error [rad] (> 0)
  std::optional<double> t_end;                   ///< horizon [s]; absent: the reference's first lock
  std::optional<SceneDescription> alternative;   ///< another reduction of the same mechanism
  std::vector<int> few_modes = {2};              ///< "a few" internal modes per body (besides 0 and all)
  int grid_points = 400;                         ///< comparison grid over the horizon (at least)
};

struct AdviseRow {
  std::string name;               ///< e.g. "rigid", "flexible / full inertia / 2 modes", "FFRF-LM / flexible / all modes", "alternative: ..."
  bool reference = false;        ///< the finest variant (flexible / full inertia / all modes)
  int dofs = 0;                   ///< unknowns of the motion (FFRF-LM, rigid-LM: coordinates)
  int multipliers = 0;            ///< Lagrange multipliers (FFRF-LM, rigid-LM)
  bool ran = false;              ///< built and integrated to the horizon
  std::string failure;           ///< why not (build or convergence error)
  double cpu_seconds = 0.0;      ///< process CPU time of the integration (not the file loading)
  long steps = 0;
  double max_error = 0.0;        ///< max over hinges and grid times of |phi - phi_ref| [rad]; inf if !ran
  std::string worst_hinge;       ///< where max_error occurred
  double worst_time = 0.0;       ///< [s]
  bool within = false;           ///< ran and max_error <= tolerance
};

struct AdviseReport {
  double horizon = 0.0;          ///< [s]
  bool horizon_at_lock = false;  ///< the horizon is the reference's first lock
  std::string horizon_lock;      ///< which lock (when horizon_at_lock)
  double tolerance = 0.0;        ///< [rad]
  std::vector<AdviseRow> rows;   ///< reference first, then the variants in the order made
  int recommended = -1;          ///< index into rows (the reference qualifies if nothing cheaper does)
};

/// Run the study. InputError if the scene cannot be built or the options are invalid (the
/// alternative must have the same hinge names); a variant that fails is reported, not thrown.
AdviseReport advise(const SceneDescription& scene, const AdviseOptions& options);

}  // namespace seflex::io
