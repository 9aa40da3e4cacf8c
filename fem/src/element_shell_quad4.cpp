// CQUAD4: QM6 membrane + MITC4 plate + drilling penalty on the mean plane, with rigid-link warping
// correction (see element_shell_quad4.hpp for the formulation and references).
#include "seflex/fem/element_shell_quad4.hpp"
#include "seflex/fem/element_results.hpp"

#include <Eigen/LU>
#include <algorithm>
#include <cmath>

#include "model_lookup.hpp"
#include "shell_results.hpp"
#include "seflex/fem/element_membrane_drilling.hpp"
#include "seflex/fem/element_plate_min4t.hpp"
#include "seflex/common/error.hpp"

namespace seflex::fem {
namespace {

using Matrix24 = NodeMatrix<4>;

constexpr double kXi[4] = {-1, 1, 1, -1};
constexpr double kEta[4] = {-1, -1, 1, 1};
constexpr int kU = 0, kV = 1, kW = 2, kRx = 3, kRy = 4, kRz = 5;

// Mean-plane frame (columns e1 e2 e3 in basic), projected corner coordinates and corner heights.
struct Geometry {
  Eigen::Matrix3d R_BL;
  std::array<Eigen::Vector2d, 4> p;
  std::array<double, 4> h;
};

Geometry geometry(const Quad4Element& e) {
  const auto& x = e.x;
  const Eigen::Vector3d c = 0.25 * (x[0] + x[1] + x[2] + x[3]);
  const Eigen::Vector3d n = (x[2] - x[0]).cross(x[3] - x[1]);
  SEFLEX_DEMAND(n.norm() > 0.0, "CQUAD4 with zero area");
  const Eigen::Vector3d e3 = n.normalized();
  const Eigen::Vector3d a = (x[1] - x[0]) - (x[1] - x[0]).dot(e3) * e3;
  SEFLEX_DEMAND(a.norm() > 0.0, "CQUAD4 with a degenerate edge");
  const Eigen::Vector3d e1 = a.normalized();
  Geometry g;
  g.R_BL.col(0) = e1;
  g.R_BL.col(1) = e3.cross(e1);
  g.R_BL.col(2) = e3;
  for (int i = 0; i < 4; ++i) {
    const Eigen::Vector3d r = g.R_BL.transpose() * (x[i] - c);
    g.p[i] = r.head<2>();
    g.h[i] = r.z();
  }
  return g;
}

// Shape functions and their natural derivatives at (xi, eta).
struct Shape {
  Eigen::Vector4d N, dxi, deta;
};
Shape shape(double xi, double eta) {
  Shape s;
  for (int i = 0; i < 4; ++i) {
    s.N[i] = 0.25 * (1 + xi * kXi[i]) * (1 + eta * kEta[i]);
    s.dxi[i] = 0.25 * kXi[i] * (1 + eta * kEta[i]);
    s.deta[i] = 0.25 * kEta[i] * (1 + xi * kXi[i]);
  }
  return s;
}

// J = [x_xi y_xi; x_eta y_eta]
Eigen::Matrix2d jacobian(const Geometry& g, const Shape& s) {
  Eigen::Matrix2d J = Eigen::Matrix2d::Zero();
  for (int i = 0; i < 4; ++i) {
    J(0, 0) += s.dxi[i] * g.p[i].x();
    J(0, 1) += s.dxi[i] * g.p[i].y();
    J(1, 0) += s.deta[i] * g.p[i].x();
    J(1, 1) += s.deta[i] * g.p[i].y();
  }
  return J;
}

// The flat element's stiffness splits into two 12 x 12 parts, coupled only by the section's B:
// membrane + drilling on (u, v, theta_z) and plate on (w, theta_x, theta_y) of each corner (index
// 3 i + k below).
using Row12 = Eigen::Matrix<double, 1, 12>;
using Matrix12 = Eigen::Matrix<double, 12, 12>;
constexpr int kMembraneDof[3] = {kU, kV, kRz};
constexpr int kPlateDof[3] = {kW, kRx, kRy};
constexpr int pW = 0, pRx = 1, pRy = 2;  // plate part
constexpr int mU = 0, mV = 1, mRz = 2;   // membrane part

// Covariant transverse shear strain along xi (dir = 0) or eta (dir = 1) at (xi, eta), on the plate
// dofs: gamma_dir = dw/d(dir) + beta . g_dir, beta = (theta_y, -theta_x).
Row12 covariant_shear(const Geometry& g, double xi, double eta, int dir) {
  const Shape s = shape(xi, eta);
  const Eigen::Matrix2d J = jacobian(g, s);
  const Eigen::Vector4d& dN = dir == 0 ? s.dxi : s.deta;
  const double gx = J(dir, 0), gy = J(dir, 1);
  Row12 r = Row12::Zero();
  for (int i = 0; i < 4; ++i) {
    r(3 * i + pW) = dN[i];
    r(3 * i + pRy) = s.N[i] * gx;
    r(3 * i + pRx) = -s.N[i] * gy;
  }
  return r;
}

// Drilling row theta_z - (v,x - u,y)/2 on the membrane dofs, for shape values N and Cartesian
// derivatives dN (rows d/dx, d/dy).
Row12 drilling_row(const Eigen::Vector4d& N, const Eigen::Matrix<double, 2, 4>& dN) {
  Row12 d = Row12::Zero();
  for (int i = 0; i < 4; ++i) {
    d(3 * i + mRz) = N[i];
    d(3 * i + mV) = -0.5 * dN(0, i);
    d(3 * i + mU) = 0.5 * dN(1, i);
  }
  return d;
}

const double kGauss = 1.0 / std::sqrt(3.0);

// Cartesian shape derivatives (rows d/dx, d/dy) at (xi, eta).
Eigen::Matrix<double, 2, 4> cartesian_derivatives(const Geometry& g, const Shape& s) {
  Eigen::Matrix<double, 2, 4> dN;
  dN.row(0) = s.dxi.transpose();
  dN.row(1) = s.deta.transpose();
  return jacobian(g, s).inverse() * dN;
}

// Bending: kappa = (theta_y,x, -theta_x,y, theta_y,y - theta_x,x).
Eigen::Matrix<double, 3, 12> curvature_B(const Eigen::Matrix<double, 2, 4>& dN) {
  Eigen::Matrix<double, 3, 12> Bb = Eigen::Matrix<double, 3, 12>::Zero();
  for (int i = 0; i < 4; ++i) {
    Bb(0, 3 * i + pRy) = dN(0, i);
    Bb(1, 3 * i + pRx) = -dN(1, i);
    Bb(2, 3 * i + pRy) = dN(1, i);
    Bb(2, 3 * i + pRx) = -dN(0, i);
  }
  return Bb;
}

}  // namespace

NodeMatrix<4> quad4_stiffness(const Quad4Element& e, double k6rot, const MystranPlate* mystran) {
  const Geometry g = geometry(e);
  const ShellSection& sec = e.section;
  const Eigen::Matrix3d& Am = sec.A;
  const Eigen::Matrix3d& Db = sec.D;
  const Eigen::Matrix3d& Bc = sec.B;  // membrane-bending coupling
  const bool coupled = !Bc.isZero(0.0);
  // Shear stabilisation (Lyly, Stenberg & Vihinen 1993), h the longest edge (ShellSection).
  double h2 = 0.0;
  for (int k = 0; k < 4; ++k) h2 = std::max(h2, (g.p[(k + 1) % 4] - g.p[k]).squaredNorm());
  const Eigen::Matrix2d Ss = sec.stabilised_shear(h2);
  const double kd = sec.has_membrane ? k6rot * 1e-6 * sec.drill_Gt : 0.0;

  // MITC4 tying points: gamma_xi at A (0,-1), C (0,1); gamma_eta at D (-1,0), B (1,0).
  const Row12 gA = covariant_shear(g, 0, -1, 0), gC = covariant_shear(g, 0, 1, 0);
  const Row12 gD = covariant_shear(g, -1, 0, 1), gB = covariant_shear(g, 1, 0, 1);

  const Shape s0 = shape(0, 0);
  const Eigen::Matrix2d J0 = jacobian(g, s0);
  const Eigen::Matrix2d J0inv = J0.inverse();
  const double det0 = J0.determinant();

  Matrix12 Km = Matrix12::Zero(), Kp = Matrix12::Zero(), Kmp = Matrix12::Zero();
  Eigen::Matrix<double, 12, 4> Kua = Eigen::Matrix<double, 12, 4>::Zero(), Kpa = Eigen::Matrix<double, 12, 4>::Zero();
  Eigen::Matrix4d Kaa = Eigen::Matrix4d::Zero();
  for (double xi : {-kGauss, kGauss})
    for (double eta : {-kGauss, kGauss}) {
      const Shape s = shape(xi, eta);
      const Eigen::Matrix2d J = jacobian(g, s);
      const double det = J.determinant();
      SEFLEX_DEMAND(det > 0.0, "CQUAD4 with a non-positive Jacobian (non-convex or misordered corners)");
      const Eigen::Matrix2d Jinv = J.inverse();
      const Eigen::Matrix<double, 2, 4> dN = cartesian_derivatives(g, s);
      const double w = det;  // Gauss weights are 1

      // Membrane, compatible part and QM6 incompatible modes (1 - xi^2, 1 - eta^2 per direction).
      Eigen::Matrix<double, 3, 12> Bm = Eigen::Matrix<double, 3, 12>::Zero();
      for (int i = 0; i < 4; ++i) {
        Bm(0, 3 * i + mU) = dN(0, i);
        Bm(1, 3 * i + mV) = dN(1, i);
        Bm(2, 3 * i + mU) = dN(1, i);
        Bm(2, 3 * i + mV) = dN(0, i);
      }
      const Eigen::Vector2d P1 = (det0 / det) * (J0inv * Eigen::Vector2d(-2 * xi, 0));
      const Eigen::Vector2d P2 = (det0 / det) * (J0inv * Eigen::Vector2d(0, -2 * eta));
      Eigen::Matrix<double, 3, 4> Gm;
      Gm << P1.x(), P2.x(), 0, 0, 0, 0, P1.y(), P2.y(), P1.y(), P2.y(), P1.x(), P2.x();
      const Eigen::Matrix<double, 12, 3> BtA = w * Bm.transpose() * Am;
      Km.noalias() += BtA.lazyProduct(Bm);
      Kua.noalias() += BtA.lazyProduct(Gm);
      Kaa.noalias() += (w * Gm.transpose() * Am).lazyProduct(Gm);

      const Eigen::Matrix<double, 3, 12> Bb = curvature_B(dN);
      if (!mystran) {
        const Eigen::Matrix<double, 12, 3> BtD = w * Bb.transpose() * Db;
        Kp.noalias() += BtD.lazyProduct(Bb);
      }
      if (coupled) {  // N = B kappa, M = B^T-side: membrane (incl. incompatible modes) x bending
        const Eigen::Matrix<double, 3, 12> BcBb = w * Bc * Bb;
        Kmp.noalias() += Bm.transpose().lazyProduct(BcBb);
        Kpa.noalias() += BcBb.transpose().lazyProduct(Gm);
      }

      // MITC4 transverse shear: assumed covariant strains, then Cartesian (gxz, gyz) = J^-1 (g_xi, g_eta).
      if (!mystran) {
        Eigen::Matrix<double, 2, 12> Gcov;
        Gcov.row(0) = 0.5 * (1 - eta) * gA + 0.5 * (1 + eta) * gC;
        Gcov.row(1) = 0.5 * (1 - xi) * gD + 0.5 * (1 + xi) * gB;
        const Eigen::Matrix<double, 2, 12> Bs = Jinv * Gcov;
        Kp.noalias() += (w * Bs.transpose() * Ss).lazyProduct(Bs);
      }

      // Drilling penalty on theta_z - omega, omega = (v,x - u,y)/2 of the membrane field including
      // its incompatible modes (so that the exact in-plane bending of QM6 is not penalised).
      if (kd > 0.0) {
        const Row12 d = drilling_row(s.N, dN);
        const Eigen::RowVector4d da(0.5 * P1.y(), 0.5 * P2.y(), -0.5 * P1.x(), -0.5 * P2.x());
        Km.noalias() += ((w * kd) * d.transpose()).lazyProduct(d);
        Kua.noalias() += ((w * kd) * d.transpose()).lazyProduct(da);
        Kaa.noalias() += ((w * kd) * da.transpose()).lazyProduct(da);
      }
    }
  // MYSTRAN's MIN4T bending + transverse shear instead of MITC4's (the coupling B above is kept).
  if (mystran) Kp.noalias() += min4t_stiffness(g.p, Db, sec.S, mystran->cb_quad);
  // Drilling coupling at the centre (Hughes & Brezzi): G t A (theta_z - omega)^2 at xi = eta = 0,
  // where the incompatible modes do not rotate.
  if (sec.has_membrane) {
    Eigen::Matrix<double, 2, 4> dN;
    dN.row(0) = s0.dxi.transpose();
    dN.row(1) = s0.deta.transpose();
    const Row12 d = drilling_row(s0.N, J0inv * dN);
    Km.noalias() += ((4.0 * det0 * sec.drill_Gt) * d.transpose()).lazyProduct(d);
  }
  if (e.drilling && sec.has_membrane) {
    // CQUADR: the Allman-type membrane (its drilling rotations in the displacement field and the
    // Hughes-Brezzi term at the centre) replaces QM6 and the drilling terms; the coupling B with the
    // MITC4 curvatures over its own 3 x 3 points.
    Km = drilling_membrane_stiffness<4>(g.p, Am, sec.drill_Gt);
    Kmp.setZero();
    if (coupled)
      for (const auto& q : drilling_membrane_points(g.p))
        Kmp.noalias() += q.weight * q.B.transpose() * Bc * curvature_B(cartesian_derivatives(g, shape(q.xi.x(), q.xi.y())));
  } else if (Kaa.trace() > 0.0) {  // static condensation of the incompatible modes (coupled to the plate dofs through B)
    const Eigen::Matrix4d Kaa_inv = Kaa.inverse();
    Km.noalias() -= (Kua * Kaa_inv).lazyProduct(Kua.transpose());
    if (coupled) {
      Kmp.noalias() -= (Kua * Kaa_inv).lazyProduct(Kpa.transpose());
      Kp.noalias() -= (Kpa * Kaa_inv).lazyProduct(Kpa.transpose());
    }
  }

  Matrix24 K = Matrix24::Zero();
  for (int i = 0; i < 4; ++i)
    for (int j = 0; j < 4; ++j)
      for (int a = 0; a < 3; ++a)
        for (int b = 0; b < 3; ++b) {
          K(6 * i + kMembraneDof[a], 6 * j + kMembraneDof[b]) = 0.5 * (Km(3 * i + a, 3 * j + b) + Km(3 * j + b, 3 * i + a));
          K(6 * i + kPlateDof[a], 6 * j + kPlateDof[b]) = 0.5 * (Kp(3 * i + a, 3 * j + b) + Kp(3 * j + b, 3 * i + a));
          K(6 * i + kMembraneDof[a], 6 * j + kPlateDof[b]) = Kmp(3 * i + a, 3 * j + b);
          K(6 * j + kPlateDof[b], 6 * i + kMembraneDof[a]) = Kmp(3 * i + a, 3 * j + b);
        }

  // Warping: the flat element sits on the projections p_i = x_i - h_i e3 (local offset (0, 0, -h_i)).
  std::array<Eigen::Vector3d, 4> d;
  for (int i = 0; i < 4; ++i) d[i] = Eigen::Vector3d(0, 0, -g.h[i]);
  apply_node_offsets<4>(d, K);
  rotate_local_to_basic<4>(g.R_BL, K);
  return K;
}

Eigen::Matrix<double, 24, 1> quad4_mystran_pressure_load(const Quad4Element& e, double q, const MystranPlate& mystran) {
  const Geometry g = geometry(e);
  return plate_load_to_basic<4>(g.R_BL, min4t_pressure_load(g.p, e.section.D, e.section.S, mystran.cb_quad, q));
}

std::array<double, 4> quad4_lumped_masses(const Quad4Element& e) {
  const Geometry g = geometry(e);
  const double mpa = e.section.mass_per_area();
  std::array<double, 4> m{};
  for (double xi : {-kGauss, kGauss})
    for (double eta : {-kGauss, kGauss}) {
      const Shape s = shape(xi, eta);
      const double det = jacobian(g, s).determinant();
      for (int i = 0; i < 4; ++i) m[i] += mpa * s.N[i] * det;
    }
  return m;
}

NodeMatrix<4> quad4_mass(const Quad4Element& e, MassKind kind) {
  Matrix24 M = Matrix24::Zero();
  if (kind == MassKind::Lumped) {
    const auto m = quad4_lumped_masses(e);
    for (int i = 0; i < 4; ++i)
      for (int k = 0; k < 3; ++k) M(6 * i + k, 6 * i + k) = m[i];
    return M;
  }
  const Geometry g = geometry(e);
  const double mpa = e.section.mass_per_area();
  Eigen::Matrix4d Mn = Eigen::Matrix4d::Zero();
  for (double xi : {-kGauss, kGauss})
    for (double eta : {-kGauss, kGauss}) {
      const Shape s = shape(xi, eta);
      Mn.noalias() += (mpa * jacobian(g, s).determinant()) * s.N * s.N.transpose();
    }
  for (int i = 0; i < 4; ++i)
    for (int j = 0; j < 4; ++j)
      for (int k = 0; k < 3; ++k) M(6 * i + k, 6 * j + k) = Mn(i, j);
  return M;
}

Quad4Element make_quad4_element(const Model& model, const Shell& shell, const ShellSection* section) {
  Quad4Element e;
  for (int k = 0; k < 4; ++k) {
    const std::string field = std::to_string(k + 4) + " (G" + std::to_string(k + 1) + ")";
    e.x[k] = model.grids[detail::grid_index(model, shell.g[k], shell.ref, shell_card(shell), shell.id, field)].x_basic;
    for (int j = 0; j < k; ++j)
      if (shell.g[j] == shell.g[k])
        detail::fail(model, shell.ref, shell_card(shell), shell.id, field, "repeats GRID " + std::to_string(shell.g[k]));
  }
  const Eigen::Vector3d n = (e.x[2] - e.x[0]).cross(e.x[3] - e.x[1]);
  bool convex = n.norm() > 0.0;
  for (int k = 0; k < 4 && convex; ++k) {
    const Eigen::Vector3d a = e.x[(k + 1) % 4] - e.x[k], b = e.x[(k + 3) % 4] - e.x[k];
    convex = a.cross(b).dot(n) > 1e-12 * a.norm() * b.norm() * n.norm();
  }
  if (!convex)
    detail::fail(model, shell.ref, shell_card(shell), shell.id, "4-7 (G1-G4)",
                 "corners must form a convex quadrilateral, ordered around its edge (interior angles < 180 deg)");
  const Eigen::Vector3d e3 = n.normalized();
  const Eigen::Vector3d a = (e.x[1] - e.x[0]) - (e.x[1] - e.x[0]).dot(e3) * e3;
  const Eigen::Vector3d e1 = a.normalized();
  const double theta = detail::material_angle(model, shell, e1, e3.cross(e1), 0.25 * (e.x[0] + e.x[1] + e.x[2] + e.x[3]));
  e.section = (section ? *section : make_shell_section(model, shell)).in_element_axes(theta).offset(shell.zoffs);
  e.drilling = shell.drilling;
  return e;
}


Eigen::Matrix<double, 14, 1> quad4_results(const Quad4Element& e, const ShellFibres& f, const Eigen::Matrix<double, 24, 1>& u) {
  const Geometry g = geometry(e);
  const ShellSection& sec = e.section;
  // Membrane resultants: the mean of the 2 x 2 Gauss points' (the centre value: the compatible strain
  // is linear in xi, eta on a parallelogram and the incompatible modes' odd).
  Eigen::Vector3d N = Eigen::Vector3d::Zero();
  for (const Eigen::Vector3d& n : quad4_membrane_resultants(e, u)) N += 0.25 * n;
  // Plate dofs (w, theta_x, theta_y) in the mean-plane axes (the warping links move neither).
  Eigen::Matrix<double, 12, 1> q;
  for (int i = 0; i < 4; ++i) {
    const Eigen::Vector3d t = g.R_BL.transpose() * u.segment<3>(6 * i);
    const Eigen::Vector3d r = g.R_BL.transpose() * u.segment<3>(6 * i + 3);
    q.segment<3>(3 * i) << t.z(), r.x(), r.y();
  }
  const Shape s0 = shape(0, 0);
  const Eigen::Vector3d kappa = curvature_B(cartesian_derivatives(g, s0)) * q;
  Eigen::Vector2d Q = Eigen::Vector2d::Zero();
  if (sec.shear_flexible) {  // MITC4's assumed shear at the centre, times the element's (stabilised) shear stiffness
    double h2 = 0.0;
    for (int k = 0; k < 4; ++k) h2 = std::max(h2, (g.p[(k + 1) % 4] - g.p[k]).squaredNorm());
    Eigen::Matrix<double, 2, 12> Gcov;
    Gcov.row(0) = 0.5 * (covariant_shear(g, 0, -1, 0) + covariant_shear(g, 0, 1, 0));
    Gcov.row(1) = 0.5 * (covariant_shear(g, -1, 0, 1) + covariant_shear(g, 1, 0, 1));
    Q = sec.stabilised_shear(h2) * (jacobian(g, s0).inverse() * (Gcov * q));
  }
  // Nastran's element x axis bisects the angle between the diagonals G1-G3 and G2-G4.
  const Eigen::Vector2d d13 = (g.p[2] - g.p[0]).normalized(), d24 = (g.p[3] - g.p[1]).normalized();
  const Eigen::Vector2d xn = d13 - d24;
  return detail::shell_results(sec, f, N, kappa, Q, std::atan2(xn.y(), xn.x()));
}

}  // namespace seflex::fem
