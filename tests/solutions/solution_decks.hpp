#pragma once
// Decks written by the solution tests.
#include <string>

namespace seflex::test {

/// Cantilever of 10 CBARs along basic x (L = 1.5, E = 7e10, I1 = I2 = 2e-8), clamped at grid 1,
/// FORCE 7 of 120 along basic z at the tip, grid 11; the tip's displacement system CD = 5 is a
/// CORD2R with e1 = basic y, e2 = -basic x, e3 = basic z.
inline std::string cantilever_deck() {
  std::string d =
      "SOL 101\nCEND\nTITLE = cantilever\nSPC = 1\nLOAD = 7\nBEGIN BULK\n"
      "CORD2R,5,0,0.,0.,0.,0.,0.,1.,+C5\n+C5,0.,1.,0.\n"
      "MAT1,1,7.e10,,0.3,2700.\nPBAR,1,1,1.e-4,2.e-8,2.e-8,4.e-8\nSPC1,1,123456,1\n"
      "FORCE,7,11,0,120.,0.,0.,1.\n";
  for (int i = 1; i <= 11; ++i)
    d += "GRID," + std::to_string(i) + ",," + std::to_string(0.15 * (i - 1)) + ",0.,0." + (i == 11 ? ",5\n" : "\n");
  for (int i = 1; i <= 10; ++i)
    d += "CBAR," + std::to_string(i) + ",1," + std::to_string(i) + "," + std::to_string(i + 1) + ",0.,1.,0.\n";
  return d + "ENDDATA\n";
}

/// Free aluminium plate 0.6 x 0.4 x 3 mm of nx x ny CQUAD4 in the basic x-y plane, EIGRL 1 with
/// ND = nd selected by METHOD = 1.
inline std::string free_plate_deck(int nx, int ny, int nd) {
  std::string d = "SOL 103\nCEND\nMETHOD = 1\nBEGIN BULK\nEIGRL,1,,," + std::to_string(nd) +
                  "\nMAT1,1,7.e10,,0.33,2700.\nPSHELL,1,1,0.003,1,,1\n";
  for (int j = 0; j <= ny; ++j)
    for (int i = 0; i <= nx; ++i)
      d += "GRID," + std::to_string(1 + i + (nx + 1) * j) + ",," + std::to_string(0.6 * i / nx) + "," +
           std::to_string(0.4 * j / ny) + ",0.\n";
  int id = 1;
  for (int j = 0; j < ny; ++j)
    for (int i = 0; i < nx; ++i) {
      const int g = 1 + i + (nx + 1) * j;
      d += "CQUAD4," + std::to_string(id++) + ",1," + std::to_string(g) + "," + std::to_string(g + 1) + "," +
           std::to_string(g + nx + 2) + "," + std::to_string(g + nx + 1) + "\n";
    }
  return d + "ENDDATA\n";
}

}  // namespace seflex::test
