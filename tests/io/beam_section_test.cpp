// PBARL/PBEAML section library (fem/beam_section.hpp) against hand formulas: each section rebuilt
// from its rectangles with the parallel-axis theorem, torsion of a solid rectangle against the exact
// Saint-Venant series (Timoshenko & Goodier, Theory of Elasticity, sec. 109).
#include <gtest/gtest.h>

#include <cmath>
#include <numbers>
#include <string>
#include <utility>
#include <vector>

#include "seflex/common/error.hpp"
#include "seflex/fem/beam_section.hpp"

using seflex::fem::beam_section;
using seflex::fem::BeamSection;
constexpr double kPi = std::numbers::pi;

namespace {

/// Exact torsion constant of an a x b rectangle (a >= b): J = a b^3/3 [1 - 192 b/(pi^5 a) sum tanh(n pi a/2b)/n^5].
double saint_venant_rectangle(double a, double b) {
  double s = 0;
  for (int n = 1; n < 400; n += 2) s += std::tanh(n * kPi * a / (2 * b)) / std::pow(n, 5);
  return a * b * b * b / 3.0 * (1.0 - 192.0 / std::pow(kPi, 5) * (b / a) * s);
}

/// Rectangle of width w (along z) and height h (along y) centred at y = yc: its I about y = 0.
double rect_Izz(double w, double h, double yc) { return w * h * h * h / 12.0 + w * h * yc * yc; }

}  // namespace

TEST(BeamSection, RodAndTubeAreExact) {
  const BeamSection r = beam_section("ROD", {0.1});
  EXPECT_DOUBLE_EQ(r.A, kPi * 0.01);
  EXPECT_DOUBLE_EQ(r.I1, kPi * 1e-4 / 4);
  EXPECT_DOUBLE_EQ(r.I2, r.I1);
  EXPECT_DOUBLE_EQ(r.J, kPi * 1e-4 / 2);
  const BeamSection t = beam_section("TUBE", {0.1, 0.08});
  EXPECT_DOUBLE_EQ(t.A, kPi * (0.01 - 0.0064));
  EXPECT_NEAR(t.I1, kPi * (1e-4 - std::pow(0.08, 4)) / 4, 1e-18);
  EXPECT_NEAR(t.J, 2 * t.I1, 1e-18);  // polar moment of a circular tube
}

TEST(BeamSection, BarAgainstSaintVenant) {
  // DIM1 = 0.03 along z (width), DIM2 = 0.06 along y (height).
  const BeamSection s = beam_section("BAR", {0.03, 0.06});
  EXPECT_DOUBLE_EQ(s.A, 0.03 * 0.06);
  EXPECT_DOUBLE_EQ(s.I1, 0.03 * std::pow(0.06, 3) / 12);  // bending in plane 1 (x-y): about z
  EXPECT_DOUBLE_EQ(s.I2, 0.06 * std::pow(0.03, 3) / 12);
  // Roark's formula is within 0.18 % of the series for every aspect ratio (largest at a square).
  for (const double ratio : {1.0, 1.5, 2.0, 5.0, 20.0}) {
    const BeamSection b = beam_section("BAR", {1.0, ratio});
    EXPECT_NEAR(b.J / saint_venant_rectangle(ratio, 1.0), 1.0, 2e-3) << ratio;
    const BeamSection c = beam_section("BAR", {ratio, 1.0});
    EXPECT_DOUBLE_EQ(c.J, b.J) << ratio;  // J does not depend on which side is which
  }
}

TEST(BeamSection, BoxFromItsFourWalls) {
  // b = 0.1 (z), h = 0.2 (y), top/bottom walls t1 = 0.01, side walls t2 = 0.005
  const double b = 0.1, h = 0.2, t1 = 0.01, t2 = 0.005;
  const BeamSection s = beam_section("BOX", {b, h, t1, t2});
  const double hw = h - 2 * t1;  // side walls between the top and bottom walls
  EXPECT_NEAR(s.A, 2 * b * t1 + 2 * t2 * hw, 1e-15);
  EXPECT_NEAR(s.I1, 2 * rect_Izz(b, t1, (h - t1) / 2) + 2 * rect_Izz(t2, hw, 0), 1e-15);
  EXPECT_NEAR(s.I2, 2 * (t1 * b * b * b / 12) + 2 * (hw * t2 * t2 * t2 / 12 + hw * t2 * std::pow((b - t2) / 2, 2)), 1e-15);
  // Bredt-Batho: J = 4 Am^2 / sum(s/t) on the wall mid-lines
  const double bm = b - t2, hm = h - t1;
  EXPECT_NEAR(s.J, 4 * std::pow(bm * hm, 2) / (2 * bm / t1 + 2 * hm / t2), 1e-15);
}

TEST(BeamSection, IFromItsThreePlates) {
  // Unequal flanges: height 0.3, bottom 0.2 x 0.02, top 0.1 x 0.01, web 0.008.
  const double H = 0.3, wb = 0.2, wt = 0.1, tw = 0.008, tb = 0.02, tt = 0.01;
  const BeamSection s = beam_section("I", {H, wb, wt, tw, tb, tt});
  const double hw = H - tb - tt;
  const double A = wb * tb + wt * tt + tw * hw;
  EXPECT_NEAR(s.A, A, 1e-15);
  const double yc = (wb * tb * tb / 2 + wt * tt * (H - tt / 2) + tw * hw * (tb + hw / 2)) / A;  // from the bottom
  const double I1 = rect_Izz(wb, tb, tb / 2 - yc) + rect_Izz(wt, tt, H - tt / 2 - yc) + rect_Izz(tw, hw, tb + hw / 2 - yc);
  EXPECT_NEAR(s.I1, I1, 1e-14);
  EXPECT_NEAR(s.I2, (tb * wb * wb * wb + tt * wt * wt * wt + hw * tw * tw * tw) / 12, 1e-15);
  EXPECT_NEAR(s.J, (wb * tb * tb * tb + wt * tt * tt * tt + (H - (tb + tt) / 2) * tw * tw * tw) / 3, 1e-15);
  // symmetric I: the familiar (B H^3 - (B - tw) hw^3) / 12
  const BeamSection sym = beam_section("I", {0.3, 0.15, 0.15, 0.01, 0.02, 0.02});
  EXPECT_NEAR(sym.I1, (0.15 * std::pow(0.3, 3) - 0.14 * std::pow(0.26, 3)) / 12, 1e-14);
}

TEST(BeamSection, RejectsWhatIsNoSection) {
  // User input errors: each refused with a message naming the section type and what is wrong.
  auto message = [](const char* type, const std::vector<double>& dims) {
    try {
      beam_section(type, dims);
    } catch (const seflex::InputError& e) {
      return std::string(e.what());
    }
    return std::string("(no InputError)");
  };
  const std::pair<std::string, std::string> cases[] = {
      // not in the QRG standard library
      {message("NACA", {1, 1, .1, .1}), "section TYPE NACA is not supported; expected one of "},
      // web thicker than the channel is wide
      {message("CHAN", {1, 1, 1.2, .1}), "CHAN section: web thickness DIM3 not smaller than the width DIM1 (1.2 >= 1)"},
      {message("BAR", {1}), "BAR section: has 1 dimensions; expected 2"},
      {message("BAR", {1, 0}), "BAR section: DIM2 = 0; expected a dimension > 0"},
      {message("BAR", {1, std::nan("")}), "BAR section: DIM2 = nan; expected a dimension > 0"},
      {message("TUBE", {1, 1.5}), "TUBE section: DIM2 (inner radius 1.5) must be smaller than DIM1 (outer radius 1)"},
      {message("BOX", {1, 1, .5, .1}), "BOX section: two walls of thickness DIM3 = 0.5 do not fit in the height DIM2 = 1"},
      {message("I", {1, 1, 1, .1, .6, .5}), "I section: the flanges DIM5 + DIM6 = 1.1 are not thinner than the height DIM1 = 1"},
  };
  for (const auto& [msg, expected] : cases) EXPECT_EQ(msg.rfind(expected, 0), 0u) << msg;
  EXPECT_EQ(seflex::fem::section_dimension_count("I"), 6);
  EXPECT_EQ(seflex::fem::section_dimension_count("Z"), 4);
  EXPECT_EQ(seflex::fem::section_dimension_count("DBOX"), 10);
  EXPECT_EQ(seflex::fem::section_dimension_count("NACA"), 0);
}
