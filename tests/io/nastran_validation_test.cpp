// The validation decks (tests/data/validation, MYSTRAN 12.0 benchmark archive; provenance in its
// README.md) read without error; their unsupported cards are listed with the first line where they
// occur (found here by a plain text search of the deck), and the cards' values are the ones written
// in the decks.
#include <gtest/gtest.h>

#include <sstream>

#include "seflex/fem/components.hpp"
#include "seflex/fem/finalize.hpp"
#include "seflex/io/nastran.hpp"
#include "test_support.hpp"

using namespace seflex;

namespace {

std::filesystem::path deck(const char* rel) { return test::validation_dir() / rel; }

/// 1-based line of the first line starting with `prefix` (0 if none): an independent text search.
std::uint32_t first_line_starting(const std::filesystem::path& p, const std::string& prefix) {
  std::istringstream in(test::read_file(p));
  std::string line;
  for (std::uint32_t n = 1; std::getline(in, line); ++n)
    if (line.rfind(prefix, 0) == 0) return n;
  return 0;
}

void expect_unsupported(const fem::Model& m, const std::filesystem::path& p, const std::string& name, std::size_t count) {
  for (const auto& u : m.unsupported)
    if (u.name == name) {
      EXPECT_EQ(u.count, count) << name;
      EXPECT_EQ(u.first.file, 0u);
      EXPECT_EQ(u.first.line, first_line_starting(p, name)) << name;
      return;
    }
  ADD_FAILURE() << name << " not listed as unsupported";
}

const fem::Grid& grid(const fem::Model& m, int id) { return m.grids.at(m.grid_index.at(id)); }

}  // namespace

TEST(NastranValidationDecks, CantileverBar) {
  const auto p = deck("mystran_cbar_cantilever_and_freefree_modes/BAR-CC-GIV.DAT");
  const fem::Model m = io::read_nastran(p);
  ASSERT_TRUE(m.finalized);
  EXPECT_EQ(m.grids.size(), 5u);
  EXPECT_EQ(m.bars.size(), 4u);
  ASSERT_EQ(m.unsupported.size(), 1u);
  expect_unsupported(m, p, "DEBUG", 3);
  EXPECT_EQ(m.card_counts.at("PARAM"), 31u);
  // case control
  EXPECT_EQ(m.case_control.sol.value_or(""), "3");
  EXPECT_EQ(m.case_control.title, "BAR WITH 4 ELEMENTS");
  EXPECT_EQ(m.case_control.subtitle, "FIXED BASE EIGENVALUES - GIV");
  EXPECT_EQ(m.case_control.global.spc.value_or(0), 1);
  EXPECT_EQ(m.case_control.global.method.value_or(0), 1);
  // GRDSET "12 4 6" (embedded blanks) on every grid
  for (const auto& g : m.grids) EXPECT_EQ(fem::component_string(g.ps), "1246") << g.id;
  EXPECT_DOUBLE_EQ(grid(m, 5).x_basic.x(), 100.0);
  // MAT1 20: E = 10.+06, NU = .3, RHO = .1; G blank -> E / (2 (1 + NU))
  ASSERT_EQ(m.mat1.size(), 1u);
  EXPECT_DOUBLE_EQ(m.mat1[0].E, 1.0e7);
  EXPECT_DOUBLE_EQ(m.mat1[0].G, 1.0e7 / 2.6);
  EXPECT_DOUBLE_EQ(m.mat1[0].rho, 0.1);
  // PBAR 25 and the bars' orientation
  EXPECT_DOUBLE_EQ(m.bar_props[0].A, 0.1);
  EXPECT_DOUBLE_EQ(m.bar_props[0].J, 0.1);
  EXPECT_DOUBLE_EQ(m.bar_props[0].K1, 0.0);
  for (const auto& b : m.bars) EXPECT_EQ(b.v, Eigen::Vector3d(0, 0, 1));
  // SPC1 1 35 1; EIGR 1 GIV ND 4 NORM MAX; PARAM WTMASS .002591, GRDPNT 0
  ASSERT_EQ(m.spcs.size(), 1u);
  EXPECT_EQ(fem::component_string(m.spcs[0].c), "35");
  EXPECT_EQ(m.spcs[0].grid, 1);
  ASSERT_EQ(m.eigen_methods.size(), 1u);
  EXPECT_EQ(m.eigen_methods[0].method, "GIV");
  EXPECT_EQ(m.eigen_methods[0].nd.value_or(0), 4);
  EXPECT_EQ(m.eigen_methods[0].norm, "MAX");
  EXPECT_DOUBLE_EQ(fem::param_number(m, "WTMASS", 1.0), 0.002591);
  EXPECT_DOUBLE_EQ(fem::param_number(m, "GRDPNT", -1.0), 0.0);
}

TEST(NastranValidationDecks, FreeFreeBar) {
  const auto p = deck("mystran_cbar_cantilever_and_freefree_modes/BAR-FF-GIV.DAT");
  const fem::Model m = io::read_nastran(p);
  expect_unsupported(m, p, "DEBUG", 3);
  EXPECT_FALSE(m.case_control.global.spc.has_value());
  EXPECT_EQ(m.case_control.subtitle, "FREE-FREE EIGENVALUES - GIV");
  ASSERT_EQ(m.eigen_methods.size(), 1u);
  EXPECT_EQ(m.eigen_methods[0].norm, "POINT");
  EXPECT_EQ(m.eigen_methods[0].norm_grid, 5);
  EXPECT_EQ(m.eigen_methods[0].norm_component, 3);
}

TEST(NastranValidationDecks, CraigBamptonFrame) {
  for (const char* rel : {"mystran_craig_bampton_cbar_frame/CB-EXAMPLE-12.DAT",
                          "mystran_craig_bampton_cbar_frame/CB-EXAMPLE-12_noOUTPUT4.DAT"}) {
    const auto p = deck(rel);
    const fem::Model m = io::read_nastran(p);
    EXPECT_EQ(m.case_control.sol.value_or(""), "31");
    EXPECT_EQ(m.case_control.subtitle, "FRAME USING CBAR's");
    expect_unsupported(m, p, "DEBUG", 2);
    EXPECT_EQ(m.grids.size(), 7u);
    EXPECT_EQ(m.bars.size(), 10u);
    // CBAR 101 +C1: PA = 56, PB = 456
    const fem::Bar& b = m.bars[0];
    EXPECT_EQ(b.id, 101);
    EXPECT_EQ(fem::component_string(b.pa), "56");
    EXPECT_EQ(fem::component_string(b.pb), "456");
    EXPECT_EQ(b.v, Eigen::Vector3d(0.0, 0.5, 1.0));
    // CONM2 901..905: 150. at an offset of -5 in z, CID blank
    ASSERT_EQ(m.conm2.size(), 5u);
    for (const auto& c : m.conm2) {
      EXPECT_DOUBLE_EQ(c.m, 150.0);
      EXPECT_EQ(c.x, Eigen::Vector3d(0, 0, -5));
      EXPECT_EQ(c.cid, 0);
    }
    ASSERT_EQ(m.rbe2.size(), 1u);
    EXPECT_EQ(m.rbe2[0].gn, 31);
    EXPECT_EQ(m.rbe2[0].gm, std::vector<int>{32});
    // SUPORT 11 123 12 23 13 123
    ASSERT_EQ(m.suport.size(), 3u);
    EXPECT_EQ(fem::component_string(m.suport[1].c), "23");
    EXPECT_EQ(m.suport[2].grid, 13);
    // EIGRL 1 ND 3 NORM MASS; EIGR 2 MGIV NE 1 ND 24 NORM MASS
    ASSERT_EQ(m.eigen_methods.size(), 2u);
    EXPECT_EQ(m.eigen_methods[0].nd.value_or(0), 3);
    EXPECT_EQ(m.eigen_methods[1].method, "MGIV");
    EXPECT_EQ(m.eigen_methods[1].nd.value_or(0), 24);
    EXPECT_DOUBLE_EQ(m.bar_props[2].A, 6.0);
  }
  const auto p = deck("mystran_craig_bampton_cbar_frame/CB-EXAMPLE-12.DAT");
  expect_unsupported(io::read_nastran(p), p, "PARVEC", 69);
}

TEST(NastranValidationDecks, MixedElements) {
  const auto p = deck("mystran_mixed_cbar_crod_cquad4_ctria3_celas_modes/ALL-ELEM-TEST-GIV.DAT");
  const fem::Model m = io::read_nastran(p);
  expect_unsupported(m, p, "DEBUG", 3);
  EXPECT_EQ(m.unsupported.size(), 1u);
  // PLOAD2 1991 -.75 on CQUAD4 11, 12 and CTRIA3 21-24 (read since PLOAD2 is supported)
  ASSERT_EQ(m.pressure_loads.size(), 1u);
  EXPECT_EQ(m.pressure_loads[0].sid, 1991);
  EXPECT_DOUBLE_EQ(m.pressure_loads[0].p, -0.75);
  EXPECT_EQ(m.pressure_loads[0].elements, (std::vector<int>{11, 12, 21, 22, 23, 24}));
  EXPECT_FALSE(m.pressure_loads[0].thru);
  EXPECT_EQ(m.case_control.global.label, "EIGENVALUES");
  EXPECT_EQ(m.case_control.global.spc.value_or(0), 998);
  EXPECT_EQ(m.case_control.global.method.value_or(0), 2);
  EXPECT_EQ(m.bars.size(), 14u);
  EXPECT_EQ(m.rods.size(), 6u);
  EXPECT_EQ(m.shells.size(), 6u);
  EXPECT_EQ(m.springs.size(), 1u);
  // BAROR gives every CBAR its orientation (0, 0, 1)
  for (const auto& b : m.bars) EXPECT_EQ(b.v, Eigen::Vector3d(0, 0, 1)) << b.id;
  // MAT1 20 with E, G and NU all given, and its continuation
  EXPECT_DOUBLE_EQ(m.mat1[0].E, 1.0e7);
  EXPECT_DOUBLE_EQ(m.mat1[0].G, 4.0e6);
  EXPECT_DOUBLE_EQ(m.mat1[0].nu, 0.25);
  // PSHELL 91: MID1 = MID2 = MID3 = 20, T = .125, 12I/T^3 blank = 1, TS/T blank = .833333
  const fem::ShellProperty& s = m.shell_props[0];
  EXPECT_EQ(s.mid2, 20);
  EXPECT_EQ(s.mid3, 20);
  EXPECT_DOUBLE_EQ(s.t, 0.125);
  EXPECT_DOUBLE_EQ(s.bend_ratio, 1.0);
  EXPECT_DOUBLE_EQ(s.ts_t, 0.833333);
  // PBAR 97/98: the continuation holds stress points, so K1 = K2 = 0 (no shear flexibility)
  for (const auto& b : m.bar_props) {
    EXPECT_DOUBLE_EQ(b.K1, 0.0);
    EXPECT_DOUBLE_EQ(b.A, 2.0);
  }
  EXPECT_DOUBLE_EQ(m.bar_props[1].I1, 8.0);
  // CELAS1 58 -> PELAS 75: K = 1.5E+4, GE blank, S = .75
  EXPECT_DOUBLE_EQ(m.spring_props[0].k, 1.5e4);
  EXPECT_DOUBLE_EQ(m.spring_props[0].s, 0.75);
  EXPECT_EQ(m.springs[0].g2, 1051);
  // GRID 1051 PS 123456; GRID 1013 has a '1' in field 10, which is ignored
  EXPECT_EQ(grid(m, 1051).ps, 0b111111);
  EXPECT_EQ(grid(m, 1013).ps, 0);
  EXPECT_EQ(grid(m, 1013).cd, 0);
  // SPC1 998 "12 456" on 1041..1043
  ASSERT_EQ(m.spcs.size(), 6u);
  EXPECT_EQ(fem::component_string(m.spcs[5].c), "12456");
  EXPECT_EQ(m.spcs[5].grid, 1043);
  ASSERT_EQ(m.point_loads.size(), 3u);
  EXPECT_EQ(m.point_loads[0].n, Eigen::Vector3d(0, 1, -3));
}

TEST(NastranValidationDecks, DemonstrationMeshes) {
  // meshes/*.bdf (solar-array.md): read without unsupported cards.
  for (const char* name : {"yoke.bdf", "panel.bdf"}) {
    const fem::Model m = io::read_nastran(test::source_dir() / "meshes" / name);
    EXPECT_TRUE(m.unsupported.empty()) << name;
    EXPECT_GT(m.conm2.size(), 10u) << name;
  }
}

TEST(NastranValidationDecks, InfoCommandListsCountsAndUnsupportedCards) {
  const auto p = deck("mystran_craig_bampton_cbar_frame/CB-EXAMPLE-12.DAT");
  const auto r = test::run_seflex("info '" + p.string() + "'");
  ASSERT_EQ(r.exit_code, 0) << r.err;
  // the line of a table that starts with `label`, its words
  auto row = [&](const std::string& label) {
    std::istringstream in(r.out);
    std::string line;
    while (std::getline(in, line)) {
      std::istringstream words(line);
      std::string first;
      words >> first;
      if (first == label) {
        std::vector<std::string> w{first};
        for (std::string x; words >> x;) w.push_back(x);
        return w;
      }
    }
    return std::vector<std::string>{};
  };
  EXPECT_EQ(row("solution"), (std::vector<std::string>{"solution", "SOL", "31"}));
  EXPECT_EQ(row("grids"), (std::vector<std::string>{"grids", "7"}));
  EXPECT_EQ(row("CBAR"), (std::vector<std::string>{"CBAR", "10"}));
  const std::string first = p.string() + ":" + std::to_string(first_line_starting(p, "PARVEC"));
  EXPECT_EQ(row("PARVEC"), (std::vector<std::string>{"PARVEC", "69", "first", "at", first}));
}
