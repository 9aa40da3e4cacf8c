#pragma once
// Thermal loads of the CQUAD4 and CTRIA3 shells: a temperature rise dT uniform over the element and
// through its thickness (Nastran's element temperature from TEMP/TEMPD: the mean of its grids'
// temperatures; no TEMPP1 gradient).
//
// The section's thermal resultants dT [N_T; M_T] (section.hpp: int Qbar alpha dz, int Qbar alpha z dz,
// in element axes, about the grids' plane) give the free thermal deformation, the constant
// reference-surface strains and curvatures
//   [eps0; kappa] = [A B; B D]^-1 dT [N_T; M_T]   (classical lamination theory; Jones, Mechanics of
//                                                   Composite Materials, 2nd ed., sec. 4.5),
// i.e. in the element's mean-plane axes (x, y, z; origin at the centroid) the displacement field
//   u = eps_xx x + gamma_xy y / 2 + z theta_y,   v = gamma_xy x / 2 + eps_yy y - z theta_x,
//   w = -(k_xx x^2 + k_yy y^2 + k_xy x y) / 2,   theta_x = w,y,  theta_y = -w,x,  theta_z = 0,
// with no transverse shear and no drilling strain. Both elements represent it exactly (constant
// membrane strain and curvature patch tests; the MITC shear strains vanish at their tying points;
// the incompatible modes are not excited since int G dA = 0), so the consistent load
// f = int B^T [N_T; M_T] dT dA equals K u_free, the same construction as the bars' thermal loads
// (element_bar.hpp). A section without bending stiffness (membrane only) gets kappa = 0.
#include <Eigen/Core>

#include "seflex/fem/element_shell_quad4.hpp"
#include "seflex/fem/element_shell_tria3.hpp"

namespace seflex::fem {

/// Equivalent grid loads (24, basic, 6 per grid) of a uniform temperature rise dT (T - section tref)
/// of a CQUAD4. k6rot: PARAM K6ROT (the drilling terms vanish on the free deformation); mystran: the
/// element of PARAM QUAD4TYP MIN4T (quad4_stiffness).
Eigen::Matrix<double, 24, 1> quad4_thermal_load(const Quad4Element& e, double dT, double k6rot,
                                                const MystranPlate* mystran = nullptr);
/// The same for a CTRIA3 (18, basic).
Eigen::Matrix<double, 18, 1> tria3_thermal_load(const Tria3Element& e, double dT, double k6rot,
                                                const MystranPlate* mystran = nullptr);

/// Section strains (eps0 xx yy xy, kappa xx yy xy; element axes) of the free thermal deformation of
/// a section under dT (least-squares solution when the section has no bending stiffness).
Eigen::Matrix<double, 6, 1> shell_free_thermal_strains(const ShellSection& s, double dT);

}  // namespace seflex::fem
