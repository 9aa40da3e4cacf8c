#pragma once
// Model no more than a scene needs: a short study of cheaper variants of a scene (all bodies
// rigid; fewer internal modes; the simplified mass; no geometric stiffening; alternative
// reductions such as beam-like superelements for 3D ones or a beam cut into fewer superelements;
// the classic floating frame and rigid bodies with Lagrange multipliers, FFRF-LM and rigid-LM, as
// other formulations of the finest model), each compared with the finest variant (every body
// flexible, full inertia, all internal modes of the scene as written, geometric stiffening where the
// superelement files carry its invariants) on the hinge angles, and optionally on the positions of
// named nodes (a beam's tip), over a short horizon (up to the finest variant's first lock, or a
// given end time). The cheapest variant (CPU time) whose largest hinge-angle difference (and node
// position difference) stays within the tolerance is recommended; the evidence table lists every
// variant.
//
//   AdviseOptions o; o.tolerance = 0.5 * pi / 180;
//   AdviseReport r = advise(read_scene("array.yaml"), o);
//   o.nodes = {"beam.11"}; o.position_tolerance = 0.01;   // also the tip within 1 cm
#include <optional>
#include <string>
#include <vector>

#include "seflex/scene/scene.hpp"

namespace seflex::scene {

struct AdviseOptions {
  double tolerance = 0.0;                        ///< largest acceptable hinge-angle error [rad] (> 0)
  std::optional<double> t_end;                   ///< horizon [s]; absent: the reference's first lock
  std::vector<SceneDescription> alternatives;    ///< other reductions of the same mechanism (same hinge names)
  /// Also compare the positions of these nodes of the scene (names body.grid, e.g. a tip "beam.11");
  /// in an alternative scene, the node of the same name, else the node at the same initial position.
  std::vector<std::string> nodes;
  double position_tolerance = 0.0;               ///< largest acceptable node-position error [m] (> 0 with nodes)
  /// Largest acceptable error of the peak element results (stress modes, docs/stresses.md) as a fraction
  /// of the largest reference peak of the same body (0: not compared). Each element's peak over the
  /// horizon (von Mises, moment, force) is compared with the finest variant's; a variant without stress
  /// modes (rigid bodies) has none, an error of 1.
  double stress_tolerance = 0.0;
  std::vector<int> few_modes = {2};              ///< "a few" internal modes per body (besides 0 and all)
  int grid_points = 400;                         ///< comparison grid over the horizon (at least)
};

struct AdviseRow {
  std::string name;               ///< e.g. "rigid", "flexible / full inertia / 2 modes", "flexible / full inertia / all modes / no stiffening",
                                  ///< "FFRF-LM / flexible / all modes", "alternative NAME: ..." (NAME: the alternative's file stem)
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
  double max_position_error = 0.0;  ///< max over the nodes and grid times of |p - p_ref| [m]; inf if !ran; 0 without nodes
  std::string worst_node;        ///< where max_position_error occurred (the scene's node name)
  double max_stress_error = 0.0;  ///< max over bodies and elements of |peak - peak_ref| / max peak_ref of the body; 0 when not compared
  std::string worst_element;      ///< where max_stress_error occurred ("body element ID")
  double worst_node_time = 0.0;  ///< [s]
  bool stiffening = false;       ///< some flexible body of the variant has geometric stiffening
  bool within = false;           ///< ran, max_error <= tolerance, max_position_error <= position_tolerance and
                                 ///< max_stress_error <= stress_tolerance (when compared)
};

struct AdviseReport {
  double horizon = 0.0;          ///< [s]
  bool horizon_at_lock = false;  ///< the horizon is the reference's first lock
  std::string horizon_lock;      ///< which lock (when horizon_at_lock)
  double tolerance = 0.0;        ///< [rad]
  double position_tolerance = 0.0;  ///< [m] (nodes given)
  double stress_tolerance = 0.0;    ///< fraction (0: stresses not compared)
  std::vector<std::string> nodes;   ///< the compared nodes
  std::vector<AdviseRow> rows;   ///< reference first, then the variants in the order made
  int recommended = -1;          ///< index into rows (the reference qualifies if nothing cheaper does)
};

/// Run the study. InputError if the scene cannot be built or the options are invalid (an
/// alternative must have the same hinge names and a node at the place of each compared node; a
/// compared node must exist in the scene); a variant that fails is reported, not thrown.
AdviseReport advise(const SceneDescription& scene, const AdviseOptions& options);

}  // namespace seflex::scene
