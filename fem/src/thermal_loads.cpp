// Thermal loads of TEMP / TEMPD / TEMPRB sets on bars and rods (see loads.hpp).
#include <optional>
#include <unordered_map>

#include "model_lookup.hpp"
#include "seflex/common/error.hpp"
#include "seflex/fem/assembly.hpp"
#include "seflex/fem/element_bar.hpp"
#include "seflex/fem/element_rod.hpp"
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
        const char* card = r.inline_property ? "CONROD" : "CROD";
        T = 0.5 * (grid_temperature(r.ga, r.ref, card, r.id) + grid_temperature(r.gb, r.ref, card, r.id));
      }
      if (mat.alpha == 0.0 || T == mat.tref) continue;
      scatter(r.ga, r.gb, rod_thermal_load(e, mat.alpha, T - mat.tref));
    }
    for (const auto& [eid, t] : bar_t_)
      if (!used.count(eid))
        detail::fail(m_, t->ref, "TEMPRB", t->sid, "EID",
                     "element " + std::to_string(eid) + " is not a CBAR, CBEAM, CROD or CONROD; expected one of them");
    for (const Shell& s : m_.shells) shell_check(s);
    return p_;
  }

 private:
  const Mat1& mat1(int mid) const { return m_.mat1[m_.mat1_index.at(mid)]; }

  /// Temperature of grid id `g` in the set (TEMP, else TEMPD); throws naming the element if neither.
  double grid_temperature(int g, const CardRef& ref, const char* card, int eid) const {
    const std::uint32_t gi = detail::grid_index(m_, g, ref, card, eid, "G");
    if (const auto it = grid_t_.find(gi); it != grid_t_.end()) return it->second;
    if (tempd_) return *tempd_;
    detail::fail(m_, ref, card, eid, "",
                 "GRID " + std::to_string(g) + " has no temperature in thermal load set " + std::to_string(sid_) +
                     " (no TEMP card gives it, no TEMPD and no TEMPRB for the element); expected one of them");
  }

  /// Thermal loads of shells are not computed: a shell that would have one is an error.
  void shell_check(const Shell& s) const {
    const auto pit = m_.shell_prop_index.find(s.pid);
    if (pit == m_.shell_prop_index.end()) return;  // PCOMP or missing: checked by assembly
    const ShellProperty& p = m_.shell_props[pit->second];
    double alpha = 0, tref = 0;
    for (const int mid : {p.mid1, p.mid2}) {
      const auto mit = m_.mat1_index.find(mid);
      if (mit != m_.mat1_index.end() && m_.mat1[mit->second].alpha != 0.0) {
        alpha = m_.mat1[mit->second].alpha;
        tref = m_.mat1[mit->second].tref;
      }
    }
    if (alpha == 0.0) return;
    const char* card = s.nnode == 4 ? "CQUAD4" : "CTRIA3";
    for (int k = 0; k < s.nnode; ++k) {
      const std::uint32_t gi = detail::grid_index(m_, s.g[k], s.ref, card, s.id, "G");
      const auto it = grid_t_.find(gi);
      const std::optional<double> T = it != grid_t_.end() ? std::optional<double>(it->second) : tempd_;
      if (T && *T != tref)
        detail::fail(m_, s.ref, card, s.id, "",
                     "thermal load set " + std::to_string(sid_) +
                         " gives it a temperature other than its material's TREF, "
                         "and seflex does not compute thermal loads of shells (only of CBAR, CBEAM, CROD, CONROD)");
    }
  }

  void scatter(int ga, int gb, const Eigen::Matrix<double, 12, 1>& f) {
    const int g[2] = {ga, gb};
    for (int n = 0; n < 2; ++n) {
      const std::uint32_t gi = m_.grid_index.at(g[n]);
      for (int part = 0; part < 2; ++part) {
        Eigen::Vector3d v = f.segment<3>(6 * n + 3 * part);
        if (cd_[gi]) v = cd_[gi]->transpose() * v;
        for (int k = 0; k < 3; ++k) p_[dofs_.grid_dof(gi, 1 + 3 * part + k)] += v[k];
      }
    }
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
