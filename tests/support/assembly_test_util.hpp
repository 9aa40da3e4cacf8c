#pragma once
// The InputError message of assembling a deck that reads (element checks made at assembly).
#include <string>

#include "nastran_test_util.hpp"
#include "seflex/fem/assembly.hpp"

namespace seflex::test {

/// The InputError message of assembling the deck ("" and a test failure if it assembles).
inline std::string assembly_error(const std::string& deck) {
  const fem::Model m = read_deck(deck);
  return input_error([&] { fem::assemble(m, fem::assembly_options(m)); });
}

}  // namespace seflex::test
