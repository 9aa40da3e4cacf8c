#pragma once
// A superelement as a Nastran deck of direct matrix input (DMIG), the form in which Craig-Bampton
// models are exchanged in coupled-loads work. The deck runs as is (SOL 103): its normal modes are
// the free-free modes of the reduced model.
//
//   SOL 103 / CEND / K2GG = KAAX / M2GG = MAAX / METHOD = 1 / BEGIN BULK
//   GRID*   for each interface node, in basic (CP = CD = 0), large field
//   SPOINT  for the m fixed-interface modal coordinates (ids first_spoint ... first_spoint + m - 1)
//   EIGRL   1 with ND = n (all modes of the reduced model)
//   DMIG    KAAX and MAAX, IFO 6 (symmetric: each column j lists rows i >= j, the lower triangle),
//           TIN 2 (double precision), terms in large field with 11-12 significant digits (the implicit
//           exponent form -1.2345678901+05); exact zeros are omitted.
// Dof order of the matrices: interface grids in the superelement's order (components 1-6, basic
// axes = body axes), then the SPOINTs. PARAM WTMASS is not written: the matrices are already in
// consistent units (M2GG is not scaled by WTMASS in Nastran anyway).
#include <filesystem>
#include <string>

#include "seflex/superelement/superelement.hpp"

namespace seflex::io {

struct DmigExportOptions {
  int first_spoint = 0;  ///< id of the first modal SPOINT; 0 = 9000001, or above the largest interface id
  std::string stiffness_name = "KAAX";
  std::string mass_name = "MAAX";
  bool overwrite = false;
};

/// The deck as text. Throws InvariantError for an inconsistent superelement, InputError for ids
/// that do not fit Nastran's 8-digit fields or matrix names that are not 1-8 letters/digits.
std::string dmig_deck(const se::Superelement& body, const DmigExportOptions& options = {});

/// Write the deck (atomically). Throws InputError if the file exists and !overwrite, or cannot be
/// written.
void write_dmig_deck(const se::Superelement& body, const std::filesystem::path& path,
                     const DmigExportOptions& options = {});

}  // namespace seflex::io
