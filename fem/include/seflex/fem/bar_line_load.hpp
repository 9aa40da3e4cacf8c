#pragma once
// PLOAD1: distributed or concentrated loads on a CBAR/CBEAM, as work-equivalent grid loads.
//
// The load p(x) = P1 + (P2 - P1)(x - X1)/(X2 - X1) acts on x in [X1, X2] along the bar (x from
// offset end A, x = X L for SCALE = FR/FRPR); X1 = X2 is a concentrated force or moment P1 at X1.
// Direction: basic x, y, z (FX ... MZ) or element axes (FXE ... MZE). LEPR/FRPR: P per unit length
// of the bar projected on the plane normal to the load direction, p_bar = P |e_load x e_x| (basic
// directions; with an element-axis TYPE, LEPR/FRPR are LE/FR).
// Equivalent end loads (element axes) are the integrals of p against the bar's shape functions:
// linear for axial force and torque; cubic Hermite for transverse forces,
//   N1 = 1 - 3s^2 + 2s^3, N2 = L (s - 2s^2 + s^3), N3 = 3s^2 - 2s^3, N4 = L (s^3 - s^2), s = x / L,
// (v = N1 v_A + N2 th_zA + N3 v_B + N4 th_zB; w = N1 w_A - N2 th_yA + N3 w_B - N4 th_yB), and their
// slopes for distributed bending moments (work m_z v' and -m_y w'). These are the fixed-end forces of
// beam theory (e.g. a uniform load q: qL/2 and qL^2/12 at each end; Przemieniecki, 1968, sec. 5.8),
// exact at the grids for an Euler-Bernoulli bar. The end loads reach the grids through the offsets
// (force F at P = G + w: F and w x F + M at G).
#include <Eigen/Core>

#include "seflex/fem/element_bar.hpp"
#include "seflex/fem/model.hpp"

namespace seflex::fem {

/// Grid loads (12: force and moment at GA, then at GB; basic) of one PLOAD1 on the bar `e` of length
/// L (between its offset ends). Precondition: the load was checked (X1 <= X2 within the bar).
Eigen::Matrix<double, 12, 1> bar_line_load(const BarElement& e, const BarLineLoad& l);

/// The PLOAD1 of a finalized model as grid loads with the bar's grid indices. Throws InputError if
/// the element is not a CBAR/CBEAM, has pin flags (not supported with PLOAD1), or X2 exceeds its
/// length.
struct BarLineLoadAtGrids {
  std::uint32_t grid_A = 0, grid_B = 0;
  Eigen::Matrix<double, 12, 1> f = Eigen::Matrix<double, 12, 1>::Zero();
};
BarLineLoadAtGrids bar_line_load(const Model& model, const BarLineLoad& l);

}  // namespace seflex::fem
