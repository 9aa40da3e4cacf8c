// Bad input to seflex reduce / seflex export and to DMIG direct matrix input: clear messages that
// name the node, card or option and why, non-zero exit codes, no crash (also run under ASan/UBSan).
#include <gtest/gtest.h>

#include "seflex/fem/assembly.hpp"
#include "seflex/io/nastran.hpp"
#include "seflex/reduction/craig_bampton_superelement.hpp"
#include "test_support.hpp"

namespace seflex {
namespace {

std::string q(const std::filesystem::path& p) { return "'" + p.string() + "'"; }
std::filesystem::path yoke() { return test::source_dir() / "meshes" / "yoke.bdf"; }
std::filesystem::path cb_deck() {
  return test::validation_dir() / "mystran_craig_bampton_cbar_frame" / "CB-EXAMPLE-12_noOUTPUT4.DAT";
}

void expect_error(const std::string& args, int code, const std::vector<std::string>& parts) {
  test::TempDir tmp;
  const auto r = test::run_seflex(args + " -o " + q(tmp / "x.se"));
  EXPECT_EQ(r.exit_code, code) << args << "\n" << r.err;
  for (const auto& p : parts) EXPECT_NE(r.err.find(p), std::string::npos) << args << "\n" << r.err << "\nlacks: " << p;
  EXPECT_FALSE(std::filesystem::exists(tmp / "x.se"));
}

TEST(ReduceInput, BadInterfaceNodesNameTheNodeAndWhy) {
  expect_error("reduce " + q(yoke()) + " --interface 1,99", 3, {"interface node 99", "there is no GRID 99"});
  expect_error("reduce " + q(yoke()) + " --interface 1,3,1", 3, {"interface node 1", "listed twice"});
  expect_error("reduce " + q(cb_deck()) + " --interface 13,11", 3,
               {"interface node 13", "components 456 are constrained by SPC set 1", "CB-EXAMPLE-12_noOUTPUT4.DAT:"});
  expect_error("reduce " + q(cb_deck()) + " --interface 11,32", 3, {"interface node 32", "depend on RBE2 401"});
  expect_error("reduce " + q(cb_deck()) + " --interface suport", 3,
               {"SUPORT grid 11 names components 123", "expected 123456"});
  expect_error("reduce " + q(yoke()) + " --interface aset", 3, {"no ASET/ASET1 card"});
  expect_error("reduce " + q(yoke()) + " --interface hinges", 3, {"no node set named 'hinges'"});
  expect_error("reduce " + q(yoke()) + " --interface 1,5 --frame 5", 3, {"frame node 5 is an interface node"});
  expect_error("reduce " + q(yoke()) + " --interface 1,5 --frame 77", 3, {"frame node 77", "no GRID 77"});
}

TEST(ReduceInput, UsageErrors) {
  expect_error("reduce " + q(yoke()), 2,
               {"seflex reduce: missing --interface (grid ids like 1,3,4; aset, bset, suport; or a node set name)"});
  expect_error("reduce " + q(yoke()) + " --interface 1,5 --modes 3 --fmax 10", 2,
               {"seflex reduce: give either --modes or --fmax, not both"});
  expect_error("reduce " + q(yoke()) + " --interface 1,5 --modes -2", 2, {"seflex reduce: option --modes expects a number >= 0"});
  expect_error("reduce " + q(yoke()) + " --interface 1,,5", 2,
               {"seflex reduce: option --interface: '1,,5': expected grid ids or node set names separated by commas"});
  expect_error("reduce " + q(yoke()) + " --interface 1,5 --fmax -1", 2, {"seflex reduce: option --fmax expects a frequency > 0 (Hz)"});
  expect_error("reduce " + q(yoke()) + " --interface 1,5 --eigensolver lapack", 2,
               {"seflex reduce: option --eigensolver expects block, spectra, arpack or dense, got 'lapack'"});
  expect_error("reduce " + q(test::source_dir() / "meshes" / "missing.bdf") + " --interface 1", 3,
               {"missing.bdf: no such file; expected a Nastran deck"});
  const auto r = test::run_seflex("export " + q(yoke()) + " --op4 x.op4");
  EXPECT_EQ(r.exit_code, 3) << r.err;  // not a superelement file
  EXPECT_NE(r.err.find(yoke().string() + ": not a seflex superelement file (expected the magic bytes 'SEFLEXSE' at the start)"),
            std::string::npos)
      << r.err;
  const auto nothing = test::run_seflex("export x.se");
  EXPECT_EQ(nothing.exit_code, 2) << nothing.err;
  EXPECT_NE(nothing.err.find("seflex export: nothing to export: give --dmig FILE and/or --op4 FILE"), std::string::npos)
      << nothing.err;
}

void expect_dmig_error(const std::string& bulk, const std::vector<std::string>& parts) {
  const std::string deck =
      "SOL 103\nCEND\nK2GG = KX\nBEGIN BULK\nGRID    1               0.      0.      0.\nSPOINT  7\n" + bulk +
      "ENDDATA\n";
  try {
    const fem::Model m = io::read_nastran_text(deck, "d.bdf");
    fem::assemble(m, fem::assembly_options(m));
    ADD_FAILURE() << "no error for\n" << bulk;
  } catch (const InputError& e) {
    for (const auto& p : parts)
      EXPECT_NE(std::string(e.what()).find(p), std::string::npos) << e.what() << "\nlacks: " << p;
  }
}

TEST(DmigInput, K2ggMatricesMustBeSymmetricDmigsGivenOnce) {
  expect_dmig_error("DMIG    KX      0       1       2\nDMIG    KX      1       1               1       1       1.0\n",
                    {"d.bdf:", "DMIG KX, field 4 (IFO): got 1", "expected 6"});
  expect_dmig_error(
      "DMIG    KX      0       6       2\nDMIG    KX      1       1               7       0       1.0\n"
      "DMIG    KX      7       0               1       1       1.0\n",
      {"DMIG KX", "(1-1, 7)", "given twice"});
  expect_dmig_error(
      "DMIG    KX      0       6       2\nDMIG    KX      1       1               1       1       1.0\n"
      "DMIG    KX      1       1               1       1       2.0\n",
      {"DMIG KX", "given twice"});
}

}  // namespace
}  // namespace seflex
