#pragma once
// Part of model.hpp (the FE model as data; conventions there), kept apart to keep headers short:
// materials (MAT1, MAT2, MAT8) and element properties (PCOMP/PCOMPG, PBAR/PBARL/PBEAM/PBEAML,
// PROD, PSHELL, PELAS, PBUSH, PMASS). No parsing and no numerics here.
#include <array>
#include <cstdint>
#include <string>
#include <vector>

#include "seflex/fem/card_ref.hpp"

namespace seflex::fem {

// ---------------------------------------------------------------------------------------------
// Materials and properties
struct Mat1 {
  int id = 0;
  double E = 0, G = 0, nu = 0;  ///< completed with Nastran's rule when one is blank
  double rho = 0, alpha = 0, tref = 0, ge = 0;
  CardRef ref;
};

/// MAT2: anisotropic plane-stress material, G = [G11 G12 G13; G12 G22 G23; G13 G23 G33] (Voigt xx,
/// yy, xy with engineering shear strain). As a PSHELL MID3 (transverse shear), [G11 G12; G12 G22] is
/// the 2 x 2 transverse shear matrix (QRG MAT2).
struct Mat2 {
  int id = 0;
  double G11 = 0, G12 = 0, G13 = 0, G22 = 0, G23 = 0, G33 = 0;
  double rho = 0, ge = 0;
  double a1 = 0, a2 = 0, a3 = 0;  ///< thermal expansion (xx, yy, xy engineering), material axes
  double tref = 0;
  CardRef ref;
};

/// MAT8: orthotropic plane-stress material in its axes 1 (fibre), 2. G1Z, G2Z: transverse shear
/// moduli; 0 (blank) = infinite (rigid in transverse shear), as the QRG says for MAT8.
struct Mat8 {
  int id = 0;
  double E1 = 0, E2 = 0, nu12 = 0, G12 = 0, G1z = 0, G2z = 0;
  double rho = 0, ge = 0;
  double a1 = 0, a2 = 0;          ///< thermal expansion along axes 1 and 2
  double tref = 0;
  CardRef ref;
};

/// PCOMP or PCOMPG: a laminate of plies listed from the bottom (most negative z) up.
struct CompositeProperty {
  enum class Lam : std::uint8_t { Blank, Sym, Mem, Bend, Smear, SmCore };
  struct Ply {
    int gplyid = 0;                 ///< PCOMPG global ply id (0 for PCOMP)
    int mid = 0;
    double t = 0;
    double theta_deg = 0;           ///< ply angle from the element's material x axis, degrees
    bool sout = false;
  };
  int id = 0;
  bool global = false;              ///< PCOMPG
  bool has_z0 = false;
  double z0 = 0;                    ///< bottom surface from the reference plane (blank: -T/2)
  double nsm = 0, sb = 0, tref = 0, ge = 0;
  std::string ft;                   ///< failure theory (not used)
  Lam lam = Lam::Blank;
  std::vector<Ply> plies;           ///< as written (LAM = SYM: the lower half only)
  CardRef ref;
};

/// Bar/beam section, from PBAR, PBARL, PBEAM (end A) or PBEAML (end A), in element axes.
struct BarProperty {
  enum class Source : std::uint8_t { PBAR, PBARL, PBEAM, PBEAML };
  int id = 0;
  int mid = 0;
  Source source = Source::PBAR;
  double A = 0, I1 = 0, I2 = 0, I12 = 0, J = 0, nsm = 0;
  double nsi = 0;                   ///< PBEAM NSI(A): non-structural mass moment of inertia per length
  double K1 = 0, K2 = 0;            ///< shear factors; 0 (blank) = no transverse shear flexibility
  /// PBEAM M1/M2 and N1/N2 (element y, z from the shear centre, the beam's reference axis): the centre
  /// of gravity of the non-structural mass and the neutral axis at end A and end B (QRG defaults: 0 at
  /// end A, end B as end A); linear between the ends.
  std::array<double, 2> m_A{}, m_B{}, n_A{}, n_B{};
  std::string section_type;         ///< PBARL/PBEAML TYPE (ROD, TUBE, BAR, BOX, I, ...)
  std::vector<double> dims;         ///< PBARL/PBEAML DIMi
  /// PBEAM/PBEAML taper: the sections at the stations x = X/XB (0 end A, 1 end B), end A first and
  /// end B last, each field as written or, when blank, end A's (PBEAM) or the previous station's
  /// dimensions (PBEAML); empty when every station equals end A (a prismatic beam).
  struct Station {
    double x = 0;
    double A = 0, I1 = 0, I2 = 0, I12 = 0, J = 0, nsm = 0, nsi = 0;
    std::vector<double> dims;       ///< PBEAML
  };
  std::vector<Station> stations;
  CardRef ref;
};

/// The bulk-data card a bar property came from ("PBAR", "PBARL", "PBEAM", "PBEAML").
inline const char* card_name(BarProperty::Source s) {
  switch (s) {
    case BarProperty::Source::PBAR: return "PBAR";
    case BarProperty::Source::PBARL: return "PBARL";
    case BarProperty::Source::PBEAM: return "PBEAM";
    case BarProperty::Source::PBEAML: return "PBEAML";
  }
  return "PBAR";
}

/// PROD, or PTUBE (tube): its section A = pi T (OD - T), J = pi T (OD - T) ((OD - T)^2 + T^2) / 4 and
/// C = OD / 2 computed as it is read (T = 0 or blank: a solid rod of diameter OD; QRG PTUBE).
/// (CONROD stores its own inline copy, id = 0.)
struct RodProperty {
  int id = 0, mid = 0;
  double A = 0, J = 0, C = 0, nsm = 0;
  bool tube = false;                ///< PTUBE
  double od = 0, t = 0, od2 = 0;    ///< PTUBE OD, T, OD2 (OD2 tapers the tube in heat transfer only, QRG)
  CardRef ref;
};

inline const char* rod_property_card(const RodProperty& p) { return p.tube ? "PTUBE" : "PROD"; }

/// PSHEAR: shear panel thickness T, NSM per area, extensional effectiveness factors F1 (edges 1-2,
/// 3-4) and F2 (edges 2-3, 1-4), 0 = none (QRG PSHEAR remark 2).
struct ShearProperty {
  int id = 0, mid = 0;
  double t = 0, nsm = 0, f1 = 0, f2 = 0;
  CardRef ref;
};

/// PBEND: the section of a curved beam (A, I1 in the plane of the bend, I2 out of it, J; K1, K2 shear
/// factors, 0 = rigid in shear (QRG remark 4)), or of a curved pipe (pipe = true: FSI, mean radius RM,
/// wall T, pressure P; the section of the tube computed), with the bend's radius RB and arc angle
/// THETAB (degrees) that CBEND GEOM 3 and 4 use. RC, ZC, DELTAN: centroid and neutral-axis offsets.
struct BendProperty {
  int id = 0, mid = 0;
  bool pipe = false;
  double A = 0, I1 = 0, I2 = 0, J = 0, K1 = 0, K2 = 0, nsm = 0;
  int fsi = 0;
  double rm = 0, t = 0, p = 0;                  ///< pipe format
  double rb = 0, thetab_deg = 0;                ///< 0 = blank
  double rc = 0, zc = 0, deltan = 0;
  bool has_deltan = false;
  CardRef ref;
};

struct ShellProperty {  ///< PSHELL
  int id = 0;
  int mid1 = 0;                     ///< membrane (0 = none)
  double t = 0;
  int mid2 = 0;                     ///< bending (0 = none)
  double bend_ratio = 1.0;          ///< 12I/T^3 (blank = 1)
  int mid3 = 0;                     ///< transverse shear (0 = none)
  double ts_t = 0.833333;           ///< TS/T (blank = .833333)
  double nsm = 0;
  double z1 = 0, z2 = 0;            ///< fibre distances (stress only)
  int mid4 = 0;                     ///< membrane-bending coupling (0 = none): B = T^2 G4
  CardRef ref;
};

struct SpringProperty {  ///< PELAS
  int id = 0;
  double k = 0, ge = 0, s = 0;
  CardRef ref;
};


/// PBUSH: stiffness K1-K6 in the CBUSH element axes (T1 T2 T3 R1 R2 R3; blank = 0). B (damping),
/// GE, RCV and M are read and kept for `seflex convert`; statics and modes do not use them.
/// PBUSH K1-K6, B1-B6, GE1-GE6; or PBUSH1D (one_d): K in k[0], C in b[0], M the total mass of the
/// element (lumped half at each grid's translations; the mass of a grounded element's ground half is
/// left out, as a CROD's would be).
struct BushProperty {
  int id = 0;
  std::array<double, 6> k{}, b{}, ge{};
  bool has_b = false, has_ge = false;
  bool one_d = false;  ///< PBUSH1D
  double mass = 0;     ///< PBUSH1D M
  double sa = 1.0, se = 1.0;  ///< PBUSH1D stress and strain recovery coefficients (read, written back)
  CardRef ref;
};

/// PMASS: scalar mass value of CMASS1/CMASS3.
struct MassProperty {
  int id = 0;
  double m = 0;
  CardRef ref;
};

/// TABLEM1-TABLEM4: a material property table, for the temperature-dependent materials (MATTi)
/// that seflex does not model: read, checked and written back, used by no solution (a MATTi naming
/// it is listed as unsupported). values: x1 y1 x2 y2 ... (TABLEM1-3, SKIP pairs left out) or the
/// coefficients A0 A1 ... (TABLEM4).
struct MaterialTable {
  int id = 0;
  int type = 1;                       ///< 1-4
  std::string xaxis, yaxis;           ///< TABLEM1: LINEAR (blank) or LOG
  std::array<double, 4> x{};          ///< TABLEM2 X1; TABLEM3 X1 X2; TABLEM4 X1 X2 X3 X4
  std::vector<double> values;
  CardRef ref;
};

}  // namespace seflex::fem
