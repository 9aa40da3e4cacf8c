#pragma once
// Stress modes of a superelement (format 1.4, optional; `seflex reduce --stresses`): for each element of
// the chosen set its linear result components (fem/element_results.hpp: Nastran's element forces and
// stresses, element coordinate systems) for each column of the Craig-Bampton basis, so that the results
// of a deformed body are S q (q its elastic coordinates, as U = recovery q). Kept beside the
// se::Superelement (the multibody solver never needs them): io reads and writes them with the body's
// file, scene recovers them in a run.
#include <Eigen/Core>
#include <cstdint>
#include <string>
#include <vector>

namespace seflex::se {

struct StressModes {
  std::vector<std::int32_t> element_ids;  ///< E element ids
  std::vector<std::int32_t> kinds;        ///< E: fem::ResultKind (0 shell, 1 bar, 2 rod, 3 solid, 4 spring, 5 bush)
  std::vector<std::int32_t> rows;         ///< E: first row of each element's components in S (increasing)
  Eigen::MatrixXd S;                      ///< R x n
  bool present() const { return !element_ids.empty(); }
  /// The same modes for the body's first n coordinates (fewer fixed-interface modes: leading columns).
  StressModes first_columns(Eigen::Index n) const {
    StressModes r = *this;
    r.S = S.leftCols(n);
    return r;
  }
};

/// Structural problems of stress modes for a body of reduced size n (empty: consistent).
inline std::vector<std::string> check_consistency(const StressModes& s, Eigen::Index n) {
  std::vector<std::string> problems;
  if (!s.present()) return problems;
  if (s.S.cols() != n) problems.push_back("stress modes have " + std::to_string(s.S.cols()) + " columns, expected " + std::to_string(n));
  if (s.kinds.size() != s.element_ids.size() || s.rows.size() != s.element_ids.size())
    problems.push_back("stress modes need one kind and one first row per element");
  for (std::size_t e = 0; e < s.rows.size() && e < s.kinds.size(); ++e)
    if (s.kinds[e] < 0 || s.kinds[e] > 5 || s.rows[e] < 0 || s.rows[e] >= s.S.rows() || (e > 0 && s.rows[e] <= s.rows[e - 1])) {
      problems.push_back("stress modes: element " + std::to_string(s.element_ids[e]) + " has an unknown result kind or a row out of order");
      break;
    }
  if (s.S.size() > 0 && !s.S.allFinite()) problems.push_back("stress modes have non-finite entries");
  return problems;
}

}  // namespace seflex::se
