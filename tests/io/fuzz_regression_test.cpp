// Inputs the fuzzers (fuzz/, bench/fuzz.sh) found that a reader mishandled, kept as regressions: each
// must now be refused with an InputError naming the file (and line or header key) and what was
// expected - not crash, not throw yaml-cpp's own exception, not allocate gigabytes.
// The inputs are in tests/data/fuzz-regressions/<harness>/ (README.md there says where each came from).
// These tests also run under AddressSanitizer + UndefinedBehaviorSanitizer in CI.
#include <algorithm>
#include <cstdint>
#include <gtest/gtest.h>

#include "nastran_test_util.hpp"
#include "seflex/common/error.hpp"
#include "seflex/io/gmsh.hpp"
#include "seflex/io/superelement_file.hpp"
#include "test_support.hpp"

using namespace seflex;
using seflex::test::mentions;

namespace {

std::filesystem::path regression(const std::string& rel) { return test::data_dir() / "fuzz-regressions" / rel; }

template <class F>
std::string input_error(F&& read) {
  try {
    read();
  } catch (const InputError& e) {
    return e.what();
  } catch (const std::exception& e) {
    ADD_FAILURE() << "not an InputError: " << e.what();
    return e.what();
  }
  ADD_FAILURE() << "read without error";
  return "";
}

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

// libgmsh allocates what a node block declares before reading it: 2e9 nodes in a 150-byte file took
// more than 10 GB in 20 s. The declared counts are now checked against the section's size first.
TEST(FuzzRegression, GmshNodeBlockCountBeyondTheFileIsRefusedBeforeGmshAllocatesIt) {
  EXPECT_TRUE(mentions(msh_error("node_block_ascii.msh"),
                       {"node_block_ascii.msh:9: $Nodes: 2000000000 nodes in a block, but the rest of the section holds at most 2",
                        "expected a count that matches the data"}));
  EXPECT_TRUE(mentions(msh_error("node_block_binary.msh"),
                       {"node_block_binary.msh:27: $Nodes: 2000000000 nodes in a block, but the rest of the section holds at most 88"}));
  EXPECT_TRUE(mentions(msh_error("node_count_msh2.msh"),
                       {"node_count_msh2.msh:5: $Nodes: 2000000000 nodes, but the rest of the section holds at most 1"}));
}

TEST(FuzzRegression, GmshNodeDataEntityCountBeyondTheFileIsRefused) {
  EXPECT_TRUE(mentions(msh_error("node_data_count.msh"),
                       {"node_data_count.msh:29: $NodeData: 2000000000 entities, but the rest of the section holds at most 0"}));
}

// A binary MSH 4.1 file whose $Entities declares 3,959,422,977 physical tags for one entity (the
// fuzzer's mutation of the panel mesh): libgmsh spent more than 10 s allocating and clearing memory.
TEST(FuzzRegression, GmshEntityTagCountBeyondTheFileIsRefused) {
  EXPECT_TRUE(mentions(msh_error("entities_physical_tags_binary.msh"),
                       {"entities_physical_tags_binary.msh:21: $Entities: 3959422977 physical tags of an entity, but the rest "
                        "of the section holds at most"}));
}

// Two meshes pasted into one file, the first with a damaged $PhysicalNames: the check took everything up
// to the missing $EndPhysicalNames as one section and never saw the $NodeData of 2,000,000,000 entities
// near the end, which gmsh found (timeout). A section now ends at the next line starting with '$'.
TEST(FuzzRegression, GmshSectionAfterADamagedOneIsStillChecked) {
  // Its $Elements (lines 57-62) is damaged too: refused there since the element lines are checked.
  EXPECT_TRUE(mentions(msh_error("node_data_after_damaged_section.msh"),
                       {"node_data_after_damaged_section.msh:59: $Elements: the line holds 4 numbers"}));
  // Without that section, the $NodeData after the damaged $PhysicalNames is reached (the line of its
  // count in the shortened text).
  std::string text = test::read_file(regression("gmsh/node_data_after_damaged_section.msh"));
  const auto begin = text.find("$Elements\n"), end = text.find("$EndElements\n");
  ASSERT_TRUE(begin != std::string::npos && end != std::string::npos);
  text.erase(begin, end + std::string("$EndElements\n").size() - begin);
  const auto count_at = text.find("\n2000000000\n");
  ASSERT_NE(count_at, std::string::npos);
  const auto line = 2 + std::count(text.begin(), text.begin() + static_cast<long>(count_at), '\n');
  EXPECT_TRUE(mentions(msh_text_error("node_data_after_damaged_section.msh", text),
                       {"node_data_after_damaged_section.msh:" + std::to_string(line) + ": $NodeData: 2000000000 entities"}));
}

// A binary MSH 4.1 file whose element block declares 2^51 elements (the fuzzer's mutation): libgmsh
// allocated the block's data before reading it (allocation-size-too-big under ASan). The counts of
// every element block are now checked against the bytes left, as the node blocks' were.
TEST(FuzzRegression, GmshElementBlockCountBeyondTheFileIsRefused) {
  EXPECT_TRUE(mentions(msh_error("element_block_count_binary_msh4.msh"),
                       {"element_block_count_binary_msh4.msh:", "$Elements: ", "elements in a block, but the rest of the section holds at most"}));
}

// A format 2.2 text mesh whose element 3 lost its tag count ("3 15  4 23 3"): libgmsh reads the
// numbers across line ends, so the rest of $Elements was shifted, and it aborted the process on an
// assertion (GModelIO_MSH2.cpp: a node it does not know). Each element line is now checked: the count
// of numbers for its type and tags, and its nodes against $Nodes.
TEST(FuzzRegression, GmshMsh2ElementLineOfTheWrongLengthIsRefused) {
  EXPECT_TRUE(mentions(msh_error("element_tag_count_missing_msh2.msh"),
                       {"element_tag_count_missing_msh2.msh:", "$Elements: the line holds 5 numbers; expected 'tag type ntags', "
                        "ntags tags and the type's 1 nodes"}));
  std::string text = test::read_file(regression("gmsh/element_tag_count_missing_msh2.msh"));
  const auto at = text.find("\n3 15  4 23 3\n");
  ASSERT_NE(at, std::string::npos);
  text.replace(at, 14, "\n3 15 2 4 3 999\n");  // well formed, but node 999 does not exist
  EXPECT_TRUE(mentions(msh_text_error("unknown_node.msh", text),
                       {"unknown_node.msh:", "$Elements: element 3 refers to node 999, which is not in $Nodes"}));
}

// The fuzzer's 13 bytes "$M\0\0\0\0\0" "2Eata\xA7" (a damaged $MeshFormat line): gmsh chooses its reader by
// the first line, not the name, and parsed this .msh as a .geo script - a language with SystemCall (a
// shell command), file output and Exit (found by a leak scan of the corpus, looking for why a 458 s run
// had grown to 2 GB). A .msh must now start with $MeshFormat before gmsh sees it.
TEST(FuzzRegression, GmshMeshNotStartingWithMeshFormatIsNotReadAsAScript) {
  EXPECT_TRUE(mentions(msh_error("script_first_line.msh"),
                       {"script_first_line.msh:1: the file starts with '$M\\x00\\x00\\x00\\x00\\x002Eata\\xA7'",
                        "expected a gmsh mesh (MSH format 2 or 4), whose first line is $MeshFormat"}));
  test::TempDir dir;
  const std::string ran = (dir / "ran").string();
  EXPECT_TRUE(mentions(msh_text_error("s.msh", "SystemCall \"touch " + ran + "\";\n"),
                       {"s.msh:1: the file starts with 'SystemCall", "a script must be named .geo"}));
  EXPECT_FALSE(std::filesystem::exists(ran)) << "gmsh ran the .msh as a script";
  EXPECT_TRUE(mentions(msh_text_error("e.msh", ""), {"e.msh:1: the file is empty; expected a gmsh mesh"}));
}

// Binary MSH 4.1 whose $Entities ends before the data it declares (the fuzzer's input, minimised to an
// empty section; first found as one byte inserted into the panel's entities): libgmsh does not stop at
// "$EndEntities" but reads on and took the following bytes for counts - an allocation of 2^50 bytes
// (allocation-size-too-big under ASan). The check stopped quietly where the section ended; now a binary
// $Entities or $Elements that ends inside what it declares is refused.
TEST(FuzzRegression, GmshBinarySectionEndingInsideItsDataIsRefused) {
  EXPECT_TRUE(mentions(msh_error("entities_section_ends_early_binary.msh"),
                       {"entities_section_ends_early_binary.msh:21: $Entities: the section ends inside its four entity counts",
                        "expected the data of everything it declares"}));
  // The panel mesh with its $Entities cut 10 bytes into entity 10 of its 46 curves (the counts alone
  // still fit the bytes left, so only reading the entities one by one finds the cut).
  std::string text = test::read_file(test::data_dir() / "gmsh" / "panel_msh4_binary.msh");
  const auto begin = text.find("\n$Entities\n"), end = text.find("\n$EndEntities");
  ASSERT_TRUE(begin != std::string::npos && end != std::string::npos);
  text.erase(begin + 11 + 2010, end - (begin + 11 + 2010));
  EXPECT_TRUE(mentions(msh_text_error("cut.msh", text),
                       {"cut.msh:21: $Entities: the section ends inside entity 10 of the 46 of dimension 1"}));
  // The same for an element block's header: $Elements cut 5 bytes into block 35 of 61 (the counts of
  // 61 blocks and 61 elements still fit the 1,286 bytes left).
  text = test::read_file(test::data_dir() / "gmsh" / "panel_msh4_binary.msh");
  const auto elements = text.find("\n$Elements\n"), end_elements = text.find("\n$EndElements");
  ASSERT_TRUE(elements != std::string::npos && end_elements != std::string::npos);
  text.erase(elements + 11 + 1285, end_elements - (elements + 11 + 1285));
  EXPECT_TRUE(mentions(msh_text_error("cut.msh", text),
                       {"cut.msh:32: $Elements: the section ends inside the header of element block 35 of 61"}));
}

// A binary format 2 file (fuzz_gmsh, long campaign): the count lines of $Nodes and $Elements held
// "1 2 1 2" and "1 1 1 1", which libgmsh reads with sscanf("%d") as 1 and the check took for no count, so
// nothing was checked; libgmsh then read text bytes as an element block's tag count and allocated its
// 1 + tags + nodes ints before looking at the block (4.66 GB, GModelIO_MSH2.cpp). The counts are now
// read as libgmsh reads them, and every binary format 2 element block is bounded: its tag count by one
// element, its element count by all of them.
TEST(FuzzRegression, GmshBinaryMsh2ElementBlocksAreBounded) {
  EXPECT_TRUE(mentions(msh_error("count_lines_binary_msh2.msh"),
                       {"count_lines_binary_msh2.msh:5: $Nodes: 1 nodes, but the rest of the section holds at most 0"}));
  // The panel in binary format 2 (gmsh -format msh22 -bin): 68 blocks of one element each, 2,152 bytes.
  const std::string panel = test::read_file(test::data_dir() / "gmsh" / "panel_msh2_binary.msh");
  const std::size_t blocks = panel.find("\n$Elements\n68\n");
  ASSERT_NE(blocks, std::string::npos);
  auto with_int = [&](std::size_t offset, std::uint32_t value) {  // an int of the element data replaced
    std::string text = panel;
    for (int k = 0; k < 4; ++k) text[blocks + 14 + offset + k] = static_cast<char>((value >> (8 * k)) & 0xff);
    return text;
  };
  // block 2's num-tags (its header at byte 28) 2^30: one element would not fit the 2,113 bytes left
  EXPECT_TRUE(mentions(msh_text_error("b.msh", with_int(28 + 8, 1u << 30)),
                       {"b.msh:27: $Elements: 1073741824 tags per element in element block 2 (type 15), but the rest of the "
                        "section holds at most 528"}));
  // block 3's num-elm-follow (header at byte 56) 10^6 points of 16 bytes in the 2,085 bytes left
  EXPECT_TRUE(mentions(msh_text_error("b.msh", with_int(56 + 4, 1000000)),
                       {"b.msh:27: $Elements: 1000000 elements in element block 3 (type 15), but the rest of the section "
                        "holds at most 130"}));
  // a count line with more after the count is read as libgmsh reads it, by its first number: the panel
  // still reads, with all its elements
  std::string junk = panel;
  junk.replace(blocks + 11, 3, "68 x\n");
  test::TempDir dir;
  io::ModelReadOptions o;
  o.properties = test::source_dir() / "meshes" / "panel.props.bdf";
  fem::Model m;
  EXPECT_NO_THROW(m = io::read_gmsh(dir.write("j.msh", junk), o));
  EXPECT_EQ(m.shells.size(), 16u);
  EXPECT_EQ(m.bars.size(), 14u);
}

// A binary format 2 file (fuzz_gmsh, 2026-11-28 campaign, found after 173 s): element block 19 has type
// 0, which neither the check's node table nor gmsh knows. The check stopped walking the blocks there;
// gmsh reads on (an element of an unknown type is 1 + tags ints to it), took later bytes for a block
// header and asked for 12,872,318,976 bytes. A block of a type the table does not know is now refused,
// as a text MSH 2 element line of such a type already was: its size, and so where the next header
// starts, would be gmsh's guess. The same in the format 4 walks, text and binary.
TEST(FuzzRegression, GmshElementBlockOfAnUnknownTypeIsRefused) {
  EXPECT_TRUE(mentions(msh_error("element_type_unknown_binary_msh2.msh"),
                       {"element_type_unknown_binary_msh2.msh:27: $Elements: element block 19 has element type 0, which "
                        "seflex does not read; expected a type of the gmsh reference manual (1-31, 92, 93"}));
  // The panel in format 4.1 text: the first block's type 15 (point) made 99.
  std::string text = test::read_file(test::data_dir() / "gmsh" / "panel_msh4.msh");
  const std::size_t at = text.find("$Elements\n61 61 1 61\n0 1 15 1\n");
  ASSERT_NE(at, std::string::npos);
  text.replace(at + 25, 2, "99");
  EXPECT_TRUE(mentions(msh_text_error("t.msh", text), {"t.msh:244: $Elements: element block 1 has element type 99"}));
  // The panel in format 4.1 binary: the first block's type (after 4 size_t counts and two ints) made 99.
  std::string binary = test::read_file(test::data_dir() / "gmsh" / "panel_msh4_binary.msh");
  const std::size_t e = binary.find("$Elements\n");
  ASSERT_NE(e, std::string::npos);
  const std::size_t type_at = e + 10 + 4 * 8 + 2 * 4;
  ASSERT_EQ(binary[type_at], 15);
  binary[type_at] = 99;
  EXPECT_TRUE(mentions(msh_text_error("b.msh", binary), {"$Elements: element block 1 of 61 has element type 99"}));
}

// A format 4 $PhysicalNames line "5 13 "interface_beam"" (the fuzzer changed the panel's dimension 0 to 5;
// minimised by hand to that one line): libgmsh 4.8 crashed (SEGV in GModel::setPhysicalName) on a
// dimension outside 0-3. Every physical name's dimension is now checked first.
TEST(FuzzRegression, GmshPhysicalNameOfAnImpossibleDimensionIsRefused) {
  EXPECT_TRUE(mentions(msh_error("physical_name_dimension_msh4.msh"),
                       {"physical_name_dimension_msh4.msh:6: $PhysicalNames: physical group 13 has dimension 5; expected 0 "
                        "(point), 1 (curve), 2 (surface) or 3 (volume)"}));
  EXPECT_TRUE(mentions(msh_text_error("n.msh", "$MeshFormat\n4 0 8\n$EndMeshFormat\n$PhysicalNames\n2\n1 2 \"a\"\n-1 3 \"b\"\n"
                                               "$EndPhysicalNames\n"),
                       {"n.msh:7: $PhysicalNames: physical group 3 has dimension -1"}));
  // CI's fuzz_gmsh (seed 1, 2026-11-28): "5 13\"in$EndElements\"" - gmsh's fscanf("%d %d") reads the tag
  // to its first non-digit (13); the check took the token for no number and let the line through.
  // Every number of the text sections is now read as scanf reads it.
  EXPECT_TRUE(mentions(msh_error("physical_name_tag_prefix_msh4.msh"),
                       {"physical_name_tag_prefix_msh4.msh:6: $PhysicalNames: physical group 13 has dimension 5"}));
  EXPECT_TRUE(mentions(msh_text_error("c.msh", "$MeshFormat\n2.2 0 8\n$EndMeshFormat\n$Nodes\n2000000000x\n1 0 0 0\n$EndNodes\n"),
                       {"c.msh:5: $Nodes: 2000000000 nodes, but the rest of the section holds at most 1"}));
}

// A format 4.1 $PhysicalNames whose count line reads '110 "hi$EndEntitiesframe"' (fuzz_gmsh, random seed,
// 2026-11-28): libgmsh reads the count line with fgets and sscanf and ignores the rest of it, then
// read "5 12" on the next line and crashed in GModel::setPhysicalName (SEGV). The check read the
// count as a token and took '"hi...' for the first group's dimension, a syntax error it left to gmsh.
// The section's lines are now read as libgmsh reads them, names by fgets into 256 bytes included.
TEST(FuzzRegression, GmshPhysicalNamesAreReadAsGmshReadsThem) {
  EXPECT_TRUE(mentions(msh_error("physical_names_count_line_msh4.msh"),
                       {"physical_names_count_line_msh4.msh:6: $PhysicalNames: physical group 12 has dimension 5"}));
  // A name line of 263 bytes: libgmsh's fgets takes 255 of them after "0 1" and reads the next group,
  // dimension 5, from the rest of the line.
  const std::string head = "$MeshFormat\n4.1 0 8\n$EndMeshFormat\n$PhysicalNames\n2\n0 1 \"";
  const std::string tail = "\n$EndPhysicalNames\n";
  EXPECT_TRUE(mentions(msh_text_error("l.msh", head + std::string(253, 'a') + "5 12 \"x\"" + tail),
                       {"l.msh:6: $PhysicalNames: physical group 12 has dimension 5"}));
  // A name of 200 characters is one name: the next line's group is read, and its dimension checked.
  EXPECT_TRUE(mentions(msh_text_error("m.msh", head + std::string(200, 'a') + "\"\n7 3 \"y\"" + tail),
                       {"m.msh:7: $PhysicalNames: physical group 3 has dimension 7"}));
}

// CI's fuzz_gmsh (seed 1, 2026-11-28, on the checker of the two fixes above): a binary format 4.1 file
// whose line after "4.1 1 8" reads "$Nod". libgmsh reads those 4 bytes as the file's byte-order int,
// finds it is not 1 and swaps the bytes of every binary number after it; the check read them
// little-endian, so it bounded other numbers than gmsh used (allocation of 2^58 bytes). The check now
// reads the byte-order int where libgmsh does and swaps as it does.
TEST(FuzzRegression, GmshBinaryByteOrderIsReadAsGmshReadsIt) {
  // the 4 bytes "$Nod" were also taken for a section header, whose binary body ran to "$EndNodes" and
  // hid $Entities from the check: it is checked now, its count of 31 points read byte-swapped, 31 * 2^56
  EXPECT_TRUE(mentions(msh_error("byte_order_marker_msh4.msh"),
                       {"byte_order_marker_msh4.msh:21: $Entities: 2233785415175766016 entities of dimension 0, but the rest "
                        "of the section holds at most 173"}));
  // The binary panel with its byte-order int 1 written big-endian: the same count, read as gmsh reads it.
  std::string panel = test::read_file(test::data_dir() / "gmsh" / "panel_msh4_binary.msh");
  const std::size_t one = panel.find("4.1 1 8\n") + 8;
  ASSERT_EQ(panel.substr(one, 4), std::string("\x01\0\0\0", 4));
  panel.replace(one, 4, std::string("\0\0\0\x01", 4));
  EXPECT_TRUE(mentions(msh_text_error("b.msh", panel),
                       {"b.msh:21: $Entities: 2233785415175766016 entities of dimension 0, but the rest of the section holds "
                        "at most 173"}));
}

// CI's fuzz_gmsh (seed 1, on the checker of the fix above): a binary format 2 file whose $PhysicalNames
// ends in a damaged "$EndPhysicalNa..." line, with "$Nodes", "$EndNodes" and "$Elements" after it and
// a "$EndPhysicalNames" only further down. libgmsh's format 2 reader looks for the next section at the
// next line that starts with '$' and read that $Elements (2.16 GB); the check ran the body of
// $PhysicalNames, text in a binary file too, to "$EndPhysicalNames" as if it were binary data, and
// never saw it. Only sections with binary data now run to their $End line.
TEST(FuzzRegression, GmshTextSectionsOfABinaryFileEndAtTheNextSection) {
  EXPECT_TRUE(mentions(msh_error("physical_names_body_binary_msh2.msh"),
                       {"physical_names_body_binary_msh2.msh:56: $Elements: 68 elements, but the rest of the section holds at "
                        "most 12"}));
}

// fuzz_gmsh (CI's seed 1, run locally on the checker of the fix above): a format 4.1 $Nodes that declares
// 0 nodes in all and then a block of 2. libgmsh keeps the section's nodes in an array of the declared
// count and fills it block by block without looking at it: a heap overflow (ASan: alloc-dealloc-mismatch
// at the next delete). The same holds for $Elements. The blocks' counts are now summed against the
// section's, text and binary.
TEST(FuzzRegression, GmshBlocksHoldNoMoreThanTheSectionDeclares) {
  EXPECT_TRUE(mentions(msh_error("node_blocks_beyond_total_msh4.msh"),
                       {"node_blocks_beyond_total_msh4.msh:10: $Nodes: block 1 holds 2 nodes, but the section declares 0; "
                        "expected the blocks to hold the section's count"}));
  // The panel in format 4.1 text: 61 element blocks of one element each, the total made 60.
  std::string text = test::read_file(test::data_dir() / "gmsh" / "panel_msh4.msh");
  const std::size_t at = text.find("$Elements\n61 61 1 61\n");
  ASSERT_NE(at, std::string::npos);
  text.replace(at + 13, 2, "60");
  EXPECT_TRUE(mentions(msh_text_error("t.msh", text), {"t.msh:", "$Elements: blocks 1 to 61 hold 61 elements, but the section declares 60"}));
}

// The fuzzer's first line "$MeshFormat"Nodes", then "1 2 1 2": gmsh recognises a section by the first
// letters of its line (this is $MeshFormat to it) and takes any file-type but 0 as binary; the check
// compared whole names and file-type "1" only, so it skipped the whole file, and libgmsh's _readMSH2
// asked for 2,160,361,668 bytes (libFuzzer: out-of-memory, malloc over the 2 GB limit). Section names are
// now matched as gmsh matches them.
TEST(FuzzRegression, GmshSectionNamesAreRecognisedAsGmshRecognisesThem) {
  EXPECT_TRUE(mentions(msh_error("mesh_format_keyword_prefix.msh"),
                       {"mesh_format_keyword_prefix.msh:23: $Nodes: 31 nodes, but the rest of the section holds at most 15"}));
  EXPECT_TRUE(mentions(msh_text_error("p.msh", "$MeshFormat\"x\n2.2 0 8\n$EndMeshFormat\n$NodesX\n2000000000\n1 0 0 0\n$EndNodes\n"),
                       {"p.msh:5: $Nodes: 2000000000 nodes, but the rest of the section holds at most 1"}));
}

TEST(FuzzRegression, GmshCountCheckAcceptsEveryFormatGmshWrites) {
  // text and binary, formats 2.2, 4.0 and 4.1: the check refuses none of the valid meshes
  io::ModelReadOptions o;
  o.properties = test::source_dir() / "meshes" / "panel.props.bdf";
  for (const char* name : {"panel_msh2.msh", "panel_msh2_binary.msh", "panel_msh40.msh", "panel_msh4.msh", "panel_msh4_binary.msh"}) {
    test::TempDir dir;
    const auto mesh = dir.write(name, test::read_file(test::data_dir() / "gmsh" / name));
    EXPECT_NO_THROW(io::read_gmsh(mesh, o)) << name;
  }
  // Format 4.0 (gmsh -format msh40) reads to the model of format 4.1: the same grids at the same
  // coordinates, the same elements on the same grids.
  const fem::Model v41 = io::read_gmsh(test::data_dir() / "gmsh" / "panel_msh4.msh", o);
  const fem::Model v40 = io::read_gmsh(test::data_dir() / "gmsh" / "panel_msh40.msh", o);
  ASSERT_EQ(v40.grids.size(), 31u);
  ASSERT_EQ(v40.grids.size(), v41.grids.size());
  for (std::size_t k = 0; k < v41.grids.size(); ++k) {
    EXPECT_EQ(v40.grids[k].id, v41.grids[k].id) << k;
    EXPECT_EQ(v40.grids[k].x_basic, v41.grids[k].x_basic) << v41.grids[k].id;
  }
  ASSERT_EQ(v40.shells.size(), 16u);
  ASSERT_EQ(v40.shells.size(), v41.shells.size());
  for (std::size_t k = 0; k < v41.shells.size(); ++k) EXPECT_EQ(v40.shells[k].g, v41.shells[k].g) << v41.shells[k].id;
  ASSERT_EQ(v40.bars.size(), 14u);
  ASSERT_EQ(v40.bars.size(), v41.bars.size());
  for (std::size_t k = 0; k < v41.bars.size(); ++k) {
    EXPECT_EQ(v40.bars[k].ga, v41.bars[k].ga) << v41.bars[k].id;
    EXPECT_EQ(v40.bars[k].gb, v41.bars[k].gb) << v41.bars[k].id;
  }
  ASSERT_EQ(v40.conm2.size(), 25u);
  ASSERT_EQ(v40.conm2.size(), v41.conm2.size());
  for (std::size_t k = 0; k < v41.conm2.size(); ++k) EXPECT_EQ(v40.conm2[k].grid, v41.conm2[k].grid) << k;
  EXPECT_EQ(v40.node_sets, v41.node_sets);
  // Format 4.0 binary (tests/data/gmsh/msh40_to_binary.py: gmsh >= 4.1 writes 4.0 as text only) passes
  // the check; libgmsh 4.8 then refuses it itself.
  EXPECT_TRUE(mentions(msh_text_error("panel_msh40_binary.msh", test::read_file(test::data_dir() / "gmsh" / "panel_msh40_binary.msh")),
                       {"panel_msh40_binary.msh: gmsh cannot read it", "Can only read MSH 4.0 format in ASCII mode"}));
}

namespace {

/// The text of a data file with `from` (which must occur once) replaced by `to`.
std::string replaced(const std::string& name, const std::string& from, const std::string& to) {
  std::string text = test::read_file(test::data_dir() / "gmsh" / name);
  const auto at = text.find(from);
  EXPECT_NE(at, std::string::npos) << from;
  EXPECT_EQ(text.find(from, at + 1), std::string::npos) << from;
  if (at != std::string::npos) text.replace(at, from.size(), to);
  return text;
}

/// `bytes` little-endian, as an MSH binary file holds a number.
std::string little_endian(std::uint64_t value, int bytes) {
  std::string s;
  for (int k = 0; k < bytes; ++k) s += static_cast<char>((value >> (8 * k)) & 0xff);
  return s;
}

/// `text` with the 8-byte little-endian count that ends `prefix` (its first occurrence) set to `value`.
std::string with_count_ending(const std::string& text, const std::string& prefix, std::uint64_t value) {
  const auto at = text.find(prefix);
  if (at == std::string::npos) {
    ADD_FAILURE() << "the block header to damage is not in the file";
    return text;
  }
  std::string out = text;
  out.replace(at + prefix.size() - 8, 8, little_endian(value, 8));
  return out;
}

}  // namespace

// MSH 4.0 lays out $Nodes otherwise than 4.1 (no min/max tags in the header, entity tag before its
// dimension, each node's tag beside its coordinates; in binary, int node tags). The check read 4.0 as
// 4.1: it lost its place in the section and passed a text block of 2^40 nodes to libgmsh, which
// allocates the block's tags before reading them; a valid binary 4.0 file it refused with a count
// read from the coordinates.
TEST(FuzzRegression, GmshMsh40NodeBlockCountBeyondTheFileIsRefused) {
  // The first node block (point 1, dimension 0, not parametric, 1 node), line 118.
  EXPECT_TRUE(mentions(msh_text_error("panel_msh40.msh", replaced("panel_msh40.msh", "\n$Nodes\n61 31\n1 0 0 1\n",
                                                                  "\n$Nodes\n61 31\n1 0 0 1099511627776\n")),
                       {"panel_msh40.msh:118: $Nodes: 1099511627776 nodes in a block, but the rest of the section holds at most 91",
                        "expected a count that matches the data"}));
  // The last block (surface 315, no nodes), reached through 60 blocks read with the 4.0 layout.
  EXPECT_TRUE(mentions(msh_text_error("panel_msh40.msh", replaced("panel_msh40.msh", "\n315 2 0 0\n", "\n315 2 0 1\n")),
                       {"panel_msh40.msh:209: $Nodes: 1 nodes in a block, but the rest of the section holds at most 0"}));
  // Binary: the first block's count (after the header's 2 counts and the block's 3 ints), the line of $Nodes.
  const std::string binary = test::read_file(test::data_dir() / "gmsh" / "panel_msh40_binary.msh");
  const std::string first_block = "$Nodes\n" + little_endian(61, 8) + little_endian(31, 8) + little_endian(1, 4) +
                                  little_endian(0, 4) + little_endian(0, 4) + little_endian(1, 8);
  EXPECT_TRUE(mentions(msh_text_error("panel_msh40_binary.msh", with_count_ending(binary, first_block, 1ULL << 40)),
                       {"panel_msh40_binary.msh:27: $Nodes: 1099511627776 nodes in a block, but the rest of the section holds at most 73"}));
}

// The element blocks of MSH 4.0 are checked as those of 4.1 (the header has no min/max tags; in binary,
// tags and nodes are ints), no longer the section's totals only.
TEST(FuzzRegression, GmshMsh40ElementBlockCountBeyondTheFileIsRefused) {
  // The first element block (point 1, dimension 0, type 15, 1 element), line 213.
  EXPECT_TRUE(mentions(msh_text_error("panel_msh40.msh", replaced("panel_msh40.msh", "\n$Elements\n61 61\n1 0 15 1\n",
                                                                  "\n$Elements\n61 61\n1 0 15 1099511627776\n")),
                       {"panel_msh40.msh:213: $Elements: 1099511627776 elements in a block, but the rest of the section holds at most 212"}));
  const std::string binary = test::read_file(test::data_dir() / "gmsh" / "panel_msh40_binary.msh");
  const std::string first_block = "$Elements\n" + little_endian(61, 8) + little_endian(61, 8) + little_endian(1, 4) +
                                  little_endian(0, 4) + little_endian(15, 4) + little_endian(1, 8);
  EXPECT_TRUE(mentions(msh_text_error("panel_msh40_binary.msh", with_count_ending(binary, first_block, 1ULL << 40)),
                       {"panel_msh40_binary.msh:32: $Elements: 1099511627776 elements in a block, but the rest of the section holds at most 242"}));
}

// A header value of the wrong kind where the reader looks up a key (a scalar or a list instead of an
// object) made yaml-cpp throw its own exception ("operator[] call on a scalar"): `seflex` exited 1 with
// a message naming neither the file nor the key.
TEST(FuzzRegression, SuperelementHeaderValueOfTheWrongKindIsAnInputError) {
  EXPECT_TRUE(mentions(se_error("dataset_entry_scalar.se"),
                       {"dataset_entry_scalar.se", "dataset 'K': its table entry must be an object"}));
  EXPECT_TRUE(mentions(se_error("interface_scalar.se"),
                       {"interface_scalar.se", "header: expected an object with the key 'id', got the value '7'"}));
  EXPECT_TRUE(mentions(se_error("source_warning_object.se"),
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
