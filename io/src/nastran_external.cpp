// External superelements' matrices from OP4 files (nastran_external.hpp).
#include "nastran_external.hpp"

#include <algorithm>
#include <cctype>
#include <map>
#include <system_error>

#include "seflex/common/error.hpp"
#include "seflex/fem/finalize.hpp"
#include "seflex/io/op4.hpp"

namespace seflex::io::nastran {
namespace {

std::string lower(std::string s) {
  for (char& c : s) c = static_cast<char>(std::tolower(static_cast<unsigned char>(c)));
  return s;
}

/// The files whose path below `dir` equals `rel` but for the case of letters (component by component).
std::vector<std::filesystem::path> case_insensitive_matches(const std::filesystem::path& dir, const std::filesystem::path& rel) {
  std::vector<std::filesystem::path> found{dir};
  for (const auto& part : rel) {
    const std::string want = lower(part.string());
    std::vector<std::filesystem::path> next;
    for (const auto& d : found) {
      if (want == "." || want == "..") {
        next.push_back(d / part);
        continue;
      }
      std::error_code ec;
      for (std::filesystem::directory_iterator it(d, ec), end; !ec && it != end; it.increment(ec))
        if (lower(it->path().filename().string()) == want) next.push_back(it->path());
    }
    found.swap(next);
  }
  std::vector<std::filesystem::path> files;
  for (const auto& f : found)
    if (std::filesystem::is_regular_file(f)) files.push_back(f);
  return files;
}

std::filesystem::path resolve(const AssignedUnit& a, const std::filesystem::path& deck_dir, fem::Model& residual) {
  const std::filesystem::path p(a.path), main_dir = deck_dir.empty() ? std::filesystem::path(".") : deck_dir;
  const std::filesystem::path full = p.is_absolute() ? p : main_dir / p;
  if (std::filesystem::is_regular_file(full)) return full;
  const std::vector<std::filesystem::path> m =
      p.is_absolute() ? case_insensitive_matches(p.root_path(), p.relative_path()) : case_insensitive_matches(main_dir, p);
  if (m.size() == 1) {
    residual.read_warnings.push_back(a.where + ": ASSIGN INPUTT4 names '" + a.path + "', which does not exist; read " + m[0].string() +
                                     ", the one file whose path differs only in the case of letters (as Nastran on a "
                                     "case-insensitive file system would)");
    return m[0];
  }
  throw InputError(a.where + ": ASSIGN INPUTT4: the file '" + a.path + "' does not exist (looked for " + full.string() +
                   (m.empty() ? std::string() : ", and " + std::to_string(m.size()) + " files match it but for case") +
                   "); expected the OP4 file of the external superelement, relative to the main deck's folder");
}

/// A square matrix on n dofs, symmetric to 1e-6 of its largest term: the mean of its triangles.
Eigen::MatrixXd symmetric(const Op4Matrix& m, Eigen::Index n, const std::string& file, const std::string& part) {
  if (m.values.rows() != n || m.values.cols() != n)
    throw InputError(file + ": OP4 matrix " + m.name + " is " + std::to_string(m.values.rows()) + " x " + std::to_string(m.values.cols()) +
                     "; expected " + std::to_string(n) + " x " + std::to_string(n) + ", the a-set of " + part +
                     " (its EXTRN points: 6 dofs a grid with components 123456, 1 a scalar point)");
  const double big = m.values.cwiseAbs().maxCoeff();
  const double asym = (m.values - m.values.transpose()).cwiseAbs().maxCoeff();
  if (asym > 1e-6 * big)
    throw InputError(file + ": OP4 matrix " + m.name + " is not symmetric (terms differ from their transposes by " +
                     std::to_string(asym / big) + " of the largest); expected a symmetric stiffness or mass matrix");
  return 0.5 * (m.values + m.values.transpose());
}

}  // namespace

void read_external_matrices(fem::Model& residual, std::vector<fem::Part>& parts, const std::vector<AssignedUnit>& units,
                            const std::filesystem::path& main_dir) {
  for (const fem::PartBulk& b : residual.part_bulks) {
    if (b.type != "EXTOP4") continue;
    const std::string card = "SEBULK " + std::to_string(b.seid);
    const auto u = std::find_if(units.begin(), units.end(), [&](const AssignedUnit& a) { return a.unit == b.unit; });
    if (u == units.end())
      throw InputError(fem::where(residual, b.ref), card + ", field 8 (UNITNO): unit " + std::to_string(b.unit) +
                                                        " has no ASSIGN INPUTT4 in the executive control; expected "
                                                        "ASSIGN INPUTT4='file',UNIT=" + std::to_string(b.unit));
    const auto p = std::find_if(parts.begin(), parts.end(), [&](const fem::Part& q) { return q.seid == b.seid; });
    if (p == parts.end())
      throw InputError(fem::where(residual, b.ref), card + ": no BEGIN SUPER = " + std::to_string(b.seid) +
                                                        " section; expected the part's bulk data (its EXTRN and boundary GRIDs: "
                                                        "the .pch file Nastran writes with the matrices)");
    const std::string part = "part " + std::to_string(b.seid);
    fem::Model& m = p->model;
    // the a-set: EXTRN points by id
    std::map<int, unsigned> points;
    for (const auto& e : m.external_points)
      for (const auto& [id, mask] : e.points)
        if (!points.emplace(id, mask).second)
          throw InputError(fem::where(residual, e.ref), "EXTRN of " + part + ": point " + std::to_string(id) +
                                                            " is listed twice; expected each boundary point once");
    if (points.empty())
      throw InputError(fem::where(residual, b.ref), card + ": " + part +
                                                        " has no EXTRN card; expected EXTRN listing its boundary points (the "
                                                        "rows of its matrices) in its BEGIN SUPER section");
    fem::ExternalMatrices x;
    x.seid = b.seid;
    x.ref = b.ref;
    for (const auto& [id, mask] : points) {
      if (mask == 0) x.dofs.emplace_back(id, 0);
      for (int c = 1; c <= 6; ++c)
        if ((mask >> (c - 1)) & 1u) x.dofs.emplace_back(id, c);
    }
    const std::filesystem::path file = resolve(*u, main_dir, residual);
    x.source = file.string();
    const std::vector<Op4Matrix> mats = read_op4(file);
    const auto find = [&](const char* name) -> const Op4Matrix* {
      for (const auto& q : mats)
        if (q.name == name) return &q;
      return nullptr;
    };
    const Op4Matrix* K = find("KAA");
    if (!K)
      throw InputError(x.source + ": no OP4 matrix KAA (the stiffness of " + part + ", " + card + " at " +
                       fem::where(residual, b.ref).str() + "); expected KAA and MAA");
    const auto n = static_cast<Eigen::Index>(x.dofs.size());
    x.K = symmetric(*K, n, x.source, part);
    if (const Op4Matrix* M = find("MAA"))
      x.M = symmetric(*M, n, x.source, part);
    else {
      x.M = Eigen::MatrixXd::Zero(n, n);
      residual.read_warnings.push_back(x.source + ": no OP4 matrix MAA: " + part + " has no mass");
    }
    std::string unused;
    for (const auto& q : mats)
      if (q.name != "KAA" && q.name != "MAA" && q.values.size() && q.values.cwiseAbs().maxCoeff() > 0)
        unused += (unused.empty() ? "" : ", ") + q.name;
    if (!unused.empty())
      residual.read_warnings.push_back(x.source + ": OP4 matrices " + unused + " of " + part +
                                       " not used (seflex assembles its stiffness KAA and mass MAA: no damping, no loads of "
                                       "the part, no data recovery inside it)");
    m.external_parts.push_back(std::move(x));
  }
}

}  // namespace seflex::io::nastran
