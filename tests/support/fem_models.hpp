#pragma once
// FE models built in code for the solution tests (the fem tests' builders, plus a plate).
#include "fem_test_util.hpp"

namespace seflex::test {

using fem::test::add_cbar;
using fem::test::add_grid;
using fem::test::add_mat1;
using fem::test::add_pbar;
using fem::test::add_pshell;
using fem::test::add_shell;
using fem::test::add_spc1;
using fem::test::finalize_for_test;
using fem::test::mask;

/// The bar of the MYSTRAN decks BAR-CC-GIV / BAR-FF-GIV, transcribed card by card: 4 CBARs of
/// 25 along basic x, PBAR 25 (A = I1 = I2 = J = 0.1), MAT1 20 (E = 1e7, nu = 0.3, rho = 0.1),
/// GRDSET PS 1246, PARAM WTMASS 0.002591; EIGR 1 with ND = 4. `cantilever` adds SPC1 1 35 1 and
/// selects it (SPC = 1), NORM = MAX; otherwise NORM = POINT grid 5 component 3 (BAR-FF).
inline fem::Model mystran_bar(bool cantilever) {
  fem::Model m;
  m.files = {cantilever ? "BAR-CC-GIV.DAT" : "BAR-FF-GIV.DAT"};
  m.grdset.present = true;
  m.grdset.ps = mask("1246");
  for (int i = 0; i <= 4; ++i) add_grid(m, i + 1, 25.0 * i, 0, 0);
  add_mat1(m, 20, 1.0e7, 0.3, 0.1);
  add_pbar(m, 25, 20, 0.1, 0.1, 0.1, 0.1);
  const int ids[4] = {102, 203, 304, 405};
  for (int i = 0; i < 4; ++i) add_cbar(m, ids[i], 25, i + 1, i + 2, {0, 0, 1});
  m.params.push_back(fem::Param{"WTMASS", {".002591"}, {}});
  fem::EigenMethod method;
  method.sid = 1;
  method.is_eigr = true;
  method.method = "GIV";
  method.nd = 4;
  if (cantilever) {
    method.norm = "MAX";
    add_spc1(m, 1, mask("35"), 1);
    m.case_control.global.spc = 1;
  } else {
    method.norm = "POINT";
    method.norm_grid = 5;
    method.norm_component = 3;
  }
  m.eigen_methods.push_back(method);
  m.case_control.global.method = 1;
  finalize_for_test(m);
  return m;
}

/// A flat rectangular plate a x b in the basic x-y plane, nx x ny CQUAD4 (PSHELL 1, MAT1 1), grid
/// ids 1 + i + (nx + 1) j. Not finalized (add constraints first).
inline fem::Model quad_plate(int nx, int ny, double a, double b, double t, double E, double nu, double rho) {
  fem::Model m;
  m.files = {"plate.bdf"};
  for (int j = 0; j <= ny; ++j)
    for (int i = 0; i <= nx; ++i) add_grid(m, 1 + i + (nx + 1) * j, a * i / nx, b * j / ny, 0);
  add_mat1(m, 1, E, nu, rho);
  add_pshell(m, 1, 1, t);
  int id = 1;
  for (int j = 0; j < ny; ++j)
    for (int i = 0; i < nx; ++i) {
      const int g = 1 + i + (nx + 1) * j;
      add_shell(m, id++, 1, {g, g + 1, g + 1 + (nx + 1), g + (nx + 1)});
    }
  return m;
}

}  // namespace seflex::test
