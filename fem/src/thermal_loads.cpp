// Thermal loads of TEMP / TEMPD / TEMPRB sets on bars, rods, shells and solids (see loads.hpp).
#include <initializer_list>
#include <optional>
#include <unordered_map>
#include <vector>

#include "model_lookup.hpp"
#include "seflex/common/error.hpp"
#include "seflex/fem/assembly.hpp"
#include "seflex/fem/element_bar.hpp"
#include "seflex/fem/element_rod.hpp"
#include "seflex/fem/element_shell_quadratic.hpp"
#include "seflex/fem/element_shell_thermal.hpp"
#include "seflex/fem/element_solid.hpp"
#include "seflex/fem/finalize.hpp"
#include "seflex/fem/loads.hpp"

namespace seflex::fem {
namespace {

class ThermalLoads {
 public:
  ThermalLoads(const Model& model, const DofMap& dofs, int sid)
      : m_(model), dofs_(dofs), sid_(sid), cd_(grid_cd_axes(model)), p_(Eigen::VectorXd::Zero(dofs.size())) {
    bool any = false;
    for (const DefaultTemperature& t : m_.default_temperatures)
      if (t.sid == sid) {
        if (tempd_)
          detail::fail(m_, t.ref, "TEMPD", t.sid, "",
                       "a second default temperature for set " + std::to_string(sid) + "; expected one");
        tempd_ = t.t;
        any = true;
      }
    for (const GridTemperature& t : m_.grid_temperatures)
      if (t.sid == sid) {
        const auto it = m_.grid_index.find(t.grid);
        if (it == m_.grid_index.end())
          detail::fail(m_, t.ref, "TEMP", t.sid, "G",
                       "references GRID " + std::to_string(t.grid) + ", which is not defined");
        if (!grid_t_.emplace(it->second, t.t).second)
          detail::fail(m_, t.ref, "TEMP", t.sid, "G",
                       "a second temperature for GRID " + std::to_string(t.grid) + " in set " + std::to_string(sid) +
                           "; expected one per grid");
        any = true;
      }
    for (const BarTemperature& t : m_.bar_temperatures)
      if (t.sid == sid) {
        if (!bar_t_.emplace(t.element, &t).second)
          detail::fail(m_, t.ref, "TEMPRB", t.sid, "EID",
                       "a second TEMPRB for element " + std::to_string(t.element) + " in set " + std::to_string(sid) +
                           "; expected one");
        any = true;
      }
    if (!any)
      throw InputError(SourceRef{m_.files.empty() ? std::string() : m_.files.front(), 0},
                       "case control TEMPERATURE(LOAD) = " + std::to_string(sid) +
                           ": no TEMP, TEMPD or TEMPRB bulk data card has SID " + std::to_string(sid));
  }

  Eigen::VectorXd run() {
    std::unordered_map<int, bool> used;  // TEMPRB element ids that are bars or rods
    for (const Bar& b : m_.bars) {
      const BarElement e = make_bar_element(m_, b);
      const Mat1& mat = mat1(e.material.id);
      BarTemperatureField t;
      if (const auto it = bar_t_.find(b.id); it != bar_t_.end()) {
        const BarTemperature& r = *it->second;
        t = {0.5 * (r.ta + r.tb) - mat.tref, r.tp1a, r.tp1b, r.tp2a, r.tp2b};
        used[b.id] = true;
      } else {
        const char* card = b.is_beam ? "CBEAM" : "CBAR";
        t.dT = 0.5 * (grid_temperature(b.ga, b.ref, card, b.id) + grid_temperature(b.gb, b.ref, card, b.id)) - mat.tref;
      }
      if (mat.alpha == 0.0 || (t.dT == 0.0 && t.tp1a == 0.0 && t.tp1b == 0.0 && t.tp2a == 0.0 && t.tp2b == 0.0))
        continue;
      scatter(b.ga, b.gb, bar_thermal_load(e, mat.alpha, t));
    }
    for (const Rod& r : m_.rods) {
      const RodElement e = make_rod_element(m_, r);
      const Mat1& mat = mat1(e.material.id);
      double T = 0;
      if (const auto it = bar_t_.find(r.id); it != bar_t_.end()) {
        T = 0.5 * (it->second->ta + it->second->tb);
        used[r.id] = true;
      } else {
        const char* card = rod_card(r);
        T = 0.5 * (grid_temperature(r.ga, r.ref, card, r.id) + grid_temperature(r.gb, r.ref, card, r.id));
      }
      if (mat.alpha == 0.0 || T == mat.tref) continue;
      scatter(r.ga, r.gb, rod_thermal_load(e, mat.alpha, T - mat.tref));
    }
    for (const auto& [eid, t] : bar_t_)
      if (!used.count(eid))
        detail::fail(m_, t->ref, "TEMPRB", t->sid, "EID",
                     "element " + std::to_string(eid) + " is not a CBAR, CBEAM, CROD, CTUBE or CONROD; expected one of them");
    const AssemblyOptions options = assembly_options(m_);
    for (const Shell& s : m_.shells) shell(s, options.k6rot, options.mystran_plate ? &*options.mystran_plate : nullptr);
    for (const Solid& s : m_.solids) solid(s);
    for (const QuadraticShell& q : m_.shells8) quadratic_shell(q, options.k6rot);
    for (const ShearPanel& s : m_.shear_panels)
      refuse_heated("CSHEAR", s.id, s.ref, m_.shear_props[m_.shear_prop_index.at(s.pid)].mid, {s.g[0], s.g[1], s.g[2], s.g[3]});
    for (const Bend& b : m_.bends) refuse_heated("CBEND", b.id, b.ref, m_.bend_props[m_.bend_prop_index.at(b.pid)].mid, {b.ga, b.gb});
    return p_;
  }

  /// A CTRIA6/CQUAD8: the mean of its grids' temperatures (corners and mid-side grids), uniform
  /// through the thickness, from the section's TREF, as the CQUAD4's.
  void quadratic_shell(const QuadraticShell& q, double k6rot) {
    const QuadraticShellElement e = make_quadratic_shell_element(m_, q);
    const Shell& s = q.shell;
    const bool mid4_expands = pshell_mid4_expands(s);
    if (!e.section.thermal() && !mid4_expands) return;
    const char* card = quadratic_shell_card(q);
    std::vector<int> ids, slots;  // present grids and their element positions
    double T = 0;
    for (int k = 0; k < 2 * s.nnode; ++k) {
      const int g = k < s.nnode ? s.g[static_cast<std::size_t>(k)] : q.mid[static_cast<std::size_t>(k - s.nnode)];
      if (g == 0) continue;
      T += grid_temperature(g, s.ref, card, s.id);
      ids.push_back(g);
      slots.push_back(k);
    }
    const double dT = T / static_cast<double>(ids.size()) - e.section.tref;
    if (dT == 0.0) return;
    if (mid4_expands) refuse_mid4(s, card);
    const Eigen::Matrix<double, 48, 1> f = quadratic_shell_thermal_load(e, dT, k6rot);
    Eigen::VectorXd fg(6 * static_cast<Eigen::Index>(ids.size()));
    for (std::size_t i = 0; i < ids.size(); ++i) fg.segment<6>(6 * static_cast<Eigen::Index>(i)) = f.segment<6>(6 * slots[i]);
    scatter(ids.data(), static_cast<int>(ids.size()), fg);
  }

  /// An element seflex computes no thermal load for: refused when the set heats it (its MAT1 expands
  /// and a grid's temperature differs from TREF), never skipped.
  void refuse_heated(const char* card, int id, const CardRef& ref, int mid, std::initializer_list<int> grids) const {
    const Mat1& mat = mat1(mid);
    if (mat.alpha == 0.0) return;
    for (const int g : grids) {
      const auto gi = m_.grid_index.find(g);
      const auto it = gi == m_.grid_index.end() ? grid_t_.end() : grid_t_.find(gi->second);
      const std::optional<double> T = it != grid_t_.end() ? std::optional<double>(it->second) : tempd_;
      if (T && *T != mat.tref)
        detail::fail(m_, ref, card, id, "",
                     "thermal load set " + std::to_string(sid_) + " heats the element (grid " + std::to_string(g) + " at " +
                         std::to_string(*T) + ", MAT1 " + std::to_string(mid) + " TREF " + std::to_string(mat.tref) +
                         ", ALPHA " + std::to_string(mat.alpha) + "), whose thermal load seflex does not compute for " + card +
                         "; expected its grids at TREF, or ALPHA = 0");
    }
  }

 private:
  const Mat1& mat1(int mid) const { return m_.mat1[m_.mat1_index.at(mid)]; }

  /// Temperature of grid id `g` in the set (TEMP, else TEMPD); throws naming the element if neither.
  double grid_temperature(int g, const CardRef& ref, const char* card, int eid) const {
    const std::uint32_t gi = detail::grid_index(m_, g, ref, card, eid, "G");
    if (const auto it = grid_t_.find(gi); it != grid_t_.end()) return it->second;
    if (tempd_) return *tempd_;
    const std::string c = card;
    const bool line = c == "CBAR" || c == "CBEAM" || c == "CROD" || c == "CONROD" || c == "CTUBE";
    detail::fail(m_, ref, card, eid, "",
                 "GRID " + std::to_string(g) + " has no temperature in thermal load set " + std::to_string(sid_) +
                     (line ? " (no TEMP card gives it, no TEMPD and no TEMPRB for the element); expected one of them"
                           : " (no TEMP card gives it and no TEMPD); expected one of them"));
  }

  /// A CQUAD4/CTRIA3: the mean of its grids' temperatures (QRG TEMP: the element temperature of a
  /// shell without TEMPPi), uniform through the thickness, from the section's TREF.
  void shell(const Shell& s, double k6rot, const MystranPlate* mystran) {
    const ShellSection section = make_shell_section(m_, s);
    const char* card = shell_card(s);
    const bool mid4_expands = pshell_mid4_expands(s);
    if (!section.thermal() && !mid4_expands) return;
    double T = 0;
    for (int k = 0; k < s.nnode; ++k) T += grid_temperature(s.g[k], s.ref, card, s.id);
    const double dT = T / s.nnode - section.tref;
    if (dT == 0.0) return;
    if (mid4_expands) refuse_mid4(s, card);
    if (s.nnode == 4)
      scatter(s.g.data(), 4, quad4_thermal_load(make_quad4_element(m_, s, &section), dT, k6rot, mystran));
    else
      scatter(s.g.data(), 3, tria3_thermal_load(make_tria3_element(m_, s, &section), dT, k6rot, mystran));
  }

  [[noreturn]] void refuse_mid4(const Shell& s, const char* card) const {
    detail::fail(m_, s.ref, card, s.id, "",
                 "thermal load set " + std::to_string(sid_) + " heats it and its PSHELL " + std::to_string(s.pid) +
                     " has a MID4 (membrane-bending coupling) material with thermal expansion, whose thermal moment "
                     "seflex does not compute; expected ALPHA blank on MID4's material");
  }

  /// A PSHELL's MID4 (membrane-bending coupling) with thermal expansion: its thermal moment is not
  /// computed, so such a shell, when heated, is refused rather than loaded without it.
  bool pshell_mid4_expands(const Shell& s) const {
    const auto pit = m_.shell_prop_index.find(s.pid);
    if (pit == m_.shell_prop_index.end()) return false;
    const ShellProperty& p = m_.shell_props[pit->second];
    if (p.mid4 <= 0) return false;
    return !detail::shell_material(m_, p.mid4, p.ref, "PSHELL", p.id, "4 of continuation 1 (MID4)").alpha.isZero(0.0);
  }

  /// A CHEXA/CPENTA/CTETRA/CPYRAM: its grids' temperatures interpolated over the element.
  void solid(const Solid& s) {
    const SolidElement e = make_solid_element(m_, s);
    if (e.alpha == 0.0) return;
    Eigen::VectorXd dT(s.nnode);
    for (int k = 0; k < s.nnode; ++k) dT[k] = grid_temperature(s.g[static_cast<std::size_t>(k)], s.ref, s.card(), s.id) - e.tref;
    if (dT.isZero(0.0)) return;
    scatter_translations(s.g.data(), s.nnode, solid_thermal_load(e, e.alpha, dT));
  }

  /// Loads of n grids (6 per grid, basic) into p in the grids' CD systems.
  void scatter(const int* g, int n, const Eigen::Ref<const Eigen::VectorXd>& f) {
    for (int i = 0; i < n; ++i) {
      const std::uint32_t gi = m_.grid_index.at(g[i]);
      for (int part = 0; part < 2; ++part) {
        Eigen::Vector3d v = f.segment<3>(6 * i + 3 * part);
        if (cd_[gi]) v = cd_[gi]->transpose() * v;
        for (int k = 0; k < 3; ++k) p_[dofs_.grid_dof(gi, 1 + 3 * part + k)] += v[k];
      }
    }
  }

  /// Forces of n grids (3 per grid, basic) into p in the grids' CD systems.
  void scatter_translations(const int* g, int n, const Eigen::Ref<const Eigen::VectorXd>& f) {
    for (int i = 0; i < n; ++i) {
      const std::uint32_t gi = m_.grid_index.at(g[i]);
      Eigen::Vector3d v = f.segment<3>(3 * i);
      if (cd_[gi]) v = cd_[gi]->transpose() * v;
      for (int k = 0; k < 3; ++k) p_[dofs_.grid_dof(gi, 1 + k)] += v[k];
    }
  }

  void scatter(int ga, int gb, const Eigen::Matrix<double, 12, 1>& f) {
    const int g[2] = {ga, gb};
    scatter(g, 2, f);
  }

  const Model& m_;
  const DofMap& dofs_;
  int sid_;
  std::vector<std::optional<Eigen::Matrix3d>> cd_;
  Eigen::VectorXd p_;
  std::optional<double> tempd_;
  std::unordered_map<std::uint32_t, double> grid_t_;
  std::unordered_map<int, const BarTemperature*> bar_t_;
};

}  // namespace

Eigen::VectorXd thermal_load_vector(const Model& model, const DofMap& dofs, int sid) {
  return ThermalLoads(model, dofs, sid).run();
}

}  // namespace seflex::fem
