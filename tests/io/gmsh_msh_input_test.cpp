// Bad and damaged .msh files and seflex's MSH reader (io::gmsh::read_msh): every problem is an
// InputError naming the file, the line (text) or byte offset (binary), the section and what was
// expected; every count is refused before anything is allocated for it when the rest of the file
// cannot hold what it counts; and no truncation or single-byte change of the test meshes crashes the
// reader or gets past it as anything but an InputError. These tests also run under
// AddressSanitizer + UndefinedBehaviorSanitizer in CI.
#include <gtest/gtest.h>

#include <cstdint>
#include <cstring>

#include "nastran_test_util.hpp"
#include "seflex/common/error.hpp"
#include "seflex/io/gmsh_mesh.hpp"
#include "test_support.hpp"

using namespace seflex;
using seflex::test::mentions;
namespace gmsh = seflex::io::gmsh;

namespace {

/// The InputError of reading `text` as the file m.msh ("" and a failure if it reads).
std::string error_of(const std::string& text, const std::string& name = "m.msh") {
  return test::input_error([&] { gmsh::read_msh_bytes(text, name); });
}

std::string data(const std::string& name) { return test::read_file(test::data_dir() / "gmsh" / name); }

/// `text` with `from` (which must occur once) replaced by `to`.
std::string replaced(std::string text, const std::string& from, const std::string& to) {
  const auto at = text.find(from);
  EXPECT_NE(at, std::string::npos) << from;
  EXPECT_EQ(text.find(from, at + 1), std::string::npos) << from;
  if (at != std::string::npos) text.replace(at, from.size(), to);
  return text;
}

/// `text` with the `bytes`-byte little-endian number at `at` set to `value`.
std::string with_number(std::string text, std::size_t at, std::uint64_t value, int bytes) {
  for (int k = 0; k < bytes; ++k) text[at + static_cast<std::size_t>(k)] = static_cast<char>((value >> (8 * k)) & 0xff);
  return text;
}

const char* kHead22 = "$MeshFormat\n2.2 0 8\n$EndMeshFormat\n";
const char* kHead41 = "$MeshFormat\n4.1 0 8\n$EndMeshFormat\n";
// A triangle on surface 1 of group 1 "plate" (format 4.1, after kHead41's lines 1-3).
const char* kBody41 =
    "$PhysicalNames\n1\n2 1 \"plate\"\n$EndPhysicalNames\n"                // lines 4-7
    "$Entities\n0 0 1 0\n1 0 0 0 1 1 0 1 1 0\n$EndEntities\n"              // 8-11
    "$Nodes\n1 3 1 3\n2 1 0 3\n1\n2\n3\n0 0 0\n1 0 0\n0 1 0\n$EndNodes\n"  // 12-21 (coordinates 18-20)
    "$Elements\n1 1 1 1\n2 1 2 1\n1 1 2 3\n$EndElements\n";                // 22-26 (the block 24, the triangle 25)

}  // namespace

TEST(MshInput, NotAMeshOrNotAFormatSeflexReads) {
  EXPECT_EQ(error_of(""),
            "m.msh:1: the file is empty; expected a gmsh mesh (MSH format 2 or 4), whose first line is $MeshFormat");
  // gmsh runs a file that does not start with $MeshFormat as a script (SystemCall runs a command);
  // seflex's reader never runs anything, and says what the file is not.
  test::TempDir dir;
  const std::string ran = (dir / "ran").string();
  EXPECT_TRUE(mentions(
      error_of("SystemCall \"touch " + ran + "\";\n"),
      {"m.msh:1: the file starts with 'SystemCall", "expected a gmsh mesh", "(a gmsh script must be named .geo)"}));
  EXPECT_FALSE(std::filesystem::exists(ran));
  EXPECT_EQ(error_of("$MeshFormat\n3.0 0 8\n$EndMeshFormat\n"),
            "m.msh:2: $MeshFormat: version 3.0, which seflex does not read; expected 2.2, 4.1 or 4.0 (gmsh -format "
            "msh22 or msh41)");
  EXPECT_TRUE(mentions(error_of("$MeshFormat\n4.1 2 8\n$EndMeshFormat\n"),
                       {"m.msh:2: $MeshFormat: file-type 2; expected 0 (text) or 1 (binary)"}));
  EXPECT_TRUE(mentions(error_of("$MeshFormat\n4.1 1 4\n$EndMeshFormat\n"),
                       {"m.msh:2: $MeshFormat: data-size 4; expected 8 in a binary file"}));
  EXPECT_TRUE(mentions(
      error_of("$MeshFormat\n4.1 0 8 7\n$EndMeshFormat\n"),
      {"m.msh:2: $MeshFormat: more on the line after 3 numbers ('7'); expected 'version file-type data-size'"}));
  EXPECT_TRUE(mentions(
      error_of("$MeshFormat\n4 1 8\n\1\0\0\0\n$EndMeshFormat\n"),
      {"m.msh:2: $MeshFormat: a binary MSH 4.0 file, which seflex does not read (gmsh reads 4.0 as text only)"}));
  EXPECT_EQ(error_of(std::string("$MeshFormat\n4.1 1 8\n\2\0\0\0\n$EndMeshFormat\n", 38)),
            "m.msh: byte 20: $MeshFormat: the byte-order integer is '\\x02\\x00\\x00\\x00'; expected the integer 1, "
            "little-endian "
            "(01 00 00 00) or big-endian (00 00 00 01)");
  EXPECT_TRUE(mentions(error_of("$MeshFormat\n4.1 0 8\n$Nodes\n"),
                       {"m.msh:3: $MeshFormat: '$Nodes' where the section should end; expected $EndMeshFormat"}));
  EXPECT_TRUE(mentions(error_of(std::string(kHead41) + "$EndNodes\n"), {"m.msh:4: '$EndNodes' outside its section"}));
  EXPECT_TRUE(mentions(error_of(std::string(kHead41) + "1 2 3\n"),
                       {"m.msh:4: '1 2 3' is not a section header; expected a line $Name"}));
  EXPECT_TRUE(mentions(error_of(kHead41), {"m.msh:3: the file ends without a $Nodes section"}));
  EXPECT_TRUE(mentions(error_of(std::string(kHead41) + "$PartitionedEntities\n1\n$EndPartitionedEntities\n"),
                       {"m.msh:4: $PartitionedEntities: a partitioned mesh, which seflex does not read"}));
  EXPECT_TRUE(mentions(error_of(std::string(kHead22) + "$ParametricNodes\n0\n$EndParametricNodes\n"),
                       {"m.msh:4: $ParametricNodes: nodes with parametric coordinates (MSH 2)"}));
}

TEST(MshInput, SectionsSeflexDoesNotNeedAreSkipped) {
  // $Comments with '$' lines inside, a $NodeData (text) and a section without its end line.
  const std::string base = std::string(kHead41) + kBody41;
  const gmsh::MeshData m =
      gmsh::read_msh_bytes(std::string(kHead41) + "$Comments\n$Nodes is not a section here\n$EndComments\n" + kBody41 +
                               "$NodeData\n1\n\"T\"\n1\n0.0\n3\n0\n1\n2000000000\n1 0.5\n$EndNodeData\n",
                           "m.msh");
  ASSERT_EQ(m.groups.size(), 1u);
  EXPECT_EQ(m.groups[0].name, "plate");
  EXPECT_EQ(m.groups[0].blocks.at(0).nodes, (std::vector<std::size_t>{1, 2, 3}));
  EXPECT_TRUE(mentions(
      error_of(base + "$NodeData\n1\n$EndNodeDat\n"),
      {"m.msh:27: $NodeData: no line $EndNodeData after it; expected every section to end with its $End line"}));
  // Windows line ends: the same mesh.
  std::string crlf;
  for (const char c : base) crlf += c == '\n' ? std::string("\r\n") : std::string(1, c);
  const gmsh::MeshData w = gmsh::read_msh_bytes(crlf, "w.msh");
  EXPECT_EQ(w.coords, gmsh::read_msh_bytes(base, "m.msh").coords);
  EXPECT_EQ(w.groups.at(0).blocks.at(0).nodes, m.groups[0].blocks[0].nodes);
}

TEST(MshInput, RecordsOfTheWrongShape) {
  const std::string base = std::string(kHead41) + kBody41;
  EXPECT_EQ(error_of(replaced(base, "0 1 0\n$EndNodes", "0 1 x\n$EndNodes")),
            "m.msh:20: $Nodes: node block 1 of 1: node 3 of 3: a coordinate is 'x'; expected a finite real number");
  EXPECT_TRUE(mentions(
      error_of(replaced(base, "0 1 0\n$EndNodes", "0 1 nan\n$EndNodes")),
      {"m.msh:20: $Nodes: node block 1 of 1: node 3 of 3: a coordinate is 'nan'; expected a finite real number"}));
  EXPECT_EQ(error_of(replaced(base, "1 0 0\n0 1 0", "1 0\n0 1 0")),
            "m.msh:19: $Nodes: node block 1 of 1: node 2 of 3: the line ends after 2 numbers, before a coordinate; "
            "expected 'x y z [u v w]'");
  EXPECT_TRUE(mentions(
      error_of(replaced(base, "1 1 2 3\n", "1 1 2 3 4\n")),
      {"m.msh:25: $Elements: element block 1 of 1: element 1 of 1: more on the line after 4 numbers ('4'); expected "
       "'elementTag nodeTag...'"}));
  EXPECT_TRUE(mentions(error_of(replaced(base, "1 1 2 3\n", "1 1 2 9\n")),
                       {"m.msh:25: $Elements: element block 1 of 1: element 1 of 1: element 1 refers to node 9, which "
                        "is not in $Nodes"}));
  EXPECT_TRUE(mentions(error_of(replaced(base, "1\n2\n3\n", "1\n2\n2\n")),
                       {"$Nodes: node 2 is defined twice; expected each node tag once"}));
  EXPECT_TRUE(mentions(
      error_of(replaced(base, "2 1 2 1\n", "2 1 9 1\n")),  // 6-node triangles: the line has 3 nodes
      {"m.msh:25: $Elements: element block 1 of 1: element 1 of 1: the line ends after 4 numbers, before a node tag"}));
  EXPECT_TRUE(mentions(error_of(replaced(base, "2 1 2 1\n", "2 1 1 1\n")),
                       {"m.msh:24: $Elements: element block 1 of 1: 'Line 2' elements (dimension 1) on a surface "
                        "(dimension 2); expected elements of the entity's dimension"}));
  EXPECT_TRUE(mentions(
      error_of(replaced(base, "2 1 2 1\n", "2 4 2 1\n")),
      {"m.msh:24: $Elements: element block 1 of 1: surface 4 is neither in $Entities nor the entity of a node block"}));
  EXPECT_TRUE(mentions(error_of(replaced(base, "2 1 2 1\n", "2 1 77 1\n")),
                       {"m.msh:24: $Elements: element block 1 of 1: element type 77, which seflex does not read; "
                        "expected a gmsh element type "
                        "with a fixed number of nodes"}));
  EXPECT_TRUE(mentions(
      error_of(replaced(base, "2 1 \"plate\"", "2 1 plate")),
      {"m.msh:6: $PhysicalNames: physical name 1 of 1: the name is 'plate'; expected a name in double quotes"}));
  EXPECT_TRUE(mentions(error_of(replaced(base, "1\n2 1 \"plate\"", "2\n2 1 \"plate\"\n2 1 \"plate2\"")),
                       {"m.msh:7: $PhysicalNames: physical name 2 of 2: physical surface 1 is named twice"}));
  EXPECT_TRUE(mentions(
      error_of(replaced(base, "0 0 1 0\n1 0 0 0 1 1 0 1 1 0\n", "0 0 2 0\n1 0 0 0 1 1 0 1 1 0\n1 0 0 0 1 1 0 0 0\n")),
      {"m.msh:11: $Entities: surface 2 of 2: surface 1 is declared twice"}));
  EXPECT_TRUE(mentions(error_of(std::string(kHead41) + "$Elements\n0 0 0 0\n$EndElements\n"),
                       {"m.msh:4: $Elements: the elements come before $Nodes; expected $Nodes first"}));
  EXPECT_TRUE(mentions(error_of(base + "$Nodes\n0 0 0 0\n$EndNodes\n"),
                       {"m.msh:27: $Nodes: a second $Nodes section; expected one"}));
}

TEST(MshInput, CountsBeyondTheRestOfTheFileAreRefusedBeforeAllocation) {
  const std::string base = std::string(kHead41) + kBody41;
  // The section's count: a node takes at least 8 bytes (tag and coordinates); the 89 bytes after
  // line 13 (10 lines of 8, 2, 2, 2, 6, 6, 6, 10, 10, 8, 8, 8 and 13 bytes) hold at most 11.
  EXPECT_TRUE(mentions(
      error_of(replaced(base, "1 3 1 3\n", "1 2000000000 1 3\n")),
      {"m.msh:13: $Nodes: 2000000000 nodes, but the 89 bytes left in the file hold at most 11; expected a count that "
       "matches the data (a truncated or corrupted file?)"}));
  EXPECT_TRUE(mentions(error_of(replaced(base, "2 1 0 3\n", "2 1 0 4\n")),
                       {"m.msh:14: $Nodes: node block 1 of 1 holds 4 nodes, but the section declares 3 in all, 0 of "
                        "them in the blocks before"}));
  EXPECT_TRUE(mentions(error_of(replaced(base, "1 3 1 3\n", "1 4 1 3\n")),
                       {"$Nodes: the blocks hold 3 nodes, but the section declares 4; expected the blocks to hold the "
                        "section's count"}));
  EXPECT_TRUE(mentions(
      error_of(replaced(base, "1 3 1 3\n2 1 0 3\n", "1 4 1 3\n2 1 0 4\n")),
      {"m.msh:18: $Nodes: node block 1 of 1: node tag 4 of 4: more on the line after 1 number ('0 0'); expected "
       "'nodeTag'"}));  // the first coordinates taken for the fourth tag
  EXPECT_TRUE(mentions(
      error_of(replaced(base, "1 1 1 1\n", "1 4611686018427387904 1 1\n")),
      {"m.msh:23: $Elements: 4611686018427387904 elements, but the 29 bytes left in the file hold at most 7"}));
  EXPECT_TRUE(
      mentions(error_of(replaced(base, "0 0 1 0\n", "0 0 1000 0\n")),
               {"m.msh:9: $Entities: 1000 surface entities, but the 137 bytes left in the file hold at most 13"}));
  EXPECT_TRUE(mentions(error_of(replaced(base, "1 0 0 0 1 1 0 1 1 0\n", "1 0 0 0 1 1 0 3000000000 1 0\n")),
                       {"m.msh:10: $Entities: surface 1 of 1: 3000000000 physical tags, but the line has 28 bytes; "
                        "expected them on the line"}));
  EXPECT_TRUE(
      mentions(error_of(replaced(base, "$PhysicalNames\n1\n", "$PhysicalNames\n100\n")),
               {"m.msh:5: $PhysicalNames: 100 physical names, but the 185 bytes left in the file hold at most 26"}));
  // Format 2: the node and element counts.
  EXPECT_TRUE(mentions(error_of(std::string(kHead22) + "$Nodes\n3\n1 0 0\n"),
                       {"m.msh:5: $Nodes: 3 nodes, but the 6 bytes left in the file hold at most 0"}));
  EXPECT_TRUE(
      mentions(error_of(std::string(kHead22) + "$Nodes\n1\n1 0 0 0\n$EndNodes\n$Elements\n3\n1 15 0 1\n$EndElements\n"),
               {"m.msh:9: $Elements: 3 elements, but the 22 bytes left in the file hold at most 2"}));
  // A count that fits the bytes but not the data: the element line that is not there.
  EXPECT_TRUE(
      mentions(error_of(std::string(kHead22) +
                        "$Nodes\n1\n1 0 0 0\n$EndNodes\n$Elements\n2\n1 15 0 1\n\n\n\n\n\n\n\n\n$EndElements\n"),
               {"m.msh:19: $Elements: element 2 of 2: elm-number is '$EndElements'"}));
}

TEST(MshInput, BinaryCountsAndDataBeyondTheFileAreRefused) {
  // The panel, binary MSH 4.1 (gmsh -format msh41 -bin): counts of the first node and element blocks.
  const std::string b41 = data("panel_msh4_binary.msh");
  const std::size_t nodes = b41.find("$Nodes\n") + 7, elements = b41.find("$Elements\n") + 10;
  ASSERT_NE(nodes, std::string::npos + 7);
  // section header: numBlocks numNodes minTag maxTag (size_t); block: dim tag parametric (int), count (size_t)
  EXPECT_TRUE(mentions(error_of(with_number(b41, nodes + 8, 1ULL << 40, 8), "b.msh"),
                       {"b.msh: byte " + std::to_string(nodes) + ": $Nodes: 1099511627776 nodes, but the",
                        "bytes left in the file hold at most"}));
  EXPECT_TRUE(mentions(error_of(with_number(b41, nodes + 32 + 12, 1ULL << 40, 8), "b.msh"),
                       {"b.msh: byte " + std::to_string(nodes + 32) +
                        ": $Nodes: node block 1 of 61 holds 1099511627776 nodes, but the section "
                        "declares 31 in all"}));
  EXPECT_TRUE(mentions(
      error_of(with_number(b41, elements + 32 + 8, 77, 4), "b.msh"),
      {"b.msh: byte " + std::to_string(elements + 32) + ": $Elements: element block 1 of 61: element type 77"}));
  EXPECT_TRUE(mentions(error_of(with_number(b41, elements + 32 + 20 + 8, 1000, 8), "b.msh"),  // the first point's node
                       {"$Elements: element block 1 of 61: element 1 refers to node 1000, which is not in $Nodes"}));
  // $Entities: a point's number of physical tags (after its tag and 3 coordinates).
  const std::size_t entities = b41.find("$Entities\n") + 10;
  EXPECT_TRUE(mentions(error_of(with_number(b41, entities + 32 + 4 + 24, 3959422977ULL, 8), "b.msh"),
                       {"b.msh: byte " + std::to_string(entities + 32 + 28) +
                        ": $Entities: point 1 of 31: 3959422977 physical tags, but the"}));
  // Cut 2,010 bytes into $Entities: after the 4 counts (32 bytes) and the 31 points (1,268 bytes: 36
  // each and 38 physical tags of 4), 724 bytes are left, room for 10 of the 46 curves (68 bytes each
  // at least).
  EXPECT_TRUE(mentions(error_of(b41.substr(0, entities + 2010) + "\n$EndEntities\n", "b.msh"),
                       {"b.msh: byte " + std::to_string(entities) +
                        ": $Entities: 46 curve entities, but the 724 bytes left in the file hold "
                        "at most 10"}));
  // Big-endian byte order (the integer 1 written 00 00 00 01): every number is read swapped, so
  // the little-endian counts become huge and are refused.
  std::string swapped = b41;
  const std::size_t one = swapped.find("4.1 1 8\n") + 8;
  swapped.replace(one, 4, std::string("\0\0\0\1", 4));
  EXPECT_TRUE(mentions(error_of(swapped, "b.msh"), {"b.msh: byte " + std::to_string(entities) +
                                                    ": $Entities: 2233785415175766016 point entities, but the"}));

  // The panel, binary MSH 2.2: 68 element blocks of one element each (elm-type num-elm-follow num-tags).
  const std::string b22 = data("panel_msh2_binary.msh");
  const std::size_t blocks = b22.find("\n$Elements\n68\n") + 14;
  EXPECT_TRUE(mentions(error_of(with_number(b22, blocks + 28 + 8, 1u << 30, 4), "b.msh"),
                       {"b.msh: byte " + std::to_string(blocks + 28) +
                        ": $Elements: element block 2: 1 element of 1073741826 ints, but the"}));
  EXPECT_TRUE(mentions(error_of(with_number(b22, blocks + 56 + 4, 1000000, 4), "b.msh"),
                       {"b.msh: byte " + std::to_string(blocks + 56) +
                        ": $Elements: element block 3 holds 1000000 elements, but the section "
                        "declares 68 in all, 2 of them in the blocks before; expected 1 to 66"}));
  EXPECT_TRUE(mentions(error_of(with_number(b22, blocks + 56, 0, 4), "b.msh"),
                       {"$Elements: element block 3: element type 0, which seflex does not read"}));
  const std::size_t node_count = b22.find("$Nodes\n31\n") + 7;
  EXPECT_TRUE(mentions(error_of(replaced(b22, "$Nodes\n31\n", "$Nodes\n3100\n"), "b.msh"),
                       {"b.msh: byte " + std::to_string(node_count) + ": $Nodes: 3100 nodes, but the"}));
  EXPECT_TRUE(
      mentions(error_of(replaced(b22, "$Nodes\n31\n", "$Nodes\n30\n"), "b.msh"),
               {"$Nodes: ", "where the section should end; expected $EndNodes after the data the section declares"}));
}

TEST(MshInput, Format2GroupsAndElementOrderAreGmshs) {
  // gmsh writes an element once per group of its entity: element 2 is element 1 in group 2 (the next
  // number, the same type, entity and nodes). Element 4 repeats element 3 in the same group 2: a
  // second element. Elements are kept by number within an entity (7 is listed before 5 and 6).
  const std::string text = std::string(kHead22) +
                           "$PhysicalNames\n2\n1 1 \"a\"\n1 2 \"b\"\n$EndPhysicalNames\n"
                           "$Nodes\n4\n1 0 0 0\n2 1 0 0\n3 2 0 0\n4 3 0 0\n$EndNodes\n"
                           "$Elements\n6\n1 1 2 1 5 1 2\n2 1 2 2 5 1 2\n3 1 2 2 6 2 3\n4 1 2 2 6 2 3\n7 1 2 -1 5 3 "
                           "4\n5 1 2 1 5 2 3\n$EndElements\n";
  const gmsh::MeshData m = gmsh::read_msh_bytes(text, "m.msh");
  EXPECT_EQ(m.total_elements, 5u);
  ASSERT_EQ(m.groups.size(), 2u);
  EXPECT_EQ(m.groups[0].name, "a");
  EXPECT_EQ(m.groups[0].entities, std::vector<int>{5});
  ASSERT_EQ(m.groups[0].blocks.size(), 1u);
  EXPECT_EQ(m.groups[0].blocks[0].nodes, (std::vector<std::size_t>{1, 2, 2, 3, 3, 4}));  // elements 1(2), 5, 7
  EXPECT_EQ(m.groups[1].entities, (std::vector<int>{5, 6}));
  ASSERT_EQ(m.groups[1].blocks.size(), 2u);
  EXPECT_EQ(m.groups[1].blocks[1].entity_tag, 6);
  EXPECT_EQ(m.groups[1].blocks[1].nodes, (std::vector<std::size_t>{2, 3, 2, 3}));
  EXPECT_TRUE(mentions(
      error_of(replaced(text, "7 1 2 -1 5 3 4", "7 1 2 1 -5 3 4")),
      {"m.msh:22: $Elements: element 5 of 6: elementary tag -5; expected the tag (>= 0) of the element's entity"}));
}

namespace {

/// Reads `text`; true if it read, false on an InputError, a test failure on anything else.
bool reads_or_refuses(const std::string& text, const std::string& what) {
  try {
    gmsh::read_msh_bytes(text, "m.msh");
    return true;
  } catch (const InputError&) {
    return false;
  } catch (const std::exception& e) {
    ADD_FAILURE() << what << ": not an InputError: " << e.what();
    return false;
  }
}

}  // namespace

// The unit square of tests/data/gmsh/square.geo (two triangles, a group of each dimension) as gmsh
// writes it in every format it writes; small, so that every byte can be tried.
const char* kSquares[] = {"square_msh22.msh", "square_msh22_binary.msh", "square_msh41.msh", "square_msh41_binary.msh",
                          "square_msh40.msh"};

// Every prefix (every place a copy can be cut) is refused with an InputError, except the one that
// lacks only the final end of line.
TEST(MshInput, EveryTruncationIsRefused) {
  for (const char* name : kSquares) {
    SCOPED_TRACE(name);
    const std::string full = data(name);
    ASSERT_TRUE(reads_or_refuses(full, "the whole file"));
    EXPECT_EQ(gmsh::read_msh_bytes(full, name).total_elements, 5u);  // 2 triangles, 2 lines, 1 point
    std::size_t read = 0;
    for (std::size_t n = 0; n < full.size(); ++n)
      if (reads_or_refuses(full.substr(0, n), "the first " + std::to_string(n) + " bytes")) ++read;
    EXPECT_EQ(read, 1u);  // the file without its last '\n'
  }
}

// Every byte set to each of 0x00, 0x80, 0xFF, '9', '-', '\n' and '$': each result reads or is refused
// with an InputError (never another exception; under the sanitizers in CI, never a memory error
// either).
TEST(MshInput, EveryByteChangedIsReadOrRefused) {
  const std::string values(std::string("\x00\x80\xff", 3) + "9-\n$");
  for (const char* name : kSquares) {
    SCOPED_TRACE(name);
    const std::string full = data(name);
    std::size_t read = 0, changed = 0;
    for (std::size_t at = 0; at < full.size(); ++at)
      for (const char v : values) {
        if (full[at] == v) continue;
        std::string text = full;
        text[at] = v;
        ++changed;
        if (reads_or_refuses(text,
                             "byte " + std::to_string(at) + " set to " + std::to_string(static_cast<unsigned char>(v))))
          ++read;
      }
    EXPECT_GT(changed, 5 * full.size());
    EXPECT_LT(read, changed / 2);  // most changes are refused; those that read are another valid mesh
  }
}
