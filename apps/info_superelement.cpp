// seflex info BODY.se: a description of a superelement file (docs/superelement-format.md).
#include "info_superelement.hpp"

#include <cstdio>
#include <cstring>
#include <fstream>
#include <utility>

#include "seflex/io/superelement_file.hpp"

namespace seflex::app {

namespace {

std::string size_text(std::uint64_t bytes) {
  char buf[48];
  if (bytes < 10 * 1024)
    std::snprintf(buf, sizeof buf, "%llu bytes", static_cast<unsigned long long>(bytes));
  else if (bytes < 10 * 1024 * 1024)
    std::snprintf(buf, sizeof buf, "%.1f kB (%llu bytes)", static_cast<double>(bytes) / 1024.0,
                  static_cast<unsigned long long>(bytes));
  else
    std::snprintf(buf, sizeof buf, "%.1f MB (%llu bytes)", static_cast<double>(bytes) / (1024.0 * 1024.0),
                  static_cast<unsigned long long>(bytes));
  return buf;
}

void print_row3(const char* label, const Eigen::Vector3d& v) {
  std::printf("  %-28s %14.6E %14.6E %14.6E\n", label, v.x(), v.y(), v.z());
}

}  // namespace

bool is_superelement_file(const std::string& path) {
  std::ifstream in(path, std::ios::binary);
  char magic[8] = {};
  return in.read(magic, 8) && std::memcmp(magic, "SEFLEXSE", 8) == 0;
}

void print_superelement_info(const std::string& path) {
  const io::SuperelementFileInfo info = io::inspect_superelement(path);
  const se::Superelement& s = info.dynamics;
  std::printf("superelement %s\n", path.c_str());
  std::printf("  name                         %s\n", s.name.c_str());
  std::printf("  format                       %d.%d, %s\n", info.format_major, info.format_minor,
              size_text(info.file_bytes).c_str());
  std::printf("  written by                   seflex %s at %s\n", s.seflex_version.c_str(), s.created.c_str());
  std::printf("  source                       %s\n", s.source_file.c_str());
  std::printf("  source SHA-256               %s\n", s.source_hash.c_str());
  std::printf("  units                        %s\n", s.units.c_str());

  std::printf("\nframe node %d at (%.9g, %.9g, %.9g) in the source's basic system (body axes = basic axes)\n",
              s.frame_node_id, s.p_OBo.x(), s.p_OBo.y(), s.p_OBo.z());
  std::printf("\ninterfaces: %d nodes, %d dofs\n", s.num_interfaces(), 6 * s.num_interfaces());
  std::printf("  %8s %14s %14s %14s   (position from the frame node, body axes)\n", "grid", "x", "y", "z");
  for (const auto& n : s.interfaces) {
    std::printf("  %8d %14.6E %14.6E %14.6E\n", n.id, n.p_BoN_B.x(), n.p_BoN_B.y(), n.p_BoN_B.z());
    if (!n.R_BN.isIdentity(0.0)) {
      std::printf("  %8s triad (rows)", "");
      for (int r = 0; r < 3; ++r) std::printf("  [%.6g %.6g %.6g]", n.R_BN(r, 0), n.R_BN(r, 1), n.R_BN(r, 2));
      std::printf("\n");
    }
  }

  std::printf("\nreduced size n = %d (6 x %d interface dofs + %d fixed-interface modes)\n", s.size(),
              s.num_interfaces(), s.num_modes);
  for (int k = 0; k < s.num_modes; ++k) std::printf("  mode %4d %16.6f Hz\n", k + 1, s.mode_frequencies_hz(k));

  std::printf("\nmass properties of the full FE model (body axes)\n");
  std::printf("  %-28s %14.6E\n", "mass", s.mass);
  print_row3("centre of mass from frame", s.p_BoCm_B);
  std::printf("  inertia about the centre of mass\n");
  for (int r = 0; r < 3; ++r) print_row3("", s.I_Cm_B.row(r).transpose());

  std::printf("\ninertia invariants           ");
  if (info.has_invariants())
    std::printf("present, %s (full inertia without the mesh)\n", size_text(info.invariant_bytes()).c_str());
  else
    std::printf("absent (full inertia needs the mesh part; `seflex reduce` of format 1.2 stores them)\n");
  std::printf("stiffening invariants        ");  // datasets stiff.* (format 1.3)
  if (s.stiffening.present()) {
    std::uint64_t bytes = 0;
    for (const auto& d : info.datasets)
      if (d.name.rfind("stiff.", 0) == 0) bytes += d.bytes;
    std::printf("present: %d inertia load cases, %zu constraint modes; %s (geometric stiffening in a run)\n",
                se::StiffeningInvariants::kInertiaCases, s.stiffening.interface.size(), size_text(bytes).c_str());
  } else {
    std::printf("absent (reduced with --no-stiffening or before format 1.3: no geometric stiffening in a run)\n");
  }
  std::printf("stress modes                 ");  // datasets stress.* (format 1.4)
  if (info.stress.present()) {
    std::uint64_t bytes = 0;
    for (const auto& d : info.datasets)
      if (d.name.rfind("stress.", 0) == 0) bytes += d.bytes;
    int count[6] = {};
    for (const std::int32_t k : info.stress.kinds) ++count[k];
    static const char* kind_names[6] = {"shell", "bar", "rod", "solid", "spring", "bush"};
    std::printf("present: %zu elements (", info.stress.element_ids.size());
    bool first = true;
    for (int k = 0; k < 6; ++k)
      if (count[k]) std::printf("%s%d %s", std::exchange(first, false) ? "" : ", ", count[k], kind_names[k]);
    std::printf("), %ld result rows; %s (element results in a run)\n", static_cast<long>(info.stress.S.rows()),
                size_text(bytes).c_str());
  } else {
    std::printf("absent (reduced without --stresses: no element results in a run)\n");
  }
  std::printf("mesh part                    ");
  if (info.has_mesh())
    std::printf("present: %lld FE nodes, %lld cells, recovery %s, FE mass %s; %s\n",
                static_cast<long long>(info.num_fe_nodes), static_cast<long long>(info.num_cells),
                info.has("recovery") ? "yes" : "no", info.has("M_fe.values") ? "yes" : "no",
                size_text(info.bytes_of(true)).c_str());
  else
    std::printf("absent (reduced with --no-mesh: no animation, no FE recovery)\n");
  std::printf("dynamics part                %s (reduced matrices%s)\n", size_text(info.bytes_of(false)).c_str(),
              info.has_invariants() ? ", invariants" : "");

  print_truncation(s.truncation, "none computed (all interior modes kept, or none asked)");

  if (s.source_warnings.empty()) {
    std::printf("\nsource warnings: none\n");
  } else {
    std::printf("\nsource warnings (printed by seflex reduce about the source model)\n");
    for (const auto& w : s.source_warnings) std::printf("  %s\n", w.c_str());
  }
}

void print_truncation(const se::TruncationReport& t, const char* none_neglected) {
  std::printf("\ntruncation: what the kept modes retain of the fixed-interface dynamics\n");
  std::printf("  modal effective mass fraction (of the interior's, about the frame node)\n");
  std::printf("    %9s %9s %9s %9s %9s %9s\n", "x", "y", "z", "rx", "ry", "rz");
  std::printf("   ");
  for (double f : t.effective_mass_fraction) std::printf(" %8.4f%%", 100.0 * f);
  std::printf("\n");
  if (t.max_kept_hz > 0) std::printf("  highest kept mode          %14.6f Hz\n", t.max_kept_hz);
  if (t.first_neglected_hz > 0)
    std::printf("  first neglected mode       %14.6f Hz\n", t.first_neglected_hz);
  else
    std::printf("  first neglected mode       %s\n", none_neglected);
}

}  // namespace seflex::app
