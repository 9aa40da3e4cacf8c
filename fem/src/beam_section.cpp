#include "seflex/fem/beam_section.hpp"

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <numbers>

#include "beam_section_shapes.hpp"
#include "seflex/common/error.hpp"

namespace seflex::fem {
namespace {

constexpr double kPi = std::numbers::pi;

std::string fmt(double x) {
  char buf[32];
  std::snprintf(buf, sizeof buf, "%g", x);
  return buf;
}

[[noreturn]] void bad(std::string_view type, const std::string& what) {
  throw InputError(std::string(type) + " section: " + what);
}

BeamSection rod(const std::vector<double>& d) {
  const double r = d[0];
  BeamSection s;
  s.A = kPi * r * r;
  s.I1 = s.I2 = kPi * std::pow(r, 4) / 4.0;
  s.J = kPi * std::pow(r, 4) / 2.0;
  s.K1 = s.K2 = 0.9;
  return s;
}

BeamSection tube(const std::vector<double>& d) {
  const double ro = d[0], ri = d[1];
  if (!(ri < ro)) bad("TUBE", "DIM2 (inner radius " + fmt(ri) + ") must be smaller than DIM1 (outer radius " + fmt(ro) + ")");
  BeamSection s;
  s.A = kPi * (ro * ro - ri * ri);
  s.I1 = s.I2 = kPi * (std::pow(ro, 4) - std::pow(ri, 4)) / 4.0;
  s.J = kPi * (std::pow(ro, 4) - std::pow(ri, 4)) / 2.0;
  s.K1 = s.K2 = 0.5;
  return s;
}

BeamSection bar(const std::vector<double>& d) {
  const double b = d[0], h = d[1];  // b along z, h along y
  BeamSection s;
  s.A = b * h;
  s.I1 = b * h * h * h / 12.0;
  s.I2 = h * b * b * b / 12.0;
  // Roark (Table 10.7, case 4) for a solid rectangle, long side a and short side c:
  // J = a c^3 [1/3 - 0.21 (c/a) (1 - c^4 / (12 a^4))]
  const double a = std::max(b, h), c = std::min(b, h);
  s.J = a * c * c * c * (1.0 / 3.0 - 0.21 * (c / a) * (1.0 - std::pow(c / a, 4) / 12.0));
  s.K1 = s.K2 = 5.0 / 6.0;
  return s;
}

BeamSection box(const std::vector<double>& d) {
  const double b = d[0], h = d[1], t1 = d[2], t2 = d[3];  // t1: top/bottom walls, t2: side walls
  if (!(2.0 * t2 < b)) bad("BOX", "two side walls of thickness DIM4 = " + fmt(t2) + " do not fit in the width DIM1 = " + fmt(b));
  if (!(2.0 * t1 < h)) bad("BOX", "two walls of thickness DIM3 = " + fmt(t1) + " do not fit in the height DIM2 = " + fmt(h));
  const double bi = b - 2.0 * t2, hi = h - 2.0 * t1;
  BeamSection s;
  s.A = b * h - bi * hi;
  s.I1 = (b * h * h * h - bi * hi * hi * hi) / 12.0;
  s.I2 = (h * b * b * b - hi * bi * bi * bi) / 12.0;
  // Bredt-Batho on the mid-line rectangle bm x hm: J = 4 Am^2 / (sum of length/thickness)
  const double bm = b - t2, hm = h - t1;
  s.J = 4.0 * bm * bm * hm * hm / (2.0 * bm / t1 + 2.0 * hm / t2);
  s.K1 = 2.0 * t2 * h / s.A;  // side walls carry shear along y
  s.K2 = 2.0 * t1 * b / s.A;  // top and bottom walls carry shear along z
  return s;
}

BeamSection i_section(const std::vector<double>& d) {
  const double h = d[0], wb = d[1], wt = d[2], tw = d[3], tb = d[4], tt = d[5];
  if (!(tb + tt < h)) bad("I", "the flanges DIM5 + DIM6 = " + fmt(tb + tt) + " are not thinner than the height DIM1 = " + fmt(h));
  if (!(tw <= wb && tw <= wt)) bad("I", "the web DIM4 = " + fmt(tw) + " is wider than a flange (DIM2 = " + fmt(wb) + ", DIM3 = " + fmt(wt) + ")");
  const double hw = h - tb - tt;  // clear web height
  const double Ab = wb * tb, At = wt * tt, Aw = tw * hw;
  BeamSection s;
  s.A = Ab + At + Aw;
  const double yb = tb / 2.0, yt = h - tt / 2.0, yw = tb + hw / 2.0;  // from the bottom
  const double yc = (Ab * yb + At * yt + Aw * yw) / s.A;
  s.I1 = wb * tb * tb * tb / 12.0 + Ab * (yb - yc) * (yb - yc) + wt * tt * tt * tt / 12.0 + At * (yt - yc) * (yt - yc) +
         tw * hw * hw * hw / 12.0 + Aw * (yw - yc) * (yw - yc);
  s.I2 = tb * wb * wb * wb / 12.0 + tt * wt * wt * wt / 12.0 + hw * tw * tw * tw / 12.0;
  const double hm = h - (tb + tt) / 2.0;  // web mid-line length
  s.J = (wb * tb * tb * tb + wt * tt * tt * tt + hm * tw * tw * tw) / 3.0;
  s.K1 = tw * h / s.A;
  s.K2 = 5.0 / 6.0 * (Ab + At) / s.A;
  return s;
}

struct SectionType {
  std::string_view name;
  int ndim;
  BeamSection (*compute)(const std::vector<double>&);
};
constexpr SectionType kTypes[] = {
    {"ROD", 1, rod},  {"TUBE", 2, tube}, {"BAR", 2, bar}, {"BOX", 4, box}, {"I", 6, i_section},
    {"TUBE2", 2, detail::tube2_section}, {"T", 4, detail::t_section}, {"T1", 4, detail::t1_section},
    {"T2", 4, detail::t2_section}, {"L", 4, detail::l_section}, {"CHAN", 4, detail::chan_section},
    {"CHAN1", 4, detail::chan1_section}, {"CHAN2", 4, detail::chan2_section}, {"Z", 4, detail::z_section},
    {"I1", 4, detail::i1_section}, {"H", 4, detail::h_section}, {"CROSS", 4, detail::cross_section},
    {"HAT", 4, detail::hat_section}, {"HAT1", 5, detail::hat1_section}, {"BOX1", 6, detail::box1_section},
    {"DBOX", 10, detail::dbox_section}, {"HEXA", 3, detail::hexa_section}};

}  // namespace

int section_dimension_count(std::string_view type) {
  for (const auto& t : kTypes)
    if (t.name == type) return t.ndim;
  return 0;
}

std::string supported_section_types() {
  std::string s;
  for (const auto& t : kTypes) s += (s.empty() ? "" : ", ") + std::string(t.name);
  return s;
}

BeamSection beam_section(std::string_view type, const std::vector<double>& dims) {
  for (const auto& t : kTypes) {
    if (t.name != type) continue;
    if (dims.size() != static_cast<std::size_t>(t.ndim))
      bad(type, "has " + std::to_string(dims.size()) + " dimensions; expected " + std::to_string(t.ndim));
    for (std::size_t k = 0; k < dims.size(); ++k)
      if (!(dims[k] > 0.0)) bad(type, "DIM" + std::to_string(k + 1) + " = " + fmt(dims[k]) + "; expected a dimension > 0");
    return t.compute(dims);
  }
  throw InputError("section TYPE " + std::string(type) + " is not supported; expected one of " + supported_section_types());
}

}  // namespace seflex::fem
