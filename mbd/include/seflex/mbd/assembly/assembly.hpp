#pragma once
// Kinematics and assembly of the equations of motion, like finite elements:
//   r(x, v, vdot, t) = sum_bodies J^T (f_inertia + f_damping + f_elastic) - f_loads - tau_elements
// with J the Jacobian of each node's pose w.r.t. the dofs (Model::node_dofs). Matrices on the
// fixed sparse pattern of Data: K = dr/dx (configuration; spatial rotation increments; includes the
// geometric terms of the node tree, e.g. the hinge term of formulation 4.3), C = dr/dv, M = dr/dvdot.
// Gravity acts as a uniform acceleration field: every body sees accelerations minus g.
#include "seflex/mbd/data.hpp"
#include "seflex/mbd/model.hpp"
#include "seflex/mbd/state.hpp"

namespace seflex::mbd {

struct AssemblyOptions {
  bool matrices = true;      ///< also K, C, M
  bool dynamics = true;      ///< false: statics (velocities and accelerations taken as zero)
  double load_factor = 1.0;  ///< multiplies node loads and gravity
  /// With matrices: the flexible bodies' inertia also contributes its velocity derivative
  /// (gyroscopic/Coriolis) to C; false leaves it out (the integrator's cheaper iteration matrix).
  bool inertia_velocity_tangent = true;
  /// Only what an output sample reads (mbd::make_sample): node and hinge kinematics, the flexible
  /// bodies' frames, xi and energies, the rigid bodies' energies, the force elements. No residual,
  /// scale or matrices, and the hinges' joint torques are left at zero (the loads and the tree pass
  /// that sum them are skipped). Needs matrices = false.
  bool energies_only = false;
  /// With matrices: the coefficients of the iteration matrix the caller will combine. The flexible
  /// bodies then add their share of it in one pass (Data::S_flex: one matrix mapped per body instead
  /// of K, C, M and the convective term apart) and leave K, C and M to the other elements;
  /// combine_matrices must be called with the same coefficients. Null: K, C and M apart.
  const IterationMatrix* iteration = nullptr;
};

/// Poses, Jacobians, twists and accelerations of all nodes, and hinge quantities, at `state`
/// (time state.t; driven hinges from their drives). Velocities/accelerations zero if !dynamics.
void update_kinematics(const Model& model, const State& state, Data& data, bool dynamics);

/// Evaluate everything at `state`; fills Data::residual, Data::scale and (if requested) K, C, M,
/// per-body results and force-element results. Throws ConvergenceError if a floating frame
/// cannot be recovered.
void assemble(const Model& model, const State& state, Data& data, const AssemblyOptions& options);

/// Copy the derived poses (all nodes) and the recovered frames from `data` into `state`.
void store_derived(const Model& model, const Data& data, State& state);

/// Assemble the sparse matrix cK K + cC C + cM M on the pattern. `rotation_jacobians`, if given,
/// right-multiplies the K columns of each Free node's rotation dofs by its 3x3 matrix (Lie-group
/// tangent operator), in the order of Model::rotation_dof_starts. After an assembly with
/// AssemblyOptions::iteration, the coefficients must be those (the flexible bodies' share, Data::S_flex,
/// is added as it is).
void combine_matrices(const Model& model, Data& data, double cK, double cC, double cM,
                      const std::vector<Eigen::Matrix3d>* rotation_jacobians, Eigen::SparseMatrix<double>& S);

}  // namespace seflex::mbd
