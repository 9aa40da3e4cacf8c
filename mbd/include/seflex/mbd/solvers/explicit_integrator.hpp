#pragma once
// The explicit foil of the implicit integrator: classical fourth-order Runge-Kutta on the Lie
// group (Runge-Kutta-Munthe-Kaas, Iserles et al. 2000, section 4) with a constant step. Each stage
// evaluates the accelerations of the same model the implicit solver integrates, vdot = -M^-1 r(x,
// v, vdot = 0, t) with the assembled AIC mass matrix M = dr/dvdot (the residual is linear in vdot).
// Configuration increments u are taken from the step's start, x = x_0 (+) u (Free nodes: R = exp(u~)
// R_0), and u' = dexp_u^-1 v = J_l(u)^-1 omega for the rotations, u' = v otherwise:
//   k_i = (u'_i, vdot_i) at (x_0 (+) h c_i k_{i-1}, v_0 + h c_i vdot_{i-1}),  c = (0, 1/2, 1/2, 1)
//   u = h/6 (u'_1 + 2 u'_2 + 2 u'_3 + u'_4),  v_1 = v_0 + h/6 (vdot_1 + 2 vdot_2 + 2 vdot_3 + vdot_4)
// Lock crossings are located (the step is redone to end on the crossing, linear interpolation of
// the angle). Explicit methods are only conditionally stable: a run whose state becomes non-finite
// or moves a dof by more than pi (rad, or length scale) in one step is stopped with a
// ConvergenceError that says so, after the last good state has been delivered.
#include "seflex/mbd/data.hpp"
#include "seflex/mbd/solvers/integrator.hpp"
#include "seflex/mbd/output.hpp"

namespace seflex::mbd {

/// Integrate from state.t to settings.t_end with the constant step settings.h_initial (shortened
/// only to land on output times and lock crossings). Uses t_end, h_initial, h_min (smallest step
/// of an event retry), output_interval and event_tol of `settings`; RunStats::factorizations counts
/// the mass-matrix factorisations (4 per step), newton_iterations stays 0.
RunStats simulate_rk4(const Model& model, State& state, Data& data, const IntegratorSettings& settings,
                      Observer* observer = nullptr);

}  // namespace seflex::mbd
