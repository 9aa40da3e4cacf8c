// Fuzzes the superelement file reader (io/superelement_file.hpp, format docs/superelement-format.md):
// magic, format version, the JSON header and its dataset table, dataset sizes and offsets, the
// SHA-256 trailer, finiteness and symmetry checks - everything `load_superelement` does after
// reading the bytes.
// The checksum makes nearly every mutation fail at the trailer, so the harness fuzzes two ways, by
// the first byte of the input: odd -> the remaining bytes as they are (trailer checks); even -> the
// remaining bytes with a correct SHA-256 trailer appended (io/sha256.hpp), so the header and
// datasets behind the checksum are explored.
// Accepted outcomes: loads, or InputError. Seeds: link.se and others written by bench/fuzz.sh
// (`seflex reduce`); dictionary fuzz/dict/superelement.dict.
#include <cstddef>
#include <cstdint>
#include <string>

#include "fuzz_support.hpp"
#include "seflex/io/superelement_file.hpp"

extern "C" int LLVMFuzzerTestOneInput(const uint8_t* data, size_t size) {
  if (size == 0) return 0;
  std::string bytes(reinterpret_cast<const char*>(data) + 1, size - 1);
  if ((data[0] & 1) == 0) bytes = seflex::fuzz::with_sha256_trailer(bytes);
  seflex::fuzz::run([&] { seflex::io::parse_superelement(bytes, "fuzz.se"); });
  return 0;
}
