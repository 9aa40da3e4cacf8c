#pragma once
// The plate the distributed-backend tests share.
#include "fem_models.hpp"

namespace seflex::test {

/// Aluminium plate 0.6 x 0.4 x 3 mm, nx x ny CQUAD4, one short edge clamped.
inline fem::Model clamped_plate(int nx, int ny) {
  fem::Model m = quad_plate(nx, ny, 0.6, 0.4, 0.003, 7.0e10, 0.33, 2700);
  for (int j = 0; j <= ny; ++j) add_spc1(m, 1, mask("123456"), 1 + (nx + 1) * j);
  m.case_control.global.spc = 1;
  finalize_for_test(m);
  return m;
}

}  // namespace seflex::test
