#pragma once
// Model cards of solid elements and face pressure loads (part of model.hpp, kept apart to keep that
// header short): PSOLID, MAT9, CHEXA/CPENTA/CTETRA/CPYRAM, PLOAD4. Field layouts: MSC Nastran Quick Reference
// Guide (docs/nastran-support.md). No parsing and no numerics here.
#include <Eigen/Core>
#include <array>
#include <cstdint>
#include <string>

#include "seflex/fem/card_ref.hpp"

namespace seflex::fem {

/// PSOLID PID MID CORDM IN STRESS ISOP FCTN. MID: a MAT1 (isotropic: CORDM does not change results)
/// or a MAT9 (anisotropic, in the material axes CORDM: 0 basic or a rectangular system); IN/ISOP
/// select the integration (element_solid.hpp);
/// STRESS (stress output system) is read and ignored; FCTN other than SMECH is refused by the reader.
struct SolidProperty {
  enum class Integration : std::uint8_t { Default, Bubble, Two, Three };
  enum class Isop : std::uint8_t { Default, Reduced, Full };
  int id = 0, mid = 0;
  int cordm = 0;                     ///< -1 element system, 0 basic, > 0 a coordinate system
  Integration in = Integration::Default;
  Isop isop = Isop::Default;
  std::string stress;                ///< raw field text (GRID, blank or a system id)
  std::string fctn;                  ///< raw field text (blank = SMECH)
  CardRef ref;
};

/// MAT9: anisotropic solid material, G = the symmetric 6 x 6 matrix of G11 ... G66 (upper triangle,
/// row by row) relating stress and strain in Voigt order xx yy zz xy yz zx (engineering shear
/// strains), in the PSOLID CORDM axes; A1-A6 thermal expansion (same order), TREF, GE (QRG MAT9).
/// PSOLID only: a shell or line element property on a MAT9 is an error of fem::finalize.
struct Mat9 {
  int id = 0;
  std::array<double, 21> g{};        ///< G11 G12 G13 G14 G15 G16 G22 ... G66, as on the card
  double rho = 0;
  std::array<double, 6> a{};
  double tref = 0, ge = 0;
  CardRef ref;
};

/// CHEXA (8 to 20 grids), CPENTA (6 to 15), CTETRA (4 to 10), CPYRAM (5 to 13): the corners, then
/// the mid-edge grids present, in Nastran's order (QRG CHEXA/CPENTA/CTETRA/CPYRAM figures). A blank mid-edge grid makes that
/// edge straight (QRG): bit k of missing_mid is set when mid-edge grid k (QRG grid corners + 1 + k)
/// is blank, and g[] holds only the grids present (nnode of them), so that g[0..nnode) is always the
/// element's grid list. nnode = corners: the linear element (missing_mid ignored); all mid-edge
/// grids present: the full quadratic one (missing_mid = 0).
struct Solid {
  enum class Shape : std::uint8_t { Tetra, Penta, Hexa, Pyram };
  int id = 0, pid = 0;
  Shape shape = Shape::Hexa;
  std::uint8_t nnode = 8;
  std::uint16_t missing_mid = 0;
  std::array<int, 20> g{};
  CardRef ref;
  const char* card() const { return card(shape); }
  int corners() const { return corners(shape); }
  int edges() const { return edges(shape); }
  static const char* card(Shape s) {
    return s == Shape::Hexa ? "CHEXA" : s == Shape::Penta ? "CPENTA" : s == Shape::Pyram ? "CPYRAM" : "CTETRA";
  }
  static int corners(Shape s) { return s == Shape::Hexa ? 8 : s == Shape::Penta ? 6 : s == Shape::Pyram ? 5 : 4; }
  static int edges(Shape s) { return s == Shape::Hexa ? 12 : s == Shape::Penta ? 9 : s == Shape::Pyram ? 8 : 6; }
  bool quadratic() const { return nnode > corners(); }
  /// The QRG grid number (1-based: G1, G2, ...) of g[k], for messages.
  int grid_number(int k) const {
    if (k < corners() || !quadratic()) return k + 1;
    int present = corners();
    for (int e = 0; e < edges(); ++e)
      if (!(missing_mid >> e & 1u) && present++ == k) return corners() + e + 1;
    return k + 1;
  }
};

/// PLOAD4 SID EID P1 P2 P3 P4 G1 G3/G4 / CID N1 N2 N3 SORL LDIR, or SID EID1 P1..P4 THRU EID2 (shells).
/// P2..P4 blank = P1 (p_blank). Without a direction (N = 0) the pressure acts along the face normal:
/// a shell's normal (right-hand rule on G1 G2 G3), or a solid face's inward normal (QRG PLOAD4).
/// With N, the load per unit area p acts along N / |N| (N in system CID at the face).
struct FaceLoad {
  int sid = 0;
  int eid = 0, eid_last = 0;         ///< eid_last > 0: the THRU form, elements eid..eid_last
  std::array<double, 4> p{};
  int g1 = 0, g34 = 0;               ///< solids: face corner G1 and G3 (HEXA/PENTA/PYRAM) or G4 (TETRA)
  int cid = 0;
  Eigen::Vector3d n = Eigen::Vector3d::Zero();
  CardRef ref;
};

}  // namespace seflex::fem
