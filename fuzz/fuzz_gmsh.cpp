// Fuzzes the gmsh mesh reader (io/gmsh.hpp): a .msh file (format 2.2, 4.0 or 4.1, text or binary)
// read by seflex's own MSH reader (io/src/gmsh_msh_reader.cpp), then seflex's part - physical groups,
// element types, node numbering, the companion property file's `$seflex group` directives
// (io/gmsh_directives.cpp) and its bulk data. libgmsh is not involved: it only reads .geo scripts.
// Input: the .msh bytes, optionally followed by a line "$seflex-fuzz-props" and the companion file's
// text (the default is a valid one naming groups "plate" (PSHELL) and "edges" (PBAR)). Both are
// written to the harness's private scratch folder. INCLUDE in the companion part is rejected when a
// '/' or '\' appears in it.
// Accepted outcomes: the model reads, or InputError. Seeds: tests/data/gmsh/*.msh and meshes made by
// bench/fuzz.sh; dictionary fuzz/dict/gmsh.dict.
#include <cstddef>
#include <cstdint>
#include <string>
#include <string_view>

#include "fuzz_support.hpp"
#include "seflex/io/gmsh.hpp"

namespace {
constexpr std::string_view kMarker = "\n$seflex-fuzz-props\n";
constexpr std::string_view kDefaultProps =
    "$seflex group plate PSHELL 1\n$seflex group edges PBAR 2 0. 0. 1.\n$seflex group corner SET\n"
    "MAT1,1,7.e10,,0.3,2700.\nPSHELL,1,1,0.001,1\nPBAR,2,1,1.e-4,1.e-9,1.e-9,2.e-9\n";
}  // namespace

extern "C" int LLVMFuzzerTestOneInput(const uint8_t* data, size_t size) {
  const std::string_view all(reinterpret_cast<const char*>(data), size);
  const std::size_t cut = all.find(kMarker);
  const std::string_view mesh = all.substr(0, cut);
  const std::string_view props = cut == std::string_view::npos ? kDefaultProps : all.substr(cut + kMarker.size());
  if (seflex::fuzz::contains_nocase(props, "include") &&
      (props.find('/') != std::string_view::npos || props.find('\\') != std::string_view::npos))
    return -1;
  seflex::io::ModelReadOptions options;
  options.properties = seflex::fuzz::write_scratch("fuzz.props.bdf", props);
  const auto path = seflex::fuzz::write_scratch("fuzz.msh", mesh);
  seflex::fuzz::run([&] { seflex::io::read_gmsh(path, options); });
  return 0;
}
