// PBARL/PBEAML sections built from rectangles (see beam_section_shapes.hpp, beam_section.hpp).
// Section axes: y vertical, z horizontal as in the QRG figures (dimension meanings as drawn there and
// in pyNastran's bdf/cards/properties/bars.py); A, I1 = int y^2, I2 = int z^2, I12 = int y z about
// the centroid, from the rectangles by the parallel-axis theorem (exact).
// J: open sections sum b t^3 / 3 over the rectangles (b the long side, t the short one; Roark's
// Formulas for Stress and Strain, 7th ed., table 10.7 case 26, thin-walled open sections); closed
// cells (BOX1, HAT1, DBOX) by Bredt-Batho on the wall mid-lines, J = 4 A_m^2 / sum(s/t), two cells
// (DBOX) by the shear-flow compatibility of each cell (ibid. case 18 and sec. 10.4).
// Shear factors K1 (along y) and K2 (along z): the area of the rectangles taller than wide (K1) or
// wider than tall (K2) over A - the walls that carry each shear (the same rule as BOX; an
// approximation of Nastran's values, which the QRG does not publish).
#include "beam_section_shapes.hpp"

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <numbers>
#include <string>

#include "seflex/common/error.hpp"

namespace seflex::fem::detail {
namespace {

struct Rect {
  double z0, z1, y0, y1;  // corners; z0 < z1, y0 < y1
  double w() const { return z1 - z0; }
  double h() const { return y1 - y0; }
  double area() const { return w() * h(); }
};

std::string fmt(double x) {
  char buf[32];
  std::snprintf(buf, sizeof buf, "%g", x);
  return buf;
}

[[noreturn]] void bad(const char* type, const std::string& what) { throw InputError(std::string(type) + " section: " + what); }

/// Require a < b ("what" names the condition).
void need_less(const char* type, double a, double b, const std::string& what) {
  if (!(a < b)) bad(type, what + " (" + fmt(a) + " >= " + fmt(b) + "); expected dimensions that describe the section");
}

/// A, I1, I2, I12 about the centroid, K1, K2 by the wall rule, J = sum b t^3 / 3 (open).
BeamSection composite(const std::vector<Rect>& rects) {
  BeamSection s;
  double Ay = 0, Az = 0;
  for (const Rect& r : rects) {
    s.A += r.area();
    Ay += r.area() * 0.5 * (r.y0 + r.y1);
    Az += r.area() * 0.5 * (r.z0 + r.z1);
  }
  const double yc = Ay / s.A, zc = Az / s.A;
  double along_y = 0, along_z = 0;
  for (const Rect& r : rects) {
    const double a = r.area(), dy = 0.5 * (r.y0 + r.y1) - yc, dz = 0.5 * (r.z0 + r.z1) - zc;
    s.I1 += r.w() * r.h() * r.h() * r.h() / 12.0 + a * dy * dy;
    s.I2 += r.h() * r.w() * r.w() * r.w() / 12.0 + a * dz * dz;
    s.I12 += a * dy * dz;
    const double b = std::max(r.w(), r.h()), t = std::min(r.w(), r.h());
    s.J += b * t * t * t / 3.0;
    (r.h() >= r.w() ? along_y : along_z) += a;
  }
  s.K1 = along_y / s.A;
  s.K2 = along_z / s.A;
  if (std::abs(s.I12) < 1e-14 * std::sqrt(s.I1 * s.I2)) s.I12 = 0.0;  // symmetric up to rounding
  return s;
}

/// Bredt-Batho torsion constant of one cell: enclosed mid-line area and its walls (length, thickness).
double bredt(double area, std::initializer_list<std::pair<double, double>> walls) {
  double sum = 0;
  for (const auto& [s, t] : walls) sum += s / t;
  return 4.0 * area * area / sum;
}

}  // namespace

BeamSection tube2_section(const std::vector<double>& d) {
  need_less("TUBE2", d[1], d[0], "the thickness DIM2 is not smaller than the outer radius DIM1");
  return beam_section("TUBE", {d[0], d[0] - d[1]});
}

// T: DIM1 flange width, DIM2 height, DIM3 flange thickness (top), DIM4 web thickness.
BeamSection t_section(const std::vector<double>& d) {
  need_less("T", d[2], d[1], "flange thickness DIM3 not smaller than the height DIM2");
  need_less("T", d[3], d[0], "web thickness DIM4 not smaller than the flange width DIM1");
  return composite({{-d[0] / 2, d[0] / 2, d[1] - d[2], d[1]}, {-d[3] / 2, d[3] / 2, 0, d[1] - d[2]}});
}

// T1: DIM1 flange height (vertical flange), DIM2 web length, DIM3 flange thickness, DIM4 web thickness.
BeamSection t1_section(const std::vector<double>& d) {
  need_less("T1", d[3], d[0], "web thickness DIM4 not smaller than the flange height DIM1");
  return composite({{0, d[2], -d[0] / 2, d[0] / 2}, {d[2], d[2] + d[1], -d[3] / 2, d[3] / 2}});
}

// T2: DIM1 flange width (bottom), DIM2 height, DIM3 flange thickness, DIM4 web thickness.
BeamSection t2_section(const std::vector<double>& d) {
  need_less("T2", d[2], d[1], "flange thickness DIM3 not smaller than the height DIM2");
  need_less("T2", d[3], d[0], "web thickness DIM4 not smaller than the flange width DIM1");
  return composite({{-d[0] / 2, d[0] / 2, 0, d[2]}, {-d[3] / 2, d[3] / 2, d[2], d[1]}});
}

// L: DIM1 width (horizontal leg), DIM2 height, DIM3 horizontal leg thickness, DIM4 vertical leg thickness.
BeamSection l_section(const std::vector<double>& d) {
  need_less("L", d[2], d[1], "leg thickness DIM3 not smaller than the height DIM2");
  need_less("L", d[3], d[0], "leg thickness DIM4 not smaller than the width DIM1");
  return composite({{0, d[0], 0, d[2]}, {0, d[3], d[2], d[1]}});
}

// CHAN: DIM1 flange width (web included), DIM2 height, DIM3 web thickness, DIM4 flange thickness.
BeamSection chan_section(const std::vector<double>& d) {
  need_less("CHAN", 2 * d[3], d[1], "two flanges 2 DIM4 not thinner than the height DIM2");
  need_less("CHAN", d[2], d[0], "web thickness DIM3 not smaller than the width DIM1");
  return composite({{0, d[2], 0, d[1]}, {d[2], d[0], 0, d[3]}, {d[2], d[0], d[1] - d[3], d[1]}});
}

// CHAN1: DIM1 flange width (web excluded), DIM2 web thickness, DIM3 clear web height, DIM4 height.
BeamSection chan1_section(const std::vector<double>& d) {
  need_less("CHAN1", d[2], d[3], "the clear web height DIM3 is not smaller than the height DIM4");
  const double tf = (d[3] - d[2]) / 2;
  return composite({{0, d[1], 0, d[3]}, {d[1], d[1] + d[0], 0, tf}, {d[1], d[1] + d[0], d[3] - tf, d[3]}});
}

// CHAN2: DIM1 leg thickness, DIM2 base thickness, DIM3 height, DIM4 width (legs up).
BeamSection chan2_section(const std::vector<double>& d) {
  need_less("CHAN2", d[1], d[2], "base thickness DIM2 not smaller than the height DIM3");
  need_less("CHAN2", 2 * d[0], d[3], "two legs 2 DIM1 not narrower than the width DIM4");
  const double b = d[3] / 2;
  return composite({{-b, b, 0, d[1]}, {-b, -b + d[0], d[1], d[2]}, {b - d[0], b, d[1], d[2]}});
}

// Z: DIM1 flange width (beside the web), DIM2 web thickness, DIM3 clear web height, DIM4 height;
// the top flange to the left of the web, the bottom one to the right.
BeamSection z_section(const std::vector<double>& d) {
  need_less("Z", d[2], d[3], "the clear web height DIM3 is not smaller than the height DIM4");
  const double tf = (d[3] - d[2]) / 2, w = d[1] / 2, h = d[3] / 2;
  return composite({{-w, w, -h, h}, {-w - d[0], -w, h - tf, h}, {w, w + d[0], -h, -h + tf}});
}

// I1: DIM1 the two flange overhangs together, DIM2 web thickness, DIM3 clear web height, DIM4 height.
BeamSection i1_section(const std::vector<double>& d) {
  need_less("I1", d[2], d[3], "the clear web height DIM3 is not smaller than the height DIM4");
  const double tf = (d[3] - d[2]) / 2, bf = (d[0] + d[1]) / 2;
  return composite({{-bf, bf, 0, tf}, {-bf, bf, d[3] - tf, d[3]}, {-d[1] / 2, d[1] / 2, tf, d[3] - tf}});
}

// H: DIM1 web length (between the flanges), DIM2 the two flange thicknesses together, DIM3 flange
// height, DIM4 web thickness.
BeamSection h_section(const std::vector<double>& d) {
  need_less("H", d[3], d[2], "web thickness DIM4 not smaller than the flange height DIM3");
  const double a = d[0] / 2, b = (d[0] + d[1]) / 2;
  return composite({{-a, a, -d[3] / 2, d[3] / 2}, {a, b, -d[2] / 2, d[2] / 2}, {-b, -a, -d[2] / 2, d[2] / 2}});
}

// CROSS: DIM1 arm length (each side), DIM2 centre width, DIM3 centre height, DIM4 arm thickness.
BeamSection cross_section(const std::vector<double>& d) {
  need_less("CROSS", d[3], d[2], "arm thickness DIM4 not smaller than the height DIM3");
  const double a = d[1] / 2;
  return composite({{-a, a, -d[2] / 2, d[2] / 2}, {a, a + d[0], -d[3] / 2, d[3] / 2}, {-a - d[0], -a, -d[3] / 2, d[3] / 2}});
}

// HAT: DIM1 height, DIM2 thickness, DIM3 top width (walls included), DIM4 brim width beyond a wall.
BeamSection hat_section(const std::vector<double>& d) {
  const double h = d[0], t = d[1], b = d[2] / 2;
  need_less("HAT", 2 * t, d[2], "two walls 2 DIM2 not narrower than the top width DIM3");
  need_less("HAT", 2 * t, h, "top and brim 2 DIM2 not thinner than the height DIM1");
  return composite({{-b, b, h - t, h}, {-b, -b + t, t, h - t}, {b - t, b, t, h - t},
                    {-b - d[3], -b + t, 0, t}, {b - t, b + d[3], 0, t}});
}

// HAT1: DIM1 base plate width, DIM2 height, DIM3 hat width, DIM4 hat thickness, DIM5 base thickness.
// One closed cell (hat and base) plus the brims.
BeamSection hat1_section(const std::vector<double>& d) {
  const double B = d[0] / 2, b = d[2] / 2, h = d[1], t = d[3], tb = d[4];
  need_less("HAT1", d[2], d[0], "hat width DIM3 not smaller than the base width DIM1");
  need_less("HAT1", 2 * t, d[2], "two walls 2 DIM4 not narrower than the hat width DIM3");
  need_less("HAT1", tb + 2 * t, h, "base and hat DIM5 + 2 DIM4 not thinner than the height DIM2");
  BeamSection s = composite({{-B, B, 0, tb}, {-B, -b, tb, tb + t}, {b, B, tb, tb + t}, {-b, -b + t, tb, h},
                             {b - t, b, tb, h}, {-b + t, b - t, h - t, h}});
  const double wm = d[2] - t, hm = h - t / 2 - tb / 2;
  s.J = bredt(wm * hm, {{wm, t}, {wm, tb}, {hm, t}, {hm, t}});
  return s;
}

// BOX1: DIM1 width, DIM2 height, DIM3 top, DIM4 bottom, DIM5 right, DIM6 left wall thickness.
BeamSection box1_section(const std::vector<double>& d) {
  const double b = d[0], h = d[1];
  need_less("BOX1", d[4] + d[5], b, "side walls DIM5 + DIM6 not thinner than the width DIM1");
  need_less("BOX1", d[2] + d[3], h, "top and bottom DIM3 + DIM4 not thinner than the height DIM2");
  BeamSection s = composite({{0, b, h - d[2], h}, {0, b, 0, d[3]}, {b - d[4], b, d[3], h - d[2]}, {0, d[5], d[3], h - d[2]}});
  const double bm = b - (d[4] + d[5]) / 2, hm = h - (d[2] + d[3]) / 2;
  s.J = bredt(bm * hm, {{bm, d[2]}, {bm, d[3]}, {hm, d[4]}, {hm, d[5]}});
  return s;
}

// DBOX: DIM1 width, DIM2 height, DIM3 position of the middle wall's centre from the left, DIM4 left,
// DIM5 middle, DIM6 right wall thickness, DIM7/DIM8 top/bottom of the left cell, DIM9/DIM10 top/bottom
// of the right cell.
BeamSection dbox_section(const std::vector<double>& d) {
  const double W = d[0], H = d[1], zm = d[2];
  need_less("DBOX", d[3] + d[4] / 2, zm, "the left wall and half the middle wall DIM4 + DIM5/2 reach past DIM3");
  need_less("DBOX", zm + d[4] / 2 + d[5], W, "DIM3 + DIM5/2 + DIM6 reach past the width DIM1");
  need_less("DBOX", d[6] + d[7], H, "DIM7 + DIM8 not thinner than the height DIM2");
  need_less("DBOX", d[8] + d[9], H, "DIM9 + DIM10 not thinner than the height DIM2");
  const double l1 = d[3], m0 = zm - d[4] / 2, m1 = zm + d[4] / 2, r0 = W - d[5];
  BeamSection s = composite({{0, l1, 0, H}, {m0, m1, 0, H}, {r0, W, 0, H}, {l1, m0, H - d[6], H}, {l1, m0, 0, d[7]},
                             {m1, r0, H - d[8], H}, {m1, r0, 0, d[9]}});
  // two cells: (q_i - q_j) compatibility, a q = 2 A (G theta = 1), J = 2 sum q_i A_i
  const double w1 = zm - d[3] / 2, w2 = W - d[5] / 2 - zm;
  const double h1 = H - (d[6] + d[7]) / 2, h2 = H - (d[8] + d[9]) / 2, hmid = (h1 + h2) / 2;
  const double A1 = w1 * h1, A2 = w2 * h2;
  const double mid = hmid / d[4];
  const double a11 = w1 / d[6] + w1 / d[7] + h1 / d[3] + mid, a22 = w2 / d[8] + w2 / d[9] + h2 / d[5] + mid;
  const double det = a11 * a22 - mid * mid;
  const double q1 = 2 * (A1 * a22 + A2 * mid) / det, q2 = 2 * (A2 * a11 + A1 * mid) / det;
  s.J = 2 * (q1 * A1 + q2 * A2);
  return s;
}

// HEXA: DIM1 tip width (horizontal extent of each triangular end), DIM2 width, DIM3 height.
// Rectangle (DIM2 - 2 DIM1) x DIM3 and two triangles of base DIM3 and height DIM1:
//   A = DIM3 (DIM2 - DIM1), I1 = (DIM2 - 2 DIM1) DIM3^3 / 12 + DIM1 DIM3^3 / 24,
//   I2 = DIM3 c^3 / 12 + 2 [DIM3 DIM1^3 / 36 + (DIM3 DIM1 / 2) (c/2 + DIM1/3)^2], c = DIM2 - 2 DIM1;
// J of a solid section by Saint-Venant's approximation A^4 / (4 pi^2 Ip) (Roark, table 10.7 note;
// exact for an ellipse); shear factors 5/6 (solid).
BeamSection hexa_section(const std::vector<double>& d) {
  const double t = d[0], w = d[1], h = d[2];
  need_less("HEXA", 2 * t, w, "two tips 2 DIM1 not narrower than the width DIM2");
  const double c = w - 2 * t;
  BeamSection s;
  s.A = h * (w - t);
  s.I1 = c * h * h * h / 12 + t * h * h * h / 24;
  const double arm = c / 2 + t / 3;
  s.I2 = h * c * c * c / 12 + 2 * (h * t * t * t / 36 + 0.5 * h * t * arm * arm);
  s.J = std::pow(s.A, 4) / (4 * std::numbers::pi * std::numbers::pi * (s.I1 + s.I2));
  s.K1 = s.K2 = 5.0 / 6.0;
  return s;
}

}  // namespace seflex::fem::detail
