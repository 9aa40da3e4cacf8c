#pragma once
// Part of model.hpp (the FE model as data; conventions there), kept apart to keep headers short:
// rigid and interpolation elements (RBE2, RBAR, RBE1, CRIGD1-3, RROD, CRIGDR, RBE3), SPC/SPC1/SPCADD, MPC/MPCADD and the
// ASET/OMIT/BSET/SUPORT dof sets. No parsing and no numerics here.
#include <cstdint>
#include <string>
#include <vector>

#include "seflex/fem/card_ref.hpp"
#include "seflex/fem/model_geometry.hpp"

namespace seflex::fem {

// ---------------------------------------------------------------------------------------------
// Rigid elements and interpolation constraints
/// RBE2: the dependent components cm of every grid in gm follow the independent grid gn rigidly.
struct Rbe2 {
  int id = 0, gn = 0;
  ComponentMask cm = 0;
  std::vector<int> gm;
  CardRef ref;
};

/// RBAR: a rigid bar between GA and GB. CNA/CNB: independent components (six in all, able to
/// describe any rigid motion); CMA/CMB: dependent ones (both blank: every component not independent).
struct Rbar {
  int id = 0, ga = 0, gb = 0;
  ComponentMask cna = 0, cnb = 0, cma = 0, cmb = 0;
  double alpha = 0;                             ///< thermal expansion: read, not used
  CardRef ref;
};

/// RBE1, CRIGD1, CRIGD2, CRIGD3: a rigid body whose independent components (CNi of grids GNi, six
/// in all, able to describe any rigid motion) fix its motion; the dependent components (CMi of grids
/// GMi) follow it. CRIGD1 and CRIGD2 have one reference grid IG with all six components independent
/// (CRIGD1: all six components of each dependent grid; CRIGD2: the listed ones); CRIGD3 and RBE1
/// list the independent components over up to six grids (COSMIC NASTRAN User's Manual, CRIGD1-3;
/// MSC QRG RBE1).
struct RigidBody {
  enum class Card : std::uint8_t { Rbe1, Crigd1, Crigd2, Crigd3 };
  struct GridComponents {
    int grid = 0;
    ComponentMask c = 0;
  };
  Card card = Card::Rbe1;
  int id = 0;
  std::vector<GridComponents> independent, dependent;
  double alpha = 0;                             ///< RBE1 thermal expansion: read, not used
  CardRef ref;
};

/// "RBE1", "CRIGD1", "CRIGD2" or "CRIGD3".
inline const char* rigid_body_card(const RigidBody& r) {
  static const char* names[4] = {"RBE1", "CRIGD1", "CRIGD2", "CRIGD3"};
  return names[static_cast<int>(r.card)];
}

/// The fields of a RigidBody's grids, for messages: the independent ones ("3 (IG)" on CRIGD1/2), the
/// dependent ones ("GMi", "Gi", "DGi").
struct RigidBodyFields {
  std::string independent, dependent;
};
inline RigidBodyFields rigid_body_fields(const RigidBody& r) {
  switch (r.card) {
    case RigidBody::Card::Rbe1: return {"GNi", "GMi"};
    case RigidBody::Card::Crigd3: return {"IGi", "DGi"};
    default: return {"3 (IG)", "Gi"};
  }
}

/// RROD, CRIGDR: a pin-ended rod between GA and GB, rigid in extension: n . (u_B - u_A) = 0 with n the
/// unit vector from GA to GB (basic translations). One translation is dependent: component CMA of GA
/// or CMB of GB (1-3, in the grid's CD system; CRIGDR: C1 of its dependent grid G1 = GB, reference
/// grid G = GA). RROD with both blank: the component of GB most nearly along the rod (the constraint
/// is the same whichever translation it is solved for).
struct RigidRod {
  enum class Card : std::uint8_t { Rrod, Crigdr };
  Card card = Card::Rrod;
  int id = 0, ga = 0, gb = 0;
  int cma = 0, cmb = 0;                         ///< 1-3, 0 = blank
  double alpha = 0;                             ///< RROD thermal expansion: read, not used
  CardRef ref;
};

inline const char* rigid_rod_card(const RigidRod& r) { return r.card == RigidRod::Card::Rrod ? "RROD" : "CRIGDR"; }

/// The fields of a RigidRod's grids and dependent component, for messages (a CRIGDR card holds two
/// rods: its fields are named without numbers).
struct RigidRodFields {
  const char *ga, *gb, *cma, *cmb;
};
inline RigidRodFields rigid_rod_fields(const RigidRod& r) {
  if (r.card == RigidRod::Card::Crigdr) return {"G", "G1", "C1", "C1"};
  return {"3 (GA)", "4 (GB)", "5 (CMA)", "6 (CMB)"};
}

/// RBE3: the REFC components of REFGRID are the weighted least-squares average of the motions of
/// the groups' grids (WTi on components Ci of grids Gi,j). UM: the dependent set redefined.
struct Rbe3 {
  struct Group {
    double weight = 0;
    ComponentMask c = 0;
    std::vector<int> grids;
  };
  struct Dependent {                            ///< one UM pair GMi CMi
    int grid = 0;
    ComponentMask c = 0;
  };
  int id = 0, refgrid = 0;
  ComponentMask refc = 0;
  std::vector<Group> groups;
  std::vector<Dependent> um;                    ///< empty: REFC of REFGRID are the dependents
  bool has_alpha = false;
  double alpha = 0;                             ///< thermal expansion: read, not used
  CardRef ref;
};

// ---------------------------------------------------------------------------------------------
// Single- and multipoint constraints, dof sets
struct SpcEntry {  ///< one SPC/SPC1 grid-component entry (d = enforced value, SPC only)
  int sid = 0, grid = 0;
  ComponentMask c = 0;
  double d = 0;
  bool from_thru = false;           ///< SPC1 "G1 THRU G2": a missing grid is skipped (QRG SPC1 remark)
  CardRef ref;
};

/// SPCADD / MPCADD: set SID is the union of sets S1, S2, ...
struct SetCombination {
  int sid = 0;
  std::vector<int> sets;
  CardRef ref;
};
using SpcAdd = SetCombination;

/// MPC: one equation sum_j A_j u(G_j, C_j) = 0 (components in the grids' CD systems, 0 for a
/// scalar point); the first term's dof is the dependent one.
struct MpcTerm {
  int grid = 0, component = 0;
  double a = 0;
};
struct MpcEquation {
  int sid = 0;
  std::vector<MpcTerm> terms;
  CardRef ref;
};

using MpcAdd = SetCombination;

struct DofSetEntry {  ///< ASET/ASET1/OMIT/OMIT1/BSET/BSET1/SUPORT entries (grid or scalar point + components)
  int grid = 0;
  ComponentMask c = 0;
  CardRef ref;
};

struct Suport1Entry {  ///< one (ID, C) pair of a SUPORT1 card: the supports of set `sid` (case control SUPORT1)
  int sid = 0;
  DofSetEntry dofs;
};

}  // namespace seflex::fem
