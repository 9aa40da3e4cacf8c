#pragma once
// What the solvers deliver at output times, through an Observer: time, hinge angles and rates,
// every force element's torque and energy, lock states and latch times, energies, all node poses,
// and each body's frame pose and local elastic coordinates (so io/ can animate the full FE mesh:
// FE displacements in the body frame are U = recovery * xi).
#include <Eigen/Core>
#include <string>
#include <vector>

#include "seflex/mbd/data.hpp"
#include "seflex/mbd/model.hpp"
#include "seflex/mbd/state.hpp"

namespace seflex::mbd {

struct HingeSample {
  double phi = 0.0, phidot = 0.0, phiddot = 0.0;
  double drive_torque = 0.0;  ///< driven hinge: torque the drive applies; free hinge: residual (~0), 0 when
                              ///< the sample was evaluated without the residual (AssemblyOptions::energies_only)
};

struct ElementSample {
  double value = 0.0;                ///< spring/lock/damper torque [N m]; cable loop: net force T1 - T2 [N]
  double energy = 0.0;               ///< stored energy [J]
  std::vector<double> hinge_torques; ///< generalised force on each hinge it acts on [N m]
  bool latched = false;              ///< locks
  double t_latch = 0.0;              ///< locks, when latched
};

struct FlexibleBodySample {
  Pose frame;           ///< floating frame B in W
  Eigen::VectorXd xi;   ///< local elastic coordinates [q; eta] (superelement order)
  double kinetic = 0.0, elastic = 0.0;
  /// 6N, with FlexibleBodyOptions::interface_loads (else empty): per interface j, [force; moment about
  /// the interface node] in world axes, the load the body receives there from the rest of the
  /// mechanism = its own share of the assembled residual at the node (interface_load).
  Eigen::VectorXd interface_load;
};

struct RigidBodySample {
  Pose frame;  ///< body frame in W
  double kinetic = 0.0;
};

struct Energies {
  double kinetic = 0.0;
  double elastic = 0.0;   ///< strain energy of the flexible bodies
  double spring = 0.0;    ///< potential energy of the force elements
  double gravity = 0.0;   ///< -m g . p_cm summed over bodies
  double total() const { return kinetic + elastic + spring + gravity; }
};

struct Sample {
  double t = 0.0;
  double load_factor = 1.0;  ///< statics: the load factor of this load step
  long step = 0;
  bool event = false;        ///< a lock latched at this instant
  long newton_iterations = 0;///< time integration: Newton iterations of all accepted steps so far
  double step_size = 0.0;    ///< time integration: size of the last accepted step [s] (0 at the start)
  std::vector<Pose> nodes;
  std::vector<HingeSample> hinges;
  std::vector<ElementSample> elements;
  std::vector<FlexibleBodySample> flexible;
  std::vector<RigidBodySample> rigid;
  Energies energy;
};

/// Receives samples as the run goes (results are delivered before a failure is reported).
class Observer {
 public:
  virtual ~Observer() = default;
  virtual void on_sample(const Model& model, const Sample& sample) = 0;
  /// Called after every accepted step (e.g. for a progress bar).
  virtual void on_progress(double /*t*/, double /*t_end*/) {}
  /// Polled after every accepted step: true ends the run there (with a final sample), e.g. a
  /// stop rule of the driver ("S seconds after the last lock latched").
  virtual bool stop_requested() const { return false; }
};

/// The sample of one force element from its evaluation and (locks) its latch state (may be null).
ElementSample element_sample(const HingeForceResult& r, const LockState* lock);

/// Build a sample from `state` and `data` assembled at that state.
Sample make_sample(const Model& model, const State& state, const Data& data);
/// Same, into `out`, reusing its storage (no allocation once `out` has been filled for this model).
void make_sample(const Model& model, const State& state, const Data& data, Sample& out);

/// The load flexible body b receives from the rest of the mechanism at its interface nodes: its own
/// share of the residual at the nodes' translations and rotations, as assemble() forms it,
///   f = f_inertia + f_elastic + f_damping
/// (inertia with gravity as the uniform field -g, the velocity-quadratic terms and the elastic modes'
/// coupling; elastic force with the stress stiffening when the body has it), so that at a converged state
/// the loads of all bodies at a node balance the node's applied loads and force elements. `f` (6N): per
/// interface j, [force; moment about the node] in world axes (the moment is conjugate to the node's
/// spatial rotation increment, R <- exp(dpi) R). `data` must be assembled at the state with the residual,
/// or as an output sample with FlexibleBodyOptions::interface_loads. Allocates nothing once f is sized.
void interface_load(const Model& model, const Data& data, int body, Eigen::VectorXd& f);

/// Energies of `data` assembled at `state`.
Energies energies(const Model& model, const State& state, const Data& data);

}  // namespace seflex::mbd
