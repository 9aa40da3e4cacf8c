#pragma once
// `seflex info BODY.se`: what a superelement file holds (the Nastran-deck half of `seflex info` is
// cmd_info.cpp).
#include <string>

#include "seflex/superelement/superelement.hpp"

namespace seflex::app {

/// True when the file starts with the superelement magic bytes "SEFLEXSE".
bool is_superelement_file(const std::string& path);

/// Print provenance, units, frame node, interfaces, modes, mass properties, inertia invariants,
/// mesh part, truncation report and source warnings of a superelement file. Throws InputError
/// (from the reader) when the file is damaged.
void print_superelement_info(const std::string& path);

/// Print the truncation report (modal effective mass fractions, highest kept and first neglected
/// mode); `none_neglected` is printed when no neglected mode was computed. Shared by reduce and info.
void print_truncation(const se::TruncationReport& t, const char* none_neglected);

}  // namespace seflex::app
