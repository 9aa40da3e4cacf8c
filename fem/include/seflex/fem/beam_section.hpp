#pragma once
// Section properties of the PBARL/PBEAML cross-section library (MSC Nastran QRG, PBARL figures):
// element axes as in the figures, y_elem vertical (plane 1, bending about z: I1) and z_elem
// horizontal (plane 2, bending about y: I2); the element origin at the section's centre.
//
//   ROD   DIM1 = r                                  exact A, I, J
//   TUBE  DIM1 = r_outer, DIM2 = r_inner            exact A, I, J
//   BAR   DIM1 = width (z), DIM2 = height (y)       exact A, I; J by Roark's rectangle formula
//   BOX   DIM1 = width (z), DIM2 = height (y), DIM3 = thickness of the top and bottom walls,
//         DIM4 = thickness of the side walls        exact A, I; J by Bredt-Batho on the mid-line
//   I     DIM1 = height (y), DIM2 = bottom flange width, DIM3 = top flange width, DIM4 = web
//         thickness, DIM5 = bottom flange thickness, DIM6 = top flange thickness
//                                                   exact A, I about the centroid; J thin-walled
//                                                   open section sum(b t^3)/3 on mid-lines
// Shear factors K1 (plane 1, shear along y) and K2 are classical approximations: 5/6 for BAR,
// 0.9 for ROD, 0.5 for TUBE, (web area)/A for BOX and I in the web direction and 5/6 x (flange
// area)/A across; see docs/nastran-support.md. I12 is 0 for these symmetric sections.
#include <string>
#include <string_view>
#include <vector>

namespace seflex::fem {

struct BeamSection {
  double A = 0, I1 = 0, I2 = 0, I12 = 0, J = 0;
  double K1 = 0, K2 = 0;  ///< shear factors (K A G); 0 = no transverse shear flexibility
};

/// Number of DIMi of a section TYPE seflex computes (ROD 1, TUBE 2, BAR 2, BOX 4, I 6); 0 if unknown.
int section_dimension_count(std::string_view type);

/// "ROD, TUBE, BAR, BOX, I" - for messages.
std::string supported_section_types();

/// Properties of section `type` with dimensions `dims` (size section_dimension_count(type)).
/// Throws InputError without a location (the caller adds it) if the type is unknown or the
/// dimensions do not describe a section (non-positive, walls thicker than the section, ...).
BeamSection beam_section(std::string_view type, const std::vector<double>& dims);

}  // namespace seflex::fem
