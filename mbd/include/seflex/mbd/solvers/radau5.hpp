#pragma once
// Radau IIA of order 5 (three stages, L-stable, stiffly accurate: Hairer and Wanner, Solving ODEs II,
// section IV.8, their RADAU5) for the AIC equations of motion r(x, v, vdot, t) = 0, in
// Runge-Kutta-Munthe-Kaas form as the explicit foil (explicit_integrator.hpp): configuration stages
// x_i = x_0 (+) U_i with U_i in the Lie algebra of each Free node's rotation (R_i = exp(U_i~) R_0)
// and in R^n for positions, hinge angles and modes. The collocation polynomial of the increments
// through (0, 0) and (c_j, U_j) gives the stage rates U'_i = (1/h) sum_j (A^-1)_ij U_j, the stage
// velocities V_i = dexp_{U_i} U'_i (J_l(U_i) U'_i on rotations), and the accelerations
// A_i = (1/h) sum_j (A^-1)_ij (V_j - v_0), so the 3n stage unknowns are the U_i alone (the velocities
// of the first-order form are eliminated) and the stage equations are the residual itself,
//   r(x_0 (+) U_i, V_i, A_i, t_0 + c_i h) = 0,   i = 1, 2, 3,   x_1 = x_0 (+) U_3, v_1 = V_3.
// Simplified Newton with the Jacobian K, C, M of the last evaluation (at the predicted second stage
// of the step that needed it) has the
// matrix I (x) K + (A^-1/h) (x) C + (A^-1/h)^2 (x) M; A^-1 = T Lambda T^-1 transforms it into one real
// system K + (gamma/h) C + (gamma/h)^2 M and one complex system with mu = (alpha + i beta)/h, each
// factorised with the modal coordinates condensed (condensed_lu.hpp). As RADAU5: the Jacobian is kept
// while Newton contracts fast (IntegratorSettings::Radau), the step is predicted from Newton's rate
// when it would not converge, the error estimate is the embedded third-order one filtered by
// (gamma/h - J)^-1 (a second filtered estimate at the first step and after a rejection), and the
// step size follows Gustafsson's predictive controller. Samples at output times and lock crossings
// come from the collocation polynomial (cubic), so steps do not land on output times; a step that
// crosses a lock is redone to end on the crossing (to `event_tol`) and the method restarts there.
#include "seflex/mbd/data.hpp"
#include "seflex/mbd/output.hpp"
#include "seflex/mbd/solvers/integrator.hpp"

namespace seflex::mbd {

/// Integrate from state.t to settings.t_end with Radau IIA-5. Uses t_end, h_initial (the first
/// step; the constant step when !adaptive), h_min, h_max, adaptive, tol_position and tol_angle
/// (absolute local errors, weighted as IntegratorSettings says; configuration and velocity errors,
/// the latter times the step), output_interval, event_tol, inertia_velocity_tangent and `radau`.
/// Samples, failures (ConvergenceError after the last accepted state was delivered) and the
/// observer's stop request as `simulate`.
RunStats simulate_radau5(const Model& model, State& state, Data& data, const IntegratorSettings& settings,
                         Observer* observer = nullptr);

}  // namespace seflex::mbd
