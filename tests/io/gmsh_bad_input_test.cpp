// Bad gmsh input: every case throws InputError naming the file (and line, physical group or element
// type) and what was expected; the seflex command exits with status 3 and one "error:" line.
// These tests also run under AddressSanitizer + UndefinedBehaviorSanitizer in CI.
#include <gtest/gtest.h>

#include <algorithm>

#include "nastran_test_util.hpp"
#include "seflex/io/gmsh.hpp"
#include "seflex/io/model_reader.hpp"
#include "test_support.hpp"

using namespace seflex;
using seflex::test::mentions;

namespace {

std::filesystem::path panel_geo() { return test::source_dir() / "meshes" / "panel.geo"; }
std::string panel_props() { return test::read_file(test::source_dir() / "meshes" / "panel.props.bdf"); }

std::string replaced(std::string text, const std::string& from, const std::string& to) {
  const std::size_t p = text.find(from);
  EXPECT_NE(p, std::string::npos) << from;
  if (p != std::string::npos) text.replace(p, from.size(), to);
  return text;
}

/// 1-based number of the line of `text` that contains `what`.
int line_of(const std::string& text, const std::string& what) {
  const std::size_t p = text.find(what);
  return p == std::string::npos ? 0 : 1 + static_cast<int>(std::count(text.begin(), text.begin() + static_cast<long>(p), '\n'));
}

/// The InputError message of reading `mesh` with `options` ("" and a failure if it reads).
std::string read_error(const std::filesystem::path& mesh, const io::ModelReadOptions& options = {}) {
  return test::input_error([&] { io::read_model(mesh, options); });
}

/// The panel with a modified property file.
std::string panel_error(const test::TempDir& dir, const std::string& props) {
  io::ModelReadOptions o;
  o.properties = dir.write("panel.props.bdf", props);
  return read_error(panel_geo(), o);
}

// A small hand-written MSH 2.2 mesh: physical surface 1 "plate", physical curve 2 "edges".
const char* kMshHead = "$MeshFormat\n2.2 0 8\n$EndMeshFormat\n$PhysicalNames\n2\n1 2 \"edges\"\n2 1 \"plate\"\n$EndPhysicalNames\n";
const char* kMshNodes = "$Nodes\n6\n1 0 0 0\n2 1 0 0\n3 0 1 0\n4 0.5 0 0\n5 0.5 0.5 0\n6 0 0.5 0\n$EndNodes\n";
const char* kSmallProps = "$seflex group plate PSHELL 1\n$seflex group edges PBAR 2 0. 0. 1.\n"
                          "MAT1,1,7.e10,,0.3\nPSHELL,1,1,0.001,1\nPBAR,2,1,1.e-4,1.e-9,1.e-9,2.e-9\n";

std::string small_msh_error(const test::TempDir& dir, const std::string& elements) {
  dir.write("m.props.bdf", kSmallProps);
  return read_error(dir.write("m.msh", std::string(kMshHead) + kMshNodes + "$Elements\n" + elements + "$EndElements\n"));
}

}  // namespace

TEST(GmshBadInput, GroupNamedInPropertiesDoesNotExist) {
  test::TempDir dir;
  const std::string props = replaced(panel_props(), "$seflex group plate ", "$seflex group platee ");
  EXPECT_TRUE(mentions(panel_error(dir, props),
                       {"panel.props.bdf:" + std::to_string(line_of(props, "platee")) + ": $seflex group platee PSHELL",
                        "no physical group named 'platee' in", "panel.geo", "plate (surface)", "edges (curve)"}));
}

TEST(GmshBadInput, GroupWithoutMapping) {
  test::TempDir dir;
  const std::string props = replaced(panel_props(), "$seflex group edges ", "$ ");
  EXPECT_TRUE(mentions(panel_error(dir, props), {"panel.geo: physical curve 'edges' (8 elements) has no mapping in",
                                                 "panel.props.bdf", "expected a line '$seflex group edges PBAR"}));
}

TEST(GmshBadInput, PropertyOfTheWrongKindOrMissing) {
  test::TempDir dir;
  std::string props = replaced(panel_props(), "plate     PSHELL 100", "plate     PSHELL 7");
  EXPECT_TRUE(mentions(panel_error(dir, props), {"panel.props.bdf:" + std::to_string(line_of(props, "PSHELL 7")),
                                                 "PSHELL 7 is not defined", "expected a PSHELL card with PID 7"}));
  props = replaced(panel_props(), "$seflex group edges     PBAR   10   1. 0. 0.", "$seflex group edges     PSHELL 100");
  EXPECT_TRUE(mentions(panel_error(dir, props), {"no surface group of this name", "PSHELL maps the elements of a physical surface"}));
  props = replaced(panel_props(), "brackets  PBAR   10   0. 0. 1.", "brackets  PBAR   10");
  EXPECT_TRUE(mentions(panel_error(dir, props), {"$seflex group brackets PBAR: no orientation vector", "BAROR"}));
}

TEST(GmshBadInput, MalformedDirectives) {
  test::TempDir dir;
  std::string props = replaced(panel_props(), "masses    CONM2  0.55", "masses    CONM3  0.55");
  EXPECT_TRUE(mentions(panel_error(dir, props), {"panel.props.bdf:" + std::to_string(line_of(props, "CONM3")),
                                                 "unknown keyword 'CONM3'", "expected PSHELL, PBAR"}));
  props = replaced(panel_props(), "hinge1    GRID   1", "hinge1    GRID   one");
  EXPECT_TRUE(mentions(panel_error(dir, props), {"ID is 'one'", "expected an id (integer > 0) for ID"}));
  props = replaced(panel_props(), "$seflex group masses ", "$seflex grope masses ");
  EXPECT_TRUE(mentions(panel_error(dir, props), {"unknown directive 'grope'"}));
  props = replaced(panel_props(), "$seflex group masses    CONM2  0.55  1.98e-4 0. 1.98e-4 0. 0. 1.98e-4",
                   "$seflex group masses    CONM2  0.55  1.98e-4 0.");
  EXPECT_TRUE(mentions(panel_error(dir, props), {"the inertia has 2 terms", "expected M alone, or M I11 I21 I22 I31 I32 I33"}));
}

TEST(GmshBadInput, GridIdsThatCannotBePinned) {
  test::TempDir dir;
  std::string props = replaced(panel_props(), "hinge1    GRID   1", "masses    GRID   1");
  EXPECT_TRUE(mentions(panel_error(dir, props), {"physical point 'masses' has 25 nodes; expected a group of exactly one node"}));
  props = replaced(panel_props(), "hinge2    GRID   2", "hinge2    GRID   1");
  EXPECT_TRUE(mentions(panel_error(dir, props), {"grid id 1 is already given to group 'hinge1'"}));
}

TEST(GmshBadInput, SecondOrderAndMixedOrders) {
  test::TempDir dir;
  // a 6-node triangle (type 9) and a 2-node line (type 1)
  EXPECT_TRUE(mentions(small_msh_error(dir, "2\n1 9 2 1 1 1 2 3 4 5 6\n2 1 2 2 2 1 2\n"),
                       {"m.msh: mixed element orders", "physical curve 'edges' has order-1 'Line 2'",
                        "physical surface 'plate' order-2 'Triangle 6'", "expected first-order elements"}));
  // second order only: 6-node triangle and 3-node line
  EXPECT_TRUE(mentions(small_msh_error(dir, "2\n1 9 2 1 1 1 2 3 4 5 6\n2 8 2 2 2 1 2 4\n"),
                       {"m.msh: physical curve 'edges': 'Line 3' elements are of order 2", "not support",
                        "expected first-order elements"}));
}

TEST(GmshBadInput, MeshWithoutElementsOrGroups) {
  test::TempDir dir;
  EXPECT_TRUE(mentions(small_msh_error(dir, "0\n"), {"m.msh: the mesh has no elements"}));
  dir.write("n.props.bdf", kSmallProps);
  const std::string no_groups = "$MeshFormat\n2.2 0 8\n$EndMeshFormat\n" + std::string(kMshNodes) +
                                "$Elements\n1\n1 2 2 0 1 1 2 3\n$EndElements\n";
  EXPECT_TRUE(mentions(read_error(dir.write("n.msh", no_groups)), {"n.msh: the mesh has no physical groups"}));
}

TEST(GmshBadInput, VolumeAndUnnamedGroups) {
  test::TempDir dir;
  const std::string cards_only = "MAT1,1,7.e10,,0.3\nPSHELL,1,1,0.001,1\n";
  dir.write("v.props.bdf", cards_only);
  const std::string tet = "$MeshFormat\n2.2 0 8\n$EndMeshFormat\n$PhysicalNames\n1\n3 5 \"solid\"\n$EndPhysicalNames\n"
                          "$Nodes\n4\n1 0 0 0\n2 1 0 0\n3 0 1 0\n4 0 0 1\n$EndNodes\n$Elements\n1\n1 4 2 5 1 1 2 3 4\n$EndElements\n";
  EXPECT_TRUE(mentions(read_error(dir.write("v.msh", tet)),
                       {"v.msh: physical volume 'solid': volume elements are not supported"}));
  dir.write("u.props.bdf", "$seflex group plate PSHELL 1\n" + cards_only);
  const std::string unnamed = std::string(kMshHead) + kMshNodes + "$Elements\n2\n1 2 2 1 1 1 2 3\n2 1 2 7 3 1 2\n$EndElements\n";
  EXPECT_TRUE(mentions(read_error(dir.write("u.msh", unnamed)), {"u.msh: physical curve 7 has no name"}));
}

TEST(GmshBadInput, EntityInTwoMappedGroups) {
  test::TempDir dir;
  const std::string geo = test::read_file(panel_geo()) + "Physical Surface(\"corner\") = {300};\n";
  const std::string props = panel_props() + "$seflex group corner PSHELL 100\n";
  dir.write("p.props.bdf", props);
  EXPECT_TRUE(mentions(read_error(dir.write("p.geo", geo)),
                       {"p.geo: surface 300 is in physical surface 'plate' and physical surface 'corner'", "doubled"}));
}

TEST(GmshBadInput, FilesGmshCannotRead) {
  test::TempDir dir;
  dir.write("g.props.bdf", kSmallProps);
  // .msh files are read by seflex's reader (tests/io/gmsh_msh_input_test.cpp has the rest).
  EXPECT_TRUE(mentions(read_error(dir.write("g.msh", "$MeshFormat\n2.2 0 8\n$EndMeshFormat\n$Nodes\n1\n1 0 0 x\n$EndNodes\n")),
                       {"g.msh:6: $Nodes: node 1 of 1: a coordinate is 'x'; expected a finite real number"}));
  EXPECT_TRUE(mentions(read_error(dir.write("g.msh", "$MeshFormat\n2.2 0 8\n$EndMeshFormat\n$Nodes\n3\n1 0 0\n")),
                       {"g.msh:5: $Nodes: 3 nodes, but the 6 bytes left in the file hold at most 0", "truncated or corrupted"}));
  dir.write("s.props.bdf", kSmallProps);
  EXPECT_TRUE(mentions(read_error(dir.write("s.geo", "Point(1) = {0, 0, 0};\nLine(1) = {1, 2;\n")),
                       {"s.geo: gmsh cannot read it: ", "line 2", "syntax error"}));
  // An error inside braces: gmsh's parser must be left able to read the next file.
  dir.write("b.props.bdf", kSmallProps);
  EXPECT_TRUE(mentions(read_error(dir.write("b.geo", "Point(1) = {0, 0, 0\nfoo;\n")), {"b.geo: gmsh cannot read it: ", "line 2", "syntax error (foo)"}));
  EXPECT_EQ(io::read_model(panel_geo()).grids.size(), 31u);
  dir.write("c.props.bdf", kSmallProps);
  EXPECT_TRUE(mentions(read_error(dir.write("c.geo", "Point(1) = {0, 0, 0};\nLine(1) = {1, 2};\n")),
                       {"c.geo: gmsh cannot read it: ", "Unknown control point 2"}));
  EXPECT_TRUE(mentions(read_error(dir / "none.msh"), {"none.msh: no property file"}));
  dir.write("none.props.bdf", kSmallProps);
  EXPECT_TRUE(mentions(read_error(dir / "none.msh"), {"none.msh: no such file"}));
}

TEST(GmshBadInput, Parameters) {
  io::ModelReadOptions o;
  o.parameters.push_back({"refin", 2});
  EXPECT_TRUE(mentions(read_error(panel_geo(), o), {"panel.geo: no parameter 'refin'", "DefineConstant", "its parameters: Parameters/refine"}));
  EXPECT_TRUE(mentions(read_error(test::source_dir() / "meshes" / "panel.bdf", o), {"panel.bdf: parameter 'refin' given for a Nastran deck"}));
  o.parameters = {{"refine", 0}};  // panel.geo checks its parameter with Error(): a gmsh error
  EXPECT_TRUE(mentions(read_error(panel_geo(), o), {"panel.geo: gmsh cannot read it: refine = 0: expected a whole number >= 1"}));
  // --parameter NAME=VALUE: the message quotes the argument, says what is wrong and the form expected
  const auto parameter_error = [](const std::string& text) -> std::string {
    try {
      io::parse_gmsh_parameter(text);
    } catch (const InputError& e) {
      return e.what();
    }
    ADD_FAILURE() << "no error for '" << text << "'";
    return "";
  };
  EXPECT_EQ(parameter_error("refine"), "parameter 'refine': no '='; expected NAME=VALUE, e.g. refine=8");
  EXPECT_EQ(parameter_error("refine=x"), "parameter 'refine=x': the value 'x' is not a number; expected NAME=VALUE, e.g. refine=8");
  EXPECT_EQ(parameter_error("1x=2"), "parameter '1x=2': the name must start with a letter or '_'; expected NAME=VALUE, e.g. refine=8");
  EXPECT_EQ(parameter_error("re-fine=2"),
            "parameter 're-fine=2': the name has a character other than letters, digits and '_'; expected NAME=VALUE, e.g. refine=8");
  EXPECT_EQ(io::parse_gmsh_parameter(" refine = 8 ").value, 8.0);
}

TEST(GmshBadInput, DirectivesInNastranDecks) {
  test::TempDir dir;
  const std::string base = test::base_deck();
  EXPECT_TRUE(mentions(read_error(dir.write("a.bdf", base + "$seflex set ends 1 9\n")),
                       {"a.bdf:7: $seflex set ends: grid 9 is not defined"}));
  EXPECT_TRUE(mentions(read_error(dir.write("b.bdf", base + "$seflex group plate PSHELL 1\n")),
                       {"b.bdf:7: $seflex group", "only in the property file of a gmsh mesh"}));
  const fem::Model m = io::read_model(dir.write("c.bdf", base + "$seflex set \"two ends\" 4 1\n$SEFLEX SET \"two ends\" 3\n"));
  EXPECT_EQ(m.node_sets.at("two ends"), (std::vector<int>{1, 3, 4}));
}

TEST(GmshBadInput, CommandLineExitStatus) {
  test::TempDir dir;
  const std::string props = replaced(panel_props(), "$seflex group edges ", "$ ");
  const auto p = dir.write("panel.props.bdf", props);
  for (const std::string cmd : {"info", "convert"}) {
    const auto r = test::run_seflex(cmd + " '" + panel_geo().string() + "' --properties '" + p.string() + "' -o '" +
                                    (dir / "x.bdf").string() + "'");
    EXPECT_EQ(r.exit_code, cmd == "info" ? 2 : 3) << r.err;  // info has no -o: a usage error
  }
  const auto r = test::run_seflex("info '" + panel_geo().string() + "' --properties '" + p.string() + "'");
  EXPECT_EQ(r.exit_code, 3) << r.err;
  EXPECT_EQ(r.err.rfind("error: ", 0), 0u) << r.err;
  EXPECT_TRUE(mentions(r.err, {"physical curve 'edges' (8 elements) has no mapping"}));
  EXPECT_EQ(std::count(r.err.begin(), r.err.end(), '\n'), 1);
}
