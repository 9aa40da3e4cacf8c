#pragma once
// Scene files (YAML, format in docs/scenes.md): superelement bodies and their placement, hinges,
// force elements, loads, drives, integrator and output settings.
//
// Two stages, so that command-line options can override the file in between:
//   SceneDescription d = read_scene("scene.yaml");   // syntax and values; errors name file:line: key
//   d.bodies[0].fidelity = Fidelity::Rigid;           // (overrides)
//   Scene s = build_scene(d);                         // loads the .se files, builds the mbd::Model
// Every InputError names "scene.yaml:LINE: key.path: what was expected".
#include <Eigen/Core>
#include <filesystem>
#include <memory>
#include <optional>
#include <string>
#include <vector>

#include "seflex/common/error.hpp"
#include "seflex/mbd/solvers/integrator.hpp"
#include "seflex/mbd/solvers/simulate.hpp"
#include "seflex/mbd/model.hpp"
#include "seflex/superelement/stress_modes.hpp"
#include "seflex/superelement/superelement.hpp"

namespace seflex::scene {

/// Where an item of a scene was written: file:line and its key path ("hinges[2].child").
struct SceneWhere {
  SourceRef ref;
  std::string key;
  /// "scene.yaml:12: hinges[2].child: " (ready to prepend to a message).
  std::string prefix() const { return ref.str() + ": " + (key.empty() ? std::string() : key + ": "); }
  [[noreturn]] void fail(const std::string& what) const { throw InputError(prefix() + what); }
};

enum class Fidelity { Flexible, Rigid };

/// `ground` or `body.node` (node = FE grid id of one of the body's interface nodes).
struct SceneNodeRef {
  bool ground = false;
  std::string body;
  int grid = 0;
  SceneWhere where;
  std::string str() const { return ground ? std::string("ground") : body + "." + std::to_string(grid); }
};

struct SceneBody {
  std::string name;
  std::filesystem::path superelement;   ///< resolved against the scene file's folder
  Fidelity fidelity = Fidelity::Flexible;
  mbd::InertiaModel inertia = mbd::InertiaModel::Simplified;
  int internal_modes = -1;              ///< -1: all the file has
  mbd::Pose X_WF;                       ///< world pose of the superelement's basic (FE) frame
  double stiffness_damping = 0.0;       ///< [s] D = beta K
  double modal_damping = 0.0;           ///< damping ratio of the internal modes
  /// geometric_stiffening: on|off (docs/geometric-stiffening.md); unset: on when the file carries the invariants
  std::optional<bool> geometric_stiffening;
  SceneWhere where;
  SceneWhere file_where;                ///< where the superelement file was named
};

struct SceneHinge {
  std::string name;
  SceneNodeRef parent, child;
  Eigen::Vector3d axis_W = Eigen::Vector3d::UnitZ();
  double phi0 = 0.0, phidot0 = 0.0;     ///< [rad], [rad/s]
  SceneWhere where;
};

/// One force element on hinge angles, as written (kind: spring, lock, cable, damper).
struct SceneForce {
  std::string name;                     ///< output name, "<kind>.<name or hinge>" (e.g. spring.HL1)
  std::string kind;
  std::vector<std::string> hinges;      ///< spring/lock/damper: one; cable: pulley a's, then b's
  int hinges_a = 0;                     ///< cable: how many of `hinges` are on pulley a
  mbd::ForceElement element;            ///< hinge indices filled in by build_scene
  SceneWhere where;
  std::vector<SceneWhere> hinge_where;  ///< where each hinge name was written
};

struct SceneLoad {
  std::string name;
  SceneNodeRef node;
  Eigen::Vector3d force = Eigen::Vector3d::Zero(), moment = Eigen::Vector3d::Zero();
  bool follower = false;
  SceneWhere where;
};

/// Prescribed hinge motion: spin_up (Simo and Vu-Quoc: rate ramped smoothly from 0 over ramp_time,
/// then constant) or constant_rate.
struct SceneDrive {
  std::string hinge, kind;
  double rate = 0.0;        ///< final rate [rad/s]
  double ramp_time = 0.0;   ///< [s]
  SceneWhere where;
};

struct SceneOutput {
  double interval = 0.0;                     ///< CSV sampling [s] (0: every step)
  std::optional<double> animation_interval;  ///< VTK series [s] (absent: none)
  bool interface_loads = false;              ///< write interface_loads.csv (run_output.hpp)
  /// Instants [s] at which each flexible body's interface displacements are written as a Nastran static
  /// subcase (static_subcases/BODY_K.bdf, run_output.hpp), at the first sample at or after each.
  std::vector<double> static_subcases;
};

struct SceneDescription {
  std::filesystem::path file;
  std::string title;
  std::vector<SceneBody> bodies;
  std::vector<SceneNodeRef> ground;
  std::vector<std::vector<SceneNodeRef>> connections;
  std::vector<SceneHinge> hinges;
  std::vector<SceneForce> forces;  ///< springs, locks, cables, dampers (in that order)
  std::vector<SceneLoad> loads;
  Eigen::Vector3d gravity = Eigen::Vector3d::Zero();
  std::vector<SceneDrive> drives;
  mbd::IntegratorSettings integrator;
  mbd::IntegratorMethod method = mbd::IntegratorMethod::GeneralizedAlpha;  ///< integrator.method
  std::optional<double> stop_after_all_locked;  ///< [s]
  SceneOutput output;
};

/// A body of the built scene: which mbd body it became.
struct SceneBodyRef {
  bool rigid = false;
  int index = -1;  ///< into Model::flexible_bodies or Model::rigid_bodies
};

struct Scene {
  SceneDescription description;
  /// Per scene body, as used (internal modes kept); bodies that use the same file with the same modes
  /// share one copy.
  std::vector<std::shared_ptr<const se::Superelement>> superelements;
  /// Per scene body, the stress modes of its file (as many columns as the body keeps; null: none;
  /// docs/stresses.md).
  std::vector<std::shared_ptr<const se::StressModes>> stress;
  std::vector<SceneBodyRef> bodies;             ///< per scene body
  mbd::Model model;
};

/// Parse and check a scene file (structure, key names, values, references between items).
SceneDescription read_scene(const std::filesystem::path& file);
/// Same, from text (`file` names it in messages and anchors relative paths).
SceneDescription parse_scene(const std::string& text, const std::filesystem::path& file);

/// What build_scene keeps of the superelement files.
struct SceneBuildOptions {
  /// Keep each file's mesh part (FE nodes, recovery, FE mass, cells): needed for the animation.
  /// Without it a file is read without its mesh datasets (io::SuperelementParts::Dynamics) unless a
  /// full-inertia body needs the mesh because the file carries no inertia invariants.
  bool keep_mesh = true;
  /// Every flexible body needs the inertia invariants (or the mesh to compute them), whatever its
  /// scene inertia: the floating-frame baseline's inertia is always the full one (docs/ffrf.md).
  bool full_inertia_everywhere = false;
};

/// Load the superelement files and build the multibody model. A body with full inertia whose file
/// has no inertia invariants gets them computed from the file's mesh part
/// (se::compute_inertia_invariants); when the file has neither, InputError says what to do.
Scene build_scene(const SceneDescription& description, const SceneBuildOptions& options = {});

}  // namespace seflex::scene
