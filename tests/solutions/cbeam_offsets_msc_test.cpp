// pyNastran's cantilever_2014.1.bdf (tests/data/pynastran/cantilever_2014.1, README there): an MSC
// Patran 2014.1 channel-section cantilever of 10 CBEAMs whose shear centre is offset from the grids
// (WA = WB = 0.438 along basic y), a PBEAM with the neutral axis off the shear centre (N2(A) = N2(B) =
// 0.754758), a warping coefficient CW = 10.9761 without SA/SB, shear factors K1/K2, and a tip FORCE of
// 1000 along -z, against MSC Nastran 2014.1's displacements and CBEAM forces in the deck's OP2.
#include <gtest/gtest.h>

#include <Eigen/Core>
#include <algorithm>
#include <cmath>
#include <fstream>
#include <sstream>
#include <string>
#include <vector>

#include "nastran_test_util.hpp"
#include "test_support.hpp"
#include "seflex/fem/element_bar.hpp"
#include "seflex/fem/element_results.hpp"
#include "seflex/fem/finalize.hpp"
#include "seflex/solutions/statics.hpp"

namespace seflex {
namespace {

std::vector<std::vector<double>> read_csv(const std::filesystem::path& file) {
  std::ifstream in(file);
  std::string line;
  std::getline(in, line);  // header
  std::vector<std::vector<double>> rows;
  while (std::getline(in, line)) {
    std::istringstream row(line);
    std::vector<double> v;
    for (std::string f; std::getline(row, f, ',');) v.push_back(std::stod(f));
    rows.push_back(v);
  }
  return rows;
}

const std::filesystem::path kDir = test::data_dir() / "pynastran/cantilever_2014.1";

// The PBEAM's offsets are read (element z of the neutral axis, end B as written) and the deck lists
// no unsupported card: CW acts only through a CBEAM's SA/SB (QRG CBEAM remarks 5-6), which it has not.
TEST(CbeamOffsets, Cantilever2014ReadWithoutUnsupportedCards) {
  const fem::Model m = io::read_nastran(kDir / "cantilever_2014.1.bdf");
  ASSERT_EQ(m.bar_props.size(), 1u);
  const fem::BarProperty& p = m.bar_props[0];
  EXPECT_EQ(p.n_A[0], 0.0);
  EXPECT_EQ(p.n_A[1], 0.754758);
  EXPECT_EQ(p.n_B[1], 0.754758);
  EXPECT_EQ(p.m_A[1], 0.0);
  EXPECT_NEAR(p.K1, 0.728814, 1e-15);
  for (const auto& u : m.unsupported)  // PARAM POST and PRTMAXIM are listed as parameters seflex does not use
    EXPECT_TRUE(u.name.find("BEAM") == std::string::npos) << "listed as unsupported: " << u.name;
}

// Statics against MSC's OUGV1 (single precision, 7 digits in the CSV): the tip deflection is the
// shear-centre twist T L / (G J) (T = 1000 x 0.438) times the 0.438 arm, plus bending P L^3 / 3 E I1
// and shear P L / (G K1 A); a warping stiffness E CW would have cut the twist (it did not: MSC's
// warping torque is 0). The neutral-axis offset (along element z, the plane of the web) does not
// couple with this load: no axial force. Every component of every grid agrees to 2e-7 of the largest
// translation and rotation (measured 3.8e-8 and 7.5e-8: MSC's single precision).
TEST(CbeamOffsets, Cantilever2014AgainstMscNastran) {
  const fem::Model m = io::read_nastran(kDir / "cantilever_2014.1.bdf");
  const auto s = solutions::solve_static(m);
  const auto ref = read_csv(kDir / "cantilever_2014.1_nastran_displacements.csv");
  ASSERT_EQ(ref.size(), 11u);
  double scale_t = 0, scale_r = 0, worst_t = 0, worst_r = 0;
  for (const auto& r : ref) {
    const int id = static_cast<int>(r[0]);
    for (int c = 0; c < 6; ++c) {
      const double u = s.u_g[*fem::find_dof(m, s.dofs, id, c + 1)];  // CD blank: basic
      (c < 3 ? scale_t : scale_r) = std::max(c < 3 ? scale_t : scale_r, std::abs(r[1 + c]));
      (c < 3 ? worst_t : worst_r) = std::max(c < 3 ? worst_t : worst_r, std::abs(u - r[1 + c]));
    }
  }
  EXPECT_NEAR(scale_t, 0.2753973, 1e-7);
  EXPECT_LE(worst_t, 2e-7 * scale_t);
  EXPECT_LE(worst_r, 2e-7 * scale_r);
  // the closed form of the tip (L = 10, E = 2e6, nu = 0.3: G = E / 2.6)
  const double L = 10, E = 2e6, G = E / 2.6, P = 1000, arm = 0.438;
  const double twist = P * arm * L / (G * 0.00960286);
  const double w = arm * twist + P * L * L * L / (3 * E * 27.7245) + P * L / (G * 0.728814 * 1.84375);
  EXPECT_NEAR(s.u_g[*fem::find_dof(m, s.dofs, 11, 4)], twist, 1e-12 * twist);
  EXPECT_NEAR(s.u_g[*fem::find_dof(m, s.dofs, 11, 3)], -w, 1e-12 * w);
}

// CBEAM forces against MSC's OEF1X at both ends of each element (bm1, bm2, ts1, ts2, af, ttrq; the
// torque about the shear centre, 438 = 1000 x 0.438): to 1e-8 of the largest moment (measured 2.6e-9).
TEST(CbeamOffsets, Cantilever2014ForcesAgainstMscNastran) {
  const fem::Model m = io::read_nastran(kDir / "cantilever_2014.1.bdf");
  const auto s = solutions::solve_static(m);
  const auto ref = read_csv(kDir / "cantilever_2014.1_nastran_beam_forces.csv");
  ASSERT_EQ(ref.size(), 20u);
  double worst = 0;
  for (const auto& r : ref) {
    const int eid = static_cast<int>(r[0]);
    const auto it = std::find_if(m.bars.begin(), m.bars.end(), [&](const fem::Bar& b) { return b.id == eid; });
    ASSERT_NE(it, m.bars.end());
    const fem::BarElement e = fem::make_bar_element(m, *it);
    Eigen::Matrix<double, 12, 1> u;
    for (int c = 0; c < 6; ++c) {
      u(c) = s.u_g[*fem::find_dof(m, s.dofs, it->ga, c + 1)];
      u(6 + c) = s.u_g[*fem::find_dof(m, s.dofs, it->gb, c + 1)];
    }
    const Eigen::Matrix<double, 8, 1> f = fem::bar_results(e, u);  // M1A M2A M1B M2B V1 V2 N T
    const bool end_b = r[2] == 1.0;
    const double ours[6] = {f(end_b ? 2 : 0), f(end_b ? 3 : 1), f(4), f(5), f(6), f(7)};
    for (int k = 0; k < 6; ++k) worst = std::max(worst, std::abs(ours[k] - r[3 + k]));
    EXPECT_EQ(r[9], 0.0);  // MSC's warping torque
  }
  EXPECT_LE(worst, 1e-8 * 10000);  // measured 2.6e-5 (2.6e-9 of the root moment)
}

}  // namespace
}  // namespace seflex
