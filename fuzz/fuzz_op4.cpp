// Fuzzes the OP4 text reader (io::parse_op4: the matrices of SEBULK EXTOP4 parts): the input is an
// OUTPUT4 text file. Accepted outcomes: the matrices, or InputError naming the file, line and matrix.
// Seeds (bench/fuzz.sh): the .op4 files of tests/ under 64 kB and a dense double-precision matrix.
#include <cstddef>
#include <cstdint>
#include <string>

#include "fuzz_support.hpp"
#include "seflex/io/op4.hpp"

extern "C" int LLVMFuzzerTestOneInput(const uint8_t* data, size_t size) {
  const std::string text(reinterpret_cast<const char*>(data), size);
  seflex::fuzz::run([&] { seflex::io::parse_op4(text, "fuzz.op4"); });
  return 0;
}
