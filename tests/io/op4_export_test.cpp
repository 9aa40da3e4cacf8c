// OUTPUT4 ASCII export (io/op4.hpp), read back by a small parser written here from the format
// description (NX Nastran DMAP Programmer's Guide, OUTPUT4: header NCOL NROW NF NTYPE NAME FORMAT;
// column records ICOL IROW NW followed by the values; a record for column NCOL + 1 ends a matrix).
#include <gtest/gtest.h>

#include <cmath>
#include <cstdlib>
#include <map>
#include <sstream>

#include "seflex/io/nastran.hpp"
#include "seflex/io/op4.hpp"
#include "seflex/reduction/craig_bampton_superelement.hpp"
#include "test_support.hpp"

namespace seflex {
namespace {

struct Read {
  int form = 0, type = 0;
  std::string format;
  Eigen::MatrixXd A;
};

/// Values are fixed-width fields (the width from "1P,3E23.16"); a Fortran value may drop the E
/// of a three-digit exponent ("1.0-100").
double fortran_real(std::string s) {
  s.erase(0, s.find_first_not_of(' '));
  if (s.find('E') == std::string::npos) {
    const auto sign = s.find_first_of("+-", 1);
    if (sign != std::string::npos) s.insert(sign, "E");
  }
  return std::strtod(s.c_str(), nullptr);
}

std::map<std::string, Read> parse_op4(const std::string& text) {
  std::map<std::string, Read> out;
  std::istringstream in(text);
  std::string line;
  while (std::getline(in, line)) {
    if (line.empty()) continue;
    const int ncol = std::stoi(line.substr(0, 8)), nrow = std::stoi(line.substr(8, 8));
    Read r;
    r.form = std::stoi(line.substr(16, 8));
    r.type = std::stoi(line.substr(24, 8));
    std::string name = line.substr(32, 8);
    name.erase(name.find_last_not_of(' ') + 1);
    r.format = line.substr(40);
    const auto e = r.format.find('E');
    const int per_line = std::stoi(r.format.substr(3, e - 3));
    const int width = std::stoi(r.format.substr(e + 1, r.format.find('.') - e - 1));
    r.A = Eigen::MatrixXd::Zero(nrow, ncol);
    for (;;) {
      std::getline(in, line);
      const int icol = std::stoi(line.substr(0, 8)), irow = std::stoi(line.substr(8, 8)),
                nw = std::stoi(line.substr(16, 8));
      int read = 0;
      while (read < nw) {
        std::getline(in, line);
        for (int k = 0; k < per_line && read < nw; ++k, ++read) {
          const double v =
              fortran_real(line.substr(static_cast<std::size_t>(k * width), static_cast<std::size_t>(width)));
          if (icol <= ncol) r.A(irow - 1 + read, icol - 1) = v;
        }
      }
      if (icol > ncol) break;
    }
    out[name] = r;
  }
  return out;
}

TEST(Op4Export, SuperelementMatricesReadBackExactly) {
  const fem::Model m = io::read_nastran(test::source_dir() / "meshes" / "panel.bdf");
  reduction::SuperelementOptions o;
  o.interface_ids = {5, 6};
  o.modes.modes = 4;
  const se::Superelement s = reduction::reduce_to_superelement(m, o);
  const auto mats = parse_op4(io::op4_text(io::superelement_op4_matrices(s, true)));
  ASSERT_EQ(mats.size(), 3u);
  const std::pair<const char*, const Eigen::MatrixXd*> expected[] = {
      {"KAA", &s.K}, {"MAA", &s.M}, {"RECOVERY", &s.recovery}};
  for (const auto& [name, A] : expected) {
    const Read& r = mats.at(name);
    EXPECT_EQ(r.type, 2) << name;
    EXPECT_EQ(r.form, std::string(name) == "RECOVERY" ? 2 : 6) << name;
    EXPECT_EQ(r.format, "1P,3E23.16") << name;
    ASSERT_EQ(r.A.rows(), A->rows()) << name;
    ASSERT_EQ(r.A.cols(), A->cols()) << name;
    // 17 significant digits: the binary64 value is recovered exactly.
    EXPECT_EQ(r.A, *A) << name;
  }
}

TEST(Op4Export, ColumnRecordsAndFortranExponents) {
  Eigen::MatrixXd A = Eigen::MatrixXd::Zero(5, 3);
  A(1, 0) = 1.5;
  A(3, 0) = -2.0e-120;             // column 0: rows 2..4 written, with the zero between
  A(4, 2) = std::ldexp(1.0, 700);  // 5.2601359015483735E+210; column 1 null: not written
  const std::string text = io::op4_text({{"A", 2, A}});
  const std::string expected =
      "       3       5       2       2A       1P,3E23.16\n"
      "       1       2       3\n"
      " 1.5000000000000000E+00 0.0000000000000000E+00-2.0000000000000000-120\n"
      "       3       5       1\n"
      " 5.2601359015483735+210\n"
      "       4       1       1\n"
      " 0.0000000000000000E+00\n";
  EXPECT_EQ(text, expected);
  EXPECT_EQ(parse_op4(text).at("A").A, A);
}

TEST(Op4Export, RefusesToOverwriteAndNeedsARecoveryMatrix) {
  se::Superelement s;
  s.name = "tiny";
  s.interfaces.resize(1);
  s.K = Eigen::MatrixXd::Identity(6, 6);
  s.M = Eigen::MatrixXd::Identity(6, 6);
  s.Phi_f = Eigen::MatrixXd::Identity(6, 6);
  test::TempDir tmp;
  const auto path = tmp.write("k.op4", "keep me");
  try {
    io::write_op4(s, path);
    ADD_FAILURE() << "an existing file was overwritten";
  } catch (const InputError& e) {
    EXPECT_NE(std::string(e.what()).find("k.op4"), std::string::npos) << e.what();
    EXPECT_NE(std::string(e.what()).find("refusing to overwrite"), std::string::npos) << e.what();
  }
  EXPECT_EQ(test::read_file(path), "keep me");
  io::Op4ExportOptions o;
  o.overwrite = true;
  io::write_op4(s, path, o);
  EXPECT_EQ(parse_op4(test::read_file(path)).at("KAA").A, s.K);
  o.recovery = true;
  try {
    io::write_op4(s, path, o);
    ADD_FAILURE() << "no error";
  } catch (const InputError& e) {
    EXPECT_NE(std::string(e.what()).find("holds no recovery matrix"), std::string::npos) << e.what();
  }
}

}  // namespace
}  // namespace seflex
