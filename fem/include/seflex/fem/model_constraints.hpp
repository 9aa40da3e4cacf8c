#pragma once
// Part of model.hpp (the FE model as data; conventions there), kept apart to keep headers short:
// rigid and interpolation elements (RBE2, RBAR, RBE3), SPC/SPC1/SPCADD, MPC/MPCADD and the
// ASET/OMIT/BSET/SUPORT dof sets. No parsing and no numerics here.
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

}  // namespace seflex::fem
