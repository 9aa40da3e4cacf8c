// A superelement as a Nastran DMIG deck (dmig_export.hpp).
#include "seflex/io/dmig_export.hpp"

#include <algorithm>
#include <cctype>
#include <cmath>
#include <cstdio>
#include <string>

#include "atomic_write.hpp"
#include "seflex/common/error.hpp"

namespace seflex::io {

namespace {

constexpr int kMaxNastranId = 99999999;

/// A real number in a 16-character large field with as many digits as fit: Nastran's implicit
/// exponent form without the E ("-1.2345678901+05"), 11 significant digits (12 when positive).
std::string real16(double x) {
  char buf[64];
  for (int digits = 11; digits >= 1; --digits) {
    std::snprintf(buf, sizeof buf, "%.*E", digits, x);
    std::string s = buf;
    s.erase(s.find('E'), 1);
    if (s.size() <= 16) return std::string(16 - s.size(), ' ') + s;
  }
  SEFLEX_DEMAND(false, "a number does not fit a large field");
  return {};
}

std::string int_field(long long v, int width) {
  char buf[32];
  std::snprintf(buf, sizeof buf, "%-*lld", width, v);
  return buf;
}

std::string text_field(const std::string& s, int width) {
  return s.size() >= static_cast<std::size_t>(width) ? s.substr(0, static_cast<std::size_t>(width))
                                                     : s + std::string(static_cast<std::size_t>(width) - s.size(), ' ');
}

void check_name(const std::string& name) {
  bool ok = !name.empty() && name.size() <= 8 && std::isalpha(static_cast<unsigned char>(name[0]));
  for (char ch : name) ok = ok && std::isalnum(static_cast<unsigned char>(ch));
  if (!ok) throw InputError("DMIG matrix name '" + name + "': expected 1-8 letters or digits starting with a letter");
}

/// The point id and component (0 for a scalar point) of reduced coordinate k.
struct Dof {
  int id = 0, component = 0;
};

void append_matrix(std::string& out, const std::string& name, const Eigen::MatrixXd& A, const std::vector<Dof>& dofs) {
  out += "$\n$ " + name + ": symmetric (IFO 6), double precision (TIN 2), lower triangle by columns\n";
  out +=
      "DMIG    " + text_field(name, 8) + int_field(0, 8) + int_field(6, 8) + int_field(2, 8) + int_field(0, 8) + "\n";
  const auto n = A.rows();
  for (Eigen::Index j = 0; j < n; ++j) {
    bool any = false;
    for (Eigen::Index i = j; i < n; ++i) any = any || A(i, j) != 0.0;
    if (!any) continue;
    const Dof& cj = dofs[static_cast<std::size_t>(j)];
    out += "DMIG*   " + text_field(name, 16) + int_field(cj.id, 16) + int_field(cj.component, 16) +
           std::string(16, ' ') + "\n";
    for (Eigen::Index i = j; i < n; ++i) {
      if (A(i, j) == 0.0) continue;
      const Dof& ri = dofs[static_cast<std::size_t>(i)];
      out += "*       " + int_field(ri.id, 16) + int_field(ri.component, 16) + real16(A(i, j)) + std::string(16, ' ') +
             "\n";
    }
  }
}

}  // namespace

std::string dmig_deck(const se::Superelement& s, const DmigExportOptions& options) {
  const auto problems = se::check_consistency(s);
  SEFLEX_DEMAND(problems.empty(),
                "DMIG export of an inconsistent superelement: " + (problems.empty() ? "" : problems[0]));
  check_name(options.stiffness_name);
  check_name(options.mass_name);
  SEFLEX_DEMAND(options.stiffness_name != options.mass_name, "DMIG export: the two matrices need different names");

  int max_id = 0;
  for (const auto& node : s.interfaces) max_id = std::max(max_id, node.id);
  long long first = options.first_spoint;
  if (first == 0) first = max_id < 9000001 ? 9000001 : max_id + 1;
  for (const auto& node : s.interfaces)
    if (node.id >= first && node.id < first + s.num_modes)
      throw InputError("DMIG export: modal SPOINT ids " + std::to_string(first) + "-" +
                       std::to_string(first + s.num_modes - 1) + " clash with interface grid " +
                       std::to_string(node.id) + "; expected a first SPOINT id outside the interface ids");
  if (first < 1 || first + s.num_modes - 1 > kMaxNastranId || max_id > kMaxNastranId)
    throw InputError("DMIG export: ids must lie in 1-" + std::to_string(kMaxNastranId) + " (Nastran's 8-digit fields)");

  std::vector<Dof> dofs;
  for (const auto& node : s.interfaces)
    for (int c = 1; c <= 6; ++c) dofs.push_back({node.id, c});
  for (int k = 0; k < s.num_modes; ++k) dofs.push_back({static_cast<int>(first + k), 0});

  std::string out;
  out += "$ seflex superelement '" + s.name + "' as Nastran direct matrix input (DMIG), written by seflex " +
         s.seflex_version + "\n";
  out += "$ source " + s.source_file + " (SHA-256 " + s.source_hash + "), reduced " + s.created + ", units " + s.units +
         "\n";
  out += "$ " + std::to_string(s.num_interfaces()) + " interface grids (6 dofs each, basic axes) and " +
         std::to_string(s.num_modes) + " fixed-interface modes (SPOINT " + std::to_string(first) +
         " onwards), n = " + std::to_string(s.size()) + "\n";
  out += "$ Modes of this deck = free-free modes of the reduced model (six rigid-body modes first).\n";
  out += "SOL 103\nCEND\n";
  out += "TITLE = SEFLEX SUPERELEMENT " + s.name + "\n";
  out += "ECHO = NONE\nMETHOD = 1\nK2GG = " + options.stiffness_name + "\nM2GG = " + options.mass_name + "\n";
  out += "DISPLACEMENT = ALL\nBEGIN BULK\n";
  out += "EIGRL   " + int_field(1, 8) + std::string(16, ' ') + int_field(s.size(), 8) + "\n";
  out +=
      "$ interface grids, basic coordinates (frame node " + std::to_string(s.frame_node_id) + " at the body origin)\n";
  for (const auto& node : s.interfaces) {
    const Eigen::Vector3d x = s.p_OBo + node.p_BoN_B;
    out += "GRID*   " + int_field(node.id, 16) + int_field(0, 16) + real16(x.x()) + real16(x.y()) + "\n";
    out += "*       " + real16(x.z()) + int_field(0, 16) + "\n";
  }
  if (s.num_modes > 0) {
    out += "$ modal coordinates of the fixed-interface modes:\n";
    for (int k = 0; k < s.num_modes; ++k) {
      char buf[96];
      std::snprintf(buf, sizeof buf, "$   SPOINT %lld: mode %d, %.6g Hz\n", first + k, k + 1, s.mode_frequencies_hz(k));
      out += buf;
    }
    out += "SPOINT  " + int_field(first, 8) +
           (s.num_modes > 1 ? "THRU    " + int_field(first + s.num_modes - 1, 8) : "") + "\n";
  }
  append_matrix(out, options.stiffness_name, s.K, dofs);
  append_matrix(out, options.mass_name, s.M, dofs);
  out += "ENDDATA\n";
  return out;
}

void write_dmig_deck(const se::Superelement& body, const std::filesystem::path& path,
                     const DmigExportOptions& options) {
  detail::write_file_atomically(path, dmig_deck(body, options), options.overwrite);
}

}  // namespace seflex::io
