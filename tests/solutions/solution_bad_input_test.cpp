// Bad input to seflex static and seflex modes: exit status 3 and one "error:" line that names the
// deck (or card) and says what is expected; never a crash. Also run under ASan + UBSan in CI.
#include <gtest/gtest.h>

#include "test_support.hpp"

namespace seflex {
namespace {

const char* kBar =
    "MAT1,1,7.e10,,0.3,2700.\nPBAR,1,1,1.e-4,2.e-8,2.e-8,4.e-8\n"
    "GRID,1,,0.,0.,0.\nGRID,2,,1.,0.,0.\nGRID,3,,2.,0.,0.\n"
    "CBAR,1,1,1,2,0.,1.,0.\nCBAR,2,1,2,3,0.,1.,0.\nSPC1,1,123456,1\nFORCE,7,3,0,1.,0.,0.,1.\n"
    "EIGRL,1,,,2\nEIGRL,2\nENDDATA\n";

test::RunResult run(const std::string& command, const std::string& case_control) {
  test::TempDir dir;
  const auto deck = dir.write("bad.bdf", "CEND\n" + case_control + "BEGIN BULK\n" + kBar);
  return test::run_seflex(command + " bad.bdf", dir.path());
}

/// Exit 3 and one "error:" line, the last of stderr (warnings about unused cards may come before it).
void expect_input_error(const test::RunResult& r, std::initializer_list<const char*> parts) {
  EXPECT_EQ(r.exit_code, 3) << r.err;
  const std::size_t at = r.err.find("error: ");
  ASSERT_NE(at, std::string::npos) << r.err;
  EXPECT_TRUE(at == 0 || r.err[at - 1] == '\n') << r.err;
  EXPECT_EQ(r.err.find("error: ", at + 1), std::string::npos) << "two error lines: " << r.err;
  EXPECT_EQ(r.err.find('\n', at), r.err.size() - 1) << "the error is not the last line: " << r.err;
  for (const char* p : parts) EXPECT_NE(r.err.substr(at).find(p), std::string::npos) << "missing '" << p << "' in: " << r.err;
}

TEST(SolutionBadInput, ModesWithoutMethod) {
  expect_input_error(run("modes", "SPC = 1\n"), {"error: bad.bdf: case control selects no METHOD (EIGRL/EIGR) for normal "
                                                 "modes; add METHOD = <sid> or give the number of modes with --count"});
}

TEST(SolutionBadInput, ModesWithUndefinedMethod) {
  expect_input_error(run("modes", "SPC = 1\nMETHOD = 9\n"),
                     {"error: bad.bdf: case control METHOD: the global case control: METHOD = 9 selects no EIGRL or "
                      "EIGR card; normal modes (SOL 103) cannot run without it"});
}

TEST(SolutionBadInput, ModesWithAnUnboundedEigrl) {
  expect_input_error(run("modes", "SPC = 1\nMETHOD = 2\n"),
                     {"error: bad.bdf:15: EIGRL 2: neither ND (number of roots) nor F2 (upper frequency) is given",
                      "set one of them or use --count"});
}

TEST(SolutionBadInput, ModesWithAnUndefinedSubcase) {
  expect_input_error(run("modes --subcase 4", "SPC = 1\nMETHOD = 1\n"), {"error: bad.bdf: case control: SUBCASE 4 is not defined"});
}

// Nastran runs a subcase without LOAD (its enforced displacements drive it); seflex too, and warns
// when there is nothing at all to drive it.
TEST(SolutionBadInput, StaticWithoutLoadWarns) {
  const test::RunResult r = run("static", "SPC = 1\n");
  EXPECT_EQ(r.exit_code, 0) << r.err;
  EXPECT_NE(r.err.find("warning: case control LOAD (bad.bdf): the global case control selects no LOAD"), std::string::npos)
      << r.err;
  EXPECT_NE(
      r.err.find(
          "selects no LOAD, no TEMPERATURE(LOAD) and no enforced displacement (SPC D): its displacements are zero"),
      std::string::npos)
      << r.err;
}

TEST(SolutionBadInput, StaticOfAnUnsupportedModel) {
  expect_input_error(run("static", "LOAD = 7\n"), {"error: bad.bdf: statics: the constrained stiffness matrix is singular at "
                                                  "grid 3 component 2", "constrain it with SPC/SPC1 or GRID PS"});
}

TEST(SolutionBadInput, StaticWithAnUndefinedLoadSet) {
  expect_input_error(run("static", "SPC = 1\nLOAD = 8\n"),
                     {"error: bad.bdf: case control LOAD: the global case control: LOAD = 8 selects no load card",
                      "linear statics (SOL 101) cannot run without it"});
}

TEST(SolutionBadInput, MissingDeckAndBadOptions) {
  test::TempDir dir;
  // exit 3 for bad input, 2 for a bad command line; each message names the file or option, what it
  // got and what was expected
  const auto expect_message = [&](const std::string& args, int code, const std::string& message) {
    const auto r = test::run_seflex(args, dir.path());
    EXPECT_EQ(r.exit_code, code) << args << "\n" << r.err;
    EXPECT_NE(r.err.find(message), std::string::npos) << args << "\n" << r.err << "\nlacks: " << message;
  };
  expect_message("modes missing.bdf", 3, "error: missing.bdf: no such file; expected a Nastran deck");
  expect_message("static", 2, "seflex static: missing DECK\nusage: seflex static DECK");
  expect_message("modes x.bdf --count many", 2, "seflex modes: option --count expects an integer, got 'many'");
  expect_message("modes x.bdf --factorization lu", 2, "seflex modes: option --factorization expects cholmod or ldlt, got 'lu'");
}

}  // namespace
}  // namespace seflex
