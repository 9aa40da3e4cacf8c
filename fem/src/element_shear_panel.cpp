// CSHEAR / PSHEAR shear panel (see element_shear_panel.hpp).
#include "seflex/fem/element_shear_panel.hpp"

#include <Eigen/Dense>
#include <cmath>
#include <string>

#include "model_lookup.hpp"
#include "seflex/fem/element_rod.hpp"

namespace seflex::fem {
namespace {

/// The panel's plane: k from the diagonals, i along the projection of edge 1-2, j = k x i.
struct PanelFrame {
  Eigen::Vector3d i, j, k, centroid;
  std::array<Eigen::Vector2d, 4> p;  ///< projected corners, origin at the centroid
  std::array<double, 4> h{};         ///< distance of each corner from the plane through the centroid
};

PanelFrame panel_frame(const ShearPanelElement& e) {
  PanelFrame f;
  f.k = (e.x[2] - e.x[0]).cross(e.x[3] - e.x[1]).normalized();
  const Eigen::Vector3d d12 = e.x[1] - e.x[0];
  f.i = (d12 - d12.dot(f.k) * f.k).normalized();
  f.j = f.k.cross(f.i);
  f.centroid = 0.25 * (e.x[0] + e.x[1] + e.x[2] + e.x[3]);
  for (int n = 0; n < 4; ++n) {
    const Eigen::Vector3d r = e.x[static_cast<std::size_t>(n)] - f.centroid;
    f.p[static_cast<std::size_t>(n)] = {r.dot(f.i), r.dot(f.j)};
    f.h[static_cast<std::size_t>(n)] = r.dot(f.k);
  }
  return f;
}

/// G = t int P^T B dA (8: u, v of each corner) of the unit stress mode P (Voigt xx, yy, xy) over the
/// bilinear displacements of the projected quadrilateral; 2 x 2 Gauss (exact: P constant).
Eigen::Matrix<double, 8, 1> mode_work(const std::array<Eigen::Vector2d, 4>& p, const Eigen::Vector3d& P, double t) {
  static const double xi_n[4] = {-1, 1, 1, -1}, eta_n[4] = {-1, -1, 1, 1};
  const double g = 1.0 / std::sqrt(3.0);
  Eigen::Matrix<double, 8, 1> G = Eigen::Matrix<double, 8, 1>::Zero();
  for (const double xi : {-g, g})
    for (const double eta : {-g, g}) {
      Eigen::Matrix<double, 2, 4> dN;  // d/dxi, d/deta
      for (int n = 0; n < 4; ++n) {
        dN(0, n) = 0.25 * xi_n[n] * (1 + eta * eta_n[n]);
        dN(1, n) = 0.25 * eta_n[n] * (1 + xi * xi_n[n]);
      }
      Eigen::Matrix2d J = Eigen::Matrix2d::Zero();
      for (int n = 0; n < 4; ++n) J += dN.col(n) * p[static_cast<std::size_t>(n)].transpose();
      const Eigen::Matrix<double, 2, 4> dX = J.inverse() * dN;  // d/dx, d/dy
      const double w = t * J.determinant();
      for (int n = 0; n < 4; ++n) {
        G[2 * n] += w * (P[0] * dX(0, n) + P[2] * dX(1, n));
        G[2 * n + 1] += w * (P[1] * dX(1, n) + P[2] * dX(0, n));
      }
    }
  return G;
}

/// The effective rod area of an edge pair (QRG PSHEAR remark 2).
double rod_area(double F, double t, double PA, double La, double Lb) {
  if (F <= 0.0) return 0.0;
  return F <= 1.01 ? F * t * PA / (La + Lb) : 0.5 * F * t * t;
}

}  // namespace

double shear_panel_area(const ShearPanelElement& e) { return 0.5 * (e.x[2] - e.x[0]).cross(e.x[3] - e.x[1]).norm(); }

NodeMatrix<4> shear_panel_stiffness(const ShearPanelElement& e) {
  const PanelFrame f = panel_frame(e);
  const double PA = shear_panel_area(e);
  NodeMatrix<4> K = NodeMatrix<4>::Zero();

  // Shear: the stress mode of the mean parallelogram's edge directions, in the plane's axes.
  const Eigen::Vector2d e1 = (f.p[1] - f.p[0] + f.p[2] - f.p[3]).normalized();
  const Eigen::Vector2d e2 = (f.p[3] - f.p[0] + f.p[2] - f.p[1]).normalized();
  const Eigen::Vector3d P(2 * e1.x() * e2.x(), 2 * e1.y() * e2.y(), e1.x() * e2.y() + e1.y() * e2.x());
  const IsotropicMaterial& m = e.material;
  const double ce = m.E > 0.0 ? 1.0 / m.E : 0.0;  // a MAT1 with G only: the normal stresses cost nothing
  Eigen::Matrix3d S = Eigen::Matrix3d::Zero();      // plane-stress compliance
  S << ce, -m.nu * ce, 0, -m.nu * ce, ce, 0, 0, 0, 1 / m.G;
  const double H = e.t * PA * P.dot(S * P);
  const Eigen::Matrix<double, 8, 1> G = mode_work(f.p, P, e.t);
  std::array<Eigen::Vector3d, 4> w;  // corner forces of the mode (unit s), basic
  for (int n = 0; n < 4; ++n) w[static_cast<std::size_t>(n)] = G[2 * n] * f.i + G[2 * n + 1] * f.j;
  // Warped panel: normal kicks kappa (sum 0) cancelling the in-plane moment of the corner forces
  // about the centroid, sum h_n k x w_n + sum kappa_n p_n x k = 0; the least-norm solution.
  Eigen::Matrix<double, 3, 4> A;
  Eigen::Vector3d b = Eigen::Vector3d::Zero();
  for (int n = 0; n < 4; ++n) {
    const auto s = static_cast<std::size_t>(n);
    const Eigen::Vector3d p3 = f.p[s].x() * f.i + f.p[s].y() * f.j;
    const Eigen::Vector3d pk = p3.cross(f.k);
    A(0, n) = 1.0;
    A(1, n) = pk.dot(f.i);
    A(2, n) = pk.dot(f.j);
    const Eigen::Vector3d mk = f.h[s] * f.k.cross(w[s]);
    b[1] -= mk.dot(f.i);
    b[2] -= mk.dot(f.j);
  }
  const Eigen::Vector4d kappa = A.transpose() * (A * A.transpose()).ldlt().solve(b);
  Eigen::Matrix<double, 12, 1> w12;
  for (int n = 0; n < 4; ++n) w12.segment<3>(3 * n) = w[static_cast<std::size_t>(n)] + kappa[n] * f.k;
  const Eigen::Matrix<double, 12, 12> Ks = w12 * w12.transpose() / H;
  for (int a = 0; a < 4; ++a)
    for (int c = 0; c < 4; ++c) K.block<3, 3>(6 * a, 6 * c) += Ks.block<3, 3>(3 * a, 3 * c);

  // Extension: the effective rods on the actual edges.
  const double L[4] = {(e.x[1] - e.x[0]).norm(), (e.x[2] - e.x[1]).norm(), (e.x[3] - e.x[2]).norm(), (e.x[0] - e.x[3]).norm()};
  const double A13 = rod_area(e.f1, e.t, PA, L[0], L[2]), A24 = rod_area(e.f2, e.t, PA, L[1], L[3]);
  for (int edge = 0; edge < 4; ++edge) {
    const double area = edge % 2 == 0 ? A13 : A24;
    if (area == 0.0) continue;
    RodElement rod;
    const int a = edge, c = (edge + 1) % 4;
    rod.x_A = e.x[static_cast<std::size_t>(a)];
    rod.x_B = e.x[static_cast<std::size_t>(c)];
    rod.A = area;
    rod.material = e.material;
    const NodeMatrix<2> Kr = rod_stiffness(rod);
    for (int r = 0; r < 2; ++r)
      for (int s = 0; s < 2; ++s) K.block<6, 6>(6 * (r ? c : a), 6 * (s ? c : a)) += Kr.block<6, 6>(6 * r, 6 * s);
  }
  return K;
}

NodeMatrix<4> shear_panel_mass(const ShearPanelElement& e) {
  const double m = (e.material.rho * e.t + e.nsm) * shear_panel_area(e);
  double share[4], total = 0.0;
  for (int n = 0; n < 4; ++n) {
    const Eigen::Vector3d& prev = e.x[static_cast<std::size_t>((n + 3) % 4)];
    const Eigen::Vector3d& here = e.x[static_cast<std::size_t>(n)];
    const Eigen::Vector3d& next = e.x[static_cast<std::size_t>((n + 1) % 4)];
    share[n] = 0.5 * (next - here).cross(prev - here).norm();
    total += share[n];
  }
  NodeMatrix<4> M = NodeMatrix<4>::Zero();
  for (int n = 0; n < 4; ++n) M.block<3, 3>(6 * n, 6 * n).diagonal().setConstant(m * share[n] / total);
  return M;
}

ShearPanelElement make_shear_panel_element(const Model& model, const ShearPanel& panel) {
  ShearPanelElement e;
  static const char* fields[4] = {"4 (G1)", "5 (G2)", "6 (G3)", "7 (G4)"};
  for (int n = 0; n < 4; ++n)
    e.x[static_cast<std::size_t>(n)] =
        model.grids[detail::grid_index(model, panel.g[static_cast<std::size_t>(n)], panel.ref, "CSHEAR", panel.id, fields[n])].x_basic;
  const auto it = model.shear_prop_index.find(panel.pid);
  if (it == model.shear_prop_index.end())
    detail::fail(model, panel.ref, "CSHEAR", panel.id, "3 (PID)", "references PSHEAR " + std::to_string(panel.pid) + ", which is not defined");
  const ShearProperty& p = model.shear_props[it->second];
  e.t = p.t;
  e.nsm = p.nsm;
  e.f1 = p.f1;
  e.f2 = p.f2;
  e.material = detail::material(model, p.mid, p.ref, "PSHEAR", p.id, "3 (MID)");
  if (!(shear_panel_area(e) > 0.0))
    detail::fail(model, panel.ref, "CSHEAR", panel.id, "", "the diagonals 1-3 and 2-4 are parallel (a degenerate panel); expected four corners around a quadrilateral");
  const PanelFrame f = panel_frame(e);
  for (int n = 0; n < 4; ++n) {
    const Eigen::Vector2d a = f.p[static_cast<std::size_t>((n + 1) % 4)] - f.p[static_cast<std::size_t>(n)];
    const Eigen::Vector2d b = f.p[static_cast<std::size_t>((n + 3) % 4)] - f.p[static_cast<std::size_t>(n)];
    if (!(a.x() * b.y() - a.y() * b.x() > 0.0))
      detail::fail(model, panel.ref, "CSHEAR", panel.id, fields[n],
                   "the interior angle at G" + std::to_string(n + 1) +
                       " is 180 degrees or more; expected a convex panel with G1-G4 in order around it (QRG CSHEAR remark 3)");
  }
  if (!(e.material.G > 0.0))
    detail::fail(model, p.ref, "PSHEAR", p.id, "3 (MID)", "MAT1 " + std::to_string(p.mid) + " has no shear modulus G; expected G > 0 for a shear panel");
  return e;
}

}  // namespace seflex::fem
