// Consequences of a deck that seflex computes as written (modelling_cautions.hpp).
#include "modelling_cautions.hpp"

#include <Eigen/Geometry>
#include <algorithm>
#include <array>
#include <cmath>
#include <cstdio>
#include <map>
#include <tuple>
#include <unordered_map>

#include "seflex/common/error.hpp"
#include "seflex/fem/section.hpp"

namespace seflex::solutions::detail {
namespace {

constexpr double kTwoPi = 6.283185307179586476925286766559;

std::string number(double x, int digits = 5) {
  char buf[48];
  std::snprintf(buf, sizeof buf, "%.*g", digits, x);
  return buf;
}

std::string ids_text(const std::vector<int>& ids) {
  std::string s;
  for (std::size_t k = 0; k < ids.size(); ++k) {
    if (k == 6) return s + ", ...";
    s += (k ? ", " : "") + std::to_string(ids[k]);
  }
  return s;
}

bool before(const fem::CardRef& a, const fem::CardRef& b) { return std::tie(a.file, a.line) < std::tie(b.file, b.line); }

}  // namespace

std::vector<Caution> torsionless_bars(const fem::Model& m, bool buckling) {
  // CBAR and CBEAM elements per property without torsional stiffness (usually none: no loop)
  std::unordered_map<int, std::size_t> bars_of, beams_of;
  for (const auto& p : m.bar_props)
    if (!(p.J > 0.0)) bars_of[p.id] = 0;
  if (bars_of.empty()) return {};
  for (const auto& b : m.bars)
    if (const auto it = bars_of.find(b.pid); it != bars_of.end()) {
      if (b.is_beam)
        ++beams_of[b.pid];
      else
        ++it->second;
    }
  struct Group {
    std::vector<int> ids;
    std::size_t elements = 0;
    bool cbar = false, cbeam = false;
    fem::CardRef first{~0u, ~0u};
  };
  std::map<std::string, Group> groups;  // by property card name
  for (const auto& p : m.bar_props) {
    if (p.J > 0.0) continue;  // element_bar.cpp adds G J / L only for J > 0
    const auto nc = beams_of.find(p.id);
    const std::size_t n_bar = bars_of.at(p.id), n_beam = nc == beams_of.end() ? 0 : nc->second;
    if (n_bar + n_beam == 0) continue;  // no element of the model uses it
    Group& g = groups[fem::card_name(p.source)];
    g.ids.push_back(p.id);
    g.elements += n_bar + n_beam;
    g.cbar = g.cbar || n_bar > 0;
    g.cbeam = g.cbeam || n_beam > 0;
    if (before(p.ref, g.first)) g.first = p.ref;
  }
  std::vector<Caution> out;
  for (const auto& [card, g] : groups) {
    const std::string elements = g.cbar && g.cbeam ? "CBAR/CBEAM" : g.cbar ? "CBAR" : "CBEAM";
    std::string reason = card + " " + ids_text(g.ids) + " (" + std::to_string(g.elements) + " " +
                         elements + " element" + (g.elements > 1 ? "s" : "") +
                         "): J = 0, no torsional stiffness: the twist of these elements about their axis is held only by "
                         "what they connect to (other elements, SPC, or AUTOSPC where nothing else holds it)";
    if (buckling)
      reason += "; in buckling the torsion (Wagner) term N (I1 + I2) / (A L) of the bar's differential stiffness couples "
                "the twist to the bending rotations, so the load factors depend on those constraints; give J if the "
                "section has torsional stiffness";
    else
      reason += "; give J if the section has torsional stiffness";
    out.push_back({card, g.ids.size(), g.first, reason});
  }
  return out;
}

std::vector<Caution> thick_shells(const fem::Model& m) {
  // Per property: t_s / T of its section (t_s^2 = ShellSection::ts2; t_s = T for a homogeneous
  // PSHELL; both scale with the thickness, so corner thicknesses keep the ratio), or 0 when the
  // section has no bending or no transverse shear flexibility (Kirchhoff: nothing to converge).
  struct Section {
    double ratio = 0.0;  ///< t_s / T, 0: nothing to report
    double t = 0.0;      ///< T (PCOMP: the plies' total)
  };
  std::unordered_map<int, Section> section_of;
  int last_pid = 0;
  Section last;  // the previous element's (elements of a property usually follow each other)
  auto section = [&](const fem::Shell& s) {
    if (s.pid == last_pid && !section_of.empty()) return last;
    last_pid = s.pid;
    if (const auto it = section_of.find(s.pid); it != section_of.end()) return last = it->second;
    const auto it = section_of.emplace(s.pid, Section{}).first;
    fem::Shell plain = s;
    plain.t = {};  // the property's own thickness
    try {
      const fem::ShellSection sec = fem::make_shell_section(m, plain);
      if (sec.has_bending && sec.shear_flexible && sec.t > 0.0) it->second = {std::sqrt(sec.ts2) / sec.t, sec.t};
    } catch (const InputError&) {
      // an undefined or invalid property: refused where the element is built, with its own message
    }
    return last = it->second;
  };
  struct Group {
    std::size_t count = 0;
    fem::CardRef first{~0u, ~0u};
    int first_id = 0;
    double worst = 0.0;
    bool equivalent = false;  // a sandwich or laminate among them (t_s differs from T)
  };
  std::map<std::string, Group> groups;
  // Grid positions by id: a direct table when the ids are dense enough (the usual numbering: 4 hash
  // look-ups per element would cost a tenth of `seflex info` on a million-element deck), else the map.
  int max_id = 0;
  for (const auto& g : m.grids) max_id = std::max(max_id, g.id);
  std::vector<const Eigen::Vector3d*> by_id;
  if (max_id >= 0 && static_cast<std::size_t>(max_id) <= 4 * m.grids.size() + 1024) {
    by_id.assign(static_cast<std::size_t>(max_id) + 1, nullptr);
    for (const auto& g : m.grids)
      if (g.id >= 0) by_id[static_cast<std::size_t>(g.id)] = &g.x_basic;
  }
  auto position = [&](int id) -> const Eigen::Vector3d* {
    if (!by_id.empty()) return id >= 0 && static_cast<std::size_t>(id) < by_id.size() ? by_id[static_cast<std::size_t>(id)] : nullptr;
    const auto it = m.grid_index.find(id);
    return it == m.grid_index.end() ? nullptr : &m.grids[it->second].x_basic;
  };
  for (const auto& s : m.shells) {
    const Section sec = section(s);
    const double r = sec.ratio;
    if (r == 0.0) continue;
    std::array<const Eigen::Vector3d*, 4> x{};
    bool found = true;
    for (int k = 0; k < s.nnode && found; ++k) found = (x[k] = position(s.g[k])) != nullptr;
    if (!found) continue;
    const double area = s.nnode == 4 ? 0.5 * (*x[2] - *x[0]).cross(*x[3] - *x[1]).norm()
                                     : 0.5 * (*x[1] - *x[0]).cross(*x[2] - *x[0]).norm();
    double t = sec.t;  // PCOMP (no corner thicknesses); PSHELL as fem/src/shell_section.cpp: the corners' mean
    if (m.shell_prop_index.count(s.pid)) {
      t = 0.0;
      for (int k = 0; k < s.nnode; ++k) t += s.t[k] == 0.0 ? sec.t : (s.tflag == 1 ? s.t[k] * sec.t : s.t[k]);
      t /= s.nnode;
    }
    const double h = std::sqrt(area), ts = r * t;
    if (!(h > 0.0) || !(ts > kThickShellRatio * h)) continue;
    Group& g = groups[fem::shell_card(s)];
    ++g.count;
    if (before(s.ref, g.first)) {
      g.first = s.ref;
      g.first_id = s.id;
    }
    g.worst = std::max(g.worst, ts / h);
    g.equivalent = g.equivalent || std::abs(r - 1.0) > 0.01;
  }
  std::vector<Caution> out;
  for (const auto& [card, g] : groups)
    out.push_back({card, g.count, g.first,
                   "thick for their size (first: element " + std::to_string(g.first_id) + "; t / sqrt(area) up to " +
                       number(g.worst, 2) + ", above " + number(kThickShellRatio) +
                       (g.equivalent ? "; t of a sandwich or laminate: the homogeneous plate's with its ratio of bending "
                                       "to transverse shear stiffness"
                                     : "") +
                       "): transverse shear governs their bending and the element converges slowly on such a mesh; "
                       "check the higher modes and the stresses with a finer mesh"});
  return out;
}

std::vector<Caution> rforce_units(const fem::Model& m, const std::set<int>& used_sets) {
  std::vector<Caution> out;
  for (const auto& r : m.rotational_loads) {
    if (!used_sets.count(r.sid)) continue;
    std::string reason = "load set " + std::to_string(r.sid) + ": A = " + number(r.a) +
                         " revolutions per unit time (MSC Nastran QRG): angular velocity " + number(kTwoPi * r.a) +
                         " rad per unit time";
    if (r.racc != 0.0)
      reason += ", RACC = " + number(r.racc) + " revolutions per unit time squared: angular acceleration " +
                number(kTwoPi * r.racc) + " rad per unit time squared";
    reason += "; if A was meant in rad per unit time, give A = " + number(r.a / kTwoPi);
    if (r.racc != 0.0) reason += " and RACC = " + number(r.racc / kTwoPi);
    out.push_back({"RFORCE", 1, r.ref, reason});
  }
  return out;
}

}  // namespace seflex::solutions::detail
