// The PBARL/PBEAML section library (fem/beam_section.hpp): every type against closed-form section
// properties computed here independently, from the outline of the section as the MSC QRG figures
// draw it (dimension meanings as in pyNastran's bdf/cards/properties/bars.py, read only), with
// Green's theorem on the polygon (exact for any polygon; holes subtracted):
//   A = 1/2 sum c_i, int y^2 dA = 1/12 sum (y_i^2 + y_i y_i+1 + y_i+1^2) c_i, ...,
//   c_i = z_i y_i+1 - z_i+1 y_i   (e.g. Steger, "On the calculation of moments of polygons", 1996).
// Torsion: closed cells against Bredt-Batho, a symmetric two-cell box against the single-cell
// formula on its outer walls (by symmetry the middle wall carries no shear flow), thin open sections
// against the mid-line formula sum b t^3/3 (Roark, 7th ed., table 10.7 case 26) within the wall
// thickness ratio.
#include <gtest/gtest.h>

#include <array>
#include <cmath>
#include <map>
#include <sstream>
#include <string>
#include <vector>

#include "nastran_test_util.hpp"
#include "seflex/common/error.hpp"
#include "seflex/fem/beam_section.hpp"
#include "seflex/io/nastran_writer.hpp"

namespace seflex {
namespace {

using Poly = std::vector<std::array<double, 2>>;  // (z, y) vertices, counter-clockwise

struct Props {
  double A = 0, I1 = 0, I2 = 0, I12 = 0;
};

/// Area integrals of a counter-clockwise polygon about the origin: A, int z, int y, int y^2, int z^2, int y z.
std::array<double, 6> integrals(const Poly& p) {
  std::array<double, 6> s{};
  for (std::size_t i = 0; i < p.size(); ++i) {
    const double z0 = p[i][0], y0 = p[i][1], z1 = p[(i + 1) % p.size()][0], y1 = p[(i + 1) % p.size()][1];
    const double c = z0 * y1 - z1 * y0;
    s[0] += c / 2;
    s[1] += (z0 + z1) * c / 6;
    s[2] += (y0 + y1) * c / 6;
    s[3] += (y0 * y0 + y0 * y1 + y1 * y1) * c / 12;
    s[4] += (z0 * z0 + z0 * z1 + z1 * z1) * c / 12;
    s[5] += (z0 * y1 + 2 * z0 * y0 + 2 * z1 * y1 + z1 * y0) * c / 24;
  }
  return s;
}

Poly rect(double z0, double z1, double y0, double y1) { return {{z0, y0}, {z1, y0}, {z1, y1}, {z0, y1}}; }

/// Centroidal properties of an outline minus holes.
Props polygon(const Poly& outer, const std::vector<Poly>& holes = {}) {
  std::array<double, 6> s = integrals(outer);
  for (const Poly& h : holes) {
    const auto t = integrals(h);
    for (int k = 0; k < 6; ++k) s[k] -= t[k];
  }
  Props p;
  p.A = s[0];
  const double zc = s[1] / s[0], yc = s[2] / s[0];
  p.I1 = s[3] - p.A * yc * yc;
  p.I2 = s[4] - p.A * zc * zc;
  p.I12 = s[5] - p.A * yc * zc;
  return p;
}

void expect_props(const std::string& type, const std::vector<double>& d, const Props& ref) {
  const fem::BeamSection s = fem::beam_section(type, d);
  const double scale = std::max(ref.I1, ref.I2);
  EXPECT_NEAR(s.A, ref.A, 1e-12 * ref.A) << type;
  EXPECT_NEAR(s.I1, ref.I1, 1e-11 * scale) << type;
  EXPECT_NEAR(s.I2, ref.I2, 1e-11 * scale) << type;
  EXPECT_NEAR(s.I12, ref.I12, 1e-11 * scale) << type;
  EXPECT_GT(s.J, 0.0) << type;
  EXPECT_GE(s.K1, 0.0) << type;
  EXPECT_GE(s.K2, 0.0) << type;
  EXPECT_LE(s.K1, 1.0) << type;
  EXPECT_LE(s.K2, 1.0) << type;
}

TEST(BeamSectionLibrary, OpenSectionsAgainstTheirOutlines) {
  {  // T: DIM1 flange width b, DIM2 height h, DIM3 flange thickness, DIM4 web thickness
    const double b = 0.08, h = 0.1, tf = 0.006, tw = 0.004;
    expect_props("T", {b, h, tf, tw},
                 polygon({{-tw / 2, 0}, {tw / 2, 0}, {tw / 2, h - tf}, {b / 2, h - tf}, {b / 2, h}, {-b / 2, h}, {-b / 2, h - tf}, {-tw / 2, h - tf}}));
  }
  {  // T1: DIM1 flange height, DIM2 web length, DIM3 flange thickness, DIM4 web thickness
    const double d1 = 0.09, d2 = 0.07, d3 = 0.008, d4 = 0.005;
    expect_props("T1", {d1, d2, d3, d4},
                 polygon({{0, -d1 / 2}, {d3, -d1 / 2}, {d3, -d4 / 2}, {d3 + d2, -d4 / 2}, {d3 + d2, d4 / 2}, {d3, d4 / 2}, {d3, d1 / 2}, {0, d1 / 2}}));
  }
  {  // T2: flange at the bottom
    const double d1 = 0.08, d2 = 0.1, d3 = 0.006, d4 = 0.004;
    expect_props("T2", {d1, d2, d3, d4},
                 polygon({{-d1 / 2, 0}, {d1 / 2, 0}, {d1 / 2, d3}, {d4 / 2, d3}, {d4 / 2, d2}, {-d4 / 2, d2}, {-d4 / 2, d3}, {-d1 / 2, d3}}));
  }
  {  // L: unequal legs, non-zero I12
    const double d1 = 0.06, d2 = 0.1, d3 = 0.005, d4 = 0.007;
    const Props p = polygon({{0, 0}, {d1, 0}, {d1, d3}, {d4, d3}, {d4, d2}, {0, d2}});
    EXPECT_LT(p.I12, 0.0);  // the legs point to +z and +y from the corner: the mass lies along y z < 0 about the centroid
    expect_props("L", {d1, d2, d3, d4}, p);
  }
  {  // CHAN: DIM1 width incl. web, DIM2 height, DIM3 web, DIM4 flange thickness
    const double d1 = 0.05, d2 = 0.12, d3 = 0.005, d4 = 0.008;
    expect_props("CHAN", {d1, d2, d3, d4},
                 polygon({{0, 0}, {d1, 0}, {d1, d4}, {d3, d4}, {d3, d2 - d4}, {d1, d2 - d4}, {d1, d2}, {0, d2}}));
  }
  {  // CHAN1: DIM1 flange width beyond the web, DIM2 web, DIM3 clear height, DIM4 height
    const double d1 = 0.045, d2 = 0.005, d3 = 0.1, d4 = 0.116, tf = (d4 - d3) / 2, W = d1 + d2;
    expect_props("CHAN1", {d1, d2, d3, d4},
                 polygon({{0, 0}, {W, 0}, {W, tf}, {d2, tf}, {d2, d4 - tf}, {W, d4 - tf}, {W, d4}, {0, d4}}));
  }
  {  // CHAN2: DIM1 legs, DIM2 base, DIM3 height, DIM4 width
    const double d1 = 0.006, d2 = 0.008, d3 = 0.05, d4 = 0.1, b = d4 / 2;
    expect_props("CHAN2", {d1, d2, d3, d4},
                 polygon({{-b, 0}, {b, 0}, {b, d3}, {b - d1, d3}, {b - d1, d2}, {-b + d1, d2}, {-b + d1, d3}, {-b, d3}}));
  }
  {  // Z: anti-symmetric, non-zero I12
    const double d1 = 0.04, d2 = 0.005, d3 = 0.1, d4 = 0.112, tf = (d4 - d3) / 2, w = d2 / 2, h = d4 / 2;
    const Props p = polygon({{w, -h}, {w + d1, -h}, {w + d1, -h + tf}, {w, -h + tf}, {w, h}, {-w - d1, h}, {-w - d1, h - tf}, {-w, h - tf}, {-w, -h}});
    EXPECT_LT(p.I12, 0.0);
    expect_props("Z", {d1, d2, d3, d4}, p);
  }
  {  // I1: DIM1 both overhangs, DIM2 web, DIM3 clear height, DIM4 height
    const double d1 = 0.07, d2 = 0.006, d3 = 0.1, d4 = 0.12, tf = (d4 - d3) / 2, bf = (d1 + d2) / 2, t = d2 / 2;
    expect_props("I1", {d1, d2, d3, d4},
                 polygon({{-bf, 0}, {bf, 0}, {bf, tf}, {t, tf}, {t, d4 - tf}, {bf, d4 - tf}, {bf, d4}, {-bf, d4},
                          {-bf, d4 - tf}, {-t, d4 - tf}, {-t, tf}, {-bf, tf}}));
    // the same doubly symmetric I through TYPE I (h, bottom and top flange widths, web, flange thicknesses)
    const fem::BeamSection i1 = fem::beam_section("I1", {d1, d2, d3, d4}), i = fem::beam_section("I", {d4, d1 + d2, d1 + d2, d2, tf, tf});
    EXPECT_NEAR(i1.I1, i.I1, 1e-12 * i.I1);
    EXPECT_NEAR(i1.I2, i.I2, 1e-12 * i.I1);
  }
  {  // H: DIM1 web length, DIM2 both flange thicknesses, DIM3 flange height, DIM4 web thickness
    const double d1 = 0.08, d2 = 0.012, d3 = 0.1, d4 = 0.006, a = d1 / 2, b = (d1 + d2) / 2;
    expect_props("H", {d1, d2, d3, d4},
                 polygon({{-b, -d3 / 2}, {-a, -d3 / 2}, {-a, -d4 / 2}, {a, -d4 / 2}, {a, -d3 / 2}, {b, -d3 / 2}, {b, d3 / 2},
                          {a, d3 / 2}, {a, d4 / 2}, {-a, d4 / 2}, {-a, d3 / 2}, {-b, d3 / 2}}));
  }
  {  // CROSS: DIM1 arm length, DIM2 centre width, DIM3 centre height, DIM4 arm thickness
    const double d1 = 0.03, d2 = 0.01, d3 = 0.08, d4 = 0.006, a = d2 / 2;
    expect_props("CROSS", {d1, d2, d3, d4},
                 polygon({{-a, -d3 / 2}, {a, -d3 / 2}, {a, -d4 / 2}, {a + d1, -d4 / 2}, {a + d1, d4 / 2}, {a, d4 / 2}, {a, d3 / 2},
                          {-a, d3 / 2}, {-a, d4 / 2}, {-a - d1, d4 / 2}, {-a - d1, -d4 / 2}, {-a, -d4 / 2}}));
  }
  {  // HAT: DIM1 height, DIM2 thickness, DIM3 top width, DIM4 brim
    const double h = 0.05, t = 0.003, b = 0.04 / 2, d4 = 0.015;
    expect_props("HAT", {h, t, 2 * b, d4},
                 polygon({{-b - d4, 0}, {-b + t, 0}, {-b + t, h - t}, {b - t, h - t}, {b - t, 0}, {b + d4, 0}, {b + d4, t},
                          {b, t}, {b, h}, {-b, h}, {-b, t}, {-b - d4, t}}));
  }
  {  // HEXA: DIM1 tip width, DIM2 width, DIM3 height
    const double t = 0.02, w = 0.1, h = 0.06, c = w - 2 * t;
    expect_props("HEXA", {t, w, h}, polygon({{-c / 2, 0}, {c / 2, 0}, {w / 2, h / 2}, {c / 2, h}, {-c / 2, h}, {-w / 2, h / 2}}));
  }
  {  // TUBE2: outer radius and thickness = TUBE with inner radius r - t
    const fem::BeamSection a = fem::beam_section("TUBE2", {0.05, 0.004}), b = fem::beam_section("TUBE", {0.05, 0.046});
    EXPECT_DOUBLE_EQ(a.A, b.A);
    EXPECT_DOUBLE_EQ(a.I1, b.I1);
    EXPECT_DOUBLE_EQ(a.J, b.J);
  }
}

TEST(BeamSectionLibrary, ClosedSectionsAgainstOutlinesAndBredt) {
  {  // BOX1: DIM1 width, DIM2 height, DIM3 top, DIM4 bottom, DIM5 right, DIM6 left
    const double b = 0.1, h = 0.15, d3 = 0.006, d4 = 0.004, d5 = 0.003, d6 = 0.005;
    expect_props("BOX1", {b, h, d3, d4, d5, d6}, polygon(rect(0, b, 0, h), {rect(d6, b - d5, d4, h - d3)}));
    const double bm = b - (d5 + d6) / 2, hm = h - (d3 + d4) / 2;
    const double J = 4 * bm * bm * hm * hm / (bm / d3 + bm / d4 + hm / d5 + hm / d6);
    EXPECT_NEAR(fem::beam_section("BOX1", {b, h, d3, d4, d5, d6}).J, J, 1e-12 * J);
    // uniform walls: BOX1 = BOX
    const fem::BeamSection box = fem::beam_section("BOX", {b, h, d3, d5}), box1 = fem::beam_section("BOX1", {b, h, d3, d3, d5, d5});
    EXPECT_NEAR(box1.A, box.A, 1e-15);
    EXPECT_NEAR(box1.I1, box.I1, 1e-12 * box.I1);
    EXPECT_NEAR(box1.J, box.J, 1e-12 * box.J);
  }
  {  // HAT1: DIM1 base width, DIM2 height, DIM3 hat width, DIM4 hat thickness, DIM5 base thickness
    const double B = 0.12, h = 0.06, b = 0.07, t = 0.003, tb = 0.005;
    expect_props("HAT1", {B, h, b, t, tb},
                 polygon({{-B / 2, 0}, {B / 2, 0}, {B / 2, tb + t}, {b / 2, tb + t}, {b / 2, h}, {-b / 2, h}, {-b / 2, tb + t}, {-B / 2, tb + t}},
                         {rect(-b / 2 + t, b / 2 - t, tb, h - t)}));
    // its cell is a BOX1 of width DIM3, height DIM2, top/sides DIM4, bottom DIM5 (the brims add no torsion here)
    EXPECT_NEAR(fem::beam_section("HAT1", {B, h, b, t, tb}).J, fem::beam_section("BOX1", {b, h, t, tb, t, t}).J, 1e-12);
  }
  {  // DBOX: 10 dimensions, two cells
    const std::vector<double> d = {0.2, 0.1, 0.1, 0.006, 0.004, 0.006, 0.005, 0.005, 0.005, 0.005};
    const double W = d[0], H = d[1], zm = d[2];
    expect_props("DBOX", d,
                 polygon(rect(0, W, 0, H), {rect(d[3], zm - d[4] / 2, d[7], H - d[6]), rect(zm + d[4] / 2, W - d[5], d[9], H - d[8])}));
    // symmetric: no shear flow in the middle wall, J = Bredt on the outer walls
    const double wm = W - d[3], hm = H - d[6];
    const double J = 4 * wm * wm * hm * hm / (2 * wm / d[6] + 2 * hm / d[3]);
    EXPECT_NEAR(fem::beam_section("DBOX", d).J, J, 1e-12 * J);
  }
}

// Thin walls: the rectangles' sum b t^3 / 3 approaches the mid-line formula as t / b -> 0.
TEST(BeamSectionLibrary, OpenSectionTorsionApproachesThinWallTheory) {
  for (const double t : {0.004, 0.001}) {
    const double b = 0.08, h = 0.1;
    const double mid_T = (b * t * t * t + (h - t / 2) * t * t * t) / 3;
    EXPECT_NEAR(fem::beam_section("T", {b, h, t, t}).J / mid_T, 1.0, 0.6 * t / h) << t;
    const double mid_L = ((b - t / 2) * t * t * t + (h - t / 2) * t * t * t) / 3;
    EXPECT_NEAR(fem::beam_section("L", {b, h, t, t}).J / mid_L, 1.0, 0.6 * t / h) << t;
    const double mid_C = (2 * (b - t / 2) * t * t * t + (h - t) * t * t * t) / 3;
    EXPECT_NEAR(fem::beam_section("CHAN", {b, h, t, t}).J / mid_C, 1.0, 0.6 * t / h) << t;
  }
}

TEST(BeamSectionLibrary, ImpossibleDimensionsAreRefused) {
  const auto message = [](const std::string& type, const std::vector<double>& d) {
    try {
      fem::beam_section(type, d);
    } catch (const InputError& e) {
      return std::string(e.what());
    }
    return std::string();
  };
  EXPECT_TRUE(test::mentions(message("T", {0.08, 0.005, 0.006, 0.004}), {"T section: flange thickness DIM3 not smaller than the height DIM2 (0.006 >= 0.005); expected "
                                                                            "dimensions that describe the section"}));
  EXPECT_TRUE(test::mentions(message("CHAN1", {0.04, 0.005, 0.12, 0.1}), {"CHAN1 section: the clear web height DIM3 is not smaller than the height DIM4 (0.12 >= 0.1)"}));
  EXPECT_TRUE(test::mentions(message("DBOX", {0.2, 0.1, 0.195, 0.006, 0.004, 0.006, 0.005, 0.005, 0.005, 0.005}), {"DBOX section: DIM3 + DIM5/2 + DIM6 reach past the width DIM1 (0.203 >= 0.2)"}));
  EXPECT_TRUE(test::mentions(message("Z", {0.04, 0.005, 0.1}), {"Z section: has 3 dimensions; expected 4"}));
  EXPECT_TRUE(test::mentions(test::read_error("MAT1,1,7.e10,,0.3\nPBARL,1,1,,HAT\n,0.05,0.03,0.04,0.01\n"),
                             {"PBARL 1", "HAT section", "DIM1"}));
}

// A PBARL of a new type through the reader and `seflex convert`: I1 from the outline, kept by the
// round trip (the writer writes TYPE and DIMs).
TEST(BeamSectionLibrary, PbarlTReadAndRoundTrip) {
  const double b = 0.08, h = 0.1, tf = 0.006, tw = 0.004;
  const Props p = polygon({{-tw / 2, 0}, {tw / 2, 0}, {tw / 2, h - tf}, {b / 2, h - tf}, {b / 2, h}, {-b / 2, h}, {-b / 2, h - tf}, {-tw / 2, h - tf}});
  const std::string deck =
      "MAT1,1,7.e10,,0.3,2700.\nPBARL,1,1,,T\n,0.08,0.1,0.006,0.004\nGRID,1,,0.,0.,0.\nGRID,2,,2.,0.,0.\n"
      "CBAR,1,1,1,2,0.,1.,0.\n";
  const fem::Model m = test::read_deck(deck);
  ASSERT_EQ(m.bar_props.size(), 1u);
  EXPECT_NEAR(m.bar_props[0].I1, p.I1, 1e-12 * p.I1);
  std::ostringstream out;
  io::write_nastran(m, out);
  const fem::Model back = test::read_deck(out.str(), "converted.bdf");
  EXPECT_NEAR(back.bar_props[0].I1, p.I1, 1e-12 * p.I1);
  EXPECT_EQ(back.bar_props[0].section_type, "T");
}

}  // namespace
}  // namespace seflex
