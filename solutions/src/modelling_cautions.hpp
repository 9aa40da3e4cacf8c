#pragma once
// What a deck asks for that seflex computes as written but whose consequence a careful user wants
// to be told (card_usage.cpp reports them as CardUse::Kind::Caution, printed as warnings):
//   - bars and beams without torsional stiffness (PBAR/PBEAM J = 0),
//   - CQUAD4/CTRIA3 plates thick for their size (transverse shear governs, slow convergence),
//   - RFORCE's angular velocity, which Nastran gives in revolutions per unit time.
// Each entry counts the cards concerned and keeps the first in deck order; none throws.
#include <cstddef>
#include <set>
#include <string>
#include <vector>

#include "seflex/fem/model.hpp"

namespace seflex::solutions::detail {

struct Caution {
  std::string card;       ///< "PBAR", "CQUAD4", "RFORCE"
  std::size_t count = 0;  ///< cards concerned (properties, elements, RFORCE cards)
  fem::CardRef first;     ///< the first of them
  std::string reason;
};

/// Bar/beam properties with J <= 0 (PBAR, PBEAM; PBARL/PBEAML compute J from the section) that a
/// CBAR/CBEAM of the model uses: one entry per property card name, listing the property ids and
/// the number of elements. The element has no torsional stiffness (fem/src/element_bar.cpp), so its
/// twist is held only by what it connects to; `buckling` adds that the torsion (Wagner) term of the
/// bar's differential stiffness couples the twist to bending (fem/src/element_bar_kg.cpp).
std::vector<Caution> torsionless_bars(const fem::Model& model, bool buckling);

/// Ratio t / sqrt(area) above which a CQUAD4/CTRIA3 plate element is thick for its size. With
/// transverse shear (Mindlin), a plate wave of wavenumber k has the bending stiffness of
/// Kirchhoff's plate divided by 1 + k^2 t^2 / (6 kappa (1 - nu)) (kappa = 5/6; no rotary inertia).
/// The shortest wave a mesh of size h carries has a half-wavelength of about 2 h in both directions
/// (k^2 = 2 (pi / 2h)^2); at t = 0.5 h that factor is 1.35 (nu = 0.3): transverse shear makes a
/// quarter of the flexibility of the modes the mesh barely resolves, and the element's shear
/// interpolation and stabilisation (MITC4/MITC3) then decide those modes. Typical thin panels have
/// t/h below 0.1 (factor 1.014). The MYSTRAN deck AQ3U2S004 (t/h = 0.8, factor 1.90) gives -12.7 % in
/// frequency on its mode (3,3) at 4 x 4, -0.85 % at 16 x 16 (docs/validation-mystran.md).
constexpr double kThickShellRatio = 0.5;

/// CQUAD4/CTRIA3 with bending and transverse shear flexibility (PSHELL MID2 and MID3, or a PCOMP)
/// whose thickness exceeds kThickShellRatio * sqrt(area): one entry per element type, with the
/// largest t / sqrt(area). The thickness is that of the homogeneous plate with the section's ratio
/// of bending to transverse shear stiffness (fem::ShellSection::ts2): PSHELL T (or the corners'
/// mean) for a homogeneous plate, more for a sandwich with a soft core. A section rigid in shear
/// (MID3 blank: Kirchhoff) or without bending is not reported; nor is an element whose property or
/// grids are not defined (refused where the element is built).
std::vector<Caution> thick_shells(const fem::Model& model);

/// RFORCE cards of the load sets `used_sets`: their A (and RACC) in revolutions per unit time, as
/// MSC Nastran's QRG and seflex read them, with the angular velocity (acceleration) in radians
/// that follows, and the A to give if radians were meant. One entry per card.
std::vector<Caution> rforce_units(const fem::Model& model, const std::set<int>& used_sets);

}  // namespace seflex::solutions::detail
