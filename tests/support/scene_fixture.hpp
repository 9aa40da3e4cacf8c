#pragma once
// Shared by the scene tests: a beam superelement file written in a temporary folder (the test-only
// Craig-Bampton builder of tests/mbd, saved with io's writer), a scene file beside it, and a
// reader of the CSV files `seflex run` writes.
#include <gtest/gtest.h>

#include <cmath>
#include <cstdlib>
#include <map>
#include <sstream>
#include <string>
#include <vector>

#include "beam_superelement.hpp"
#include "seflex/io/superelement_file.hpp"
#include "test_support.hpp"

namespace seflex::test {

/// A 1 m aluminium beam along x, 4 elements, interfaces at both ends (grids 1 and 5), frame at the
/// middle node (grid 3), `modes` fixed-interface modes; written to dir/name.
inline se::Superelement write_link(const TempDir& dir, const std::string& name, int modes = 0, double E = 7e10) {
  BeamSection sec;
  sec.E = E;
  sec.G = E / 2.6;
  sec.A = 1e-4;
  sec.Iy = sec.Iz = 2e-9;
  sec.J = 4e-9;
  FrameFE fe = straight_beam(1.0, 4, sec);
  se::Superelement s = craig_bampton(fe, {0, 4}, 2, modes, "link");
  io::save_superelement(s, dir / name, io::SaveOptions{true});
  return s;
}

/// A CSV file read as columns by name.
struct Csv {
  std::vector<std::string> names;
  std::vector<std::vector<double>> rows;
  std::vector<double> column(const std::string& name) const {
    for (std::size_t c = 0; c < names.size(); ++c)
      if (names[c] == name) {
        std::vector<double> v;
        for (const auto& r : rows) v.push_back(r.at(c));
        return v;
      }
    throw std::runtime_error("no column " + name);
  }
  bool has(const std::string& name) const {
    for (const auto& n : names)
      if (n == name) return true;
    return false;
  }
};

inline Csv read_csv(const std::filesystem::path& p) {
  std::istringstream in(read_file(p));
  Csv csv;
  std::string line;
  std::getline(in, line);
  std::istringstream h(line);
  for (std::string f; std::getline(h, f, ',');) csv.names.push_back(f);
  while (std::getline(in, line)) {
    std::istringstream r(line);
    std::vector<double> row;
    for (std::string f; std::getline(r, f, ',');) {
      char* end = nullptr;
      const double x = std::strtod(f.c_str(), &end);  // text fields (body names) read as NaN
      row.push_back(f.empty() ? 0.0 : (end == f.c_str() + f.size() ? x : std::nan("")));
    }
    csv.rows.push_back(row);
  }
  return csv;
}

inline std::string q(const std::filesystem::path& p) { return "'" + p.string() + "'"; }

/// Replace the first `from` in s (a demo scene edited for a test); fails the test when it is missing.
inline void replace_once(std::string& s, const std::string& from, const std::string& to) {
  const auto at = s.find(from);
  ASSERT_NE(at, std::string::npos) << "the demo scene no longer contains '" << from << "'";
  s.replace(at, from.size(), to);
}

}  // namespace seflex::test
