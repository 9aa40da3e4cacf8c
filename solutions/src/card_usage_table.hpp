#pragma once
// The card table of check_card_usage (card_usage.hpp): for each Nastran bulk-data card name, what
// it is for and whether seflex supports it. One row per card; the rows are in card_usage_table.cpp.
#include <string_view>
#include <vector>

#include "seflex/fem/model.hpp"

namespace seflex::solutions::detail {

enum class Role : unsigned char {
  Geometry,        ///< GRID, CORDxx, SPOINT: used by every solution
  Structure,       ///< elements, properties, materials, rigid elements: used by every solution
  Damping,         ///< viscous/structural damping: not used by statics or real modes
  Nonlinear,       ///< nonlinear material/property data: not used by linear solutions
  TempMaterial,    ///< temperature-dependent material data (MATTi): used with TEMPERATURE(MATERIAL)
  Load,            ///< static load cards, selected by LOAD = SID (directly or through LOAD)
  LoadCombination, ///< LOAD
  TemperatureLoad, ///< TEMP, TEMPD, ...: selected by TEMPERATURE(LOAD)
  SpcSet,          ///< SPC, SPC1, SPCADD: selected by SPC = SID
  MpcSet,          ///< MPC, MPCADD: selected by MPC = SID
  Omit,            ///< ASET, ASET1, OMIT, OMIT1: Guyan reduction in normal modes
  Bset,            ///< BSET, BSET1, CSET, QSET ...: superelement boundary / component modes
  Suport,          ///< SUPORT
  Suport1,         ///< SUPORT1 (selected by case control SUPORT1)
  EigenMethod,     ///< EIGR, EIGRL: selected by METHOD
  BucklingMethod,  ///< EIGB
  ComplexMethod,   ///< EIGC, EIGP
  Dynamics,        ///< dynamic loads, frequencies, time steps, tables of dynamic solutions
  Dmig,            ///< DMIG: selected by K2GG / M2GG
  OtherMatrix,     ///< DMI, DMIJ, DMIK, DMIAX ...
  Param,           ///< PARAM
  Output,          ///< output requests and plot elements
  Optimization,    ///< design optimisation
  Aero,            ///< aeroelasticity
  Heat,            ///< heat transfer
  Superelement,    ///< superelement partitioning of the bulk data
  Contact,         ///< contact (nonlinear)
  Solver,          ///< other solvers' control cards (MYSTRAN DEBUG, ...), numbering (SEQGP)
};

/// Field 2 (set id) and location of each card of a supported set card type.
using MemberList = std::vector<fem::UnsupportedCard::Member>;
using MembersFn = void (*)(const fem::Model&, MemberList&);

struct CardRole {
  std::string_view name;
  Role role;
  bool supported;           ///< seflex reads it into the Model and every solution that needs it uses it
  MembersFn members;        ///< supported Load/TemperatureLoad cards: their (SID, location); else nullptr
};

/// The row of a card name (upper case), or nullptr for a name the table does not know.
const CardRole* find_card_role(std::string_view name);

/// A name of Model::unsupported that is a bulk-data card seflex does not know at all: no row in the
/// table, not a reader's note (a name with a blank: "CQUAD4/CTRIA3 TFLAG a fraction", "... (left
/// out)") and not a line of punctuation ("'&'").
bool is_unknown_card(std::string_view name);

/// Every row whose card is supported and whose members() is given (the supported load cards).
std::vector<const CardRole*> supported_set_cards();

}  // namespace seflex::solutions::detail
