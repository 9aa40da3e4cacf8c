// CTRIA3: CST membrane + MITC3 (or DKT) plate + drilling penalty (see element_shell_tria3.hpp).
#include "seflex/fem/element_shell_tria3.hpp"
#include "seflex/fem/element_results.hpp"

#include <Eigen/LU>
#include <algorithm>

#include "model_lookup.hpp"
#include "shell_results.hpp"
#include "seflex/fem/element_membrane_drilling.hpp"
#include "seflex/fem/element_plate_dkt.hpp"
#include "seflex/fem/element_plate_min3.hpp"
#include "seflex/common/error.hpp"

namespace seflex::fem {
namespace {

using Matrix18 = NodeMatrix<3>;
using Row18 = Eigen::Matrix<double, 1, 18>;
constexpr int kU = 0, kV = 1, kW = 2, kRx = 3, kRy = 4, kRz = 5;
constexpr int kPlateDof[3] = {kW, kRx, kRy};  // the plate part's (w, theta_x, theta_y) among a grid's 6

struct Geometry {
  Eigen::Matrix3d R_BL;                // columns e1 e2 e3 in basic
  std::array<Eigen::Vector2d, 3> p;    // corners relative to the centroid, local axes
  double area = 0;
  Eigen::Vector3d b, c;                // dN_i/dx = b_i, dN_i/dy = c_i
};

Geometry geometry(const Tria3Element& e) {
  const auto& x = e.x;
  const Eigen::Vector3d n = (x[1] - x[0]).cross(x[2] - x[0]);
  SEFLEX_DEMAND(n.norm() > 0.0, "CTRIA3 with zero area");
  Geometry g;
  g.R_BL.col(0) = (x[1] - x[0]).normalized();
  g.R_BL.col(2) = n.normalized();
  g.R_BL.col(1) = g.R_BL.col(2).cross(g.R_BL.col(0));
  const Eigen::Vector3d cen = (x[0] + x[1] + x[2]) / 3.0;
  for (int i = 0; i < 3; ++i) g.p[i] = (g.R_BL.transpose() * (x[i] - cen)).head<2>();
  g.area = 0.5 * n.norm();
  for (int i = 0; i < 3; ++i) {
    const int j = (i + 1) % 3, k = (i + 2) % 3;
    g.b[i] = (g.p[j].y() - g.p[k].y()) / (2 * g.area);
    g.c[i] = (g.p[k].x() - g.p[j].x()) / (2 * g.area);
  }
  return g;
}

// MITC3 shear: gamma(x, y) = (a_x - b y, a_y + b x), tangential component at each edge midpoint
// tied to the edge's (w_j - w_i)/L + (beta_i + beta_j)/2 . t, beta = (theta_y, -theta_x); returns
// (a_x, a_y, b) from the dofs (3 x 18, element axes).
Eigen::Matrix<double, 3, 18> mitc3_shear_coefficients(const Geometry& g) {
  Eigen::Matrix3d G;
  Eigen::Matrix<double, 3, 18> R = Eigen::Matrix<double, 3, 18>::Zero();
  for (int k = 0; k < 3; ++k) {
    const int i = k, j = (k + 1) % 3;
    const Eigen::Vector2d d = g.p[j] - g.p[i];
    const double L = d.norm();
    const Eigen::Vector2d t = d / L;
    const Eigen::Vector2d mid = 0.5 * (g.p[i] + g.p[j]);
    G.row(k) << t.x(), t.y(), -mid.y() * t.x() + mid.x() * t.y();
    R(k, 6 * j + kW) += 1.0 / L;
    R(k, 6 * i + kW) -= 1.0 / L;
    for (int n : {i, j}) {
      R(k, 6 * n + kRy) += 0.5 * t.x();
      R(k, 6 * n + kRx) -= 0.5 * t.y();
    }
  }
  return G.inverse() * R;
}

}  // namespace

NodeMatrix<3> tria3_stiffness(const Tria3Element& e, double k6rot, const MystranPlate* mystran) {
  const Geometry g = geometry(e);
  const ShellSection& sec = e.section;
  const double A = g.area;
  // No transverse shear flexibility (PSHELL MID3 blank, plies rigid in transverse shear): the DKT's
  // Kirchhoff bending, which cannot lock, instead of MITC3 with the Kirchhoff penalty, which does.
  const bool kirchhoff = !mystran && !sec.shear_flexible;
  Matrix18 K = Matrix18::Zero();

  // Membrane (CST): constant strains. Bending curvatures (mean over the element, which is all the
  // coupling with the constant membrane strain needs): MITC3's and MIN3's linear rotations, or the
  // DKT's.
  Eigen::Matrix<double, 3, 18> Bm = Eigen::Matrix<double, 3, 18>::Zero(), Bb = Eigen::Matrix<double, 3, 18>::Zero();
  for (int i = 0; i < 3; ++i) {
    Bm(0, 6 * i + kU) = g.b[i];
    Bm(1, 6 * i + kV) = g.c[i];
    Bm(2, 6 * i + kU) = g.c[i];
    Bm(2, 6 * i + kV) = g.b[i];
    Bb(0, 6 * i + kRy) = g.b[i];
    Bb(1, 6 * i + kRx) = -g.c[i];
    Bb(2, 6 * i + kRy) = g.c[i];
    Bb(2, 6 * i + kRx) = -g.b[i];
  }
  auto add_plate = [&K](const PlateMatrix3& Kp) {
    for (int i = 0; i < 3; ++i)
      for (int j = 0; j < 3; ++j)
        for (int a = 0; a < 3; ++a)
          for (int b = 0; b < 3; ++b) K(6 * i + kPlateDof[a], 6 * j + kPlateDof[b]) += Kp(3 * i + a, 3 * j + b);
  };
  if (kirchhoff) {
    const Eigen::Matrix<double, 3, 9> C = dkt_curvature(g.p).mean();
    Bb.setZero();
    for (int i = 0; i < 3; ++i)
      for (int a = 0; a < 3; ++a) Bb.col(6 * i + kPlateDof[a]) = C.col(3 * i + a);
    add_plate(dkt_stiffness(g.p, sec.D));
  } else if (mystran) {  // MYSTRAN's MIN3 bending + transverse shear instead of MITC3's
    add_plate(min3_stiffness(g.p, sec.D, sec.S, mystran->cb_tria));
  } else {
    K.noalias() += A * Bb.transpose() * sec.D * Bb;
  }
  const bool allman = e.drilling && sec.has_membrane;  // CTRIAR (element_membrane_drilling.hpp)
  if (allman) {
    // Allman's membrane with its drilling rotations, and its strain (linear) times B with the mean
    // curvature: at the edge midpoints, which integrate it exactly
    constexpr int kMembraneDof[3] = {kU, kV, kRz};
    const Eigen::Matrix<double, 9, 9> Km = drilling_membrane_stiffness<3>(g.p, sec.A, sec.drill_Gt);
    Eigen::Matrix<double, 3, 18> Bmean = Eigen::Matrix<double, 3, 18>::Zero();  // A x the mean strain
    for (const auto& q : drilling_membrane_points(g.p))
      for (int i = 0; i < 3; ++i)
        for (int a = 0; a < 3; ++a) Bmean.col(6 * i + kMembraneDof[a]) += q.weight * q.B.col(3 * i + a);
    for (int i = 0; i < 3; ++i)
      for (int j = 0; j < 3; ++j)
        for (int a = 0; a < 3; ++a)
          for (int b = 0; b < 3; ++b) K(6 * i + kMembraneDof[a], 6 * j + kMembraneDof[b]) += Km(3 * i + a, 3 * j + b);
    if (!sec.B.isZero(0.0)) {
      const Eigen::Matrix<double, 18, 18> Kmb = Bmean.transpose() * sec.B * Bb;
      K.noalias() += Kmb + Kmb.transpose();
    }
  } else {
    K.noalias() += A * Bm.transpose() * sec.A * Bm;
    if (!sec.B.isZero(0.0)) {  // membrane-bending coupling
      const Eigen::Matrix<double, 18, 18> Kmb = A * Bm.transpose() * sec.B * Bb;
      K.noalias() += Kmb + Kmb.transpose();
    }
  }

  if (!kirchhoff && !mystran) {
    std::array<Eigen::Vector2d, 3> mid;
    for (int k = 0; k < 3; ++k) mid[k] = 0.5 * (g.p[k] + g.p[(k + 1) % 3]);
    const Eigen::Matrix<double, 3, 18> C = mitc3_shear_coefficients(g);
    // Shear stabilisation of Lyly, Stenberg & Vihinen (ShellSection::stabilised_shear_stiffness),
    // h the longest edge; it removes the residual shear locking of the linear triangle in thin plates.
    double h2 = 0.0;
    for (int k = 0; k < 3; ++k) h2 = std::max(h2, (g.p[(k + 1) % 3] - g.p[k]).squaredNorm());
    const Eigen::Matrix2d Ss = sec.stabilised_shear(h2);
    for (int q = 0; q < 3; ++q) {  // edge-midpoint rule, exact for quadratics
      const Eigen::Vector2d& x = mid[q];
      Eigen::Matrix<double, 2, 3> P;
      P << 1, 0, -x.y(), 0, 1, x.x();
      const Eigen::Matrix<double, 2, 18> Bs = P * C;
      K.noalias() += (A / 3.0) * Bs.transpose() * Ss * Bs;
    }
  }
  // Drilling: the K6ROT penalty on (theta_z - omega)^2 at the edge midpoints and the Hughes-Brezzi
  // coupling at the centroid (see element_shell_quad4.hpp).
  const double kd = sec.has_membrane && !allman ? k6rot * 1e-6 * sec.drill_Gt : 0.0;
  const double omega_row_scale = 0.5;
  if (kd > 0.0) {
    for (int q = 0; q < 3; ++q) {
      // Linear shape functions at the midpoint of edge (q, q+1): 1/2, 1/2, 0.
      Row18 d = Row18::Zero();
      d(6 * q + kRz) = 0.5;
      d(6 * ((q + 1) % 3) + kRz) = 0.5;
      for (int i = 0; i < 3; ++i) {
        d(6 * i + kV) -= omega_row_scale * g.b[i];
        d(6 * i + kU) += omega_row_scale * g.c[i];
      }
      K.noalias() += (kd * A / 3.0) * d.transpose() * d;
    }
  }
  if (sec.has_membrane && !allman) {
    Row18 d = Row18::Zero();
    for (int i = 0; i < 3; ++i) {
      d(6 * i + kRz) = 1.0 / 3.0;
      d(6 * i + kV) = -omega_row_scale * g.b[i];
      d(6 * i + kU) = omega_row_scale * g.c[i];
    }
    K.noalias() += (A * sec.drill_Gt) * d.transpose() * d;
  }
  K = 0.5 * (K + K.transpose()).eval();
  rotate_local_to_basic<3>(g.R_BL, K);
  return K;
}

Eigen::Matrix<double, 18, 1> tria3_mystran_pressure_load(const Tria3Element& e, double q) {
  const Geometry g = geometry(e);
  return plate_load_to_basic<3>(g.R_BL, min3_pressure_load(g.p, q));
}

NodeMatrix<3> tria3_mass(const Tria3Element& e, MassKind kind) {
  const double m = e.section.mass_per_area() * 0.5 * (e.x[1] - e.x[0]).cross(e.x[2] - e.x[0]).norm();
  Matrix18 M = Matrix18::Zero();
  for (int i = 0; i < 3; ++i)
    for (int j = 0; j < 3; ++j) {
      const double mij = kind == MassKind::Lumped ? (i == j ? m / 3.0 : 0.0) : (i == j ? m / 6.0 : m / 12.0);
      for (int k = 0; k < 3; ++k) M(6 * i + k, 6 * j + k) = mij;
    }
  return M;
}

Tria3Element make_tria3_element(const Model& model, const Shell& shell, const ShellSection* section) {
  Tria3Element e;
  for (int k = 0; k < 3; ++k) {
    const std::string field = std::to_string(k + 4) + " (G" + std::to_string(k + 1) + ")";
    e.x[k] = model.grids[detail::grid_index(model, shell.g[k], shell.ref, shell_card(shell), shell.id, field)].x_basic;
    for (int j = 0; j < k; ++j)
      if (shell.g[j] == shell.g[k])
        detail::fail(model, shell.ref, shell_card(shell), shell.id, field, "repeats GRID " + std::to_string(shell.g[k]));
  }
  const Eigen::Vector3d a = e.x[1] - e.x[0], b = e.x[2] - e.x[0];
  if (!(a.cross(b).norm() > 1e-12 * a.norm() * b.norm()))
    detail::fail(model, shell.ref, shell_card(shell), shell.id, "4-6 (G1-G3)", "corners are collinear (zero area)");
  const Eigen::Vector3d e1 = a.normalized(), e3 = a.cross(b).normalized();
  const double theta = detail::material_angle(model, shell, e1, e3.cross(e1), (e.x[0] + e.x[1] + e.x[2]) / 3.0);
  e.section = (section ? *section : make_shell_section(model, shell)).in_element_axes(theta).offset(shell.zoffs);
  e.drilling = shell.drilling;
  return e;
}


Eigen::Matrix<double, 14, 1> tria3_results(const Tria3Element& e, const ShellFibres& f, const Eigen::Matrix<double, 18, 1>& u) {
  const Geometry g = geometry(e);
  const ShellSection& sec = e.section;
  Eigen::Matrix<double, 18, 1> uL;  // element axes
  Eigen::Matrix<double, 9, 1> q;     // plate dofs (w, theta_x, theta_y) per corner
  for (int i = 0; i < 6; ++i) uL.segment<3>(3 * i) = g.R_BL.transpose() * u.segment<3>(3 * i);
  for (int i = 0; i < 3; ++i) q.segment<3>(3 * i) << uL(6 * i + kW), uL(6 * i + kRx), uL(6 * i + kRy);
  Eigen::Vector3d kappa = Eigen::Vector3d::Zero();
  Eigen::Vector2d Q = Eigen::Vector2d::Zero();
  if (!sec.shear_flexible) {  // DKT (its curvature at the centroid); no transverse shear, as Nastran prints
    kappa = dkt_curvature(g.p).mean() * q;
  } else {  // linear rotations: constant curvature; MITC3's assumed shear at the centroid
    for (int i = 0; i < 3; ++i)
      kappa += Eigen::Vector3d(g.b[i] * q(3 * i + 2), -g.c[i] * q(3 * i + 1), g.c[i] * q(3 * i + 2) - g.b[i] * q(3 * i + 1));
    double h2 = 0.0;
    for (int k = 0; k < 3; ++k) h2 = std::max(h2, (g.p[(k + 1) % 3] - g.p[k]).squaredNorm());
    Q = sec.stabilised_shear(h2) * (mitc3_shear_coefficients(g) * uL).head<2>();
  }
  return detail::shell_results(sec, f, tria3_membrane_resultants(e, u), kappa, Q, 0.0);
}

}  // namespace seflex::fem
