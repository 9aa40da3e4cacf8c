#pragma once
// Command-line options of every command that reads a model (io::read_model):
//   --properties FILE    the companion bulk-data file of a gmsh mesh (default <stem>.props.bdf)
//   --set NAME=VALUE     a parameter of a .geo file (DefineConstant ... Name "Path/NAME"), repeatable
//   --symbol NAME=DIR    a logical symbol for INCLUDE 'NAME:path' (MSC Nastran's symbol=NAME=DIR), repeatable
// Call before Args::finish(); the options are consumed.
#include <string>

#include "command.hpp"
#include "seflex/common/error.hpp"
#include "seflex/io/model_reader.hpp"

namespace seflex::app {

/// The usage text of the options above, for SEFLEX_COMMAND usage strings.
inline constexpr const char* kModelOptionsUsage = "[--properties FILE] [--set NAME=VALUE]... [--symbol NAME=DIR]...";

inline io::ModelReadOptions model_read_options(Args& args) {
  io::ModelReadOptions o;
  if (auto p = args.value("properties")) o.properties = *p;
  while (auto s = args.value("set")) {
    try {
      o.parameters.push_back(io::parse_gmsh_parameter(*s));
    } catch (const InputError& e) {
      throw UsageError(std::string("--set: ") + e.what());
    }
  }
  while (auto s = args.value("symbol")) {
    try {
      o.symbols.push_back(io::parse_nastran_symbol(*s));
    } catch (const InputError& e) {
      throw UsageError(std::string("--symbol: ") + e.what());
    }
  }
  return o;
}

}  // namespace seflex::app
