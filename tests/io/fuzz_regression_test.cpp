// Inputs the fuzzers (fuzz/, bench/fuzz.sh) found that a reader mishandled, kept as regressions: each
// must now be refused with an InputError naming the file (and line or header key) and what was
// expected - not crash, not throw yaml-cpp's own exception, not allocate gigabytes.
// The inputs are in tests/data/fuzz-regressions/<harness>/ (README.md there says where each came from).
// These tests also run under AddressSanitizer + UndefinedBehaviorSanitizer in CI.
#include <algorithm>
#include <cstdint>
#include <map>
#include <gtest/gtest.h>

#include "nastran_test_util.hpp"
#include "seflex/common/error.hpp"
#include "seflex/io/gmsh.hpp"
#include "seflex/io/superelement_file.hpp"
#include "test_support.hpp"

using namespace seflex;
using seflex::test::input_error;
using seflex::test::mentions;

namespace {

std::filesystem::path regression(const std::string& rel) { return test::data_dir() / "fuzz-regressions" / rel; }

/// The InputError of reading a regression .msh (copied beside a valid companion file).
std::string msh_text_error(const std::string& name, const std::string& text) {
  test::TempDir dir;
  const auto mesh = dir.write(name, text);
  io::ModelReadOptions o;
  o.properties = dir.write("m.props.bdf", "$seflex group plate PSHELL 1\nMAT1,1,7.e10,,0.3\nPSHELL,1,1,0.001,1\n");
  return input_error([&] { io::read_gmsh(mesh, o); });
}

std::string msh_error(const std::string& name) { return msh_text_error(name, test::read_file(regression("gmsh/" + name))); }

std::string se_error(const std::string& name) {
  return input_error([&] { io::load_superelement(regression("superelement/" + name)); });
}

}  // namespace

// Every input in tests/data/fuzz-regressions/gmsh/ (README.md there: what each did to libgmsh, or to
// the count check that guarded libgmsh before seflex read .msh files itself) is now read by seflex's
// own reader; each must be refused with an InputError naming the file, the line (text) or byte
// (binary) and the section, or read to a model. Every file of the folder must be in this table.
TEST(FuzzRegression, EveryGmshInputIsReadOrRefusedWithAMessage) {
  const std::map<std::string, std::string> expected = {
      // 2e9 nodes in a block of a 150-byte file (libgmsh: > 10 GB)
      {"node_block_ascii.msh",
       ":9: $Nodes: node block 1 of 1 holds 2000000000 nodes, but the section declares 2 in all"},
      {"node_block_binary.msh",
       ": byte 6585: $Nodes: node block 1 of 93 holds 2000000000 nodes, but the section declares 31"},
      {"node_count_msh2.msh", ":5: $Nodes: 2000000000 nodes, but the 18 bytes left in the file hold at most 2"},
      // a $NodeData of 2e9 entities: skipped (seflex reads no data sections); the mesh has no groups
      {"node_data_count.msh", "node_data_count.msh: the mesh has no physical groups"},
      {"entities_physical_tags_binary.msh",
       ": byte 976: $Entities: point 17 of 31: 3959422977 physical tags, but the 7536 bytes left in the file hold at "
       "most 1884"},
      {"node_data_after_damaged_section.msh",
       ":8: $PhysicalNames: physical name 3 of 13: the name is '\"hinge2 6 6'; expected a name in double quotes"},
      {"element_tag_count_missing_msh2.msh",
       ":58: $Elements: element 3 of 68: the line ends after 5 numbers, before a tag; expected 'elm-number elm-type"},
      {"element_block_count_binary_msh4.msh",
       ": byte 10762: $Elements: element block 49 of 61 holds 140737488355329 elements, but the section declares 61 in "
       "all, 48 of them in the blocks before"},
      // gmsh ran this damaged first line as a .geo script (SystemCall, file output, Exit)
      {"script_first_line.msh",
       ":1: the file starts with '$M\\x00\\x00\\x00\\x00\\x002Eata\\xA7'; expected a gmsh mesh (MSH format 2 or 4), "
       "whose first line is $MeshFormat"},
      {"entities_section_ends_early_binary.msh",
       ": byte 183: $PhysicalNames: physical name 10 of 13: the name is '\"'"},
      {"physical_name_dimension_msh4.msh",
       ":6: $PhysicalNames: physical name 1 of 1: physical group 13 has dimension 5; expected 0"},
      {"mesh_format_keyword_prefix.msh", ":1: the file starts with '$MeshFormat\"Nodes'"},
      {"count_lines_binary_msh2.msh",
       ":2: $MeshFormat: more on the line after 3 numbers ('0 0'); expected 'version file-type data-size'"},
      {"physical_name_tag_prefix_msh4.msh",
       ":6: $PhysicalNames: physical name 1 of 1: physicalTag is '13\\\"in$EndElements\"'; expected an integer"},
      {"element_type_unknown_binary_msh2.msh",
       ": byte 1140: $Nodes: node 0 is defined twice; expected each node tag once"},
      {"physical_names_count_line_msh4.msh",
       ":5: $PhysicalNames: the count line: more on the line after 1 number ('\"hi$EndEntitiesframe\"')"},
      {"byte_order_marker_msh4.msh",
       ": byte 20: $MeshFormat: the byte-order integer is '$Nod'; expected the integer 1, little-endian"},
      {"physical_names_body_binary_msh2.msh", ":1: the file starts with '$MeshFormat\"Nodes'"},
      {"node_blocks_beyond_total_msh4.msh",
       ":10: $Nodes: node block 1 of 1 holds 2 nodes, but the section declares 0 in all"},
  };
  std::size_t seen = 0;
  for (const auto& entry : std::filesystem::directory_iterator(regression("gmsh"))) {
    const std::string name = entry.path().filename().string();
    if (entry.path().extension() != ".msh") continue;
    SCOPED_TRACE(name);
    ++seen;
    const auto it = expected.find(name);
    ASSERT_NE(it, expected.end()) << "a regression input without an expected outcome in this test";
    const std::string message = msh_error(name);
    EXPECT_NE(message.find(name + ":"), std::string::npos) << message;  // the file, then where in it
    EXPECT_TRUE(mentions(message, {it->second}));
  }
  EXPECT_EQ(seen, expected.size());
}

// A header value of the wrong kind where the reader looks up a key (a scalar or a list instead of an
// object) made yaml-cpp throw its own exception ("operator[] call on a scalar"): `seflex` exited 1 with
// a message naming neither the file nor the key.
TEST(FuzzRegression, SuperelementHeaderValueOfTheWrongKindIsAnInputError) {
  EXPECT_TRUE(mentions(se_error("dataset_entry_scalar.se"),
                       {"dataset_entry_scalar.se", "dataset 'K': its table entry must be an object"}));
  EXPECT_TRUE(mentions(se_error("interface_scalar.se"),
                       {"interface_scalar.se", "header: expected an object with the key 'id', got the value '7'"}));
  EXPECT_TRUE(
      mentions(se_error("source_warning_object.se"),
               {"source_warning_object.se", "header: 'source_warnings' must be an array of strings, got an object"}));
}

// A dataset table key that is not a name (`&K": {...}`: a YAML anchor where the quote was, found by
// fuzz_superelement in CI's 20 s run on 2026-11-27) made yaml-cpp throw "bad conversion" from the
// key's conversion to a string: exit 1, no file name.
TEST(FuzzRegression, SuperelementDatasetKeyThatIsNotANameIsAnInputError) {
  EXPECT_TRUE(mentions(se_error("dataset_key_anchor.se"),
                       {"dataset_key_anchor.se", "datasets: every key must be a dataset name, got an object"}));
}

// M_fe's column pointers were checked one column at a time, after the rows of the previous column had
// been read: a pointer beyond the number of values read past the end of M_fe.rowind (ASan:
// heap-buffer-overflow; found by fuzz_superelement in its first 8,000 executions).
TEST(FuzzRegression, SuperelementMassColumnPointerBeyondTheValuesIsRefusedBeforeItIsUsed) {
  EXPECT_TRUE(mentions(se_error("mfe_colptr_beyond_values.se"),
                       {"mfe_colptr_beyond_values.se",
                        "dataset 'M_fe.colptr' is not non-decreasing from 0 to the length of M_fe.values"}));
}

TEST(FuzzRegression, SuperelementCommandExitsThreeWithOneErrorLine) {
  test::TempDir dir;
  const auto r = test::run_seflex("export '" + regression("superelement/interface_scalar.se").string() + "' --dmig '" +
                                  (dir / "x.bdf").string() + "'");
  EXPECT_EQ(r.exit_code, 3) << r.err;
  EXPECT_TRUE(mentions(r.err, {"error: ", "interface_scalar.se", "expected an object with the key 'id'"}));
}
