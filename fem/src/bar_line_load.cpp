// PLOAD1 on CBAR/CBEAM (see bar_line_load.hpp).
#include "seflex/fem/bar_line_load.hpp"

#include <cmath>

#include "model_lookup.hpp"

namespace seflex::fem {
namespace {

// Shape functions of the bar on s in [0, 1] and their x-derivatives (length L).
struct Shapes {
  double lin[2];      // axial / torsion: 1 - s, s
  double her[4];      // N1..N4
  double dher[4];     // dN/dx
};
Shapes shapes(double s, double L) {
  Shapes h;
  h.lin[0] = 1.0 - s;
  h.lin[1] = s;
  h.her[0] = 1.0 - 3.0 * s * s + 2.0 * s * s * s;
  h.her[1] = L * (s - 2.0 * s * s + s * s * s);
  h.her[2] = 3.0 * s * s - 2.0 * s * s * s;
  h.her[3] = L * (s * s * s - s * s);
  h.dher[0] = (-6.0 * s + 6.0 * s * s) / L;
  h.dher[1] = 1.0 - 4.0 * s + 3.0 * s * s;
  h.dher[2] = (6.0 * s - 6.0 * s * s) / L;
  h.dher[3] = 3.0 * s * s - 2.0 * s;
  return h;
}

// Element-axis end loads (u v w tx ty tz at A, then B) of a force f (element axes) and a moment m
// (element axes) applied at x: the point-load version of the integrals.
void add_point(double x, double L, const Eigen::Vector3d& f, const Eigen::Vector3d& m, Eigen::Matrix<double, 12, 1>& q) {
  const Shapes h = shapes(x / L, L);
  for (int e = 0; e < 2; ++e) {
    const int o = 6 * e;
    q[o + 0] += h.lin[e] * f.x();
    q[o + 3] += h.lin[e] * m.x();
    // transverse y: v dofs (N1, N3) and th_z (N2, N4)
    q[o + 1] += h.her[2 * e] * f.y() + h.dher[2 * e] * m.z();
    q[o + 5] += h.her[2 * e + 1] * f.y() + h.dher[2 * e + 1] * m.z();
    // transverse z: w dofs (N1, N3) and th_y (-N2, -N4); moment m_y works on th_y = -w'
    q[o + 2] += h.her[2 * e] * f.z() - h.dher[2 * e] * m.y();
    q[o + 4] += -h.her[2 * e + 1] * f.z() + h.dher[2 * e + 1] * m.y();
  }
}

}  // namespace

Eigen::Matrix<double, 12, 1> bar_line_load(const BarElement& e, const BarLineLoad& l) {
  const Eigen::Matrix3d R_BE = bar_axes(e);
  const double L = bar_length(e);
  const bool fraction = l.scale == BarLineLoad::Scale::FR || l.scale == BarLineLoad::Scale::FRPR;
  // a projection is defined for the basic directions only: LEPR/FRPR with an element-axis TYPE are LE/FR
  // (MSC Nastran runs such decks, e.g. pyNastran's models/elements/static_elements.bdf)
  const bool projected = (l.scale == BarLineLoad::Scale::LEPR || l.scale == BarLineLoad::Scale::FRPR) && l.type.size() == 2;
  const double x1 = fraction ? l.x1 * L : l.x1, x2 = fraction ? l.x2 * L : l.x2;
  // direction (element axes) and kind
  const bool element_axes = l.type.size() == 3;
  const bool moment = l.type[0] == 'M';
  const int axis = l.type[1] - 'X';
  Eigen::Vector3d dir = Eigen::Vector3d::Zero();
  dir[axis] = 1.0;
  Eigen::Vector3d dir_basic = element_axes ? Eigen::Vector3d(R_BE * dir) : dir;
  double factor = 1.0;
  if (projected) factor = dir_basic.cross(R_BE.col(0)).norm();
  const Eigen::Vector3d dir_E = R_BE.transpose() * dir_basic;
  Eigen::Matrix<double, 12, 1> q = Eigen::Matrix<double, 12, 1>::Zero();
  auto at = [&](double x, double p) {
    const Eigen::Vector3d v = p * factor * dir_E;
    add_point(x, L, moment ? Eigen::Vector3d::Zero() : v, moment ? v : Eigen::Vector3d::Zero(), q);
  };
  if (x2 == x1) {
    at(x1, l.p1);
  } else {
    // integrand of degree <= 4 in x: 3-point Gauss-Legendre is exact
    static const double gx[3] = {-0.7745966692414834, 0.0, 0.7745966692414834}, gw[3] = {5.0 / 9.0, 8.0 / 9.0, 5.0 / 9.0};
    const double half = 0.5 * (x2 - x1), mid = 0.5 * (x1 + x2);
    for (int k = 0; k < 3; ++k) {
      const double x = mid + half * gx[k];
      const double p = l.p1 + (l.p2 - l.p1) * (x - x1) / (x2 - x1);
      at(x, gw[k] * half * p);
    }
  }
  // element axes -> basic, then from the bar ends to the grids through the offsets
  Eigen::Matrix<double, 12, 1> f;
  for (int b = 0; b < 4; ++b) f.segment<3>(3 * b) = R_BE * q.segment<3>(3 * b);
  f.segment<3>(3) += e.w_A.cross(f.segment<3>(0));
  f.segment<3>(9) += e.w_B.cross(f.segment<3>(6));
  return f;
}

BarLineLoadAtGrids bar_line_load(const Model& model, const BarLineLoad& l) {
  const Bar* bar = nullptr;
  for (const Bar& b : model.bars)
    if (b.id == l.element) {
      bar = &b;
      break;
    }
  if (!bar)
    detail::fail(model, l.ref, "PLOAD1", l.sid, "3 (EID)",
                 "element " + std::to_string(l.element) + " is not a CBAR or CBEAM; expected the id of a CBAR or CBEAM");
  const std::string card = bar->is_beam ? "CBEAM" : "CBAR";
  if (bar->pa || bar->pb)
    detail::fail(model, l.ref, "PLOAD1", l.sid, "3 (EID)",
                 card + " " + std::to_string(bar->id) + " has pin flags; PLOAD1 on a pinned bar is not supported");
  const BarElement e = make_bar_element(model, *bar);
  const double L = bar_length(e);
  const bool fraction = l.scale == BarLineLoad::Scale::FR || l.scale == BarLineLoad::Scale::FRPR;
  if (!fraction && !(l.x2 <= L * (1.0 + 1e-9)))
    detail::fail(model, l.ref, "PLOAD1", l.sid, "8 (X2)",
                 "X2 = " + std::to_string(l.x2) + " is beyond the end of " + card + " " + std::to_string(bar->id) +
                     " (length " + std::to_string(L) + "); expected 0 <= X1 <= X2 <= L");
  BarLineLoadAtGrids out;
  out.grid_A = detail::grid_index(model, bar->ga, bar->ref, card, bar->id, "4 (GA)");
  out.grid_B = detail::grid_index(model, bar->gb, bar->ref, card, bar->id, "5 (GB)");
  BarLineLoad clipped = l;
  if (!fraction) clipped.x2 = std::min(l.x2, L);
  out.f = bar_line_load(e, clipped);
  return out;
}

}  // namespace seflex::fem
