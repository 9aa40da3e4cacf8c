// OUTPUT4 ASCII matrices (op4.hpp).
#include "seflex/io/op4.hpp"

#include <cmath>
#include <cstdio>
#include <cstdlib>
#include <string>

#include "atomic_write.hpp"
#include "seflex/common/error.hpp"

namespace seflex::io {

namespace {

/// Fortran 1PE23.16: a sign column, d.dddddddddddddddd, and E+xx; a three-digit exponent replaces
/// the E (as Fortran does when the exponent does not fit), so every value is 23 characters wide.
std::string e23_16(double x) {
  char buf[64];
  std::snprintf(buf, sizeof buf, "%.16E", x);
  std::string s = buf;
  const auto e = s.find('E');
  const int exponent = std::atoi(s.c_str() + e + 1);
  if (std::abs(exponent) >= 100) s.erase(e, 1);  // 1.0000000000000000-100
  return std::string(23 - s.size(), ' ') + s;
}

void append_line_i8(std::string& out, std::initializer_list<long long> values) {
  char buf[16];
  for (long long v : values) {
    std::snprintf(buf, sizeof buf, "%8lld", v);
    out += buf;
  }
}

}  // namespace

void append_op4(std::string& out, const Op4Matrix& m) {
  SEFLEX_DEMAND(!m.name.empty() && m.name.size() <= 8, "OP4: a matrix name has 1-8 characters");
  SEFLEX_DEMAND(m.form == 1 || m.form == 2 || m.form == 6, "OP4: form must be 1, 2 or 6");
  SEFLEX_DEMAND(m.values.allFinite(), "OP4: matrix " + m.name + " has non-finite values");
  const Eigen::Index nr = m.values.rows(), nc = m.values.cols();
  append_line_i8(out, {nc, nr, m.form, 2});
  out += m.name + std::string(8 - m.name.size(), ' ') + "1P,3E23.16\n";
  for (Eigen::Index j = 0; j < nc; ++j) {
    Eigen::Index first = 0, last = nr - 1;
    while (first < nr && m.values(first, j) == 0.0) ++first;
    if (first == nr) continue;  // null column
    while (m.values(last, j) == 0.0) --last;
    append_line_i8(out, {j + 1, first + 1, last - first + 1});
    out += '\n';
    int on_line = 0;
    for (Eigen::Index i = first; i <= last; ++i) {
      out += e23_16(m.values(i, j));
      if (++on_line == 3) {
        out += '\n';
        on_line = 0;
      }
    }
    if (on_line) out += '\n';
  }
  append_line_i8(out, {nc + 1, 1, 1});
  out += '\n' + e23_16(0.0) + '\n';
}

std::string op4_text(const std::vector<Op4Matrix>& matrices) {
  std::string out;
  for (const Op4Matrix& m : matrices) append_op4(out, m);
  return out;
}

std::vector<Op4Matrix> superelement_op4_matrices(const se::Superelement& body, bool recovery) {
  std::vector<Op4Matrix> mats{{"KAA", 6, body.K}, {"MAA", 6, body.M}};
  if (recovery) {
    if (body.recovery.size() == 0)
      throw InputError("superelement '" + body.name +
                       "' holds no recovery matrix; expected one for the OP4 RECOVERY "
                       "matrix (reduce the model again with the full mesh)");
    mats.push_back({"RECOVERY", 2, body.recovery});
  }
  return mats;
}

void write_op4(const se::Superelement& body, const std::filesystem::path& path, const Op4ExportOptions& options) {
  detail::write_file_atomically(path, op4_text(superelement_op4_matrices(body, options.recovery)), options.overwrite);
}

}  // namespace seflex::io
