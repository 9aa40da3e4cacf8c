// Fuzzes DMIG input (direct matrices K2GG / M2GG, fem/dmig.hpp) from reading to assembly: the input is
// bulk data appended to a fixed deck (two CBARs on grids 1-3, scalar point 10, case control
// K2GG = KX and M2GG = MX), read with the Nastran reader, then K and M are assembled with the DMIG
// terms added (fem::assemble, which calls fem::add_direct_matrices), as `seflex modes` would do.
// The deck's own cards are valid, so the fuzzer spends its time on DMIG headers, columns, components,
// scalar points, symmetric duplicates and PARAM CK2/CM2. INCLUDE lines are rejected (no files read).
// Accepted outcomes: reads and assembles, or InputError. Dictionary: fuzz/dict/dmig.dict.
#include <cstddef>
#include <cstdint>
#include <string>
#include <string_view>

#include "fuzz_support.hpp"
#include "seflex/fem/assembly.hpp"
#include "seflex/io/nastran.hpp"

namespace {
constexpr std::string_view kHead =
    "SOL 103\nCEND\nK2GG = KX\nM2GG = MX\nBEGIN BULK\n"
    "GRID,1,,0.,0.,0.\nGRID,2,,1.,0.,0.\nGRID,3,,2.,0.,0.\nSPOINT,10\n"
    "CBAR,1,7,1,2,0.,0.,1.\nCBAR,2,7,2,3,0.,0.,1.\n"
    "PBAR,7,8,1.e-4,1.e-9,1.e-9,2.e-9\nMAT1,8,7.e10,,0.3,2700.\n";
}  // namespace

extern "C" int LLVMFuzzerTestOneInput(const uint8_t* data, size_t size) {
  const std::string_view bulk(reinterpret_cast<const char*>(data), size);
  if (seflex::fuzz::contains_nocase(bulk, "include")) return -1;
  std::string deck(kHead);
  deck.append(bulk);
  seflex::fuzz::run([&] {
    const seflex::fem::Model model = seflex::io::read_nastran_text(deck, "fuzz_dmig.bdf");
    seflex::fem::assemble(model, seflex::fem::assembly_options(model));
  });
  return 0;
}
