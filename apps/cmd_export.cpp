// seflex export BODY.se --dmig deck.bdf | --op4 file.op4: a superelement in the formats Craig-Bampton
// models are exchanged in (Nastran direct matrix input, OUTPUT4 ASCII matrices).
#include <cstdio>
#include <filesystem>
#include <limits>
#include <string>

#include "command.hpp"
#include "seflex/common/error.hpp"
#include "seflex/io/dmig_export.hpp"
#include "seflex/io/op4.hpp"
#include "seflex/io/superelement_file.hpp"

namespace {

using seflex::app::UsageError;

int run_export(seflex::app::Args& args) {
  constexpr int kAbsent = std::numeric_limits<int>::min();
  const auto dmig = args.value("dmig");
  const auto op4 = args.value("op4");
  const bool recovery = args.flag("recovery");
  const int first_spoint = args.integer("first-spoint", kAbsent);
  const bool force = args.flag("force");
  const std::string body_path = args.positional("BODY.se");
  args.finish();
  if (!dmig && !op4) throw UsageError("nothing to export: give --dmig FILE and/or --op4 FILE");
  if (recovery && !op4) throw UsageError("--recovery goes with --op4 (the DMIG deck holds K and M only)");
  if (first_spoint != kAbsent && first_spoint < 1) throw UsageError("option --first-spoint expects an id >= 1");
  for (const auto& p : {dmig, op4})  // before the work, not after it
    if (p && !force && std::filesystem::exists(*p))
      throw seflex::InputError(seflex::SourceRef{*p, 0},
                               "exists already; refusing to overwrite it (use --force to replace it)");

  const seflex::se::Superelement body = seflex::io::load_superelement(body_path);
  std::printf("superelement '%s' from %s: %d interface nodes, %d modes, n = %d\n", body.name.c_str(), body_path.c_str(),
              body.num_interfaces(), body.num_modes, body.size());
  for (const std::string& w : body.source_warnings)  // what seflex reduce said about the source model
    std::fprintf(stderr, "warning (reduction of %s): %s\n", body.source_file.c_str(), w.c_str());
  std::fflush(stderr);
  if (dmig) {
    seflex::io::DmigExportOptions o;
    o.overwrite = force;
    if (first_spoint != kAbsent) o.first_spoint = first_spoint;
    seflex::io::write_dmig_deck(body, *dmig, o);
    std::printf("wrote %s: Nastran DMIG deck (K2GG = %s, M2GG = %s, SOL 103 runs as is)\n", dmig->c_str(),
                o.stiffness_name.c_str(), o.mass_name.c_str());
  }
  if (op4) {
    seflex::io::Op4ExportOptions o;
    o.overwrite = force;
    o.recovery = recovery;
    seflex::io::write_op4(body, *op4, o);
    std::printf("wrote %s: OUTPUT4 ASCII matrices KAA, MAA%s\n", op4->c_str(), recovery ? ", RECOVERY" : "");
  }
  return seflex::app::kOk;
}

}  // namespace

SEFLEX_COMMAND(export, "BODY.se [--dmig DECK.bdf] [--op4 FILE.op4 [--recovery]] [--first-spoint ID] [--force]",
               "write a superelement as a Nastran DMIG deck (K and M on the interface grids and modal SPOINTs, "
               "runs in SOL 103 as is) and/or as OUTPUT4 ASCII matrices",
               run_export);
