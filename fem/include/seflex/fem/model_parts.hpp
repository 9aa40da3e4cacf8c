#pragma once
// Part of model.hpp (the FE model as data; conventions there), kept apart to keep headers short:
// the cards of part superelements (BEGIN SUPER = n sections) that say where a part sits and how it
// connects: POINT, SELOC, SEBULK, SECONCT, and what fem::assemble_parts made of each part.
// Field layouts: MSC Nastran Quick Reference Guide. No parsing and no numerics here.
#include <Eigen/Core>
#include <array>
#include <string>
#include <utility>
#include <vector>

#include "seflex/fem/card_ref.hpp"

namespace seflex::fem {

/// POINT ID CP X1 X2 X3: a geometric point (no degrees of freedom), named by SELOC and SEMPLN.
struct GeometricPoint {
  int id = 0, cp = 0;
  Eigen::Vector3d x = Eigen::Vector3d::Zero();  ///< in cp
  CardRef ref;
};

/// SELOC SEID PA1 PA2 PA3 PB1 PB2 PB3: part SEID moved rigidly so that its points (GRID or POINT of
/// the part) PA1-PA3 go onto PB1-PB3 (GRID or POINT of the residual).
struct PartLocation {
  int seid = 0;
  std::array<int, 3> pa{}, pb{};
  CardRef ref;
};

/// SEBULK SEID TYPE RSEID METHOD TOL LOC UNITNO: how part SEID is defined and connected.
struct PartBulk {
  int seid = 0;
  std::string type = "PRIMARY";   ///< PRIMARY, REPEAT, MIRROR, COLLCTR, EXTERNAL, EXTOP2, EXTOP4, ...
  int rseid = 0;                  ///< the part REPEAT/MIRROR copies
  bool manual = false;            ///< METHOD = MANUAL: boundary only from SECONCT
  double tol = 1e-5;              ///< location tolerance of the boundary search (QRG default 1.0E-5)
  bool loc = true;                ///< LOC = YES: SECONCT pairs checked for coincidence
  int unit = 0;                   ///< UNITNO: the Fortran unit (ASSIGN INPUTT4) of EXTOP4 matrices
  CardRef ref;
};

/// EXTRN GID1 C1 GID2 C2 ...: the boundary points of an external superelement, in a part's bulk data
/// (components as a mask, bit c - 1 for component c; 0 for a scalar point).
struct ExternalBoundary {
  std::vector<std::pair<int, unsigned>> points;
  CardRef ref;
};

/// The matrices of an external superelement (SEBULK EXTOP4: KAA, MAA of its OP4 file) on its a-set:
/// dofs (grid id, component 1-6) or (scalar point id, 0), in the part's ids as read and in the
/// assembled model's ids after assemble_parts; each grid dof in its grid's displacement system.
struct ExternalMatrices {
  int seid = 0;
  std::vector<std::pair<int, int>> dofs;
  Eigen::MatrixXd K, M;
  std::string source;  ///< the OP4 file, for messages
  CardRef ref;         ///< the SEBULK
};

/// SEMPLN SEID PLANE P1 P2 P3: the plane of GRIDs or POINTs of the residual that a SEBULK MIRROR part
/// is the mirror image through.
struct MirrorPlane {
  int seid = 0;
  std::array<int, 3> p{};
  CardRef ref;
};

/// SECONCT SEIDA SEIDB TOL LOC / GIDA1 GIDB1 ...: grids of two parts (0 = the residual) connected.
struct PartConnection {
  int seid_a = 0, seid_b = 0;
  double tol = 1e-5;
  bool loc = true;
  std::vector<std::pair<int, int>> pairs;  ///< (grid of SEIDA, grid of SEIDB)
  CardRef ref;
};

/// What fem::assemble_parts made of one part, for reports (`seflex info`).
struct PartSummary {
  int seid = 0;
  CardRef begin;                  ///< its BEGIN SUPER line
  std::size_t grids = 0, boundary_grids = 0, elements = 0;
  bool moved = false;             ///< by SELOC
  long long grid_offset = 0;      ///< added to its interior grid ids (0: kept)
  long long element_offset = 0;   ///< added to its element ids
  long long property_offset = 0;  ///< added to its property ids
  long long material_offset = 0;  ///< added to its material ids
};

}  // namespace seflex::fem
