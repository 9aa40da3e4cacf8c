// DMIG matrices selected by K2GG/M2GG, added to the g-set matrices (dmig.hpp).
#include "seflex/fem/dmig.hpp"

#include <algorithm>
#include <cmath>
#include <map>
#include <string>
#include <utility>
#include <vector>

#include "seflex/common/error.hpp"
#include "seflex/fem/finalize.hpp"

namespace seflex::fem {

namespace {

std::string point_name(int id, int component) {
  return component == 0 ? std::to_string(id) : std::to_string(id) + "-" + std::to_string(component);
}

const Dmig& find_dmig(const Model& model, const std::string& name, const char* command) {
  for (const Dmig& d : model.dmigs)
    if (d.name == name) return d;
  const std::string file = model.files.empty() ? std::string() : model.files[0];
  throw InputError(file + ": case control " + command + " = " + name +
                   " names no DMIG matrix; expected the name of a DMIG in the bulk data");
}

}  // namespace

DirectMatrixSelection direct_matrix_selection(const Model& model) {
  const CaseControl& cc = model.case_control;
  DirectMatrixSelection s;
  const Subcase& first = cc.subcases.empty() ? cc.global : cc.subcases.front();
  s.k2gg = first.k2gg;
  s.m2gg = first.m2gg;
  for (const Subcase& sc : cc.subcases)
    if (sc.k2gg != s.k2gg || sc.m2gg != s.m2gg) {
      const std::string file = model.files.empty() ? std::string() : model.files[0];
      throw InputError(
          file + ": case control SUBCASE " + std::to_string(sc.id) + ": K2GG/M2GG differ from SUBCASE " +
          std::to_string(first.id) +
          "; expected one K2GG and one M2GG selection for all subcases (put them above the first SUBCASE)");
    }
  return s;
}

Eigen::SparseMatrix<double> dmig_matrix(const Model& model, const DofMap& dofs, const std::vector<std::string>& names,
                                        double scale) {
  const Eigen::Index n = dofs.size();
  std::vector<Eigen::Triplet<double>> triplets;
  for (const std::string& name : names) {
    const Dmig& d = find_dmig(model, name, "K2GG/M2GG");
    const SourceRef at = where(model, d.ref);
    if (d.form != 6)
      throw InputError(at, "DMIG " + d.name + ", field 4 (IFO): got " + std::to_string(d.form) +
                               "; expected 6 (symmetric), which K2GG and M2GG require");
    // (row, col) with row >= col -> where it was given (for duplicate detection).
    std::map<std::pair<Eigen::Index, Eigen::Index>, std::pair<int, int>> seen;
    for (const DmigEntry& e : d.entries) {
      const auto col = find_dof(model, dofs, e.gj, e.cj == 0 ? 0 : e.cj);
      const auto row = find_dof(model, dofs, e.gi, e.ci == 0 ? 0 : e.ci);
      if (!col || !row) {
        const bool bad_col = !col;
        const int id = bad_col ? e.gj : e.gi, c = bad_col ? e.cj : e.ci;
        throw InputError(at, "DMIG " + d.name + ": " + (bad_col ? "column " : "row ") + point_name(id, c) +
                                 " is not a dof of the model; expected a GRID with component 1-6 or an SPOINT with 0");
      }
      const Eigen::Index i = std::max(*row, *col), j = std::min(*row, *col);
      const auto [it, inserted] = seen.emplace(std::make_pair(i, j), std::make_pair(e.gi, e.ci));
      if (!inserted)
        throw InputError(at, "DMIG " + d.name + ": the term (" + point_name(e.gi, e.ci) + ", " +
                                 point_name(e.gj, e.cj) +
                                 ") is given twice (also as its symmetric partner or a repeated entry); expected each "
                                 "term of a symmetric (IFO 6) matrix once, in either triangle");
      if (!std::isfinite(e.value))
        throw InputError(at, "DMIG " + d.name + ": the term (" + point_name(e.gi, e.ci) + ", " +
                                 point_name(e.gj, e.cj) + ") is not a finite number");
      const double v = scale * e.value;
      triplets.emplace_back(i, j, v);
      if (i != j) triplets.emplace_back(j, i, v);
    }
  }
  Eigen::SparseMatrix<double> A(n, n);
  A.setFromTriplets(triplets.begin(), triplets.end());
  return A;
}

Eigen::SparseMatrix<double> external_part_matrix(const Model& model, const DofMap& dofs, bool mass) {
  std::vector<Eigen::Triplet<double>> triplets;
  for (const ExternalMatrices& x : model.external_parts) {
    std::vector<Eigen::Index> at;
    for (const auto& [id, c] : x.dofs) {
      const auto d = find_dof(model, dofs, id, c);
      if (!d)
        throw InputError(where(model, x.ref), "SEBULK " + std::to_string(x.seid) + ": the external superelement's dof " + point_name(id, c) +
                                                  " is not a dof of the assembled model; expected a GRID component or SPOINT");
      at.push_back(*d);
    }
    const Eigen::MatrixXd& A = mass ? x.M : x.K;
    for (Eigen::Index j = 0; j < A.cols(); ++j)
      for (Eigen::Index i = 0; i < A.rows(); ++i)
        if (A(i, j) != 0.0) triplets.emplace_back(at[static_cast<std::size_t>(i)], at[static_cast<std::size_t>(j)], A(i, j));
  }
  Eigen::SparseMatrix<double> out(dofs.size(), dofs.size());
  out.setFromTriplets(triplets.begin(), triplets.end());
  return out;
}

void add_direct_matrices(const Model& model, const DofMap& dofs, Eigen::SparseMatrix<double>& K,
                         Eigen::SparseMatrix<double>& M, Eigen::SparseMatrix<double>* M_bulk) {
  const bool external = !model.external_parts.empty();
  if (external) {
    K = K + external_part_matrix(model, dofs, false);
    if (M_bulk) *M_bulk = M;
    M = M + external_part_matrix(model, dofs, true);
  }
  const DirectMatrixSelection s = direct_matrix_selection(model);
  if (!s.k2gg.empty()) K = K + dmig_matrix(model, dofs, s.k2gg, param_number(model, "CK2"));
  if (!s.m2gg.empty()) {
    const Eigen::SparseMatrix<double> M2 = dmig_matrix(model, dofs, s.m2gg, param_number(model, "CM2"));
    M = M + M2;
    if (external && M_bulk) *M_bulk = *M_bulk + M2;
  }
}

}  // namespace seflex::fem
