#pragma once
// Internal: the shell element results (element_results.hpp) from the resultants at the centroid, shared
// by CQUAD4 (element_shell_quad4.cpp) and CTRIA3 (element_shell_tria3.cpp).
#include <Eigen/Core>

#include "seflex/fem/element_results.hpp"
#include "seflex/fem/section.hpp"

namespace seflex::fem::detail {

/// Nx Ny Nxy, Mx My Mxy, Qx Qy and the fibre stresses at Z1 and Z2 (14 components), from the membrane
/// resultants N (A eps + B kappa about the grid plane), the curvature kappa and the transverse shear
/// Q, all in the element's working axes; phi is the angle (about the normal) from those axes to
/// Nastran's element x axis. The section's strain eps = A^-1 (N - B kappa) gives M = B eps + D kappa
/// about the grid plane, moved to the material mid-surface (M - zoffs N); Nastran's moment is its
/// negative (a positive Mx stretches the bottom fibre).
Eigen::Matrix<double, 14, 1> shell_results(const ShellSection& s, const ShellFibres& f, const Eigen::Vector3d& N,
                                           const Eigen::Vector3d& kappa, const Eigen::Vector2d& Q, double phi);

}  // namespace seflex::fem::detail
