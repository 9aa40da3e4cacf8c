#pragma once
// Parsers of the bulk-data cards seflex supports, one function per card (grouped by kind in
// io/src/nastran_cards_*.cpp), and what they share while a deck is read.
// Field layouts follow the MSC Nastran Quick Reference Guide; docs/nastran-support.md lists them.
#include <cstdint>
#include <string>
#include <string_view>
#include <unordered_map>
#include <vector>

#include "seflex/fem/model.hpp"
#include "seflex/io/nastran_card.hpp"

namespace seflex::io::nastran {

/// What the card parsers share while one deck is read.
struct ReaderState {
  /// `files`: the deck's file names (the residual model's Model::files, which a part's model gets only
  /// when the parts are assembled), indexed by fem::CardRef::file.
  ReaderState(fem::Model& m, const std::vector<std::string>& files) : model(m), files(files), unsupported(m.unsupported) {}
  fem::Model& model;
  const std::vector<std::string>& files;
  /// Per GRID (same order as model.grids): which of CP (1), CD (2), PS (4) were blank, for GRDSET.
  std::vector<std::uint8_t> grid_blank;
  /// DMIG name -> index in model.dmigs; whether its header card has been read.
  std::unordered_map<std::string, std::size_t> dmig_index;
  std::vector<bool> dmig_has_header;
  /// model.params[0, case_control_params) came from the case control (set at BEGIN BULK).
  std::size_t case_control_params = 0;
  /// Adds to model.unsupported.
  fem::UnsupportedNotes unsupported;

  /// Record a card (or a feature of a card) seflex reads but does not use: counted, first location kept.
  void note_unsupported(std::string_view name, const fem::CardRef& ref);
  /// A whole card seflex does not read: as note_unsupported, and its field 2 (a set id) kept when
  /// it is an integer (fem::UnsupportedCard::members).
  void note_unsupported_card(const Card& card);
  /// As note_unsupported, with `id` kept as a member (an element on a property of that id is left
  /// out by fem::finalize, as on an unsupported property card).
  void note_unsupported_member(std::string_view name, int id, const fem::CardRef& ref);
  /// "file:line" of a card read earlier (of this model or, in a part, of the deck).
  std::string where(const fem::CardRef& ref) const;
};

using CardParser = void (*)(const Card&, ReaderState&);

// Features of supported cards that seflex reads for `seflex info` but no solution may use (listed
// as unsupported; solutions/src/card_usage_table.cpp gives them the role Structure: refused).
inline constexpr const char* kShellTflagFraction = "CQUAD4/CTRIA3 TFLAG a fraction";
inline constexpr const char* kFluidGrid = "GRID CD = -1 (fluid)";
inline constexpr const char* kFluidSolid = "PSOLID FCTN = PFLUID";
inline constexpr const char* kPlaneStrainShell = "PSHELL MID2 = -1 (plane strain)";
inline constexpr const char* kPartMassSection = "part superelement: BEGIN SUPER MASSID (a mass section, skipped)";
inline constexpr const char* kMdlprmHdf5 = "MDLPRM HDF5 (output format)";

/// The parser of a bulk-data card name (upper case), or nullptr if seflex does not support it.
CardParser find_card_parser(std::string_view name);

// Geometry (nastran_cards_geometry.cpp)
void parse_grid(const Card&, ReaderState&);
void parse_grdset(const Card&, ReaderState&);
void parse_cord2(const Card&, ReaderState&);
void parse_cord1(const Card&, ReaderState&);
void parse_spoint(const Card&, ReaderState&);
// Elements (nastran_cards_elements.cpp)
void parse_cbar(const Card&, ReaderState&);
void parse_cbeam(const Card&, ReaderState&);
void parse_baror(const Card&, ReaderState&);
void parse_beamor(const Card&, ReaderState&);
void parse_crod(const Card&, ReaderState&);  ///< CROD and CTUBE
void parse_conrod(const Card&, ReaderState&);
void parse_cquad4(const Card&, ReaderState&);  ///< CQUAD4 and CQUADR
void parse_ctria3(const Card&, ReaderState&);  ///< CTRIA3 and CTRIAR
void parse_conm2(const Card&, ReaderState&);
void parse_celas1(const Card&, ReaderState&);
void parse_celas2(const Card&, ReaderState&);
void parse_rbe2(const Card&, ReaderState&);
void parse_cshear(const Card&, ReaderState&);
void parse_cbend(const Card&, ReaderState&);
void parse_shell8(const Card&, ReaderState&);  ///< CQUAD8, CTRIA6
// Solids and face pressures (nastran_cards_solids.cpp)
void parse_chexa(const Card&, ReaderState&);
void parse_cpenta(const Card&, ReaderState&);
void parse_ctetra(const Card&, ReaderState&);
void parse_cpyram(const Card&, ReaderState&);
void parse_psolid(const Card&, ReaderState&);
void parse_pload4(const Card&, ReaderState&);
// Materials and properties (nastran_cards_properties.cpp)
void parse_mat1(const Card&, ReaderState&);
void parse_mat2(const Card&, ReaderState&);
void parse_mat8(const Card&, ReaderState&);
void parse_mat9(const Card&, ReaderState&);
void parse_pbar(const Card&, ReaderState&);
void parse_pbarl(const Card&, ReaderState&);
void parse_pbeam(const Card&, ReaderState&);
void parse_pbeaml(const Card&, ReaderState&);
void parse_prod(const Card&, ReaderState&);
void parse_ptube(const Card&, ReaderState&);
void parse_pshear(const Card&, ReaderState&);
void parse_pbend(const Card&, ReaderState&);
void parse_pshell(const Card&, ReaderState&);
void parse_pcomp(const Card&, ReaderState&);
void parse_pcompg(const Card&, ReaderState&);
void parse_pelas(const Card&, ReaderState&);
// Constraints, sets and loads (nastran_cards_constraints.cpp)
void parse_spc(const Card&, ReaderState&);
void parse_spc1(const Card&, ReaderState&);
void parse_spcadd(const Card&, ReaderState&);
void parse_mpc(const Card&, ReaderState&);
void parse_mpcadd(const Card&, ReaderState&);
void parse_omit(const Card&, ReaderState&);
void parse_omit1(const Card&, ReaderState&);
void parse_rbar(const Card&, ReaderState&);
void parse_rbe3(const Card&, ReaderState&);
void parse_aset(const Card&, ReaderState&);
void parse_aset1(const Card&, ReaderState&);
void parse_bset(const Card&, ReaderState&);
void parse_bset1(const Card&, ReaderState&);
void parse_suport(const Card&, ReaderState&);
void parse_suport1(const Card&, ReaderState&);
void parse_eigb(const Card&, ReaderState&);
void parse_force(const Card&, ReaderState&);
void parse_moment(const Card&, ReaderState&);
void parse_force12(const Card&, ReaderState&);  ///< FORCE1, FORCE2, MOMENT1, MOMENT2
void parse_sload(const Card&, ReaderState&);
void parse_pload(const Card&, ReaderState&);
void parse_load(const Card&, ReaderState&);
void parse_genel(const Card&, ReaderState&);  ///< nastran_cards_genel.cpp
// Rigid elements besides RBE2 and RBAR (nastran_cards_rigid.cpp)
void parse_rbe1(const Card&, ReaderState&);
void parse_crigd1(const Card&, ReaderState&);
void parse_crigd2(const Card&, ReaderState&);
void parse_crigd3(const Card&, ReaderState&);
void parse_crigdr(const Card&, ReaderState&);
void parse_rrod(const Card&, ReaderState&);
// Pressure, inertia and thermal loads (nastran_cards_loads.cpp)
void parse_pload2(const Card&, ReaderState&);
void parse_grav(const Card&, ReaderState&);
void parse_rforce(const Card&, ReaderState&);
void parse_temp(const Card&, ReaderState&);
void parse_tempd(const Card&, ReaderState&);
void parse_temprb(const Card&, ReaderState&);
// Bushings, scalar springs and masses, CONM1 (nastran_cards_bush_mass.cpp)
void parse_cbush(const Card&, ReaderState&);
void parse_pbush(const Card&, ReaderState&);
void parse_cbush1d(const Card&, ReaderState&);
void parse_pbush1d(const Card&, ReaderState&);
void parse_tablem(const Card&, ReaderState&);
void parse_celas3(const Card&, ReaderState&);
void parse_celas4(const Card&, ReaderState&);
void parse_cmass1(const Card&, ReaderState&);  ///< CMASS1 and CMASS3
void parse_cmass2(const Card&, ReaderState&);  ///< CMASS2 and CMASS4
void parse_pmass(const Card&, ReaderState&);
void parse_conm1(const Card&, ReaderState&);
// Bar line loads and enforced motion (nastran_cards_bar_loads.cpp)
void parse_pload1(const Card&, ReaderState&);
void parse_spcd(const Card&, ReaderState&);
// Solution control and matrices (nastran_cards_solution.cpp)
void parse_eigrl(const Card&, ReaderState&);
void parse_eigr(const Card&, ReaderState&);
void parse_param(const Card&, ReaderState&);
void parse_dmig(const Card&, ReaderState&);
void parse_mdlprm(const Card&, ReaderState&);
// Part superelements: placing and connecting them (nastran_cards_parts.cpp)
void parse_point(const Card&, ReaderState&);
void parse_seloc(const Card&, ReaderState&);
void parse_sebulk(const Card&, ReaderState&);
void parse_seconct(const Card&, ReaderState&);
void parse_selabel(const Card&, ReaderState&);
void parse_extrn(const Card&, ReaderState&);
void parse_sempln(const Card&, ReaderState&);

/// A PARAM value as stored in fem::Param::values: text upper-cased; numbers rewritten in a form
/// std::from_chars reads (Nastran's "2.59-3" becomes "0.00259"), reals always with '.' or an exponent.
std::string param_value(std::string_view field);

/// Ids of a list field run starting at data field `first`: integers and "ID1 THRU ID2" ranges, blanks
/// skipped (SPC1, ASET1, BSET1, SPOINT, RBE2). Stops at the end of the card or, when stop_at_real, at
/// the first real. Ranges larger than kMaxThru ids are an error. `from_thru` (optional) receives, per
/// id, whether it belongs to a "ID1 THRU ID2" range (ID1 and ID2 included).
inline constexpr int kMaxThru = 10'000'000;
std::vector<int> id_list(const Card& card, std::size_t first, const char* what, bool stop_at_real = false,
                         std::size_t* stopped_at = nullptr, std::vector<bool>* from_thru = nullptr);

}  // namespace seflex::io::nastran
