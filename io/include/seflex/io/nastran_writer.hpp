#pragma once
// fem::Model -> Nastran input deck (what `seflex convert` writes).
//
//   seflex::io::write_nastran_file(model, "panel_r8.bdf", /*overwrite=*/false);
//
// Format: free field (comma-separated), at most 8 data fields per line, continuation lines starting
// with a comma. Reals are written in the shortest form that reads back to the same double (C++
// std::to_chars, e.g. 0.55, 1.98e-04 -> "0.000198", 7.1e+10 -> "71000000000."), so reading the deck
// back with io::read_nastran gives the same model numbers and bitwise the same assembled matrices.
//
// What is written: the executive and case control seflex keeps (SOL, TITLE, SUBTITLE, LABEL, SUBCASE,
// SPC, LOAD, METHOD, MPC, TEMPERATURE(LOAD), K2GG, M2GG), then every card of the model (incl. RBE2,
// RBAR, RBE3, MPC, MPCADD, ASET, OMIT, BSET, SUPORT, PLOAD2, GRAV, RFORCE, TEMP, TEMPD, TEMPRB (one per
// element); SPC1 entries as SPC) with the defaults the reader
// applied made explicit (GRDSET, BAROR/BEAMOR and blank PIDs are resolved; MAT1 keeps blank the one of
// E, G, NU that the reader's rule reproduces exactly). Case-control PARAMs are written as bulk PARAMs.
// Named node sets become `$seflex set NAME ID ...` comment lines (read back by io::read_model).
// Cards the reader listed as unsupported (Model::unsupported) cannot be written: they are named in a
// comment at the top of the deck and returned by unwritten_cards() so that callers can warn.
#include <filesystem>
#include <ostream>
#include <string>
#include <vector>

#include "seflex/fem/model.hpp"

namespace seflex::io {

struct NastranWriteOptions {
  /// Comment lines at the top of the deck (each written after "$ ").
  std::vector<std::string> comments;
};

/// Write `model` as a Nastran deck to `out`.
void write_nastran(const fem::Model& model, std::ostream& out, const NastranWriteOptions& options = {});

/// Write `model` to `path`. An existing file is an InputError unless `overwrite`; the deck is
/// written to a temporary file beside `path` and renamed, so a failure leaves no partial deck.
void write_nastran_file(const fem::Model& model, const std::filesystem::path& path, bool overwrite,
                        const NastranWriteOptions& options = {});

/// "NAME (count, first at file:line)" for each entry of Model::unsupported: what a written deck lacks.
std::vector<std::string> unwritten_cards(const fem::Model& model);

}  // namespace seflex::io
