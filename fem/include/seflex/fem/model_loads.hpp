#pragma once
// Part of model.hpp (the FE model as data; conventions there), kept apart to keep headers short:
// static and thermal loads (FORCE/MOMENT, FORCE1/2, MOMENT1/2, PLOAD2, PLOAD1, SPCD, GRAV, RFORCE, TEMP/TEMPD/TEMPRB,
// LOAD). PLOAD4: model_solids.hpp. No parsing and no numerics here.
#include <Eigen/Core>
#include <array>
#include <cstdint>
#include <string>
#include <utility>
#include <vector>

#include "seflex/fem/card_ref.hpp"
#include "seflex/fem/model_geometry.hpp"

namespace seflex::fem {

// ---------------------------------------------------------------------------------------------
// Loads
/// FORCE or MOMENT: value = scale * (n1, n2, n3) in system cid. FORCE1/MOMENT1 (Direction::TwoGrids):
/// scale along the unit vector from grid g[0] to g[1]; FORCE2/MOMENT2 (Direction::FourGrids): along
/// the unit vector of (x(g[1]) - x(g[0])) x (x(g[3]) - x(g[2])). The directions are taken at the
/// grids' undeformed basic positions when the load vector is built (linear Nastran; QRG FORCE1/2).
struct PointLoad {
  enum class Kind : std::uint8_t { Force, Moment };
  enum class Direction : std::uint8_t { Vector, TwoGrids, FourGrids };
  Kind kind = Kind::Force;
  Direction direction = Direction::Vector;
  int sid = 0, grid = 0, cid = 0;
  double scale = 0;
  Eigen::Vector3d n = Eigen::Vector3d::Zero();
  std::array<int, 4> g{};           ///< FORCE1/2, MOMENT1/2: G1 ... G4
  CardRef ref;
};

/// "FORCE", "MOMENT", "FORCE1", "MOMENT1", "FORCE2" or "MOMENT2".
inline const char* point_load_card(const PointLoad& l) {
  static const char* names[2][3] = {{"FORCE", "FORCE1", "FORCE2"}, {"MOMENT", "MOMENT1", "MOMENT2"}};
  return names[l.kind == PointLoad::Kind::Moment][static_cast<int>(l.direction)];
}

/// SLOAD: load F on scalar point S, or on component T1 (in its CD system) of a grid S (MSC QRG SLOAD).
struct ScalarLoad {
  int sid = 0, point = 0;
  double f = 0;
  CardRef ref;
};

/// PLOAD: pressure P on the surface of grids G1 G2 G3 (g[3] = 0: a triangle, the force P A along
/// (G1 -> G2) x (G1 -> G3) split equally over its grids) or G1-G4 (four triangles 123, 234, 341, 412,
/// each with P/2 as a triangle; QRG PLOAD remarks).
struct GridPressureLoad {
  int sid = 0;
  double p = 0;
  std::array<int, 4> g{};
  CardRef ref;
};

/// PLOAD2: uniform pressure p on CQUAD4/CTRIA3 elements, positive along the element normal (right-hand
/// rule on the grid order). `thru`: elements = {EID1, EID2} of "EID1 THRU EID2", whose ids that are
/// not shells are skipped (QRG PLOAD2 remark); otherwise the ids listed, which must be shells.
struct PressureLoad {
  int sid = 0;
  double p = 0;
  std::vector<int> elements;
  bool thru = false;
  CardRef ref;
};

/// PLOAD1: a load on CBAR/CBEAM EID distributed from X1 (P1) to X2 (P2), linearly (X1 = X2: a
/// concentrated load P1 at X1). TYPE: FX FY FZ (force per length along basic x, y, z), FXE FYE FZE
/// (along the element axes), MX MY MZ, MXE MYE MZE (moments). SCALE: LE (X1, X2 lengths along the
/// bar, P per length), FR (X fractions of the length), LEPR, FRPR (P per projected length: basic
/// types only).
struct BarLineLoad {
  enum class Scale : std::uint8_t { LE, FR, LEPR, FRPR };
  int sid = 0, element = 0;
  std::string type;                 ///< FX, FY, FZ, FXE, FYE, FZE, MX, MY, MZ, MXE, MYE, MZE
  Scale scale = Scale::LE;
  double x1 = 0, p1 = 0, x2 = 0, p2 = 0;
  CardRef ref;
};

/// SPCD: enforced value D of components C of grid G (a load set: selected by the subcase LOAD,
/// its dofs must be in the subcase's SPC set).
struct EnforcedMotion {
  int sid = 0, grid = 0;
  ComponentMask c = 0;
  double d = 0;
  CardRef ref;
};

/// GRAV: acceleration A (N1, N2, N3) in rectangular system CID applied to every mass: p = M a.
struct GravityLoad {
  int sid = 0, cid = 0;
  double a = 0;
  Eigen::Vector3d n = Eigen::Vector3d::Zero();
  CardRef ref;
};

/// RFORCE: steady rotation omega = 2 pi A (R1, R2, R3)/|R| (A in revolutions per unit time) and
/// angular acceleration 2 pi RACC (same axis) about the axis through grid G (0: basic origin),
/// components in rectangular system CID. METHOD 1 and 2 are computed alike (mass matrix times the
/// acceleration of every grid).
struct RotationalLoad {
  int sid = 0, grid = 0, cid = 0;
  double a = 0, racc = 0;
  Eigen::Vector3d r = Eigen::Vector3d::Zero();
  int method = 1;
  CardRef ref;
};

/// Temperatures of a thermal load set (selected by case control TEMPERATURE(LOAD)):
/// TEMP SID G1 T1 G2 T2 G3 T3 (grid temperatures) ...
struct GridTemperature {
  int sid = 0, grid = 0;
  double t = 0;
  CardRef ref;
};
/// ... TEMPD SID1 T1 ... (the temperature of every grid set SID does not give) ...
struct DefaultTemperature {
  int sid = 0;
  double t = 0;
  CardRef ref;
};
/// ... and TEMPRB SID EID1 TA TB TP1A TP1B TP2A TP2B / TCA ... / EID2 ... (line elements: mean
/// temperatures at ends A and B, effective linear gradients in the element's y (1) and z (2)
/// directions; the stress-point temperatures TCA ... are read and not used).
struct BarTemperature {
  int sid = 0, element = 0;
  double ta = 0, tb = 0, tp1a = 0, tp1b = 0, tp2a = 0, tp2b = 0;
  CardRef ref;
};

struct LoadCombination {  ///< LOAD: overall scale s, then (si, li) pairs
  int sid = 0;
  double s = 1;
  std::vector<std::pair<double, int>> terms;
  CardRef ref;
};

}  // namespace seflex::fem
