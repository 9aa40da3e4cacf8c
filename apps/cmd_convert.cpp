// seflex convert MODEL -o DECK: write any model seflex reads (Nastran deck, gmsh .msh/.geo with its
// property file) as a Nastran bulk-data deck that reads back to the same matrices.
#include <cstdio>
#include <filesystem>
#include <optional>
#include <string>

#include "command.hpp"
#include "model_args.hpp"
#include "usage_warnings.hpp"
#include "seflex/solutions/card_usage.hpp"
#include "seflex/fem/element_counts.hpp"
#include "seflex/io/model_reader.hpp"
#include "seflex/io/nastran_writer.hpp"
#include "seflex/io/results_csv.hpp"

namespace {

int run_convert(seflex::app::Args& args) {
  using seflex::app::UsageError;
  std::optional<std::string> output = args.value("-o");
  if (!output) output = args.value("output");
  const bool force = args.flag("force");
  const seflex::io::ModelReadOptions options = seflex::app::model_read_options(args);
  const std::string input = args.positional("MODEL");
  args.finish();
  if (!output) throw UsageError("missing -o DECK (the Nastran deck to write; also --output DECK)");
  seflex::io::check_writable(*output, force);  // before the work, not after it

  const seflex::fem::Model model = seflex::io::read_model(input, options);
  seflex::io::NastranWriteOptions w;
  w.comments.push_back("written by seflex convert from " + input);
  for (const auto& p : options.parameters) {
    char buf[64];
    std::snprintf(buf, sizeof buf, "%.17g", p.value);
    w.comments.push_back("  --set " + p.name + "=" + buf);
  }
  seflex::io::write_nastran_file(model, *output, force, w);

  const std::size_t elements = seflex::fem::element_count(model) - model.conm2.size();
  std::printf("wrote %s: %zu grids, %zu elements, %zu CONM2, %zu node sets\n", output->c_str(), model.grids.size(), elements,
              model.conm2.size(), model.node_sets.size());
  std::fflush(stdout);
  seflex::app::print_card_usage(model, seflex::solutions::check_card_usage(model, seflex::solutions::Solution::Convert, {}));
  return seflex::app::kOk;
}

}  // namespace

SEFLEX_COMMAND(convert, "MODEL -o DECK [--force] [--properties FILE] [--set NAME=VALUE]... [--symbol NAME=DIR]...",
               "write a model (Nastran deck, gmsh .msh/.geo + property file) as a Nastran bulk-data deck", run_convert);
