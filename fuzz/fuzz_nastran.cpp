// Fuzzes the Nastran deck reader (io/nastran.hpp): executive and case control, bulk data in small,
// large and free field, continuations, every card seflex reads, then fem::finalize (ids, references,
// coordinate systems) - everything `read_nastran` does.
// The input is the deck text, read in memory as "fuzz.bdf". INCLUDE is confined to the harness's
// private scratch folder (empty): inputs that contain INCLUDE together with a '/' or '\' (a path that
// could leave that folder, such as /dev/zero) are rejected, so relative includes exercise the
// missing-file, quoting and continuation paths without reading the machine's files.
// Accepted outcomes: the deck reads, or InputError. Seeds: *.bdf, *.dat, *.DAT of tests/, meshes/,
// examples/ and the validation decks (bench/fuzz.sh); dictionary fuzz/dict/nastran.dict.
#include <cstddef>
#include <cstdint>
#include <string_view>

#include "fuzz_support.hpp"
#include "seflex/io/nastran.hpp"

extern "C" int LLVMFuzzerTestOneInput(const uint8_t* data, size_t size) {
  const std::string_view text(reinterpret_cast<const char*>(data), size);
  if (seflex::fuzz::contains_nocase(text, "include") &&
      (text.find('/') != std::string_view::npos || text.find('\\') != std::string_view::npos))
    return -1;
  seflex::fuzz::run([&] { seflex::io::read_nastran_text(text, "fuzz.bdf", seflex::fuzz::scratch_dir()); });
  return 0;
}
