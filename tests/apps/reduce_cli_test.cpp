// seflex reduce and seflex export from the command line: exit codes, the summary, the files written
// and read back.
#include <gtest/gtest.h>

#include "seflex/fem/assembly.hpp"
#include "seflex/io/model_reader.hpp"
#include "seflex/io/nastran.hpp"
#include "seflex/io/provenance.hpp"
#include "seflex/io/sha256.hpp"
#include "seflex/io/superelement_file.hpp"
#include "seflex/reduction/craig_bampton_superelement.hpp"
#include "test_support.hpp"

namespace seflex {
namespace {

std::string q(const std::filesystem::path& p) { return "'" + p.string() + "'"; }
std::filesystem::path yoke() { return test::source_dir() / "meshes" / "yoke.bdf"; }

TEST(ReduceCli, WritesASuperelementAndPrintsTheSummary) {
  test::TempDir tmp;
  const auto out = tmp / "yoke.se";
  const auto r = test::run_seflex("reduce " + q(yoke()) + " --interface 1,3,4 --modes 5 -o " + q(out));
  ASSERT_EQ(r.exit_code, 0) << r.err;
  for (const char* part : {"interface: 3 nodes, 18 dofs", "frame node 18",
                           "chosen as the free grid nearest the centre of mass", "fixed-interface modes: 5 kept",
                           "modal effective mass fraction", "first neglected mode", "reduced model: n = 23", "wrote"})
    EXPECT_NE(r.out.find(part), std::string::npos) << part << "\n" << r.out;
  const se::Superelement s = io::load_superelement(out);
  EXPECT_EQ(s.name, "yoke");
  EXPECT_EQ(s.num_modes, 5);
  EXPECT_EQ(s.frame_node_id, 18);  // nearest the centre of mass (the documented choice 2 needs --frame 2)
  EXPECT_EQ(s.source_hash, io::sha256_file_hex(yoke()));  // one file read
  EXPECT_NE(s.created.find('T'), std::string::npos);
  EXPECT_NEAR(s.mass, 12.6, 1e-12);  // 14 CONM2 of 0.9 kg (meshes/README.md)

  // Refuses to overwrite without --force, leaving the file as it was.
  const std::string before = test::read_file(out);
  const auto again = test::run_seflex("reduce " + q(yoke()) + " --interface 1,5 -o " + q(out));
  EXPECT_EQ(again.exit_code, 3);
  EXPECT_NE(again.err.find("refusing to overwrite"), std::string::npos) << again.err;
  EXPECT_EQ(test::read_file(out), before);
  const auto forced = test::run_seflex("reduce " + q(yoke()) + " --interface 1,5 --fmax 200 --frame 18 --name arm -o " +
                                       q(out) + " --force");
  ASSERT_EQ(forced.exit_code, 0) << forced.err;
  const se::Superelement f = io::load_superelement(out);
  EXPECT_EQ(f.name, "arm");
  EXPECT_EQ(f.frame_node_id, 18);
  EXPECT_EQ(f.interfaces.size(), 2u);
  for (int k = 0; k < f.num_modes; ++k) EXPECT_LE(f.mode_frequencies_hz(k), 200.0);
  EXPECT_GT(f.truncation.first_neglected_hz, 200.0);
}

// --compare K prints the full model's free-free frequencies beside the reduced ones; with every
// interior mode kept they agree (the table's relative errors are round-off).
TEST(ReduceCli, CompareWithTheFullModel) {
  test::TempDir tmp;
  const auto r =
      test::run_seflex("reduce " + q(yoke()) + " --interface 1,5 --modes 1000 --compare 4 -o " + q(tmp / "y.se"));
  ASSERT_EQ(r.exit_code, 0) << r.err;
  ASSERT_NE(r.out.find("full FE (Hz)"), std::string::npos) << r.out;
  int rows = 0;
  std::istringstream in(r.out.substr(r.out.find("rel. error")));
  std::string line;
  std::getline(in, line);
  while (std::getline(in, line) && !line.empty()) {
    std::istringstream l(line);
    int mode = 0;
    double red = 0, full = 0;
    std::string err;
    l >> mode >> red >> full >> err;
    if (err != "(rigid)") {
      EXPECT_LT(std::abs(std::stod(err)), 1e-6) << line;
    }
    ++rows;
  }
  EXPECT_EQ(rows, 10);
}

// seflex export: a DMIG deck the reader takes back (its modes are the reduced model's) and OP4.
TEST(ReduceCli, ExportDmigAndOp4) {
  test::TempDir tmp;
  const auto se_path = tmp / "yoke.se";
  ASSERT_EQ(test::run_seflex("reduce " + q(yoke()) + " --interface 1,3,4 --modes 3 -o " + q(se_path)).exit_code, 0);
  const auto r = test::run_seflex("export " + q(se_path) + " --dmig " + q(tmp / "yoke_dmig.bdf") + " --op4 " +
                                  q(tmp / "yoke.op4") + " --recovery");
  ASSERT_EQ(r.exit_code, 0) << r.err;
  const se::Superelement s = io::load_superelement(se_path);
  const fem::Model deck = io::read_nastran(tmp / "yoke_dmig.bdf");
  const fem::GlobalMatrices g = fem::assemble(deck, fem::assembly_options(deck));
  EXPECT_LT((Eigen::MatrixXd(g.K) - s.K).cwiseAbs().maxCoeff(), 1e-9 * s.K.cwiseAbs().maxCoeff());
  const std::string op4 = test::read_file(tmp / "yoke.op4");
  EXPECT_EQ(op4.rfind("      21      21       6       2KAA     1P,3E23.16\n", 0), 0u) << op4.substr(0, 80);
  EXPECT_NE(op4.find("MAA     1P,3E23.16"), std::string::npos);
  EXPECT_NE(op4.find("      21     108       2       2RECOVERY1P,3E23.16"), std::string::npos);
  // Existing files are not replaced without --force.
  const auto again = test::run_seflex("export " + q(se_path) + " --op4 " + q(tmp / "yoke.op4"));
  EXPECT_EQ(again.exit_code, 3);
  EXPECT_NE(again.err.find((tmp / "yoke.op4").string() + ": exists already; refusing to overwrite it (use --force to replace it)"),
            std::string::npos)
      << again.err;
  EXPECT_EQ(test::read_file(tmp / "yoke.op4"), op4);
  EXPECT_EQ(test::run_seflex("export " + q(se_path) + " --op4 " + q(tmp / "yoke.op4") + " --force").exit_code, 0);
}

// The provenance is the library's: `seflex reduce` and a library caller (read_model,
// reduce_to_superelement, record_source, save_superelement) with the same deck and options write the
// same file, byte for byte, once `created` (the time of each call, 20 characters) is set alike. The
// deck has an INCLUDE (the hash covers both files) and a load a reduction does not use (a warning
// stored in the file).
TEST(ReduceCli, TheLibraryWritesTheSameFileAsTheCommand) {
  test::TempDir dir;
  dir.write("arm.bdf",
            "SOL 103\nCEND\nBEGIN BULK\nINCLUDE 'grids.bdf'\n"
            "MAT1,1,7.0E10,,0.3,2700.\nPBAR,10,1,1.0E-4,1.0E-9,1.0E-9,2.0E-9\n"
            "CBAR,1,10,1,2,0.,0.,1.\nCBAR,2,10,2,3,0.,0.,1.\nCBAR,3,10,3,4,0.,0.,1.\nCBAR,4,10,4,5,0.,0.,1.\n"
            "FORCE,7,3,,1.0,0.,0.,1.\nENDDATA\n");
  dir.write("grids.bdf", "GRID,1,,0.,0.,0.\nGRID,2,,0.25,0.,0.\nGRID,3,,0.5,0.,0.\nGRID,4,,0.75,0.,0.\nGRID,5,,1.,0.,0.\n");
  const std::string deck = (dir / "arm.bdf").string();  // the same path for both (the warnings name it)
  const auto r = test::run_seflex("reduce " + q(deck) + " --interface 1,5 --modes 3 --name arm -o cmd.se", dir.path());
  ASSERT_EQ(r.exit_code, 0) << r.err;

  const fem::Model model = io::read_model(deck);
  reduction::SuperelementOptions o;
  o.interface_ids = {1, 5};
  o.modes.modes = 3;
  o.modes.backend = linalg::EigenBackend::Spectra;  // the command's default --eigensolver
  o.name = "arm";
  se::Superelement s = reduction::reduce_to_superelement(model, o);
  const se::Superelement c = io::load_superelement(dir / "cmd.se");
  io::record_source(s, model, deck, c.created);
  io::save_superelement(s, dir / "lib.se");

  ASSERT_EQ(s.source_warnings.size(), 1u);
  EXPECT_NE(s.source_warnings[0].find("FORCE: 1 card, first at"), std::string::npos) << s.source_warnings[0];
  EXPECT_EQ(s.source_hash, io::sha256_hex(test::read_file(dir / "arm.bdf") + test::read_file(dir / "grids.bdf")));
  EXPECT_EQ(c.source_file, deck);
  EXPECT_EQ(c.source_warnings, s.source_warnings);
  const std::string cmd = test::read_file(dir / "cmd.se"), lib = test::read_file(dir / "lib.se");
  EXPECT_EQ(cmd.size(), lib.size());
  EXPECT_TRUE(cmd == lib) << "the two files differ first at byte "
                          << std::distance(cmd.begin(), std::mismatch(cmd.begin(), cmd.end(), lib.begin(), lib.end()).first);
  // created is the one field that differs between two calls: the current time, ISO 8601 UTC
  EXPECT_EQ(io::iso_utc_now().size(), 20u);
  EXPECT_EQ(c.created.size(), 20u);
}

}  // namespace
}  // namespace seflex
