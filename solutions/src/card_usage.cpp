// Which cards a solution uses (card_usage.hpp).
#include "seflex/solutions/card_usage.hpp"

#include <algorithm>
#include <cstdio>
#include <cstdlib>
#include <map>
#include <optional>
#include <set>
#include <tuple>

#include "card_usage_table.hpp"
#include "drilling_inertia.hpp"
#include "modelling_cautions.hpp"
#include "seflex/common/error.hpp"
#include "seflex/fem/components.hpp"
#include "seflex/fem/constraints.hpp"
#include "seflex/fem/dof_map.hpp"
#include "seflex/fem/finalize.hpp"

namespace seflex::solutions {
namespace {

using detail::CardRole;
using detail::Role;
using Kind = CardUse::Kind;
using Member = fem::UnsupportedCard::Member;

/// A case-control value without blanks around it, in upper case ("all " -> "ALL").
std::string upper_trimmed(const std::string& v) {
  std::string out;
  for (const char c : v)
    if (c != ' ') out += static_cast<char>(c >= 'a' && c <= 'z' ? c - 'a' + 'A' : c);
  return out;
}

bool runs(Solution s) {
  return s == Solution::Statics || s == Solution::NormalModes || s == Solution::Buckling || s == Solution::CraigBampton;
}

std::string ids_text(const std::set<int>& ids) {
  std::string s;
  std::size_t k = 0;
  for (const int id : ids) {
    if (k == 6) {
      s += ", ...";
      break;
    }
    s += (k++ ? ", " : "") + std::to_string(id);
  }
  return s;
}

/// Collects entries keyed by (kind, card, reason), counting cards and keeping the first location.
class Report {
 public:
  void add(Kind kind, const std::string& card, const fem::CardRef& ref, const std::string& reason, std::size_t count = 1) {
    const auto key = std::make_tuple(kind, card, reason);
    auto it = index_.find(key);
    if (it == index_.end()) {
      last_ = uses_.size();
      index_.emplace(key, uses_.size());
      uses_.push_back({kind, card, count, ref, reason});
      return;
    }
    last_ = it->second;
    CardUse& u = uses_[it->second];
    u.count += count;
    if (std::tie(ref.file, ref.line) < std::tie(u.first.file, u.first.line)) u.first = ref;
  }
  /// The entry add() made or added to last is about cards seflex does not know.
  void mark_unknown() { uses_[last_].unknown_card = true; }
  /// An entry about set `sid`: entries with the same (kind, card, before, after) are merged, their
  /// set ids listed between `before` and `after` ("load sets 5, 7 not selected ...").
  void add_set(Kind kind, const std::string& card, const fem::CardRef& ref, const std::string& before, int sid,
               const std::string& after) {
    const auto key = std::make_tuple(kind, card, before + '\x1f' + after);
    auto it = sets_.find(key);
    if (it == sets_.end()) it = sets_.emplace(key, SetEntry{{}, 0, ref, before, after}).first;
    SetEntry& e = it->second;
    e.ids.insert(sid);
    ++e.count;
    if (std::tie(ref.file, ref.line) < std::tie(e.first.file, e.first.line)) e.first = ref;
  }
  std::vector<CardUse> take() {
    for (const auto& [key, e] : sets_) {
      const std::string plural = e.ids.size() > 1 ? "s " : " ";
      add(std::get<0>(key), std::get<1>(key), e.first, e.before + plural + ids_text(e.ids) + e.after, e.count);
    }
    sets_.clear();
    std::stable_sort(uses_.begin(), uses_.end(), [](const CardUse& a, const CardUse& b) {
      return std::tie(b.kind, a.first.file, a.first.line) < std::tie(a.kind, b.first.file, b.first.line);
    });
    return std::move(uses_);
  }

 private:
  struct SetEntry {
    std::set<int> ids;
    std::size_t count = 0;
    fem::CardRef first;
    std::string before, after;
  };
  std::vector<CardUse> uses_;
  std::size_t last_ = 0;
  std::map<std::tuple<Kind, std::string, std::string>, std::size_t> index_;
  std::map<std::tuple<Kind, std::string, std::string>, SetEntry> sets_;
};

class Classifier {
 public:
  Classifier(const fem::Model& m, Solution s, const std::vector<CaseSelection>& cases, unsigned interface,
             bool ignore_unknown)
      : m_(m), s_(s), cases_(cases), interface_(interface), ignore_unknown_(ignore_unknown) {}

  std::vector<CardUse> run() {
    if (!runs(s_)) {  // info without a SOL seflex runs, convert: what seflex does not model
      unsupported();
      notes();
      cautions();
      return report_.take();
    }
    collect_sets();
    sol_mismatch();
    selections();
    loads();
    spc_sets();
    mpc_sets();
    methods();
    dof_sets();
    dmigs();
    params();
    unsupported();
    notes();
    cautions();
    return report_.take();
  }

 private:
  bool uses_loads() const { return s_ == Solution::Statics || s_ == Solution::Buckling; }
  bool uses_methods() const { return s_ == Solution::NormalModes || s_ == Solution::Buckling; }
  const char* sol() const { return solution_name(s_); }
  std::string where_file() const { return m_.files.empty() ? std::string() : m_.files.front(); }

  /// Unused set `sid` of `card` ("SPC set"): not selected, or not used at all by this solution.
  void not_selected(const std::string& card, const char* what, int sid, const fem::CardRef& ref) {
    report_.add_set(Kind::Unused, card, ref, what, sid,
                    runs(s_) ? std::string(" not selected by the case control of ") + sol()
                             : std::string(": not used by ") + sol());
  }

  // ------------------------------------------------------------------------------------------
  void collect_sets() {
    for (const auto& l : m_.load_combinations) load_combos_.emplace(l.sid, &l);
    for (const auto& e : m_.spcs) spc_defined_.insert(e.sid);
    for (const auto& a : m_.spcadds) spc_defined_.insert(a.sid);
    for (const auto& e : m_.mpcs) mpc_defined_.insert(e.sid);
    for (const auto& a : m_.mpcadds) mpc_defined_.insert(a.sid);
    // load set ids of every load card, supported or not
    for (const CardRole* r : detail::supported_set_cards()) {
      std::vector<Member> members;
      r->members(m_, members);
      std::set<int>& defined = r->role == Role::TemperatureLoad ? temp_defined_ : load_defined_;
      for (const Member& mb : members) defined.insert(mb.sid);
      if (r->role == Role::Load) supported_loads_.emplace_back(r, std::move(members));
      if (r->role == Role::TemperatureLoad) supported_temps_.emplace_back(r, std::move(members));
    }
    for (const auto& u : m_.unsupported) {
      const CardRole* r = detail::find_card_role(u.name);
      if (r && r->role == Role::Load)
        for (const Member& mb : u.members) load_defined_.insert(mb.sid);
      if (r && r->role == Role::TemperatureLoad)
        for (const Member& mb : u.members) temp_defined_.insert(mb.sid);
    }
    for (const auto& l : m_.load_combinations) load_defined_.insert(l.sid);
    if (!runs(s_)) return;
    for (const CaseSelection& c : cases_) {
      if (c.spc) used_spc_.merge(fem::expand_sets(*c.spc, m_.spcadds));
      if (c.mpc) used_mpc_.merge(fem::expand_sets(*c.mpc, m_.mpcadds));
      if (uses_loads() && c.load) {
        used_load_.insert(*c.load);
        if (const auto it = load_combos_.find(*c.load); it != load_combos_.end())
          for (const auto& [si, li] : it->second->terms) used_load_.insert(li);
      }
      if (uses_methods() && c.method) used_method_.insert(*c.method);
      if (s_ == Solution::Statics && c.temperature) used_temp_.insert(*c.temperature);
    }
  }

  /// A deck written for another solution (seflex static on a SOL 103 deck): said, not refused.
  void sol_mismatch() {
    if (s_ == Solution::CraigBampton || !m_.case_control.sol) return;
    const Solution deck = solution_of_deck(m_);
    if (deck == s_) return;
    report_.add(Kind::Unused, "executive control SOL", {0, 0},
                "the deck asks for " + (deck == Solution::Info ? "SOL " + *m_.case_control.sol : std::string(solution_name(deck))) +
                    "; " + sol() + " runs on it as asked");
  }

  // ------------------------------------------------------------------------------------------
  /// The case-control selections of the subcases the solution runs.
  void selections() {
    if (!runs(s_)) return;
    for (const CaseSelection& c : cases_) {
      const std::string in = case_name(c);
      const fem::CardRef at = c.ref;
      if (uses_loads() && c.load) {
        if (!load_defined_.count(*c.load))
          report_.add(Kind::Refused, "case control LOAD", at,
                      in + ": LOAD = " + std::to_string(*c.load) +
                          " selects no load card (no LOAD, FORCE, MOMENT, PLOAD2, "
                          "GRAV, RFORCE or other load card has that SID)");
        else if (const auto it = load_combos_.find(*c.load); it != load_combos_.end())
          for (const auto& [si, li] : it->second->terms)
            if (!load_defined_.count(li))
              report_.add(Kind::Refused, "LOAD", it->second->ref,
                          "LOAD " + std::to_string(*c.load) + " (selected by " + in + ") references load set " +
                              std::to_string(li) + ", which no load card defines");
      }
      if (s_ == Solution::Statics && !c.load && !c.temperature && !enforced_displacement(c))
        report_.add(Kind::Unused, "case control LOAD", at,
                    in + " selects no LOAD, no TEMPERATURE(LOAD) and no enforced displacement (SPC D): its "
                         "displacements are zero");
      if (c.temperature) temperature_selection(c);
      if (c.spc && !spc_defined_.count(*c.spc))
        report_.add(Kind::Refused, "case control SPC", at,
                    in + ": SPC = " + std::to_string(*c.spc) + " selects no SPC, SPC1 or SPCADD card");
      if (c.mpc && !mpc_defined_.count(*c.mpc))
        report_.add(Kind::Refused, "case control MPC", at,
                    in + ": MPC = " + std::to_string(*c.mpc) + " selects no MPC or MPCADD card");
      if (uses_methods() && c.method) {
        bool found = false;
        for (const auto& e : m_.eigen_methods) found = found || e.sid == *c.method;
        for (const auto& u : m_.unsupported)
          if (const CardRole* r = detail::find_card_role(u.name); r && r->role == Role::BucklingMethod)
            for (const Member& mb : u.members)
              if (mb.sid == *c.method) {
                found = true;
                if (s_ == Solution::Buckling)
                  report_.add(Kind::Refused, u.name, mb.ref,
                              "METHOD = " + std::to_string(*c.method) + " of " + in + " selects it; seflex does not read " + u.name);
              }
        if (!found)
          report_.add(Kind::Refused, "case control METHOD", at,
                      in + ": METHOD = " + std::to_string(*c.method) +
                          (s_ == Solution::Buckling ? " selects no EIGRL, EIGR or EIGB card" : " selects no EIGRL or EIGR card"));
      }
      if (c.suport1) suport1_selection(c);
      for (const fem::CaseCommand& cmd : c.other) command(c, cmd);
    }
  }

  /// SUPORT1 = SID of a subcase: statics holds its supports as it holds SUPORT's (statics.hpp);
  /// buckling refuses it; normal modes and reductions do not use it.
  void suport1_selection(const CaseSelection& c) {
    const std::string what = case_name(c) + ": SUPORT1 = " + std::to_string(*c.suport1);
    if (s_ == Solution::Buckling)
      return report_.add(Kind::Refused, "case control SUPORT1", c.ref,
                         what + " selects supports (SUPORT1), which seflex does not apply in buckling");
    if (s_ != Solution::Statics)
      return report_.add(Kind::Unused, "case control SUPORT1", c.ref,
                         what + ": not used by " + std::string(sol()) +
                             " (rigid-body modes come out of the eigensolution directly)");
    bool found = false;
    for (const auto& e : m_.suport1) found = found || e.sid == *c.suport1;
    if (!found) report_.add(Kind::Refused, "case control SUPORT1", c.ref, what + " selects no SUPORT1 card");
  }

  /// TEMPERATURE(LOAD) of a subcase: applied by statics (bars, rods, shells, solids), refused by
  /// buckling, unused by the others; shells whose thermal load is not computed are refused.
  void temperature_selection(const CaseSelection& c) {
    const std::string in = case_name(c);
    const std::string what = in + ": TEMPERATURE(LOAD) = " + std::to_string(*c.temperature);
    if (s_ == Solution::Buckling)
      return report_.add(Kind::Refused, "case control TEMPERATURE(LOAD)", c.ref,
                         what + " selects thermal loads, which seflex does not apply in buckling");
    if (s_ != Solution::Statics)
      return report_.add(Kind::Unused, "case control TEMPERATURE(LOAD)", c.ref,
                         what + ": temperatures are not used by " + std::string(sol()));
    if (!temp_defined_.count(*c.temperature))
      return report_.add(Kind::Refused, "case control TEMPERATURE(LOAD)", c.ref,
                         what + " selects no TEMP, TEMPD or TEMPRB card");
    heated_shells(*c.temperature);
  }

  /// Thermal expansion coefficient of material `mid` (MAT1, MAT2 or MAT8) is not zero.
  bool expands(int mid) const {
    if (const auto it = m_.mat1_index.find(mid); it != m_.mat1_index.end()) return m_.mat1[it->second].alpha != 0.0;
    if (const auto it = m_.mat2_index.find(mid); it != m_.mat2_index.end()) {
      const fem::Mat2& m = m_.mat2[it->second];
      return m.a1 != 0.0 || m.a2 != 0.0 || m.a3 != 0.0;
    }
    if (const auto it = m_.mat8_index.find(mid); it != m_.mat8_index.end())
      return m_.mat8[it->second].a1 != 0.0 || m_.mat8[it->second].a2 != 0.0;
    return false;
  }

  /// Shells of a PSHELL whose MID4 (membrane-bending coupling) has thermal expansion and that
  /// thermal load set `sid` gives a temperature: the thermal moment of MID4 is not computed
  /// (fem::thermal_load_vector computes every other shell, bar, rod and solid; an element type
  /// added later with a thermal expansion coefficient belongs here until its thermal load is).
  void heated_shells(int sid) {
    std::optional<double> tempd;
    std::set<int> grid_t;
    for (const auto& t : m_.default_temperatures)
      if (t.sid == sid) tempd = t.t;
    for (const auto& t : m_.grid_temperatures)
      if (t.sid == sid) grid_t.insert(t.grid);
    for (const auto& sh : m_.shells) {
      const auto pit = m_.shell_prop_index.find(sh.pid);
      if (pit == m_.shell_prop_index.end() || m_.shell_props[pit->second].mid4 <= 0) continue;
      if (!expands(m_.shell_props[pit->second].mid4)) continue;
      bool heated = tempd.has_value();
      for (int k = 0; k < sh.nnode; ++k) heated = heated || grid_t.count(sh.g[k]) > 0;
      if (heated)
        report_.add_set(Kind::Refused, fem::shell_card(sh), sh.ref, "thermal load set", sid,
                        " gives a temperature to shells whose PSHELL MID4 (membrane-bending coupling) has thermal "
                        "expansion, and seflex does not compute the thermal moment of MID4");
    }
  }

  bool enforced_displacement(const CaseSelection& c) const {
    if (!c.spc) return false;
    const std::set<int> sets = fem::expand_sets(*c.spc, m_.spcadds);
    for (const auto& e : m_.spcs)
      if (sets.count(e.sid) && e.d != 0.0) return true;
    return false;
  }

  void command(const CaseSelection& c, const fem::CaseCommand& cmd) {
    const std::string card = "case control " + cmd.name;
    const std::string what = case_name(c) + ": " + cmd.name + " = " + cmd.value;
    const std::string& n = cmd.name;
    if (s_ == Solution::Statics || s_ == Solution::Buckling) {
      if (n == "DEFORM")
        return report_.add(Kind::Refused, card, cmd.ref, what + " selects enforced element deformations (DEFORM), which seflex does not apply");
      if (n == "SUPORT1")  // case_selection took every SUPORT1 = SID
        return report_.add(Kind::Refused, card, cmd.ref, what + ": expected the set id of SUPORT1 cards (an integer > 0)");
      if (n == "P2G")
        return report_.add(Kind::Refused, card, cmd.ref, what + " selects direct load matrices (P2G), which seflex does not apply");
    }
    if ((n == "SUPER" || n == "SEALL") && upper_trimmed(cmd.value) == "ALL")
      return report_.add(Kind::Unused, card, cmd.ref,
                         what + ": every part superelement is merged into one model and solved in full (exact, where "
                                "Nastran reduces each part to its boundary)");
    if (n == "BC" || n == "AXISYMMETRIC" || n == "HARMONICS" || n == "SUPER" || n == "SEALL")
      return report_.add(runs(s_) ? Kind::Refused : Kind::Unused, card, cmd.ref,
                         what + ": seflex does not model " + n + " (multiple boundary conditions, axisymmetric or superelement runs)");
    if (n.rfind("TEMPERATURE(INIT", 0) == 0 && s_ == Solution::Statics)
      return report_.add(Kind::Unused, card, cmd.ref,
                         what +
                             ": thermal strains are measured from each material's TREF (MAT1), not from an initial "
                             "temperature set");
    if (n.rfind("TEMPERATURE", 0) == 0)
      return report_.add(Kind::Unused, card, cmd.ref,
                         what + ": not used by " + std::string(sol()) + " (no temperature-dependent materials)");
    if (s_ == Solution::Buckling && (n == "STATSUB" || n.rfind("STATSUB(", 0) == 0)) return;  // the preload subcase: used
    report_.add(Kind::Unused, card, cmd.ref, what + ": not used by " + std::string(sol()));
  }

  // ------------------------------------------------------------------------------------------
  void loads() {
    for (const auto& [role, members] : supported_loads_) {
      for (const Member& mb : members) {
        if (uses_loads() && used_load_.count(mb.sid)) continue;
        unused_load(std::string(role->name), mb.sid, mb.ref);
      }
    }
    // FORCE / MOMENT (and FORCE1/2, MOMENT1/2) references (checked where the set is applied when selected)
    for (const auto& l : m_.point_loads) {
      const char* card = fem::point_load_card(l);
      const bool used = uses_loads() && used_load_.count(l.sid);
      const int n_dir = l.direction == fem::PointLoad::Direction::Vector ? 0 : l.direction == fem::PointLoad::Direction::TwoGrids ? 2 : 4;
      for (int k = -1; k < n_dir; ++k) {
        const int g = k < 0 ? l.grid : l.g[static_cast<std::size_t>(k)];
        if (!m_.grid_index.count(g))
          report_.add(used ? Kind::Refused : Kind::Unused, card, l.ref,
                      "load set " + std::to_string(l.sid) + ": references grid " + std::to_string(g) +
                          ", which is not defined" + (used ? "" : " (the set is not used)"));
      }
      if (l.cid != 0 && !m_.coord_index.count(l.cid))
        report_.add(used ? Kind::Refused : Kind::Unused, card, l.ref,
                    "load set " + std::to_string(l.sid) + ": references coordinate system " + std::to_string(l.cid) +
                        ", which is not defined" + (used ? "" : " (the set is not used)"));
    }
    for (const auto& [role, members] : supported_temps_)
      for (const Member& mb : members)
        if (!used_temp_.count(mb.sid)) unused_temperature(std::string(role->name), mb.sid, mb.ref);
    for (const auto& l : m_.load_combinations) {
      const bool used = uses_loads() && used_load_.count(l.sid);
      if (!used) unused_load("LOAD", l.sid, l.ref);
      if (!used)
        for (const auto& [si, li] : l.terms)
          if (!load_defined_.count(li))
            report_.add(Kind::Unused, "LOAD", l.ref,
                        "LOAD " + std::to_string(l.sid) + " references load set " + std::to_string(li) +
                            ", which no load card defines (the LOAD is not used)");
    }
  }

  void unused_temperature(const std::string& card, int sid, const fem::CardRef& ref) {
    if (s_ != Solution::Statics)
      report_.add(Kind::Unused, card, ref, std::string("temperatures are not used by ") + sol());
    else
      report_.add_set(Kind::Unused, card, ref, "thermal load set", sid,
                      std::string(" not selected by TEMPERATURE(LOAD) of any subcase ") + sol() + " runs");
  }

  void unused_load(const std::string& card, int sid, const fem::CardRef& ref) {
    if (!uses_loads())
      report_.add(Kind::Unused, card, ref, std::string("loads are not used by ") + sol());
    else
      report_.add_set(Kind::Unused, card, ref, "load set", sid, std::string(" not selected by any subcase ") + sol() + " runs");
  }

  // ------------------------------------------------------------------------------------------
  void spc_sets() {
    const bool uses = runs(s_);
    std::set<int> reported;
    for (const auto& e : m_.spcs) {
      const bool used = uses && used_spc_.count(e.sid);
      const bool grid = m_.grid_index.count(e.grid) > 0, spoint = m_.spoint_index.count(e.grid) > 0;
      if (!grid && !spoint) {
        if (e.from_thru)
          report_.add(used ? Kind::Approximated : Kind::Unused, "SPC1", e.ref,
                      "SPC set " + std::to_string(e.sid) + ": grids of a THRU range that do not exist are skipped (QRG SPC1)");
        else
          report_.add(used ? Kind::Refused : Kind::Unused, "SPC/SPC1", e.ref,
                      "SPC set " + std::to_string(e.sid) + ": references point " + std::to_string(e.grid) +
                          ", which is not defined" + (used ? "" : " (the set is not used)"));
      }
      if (!used) not_selected("SPC/SPC1", "SPC set", e.sid, e.ref);
    }
    combinations("SPCADD", "SPC set", m_.spcadds, spc_defined_, used_spc_);
  }

  /// SPCADD / MPCADD: sets they combine that no card defines, and combinations not selected.
  void combinations(const char* card, const char* kind, const std::vector<fem::SetCombination>& all,
                    const std::set<int>& defined, const std::set<int>& used_sets) {
    for (const auto& a : all) {
      const bool used = runs(s_) && used_sets.count(a.sid);
      for (const int t : a.sets)
        if (!defined.count(t))
          report_.add(used ? Kind::Refused : Kind::Unused, card, a.ref,
                      std::string(card) + " " + std::to_string(a.sid) + " references " + kind + " " + std::to_string(t) +
                          ", which no card defines");
      if (!used) not_selected(card, kind, a.sid, a.ref);
    }
  }

  void mpc_sets() {
    const bool uses = runs(s_);
    for (const auto& e : m_.mpcs) {
      const bool used = uses && used_mpc_.count(e.sid);
      for (const auto& t : e.terms) {
        const bool grid = m_.grid_index.count(t.grid) > 0, spoint = m_.spoint_index.count(t.grid) > 0;
        if ((!grid && !spoint) || (grid && t.component == 0) || (spoint && t.component > 1))
          report_.add(used ? Kind::Refused : Kind::Unused, "MPC", e.ref,
                      "MPC set " + std::to_string(e.sid) + ": references point " + std::to_string(t.grid) + " component " +
                          std::to_string(t.component) + ", which is not a dof of the model" + (used ? "" : " (the set is not used)"));
      }
      if (!used) not_selected("MPC", "MPC set", e.sid, e.ref);
    }
    combinations("MPCADD", "MPC set", m_.mpcadds, mpc_defined_, used_mpc_);
  }

  void methods() {
    for (const auto& e : m_.eigen_methods) {
      const char* card = fem::method_card(e);
      const bool used = uses_methods() && used_method_.count(e.sid);
      if (used && e.is_eigb && s_ == Solution::NormalModes)
        report_.add(Kind::Refused, card, e.ref,
                    "METHOD = " + std::to_string(e.sid) + " selects EIGB, a buckling method; normal modes need an EIGRL or EIGR");
      if (e.norm == "POINT" && !fem::find_dof(m_, fem::make_dof_map(m_), e.norm_grid, e.norm_component))
        report_.add(used ? Kind::Approximated : Kind::Unused, card, e.ref,
                    "NORM = POINT names grid " + std::to_string(e.norm_grid) + " component " + std::to_string(e.norm_component) +
                        ", which is not a dof of the model" +
                        (used ? ": the modes are normalised to a largest component of 1 (MAX) instead; eigenvalues are not affected"
                              : " (the method is not selected)"));
      if (used) continue;
      if (s_ == Solution::CraigBampton)
        report_.add(Kind::Unused, card, e.ref, "seflex reduce takes the number of modes from --modes or --fmax, not METHOD");
      else if (uses_methods())
        report_.add_set(Kind::Unused, card, e.ref, "method", e.sid, " not selected by METHOD");
      else
        report_.add(Kind::Unused, card, e.ref, std::string("eigenvalue methods are not used by ") + sol());
    }
  }

  void dof_sets() {
    if (!runs(s_)) return;
    const bool cb = s_ == Solution::CraigBampton;
    for (const auto& e : m_.aset)
      if ((cb && !(interface_ & kInterfaceAset)) || s_ == Solution::Buckling)
        report_.add(Kind::Unused, "ASET/ASET1", e.ref,
                    cb ? "the interface is given by --interface; no Guyan reduction of the interior"
                       : "static condensation to the a-set is not done in buckling");
    for (const auto& e : m_.omit)
      if (cb || s_ == Solution::Buckling)
        report_.add(Kind::Unused, "OMIT/OMIT1", e.ref,
                    cb ? "the interface is given by --interface; no Guyan reduction of the interior"
                       : "static condensation to the a-set is not done in buckling");
    for (const auto& e : m_.bset)
      if (!(cb && (interface_ & kInterfaceBset)))
        report_.add(Kind::Unused, "BSET/BSET1", e.ref,
                    cb ? "the interface is given by --interface" : "b-set: a superelement interface, used by seflex reduce --interface bset");
    for (const auto& e : m_.suport) {
      if (s_ == Solution::Statics) continue;  // held, as Nastran's SOL 101 without inertia relief
      if (cb && (interface_ & kInterfaceSuport)) continue;
      report_.add(Kind::Unused, "SUPORT", e.ref,
                  cb ? "the interface is given by --interface"
                     : "rigid-body modes come out of the eigensolution directly (the same eigenvalues as Nastran's "
                       "r-set partition when the SUPORT is statically determinate)");
    }
    std::set<int> selected;
    for (const CaseSelection& c : cases_)
      if (c.suport1) selected.insert(*c.suport1);
    for (const auto& e : m_.suport1)
      if (s_ != Solution::Statics)
        report_.add(Kind::Unused, "SUPORT1", e.dofs.ref, std::string("supports of statics: not used by ") + sol());
      else if (!selected.count(e.sid))
        not_selected("SUPORT1", "SUPORT1 set", e.sid, e.dofs.ref);
  }

  void dmigs() {
    if (m_.dmigs.empty()) return;
    std::set<std::string> used;
    if (runs(s_))
      for (const CaseSelection& c : cases_) {
        const fem::Subcase* sc = &m_.case_control.global;
        for (const auto& s : m_.case_control.subcases)
          if (s.id == c.subcase_id) sc = &s;
        for (const auto& n : sc->k2gg) used.insert(n);
        for (const auto& n : sc->m2gg) used.insert(n);
      }
    for (const auto& d : m_.dmigs)
      if (!used.count(d.name))
        report_.add(Kind::Unused, "DMIG", d.ref, "matrix " + d.name + " not selected by K2GG or M2GG");
  }

  void params() {
    static const std::set<std::string> kUsed = {"WTMASS", "COUPMASS", "K6ROT", "GRDPNT", "AUTOSPC"};
    std::string names;
    std::size_t count = 0;
    fem::CardRef first{~0u, ~0u};
    std::set<std::string> seen;
    for (const auto& p : m_.params) {
      if (p.name == "INREL" && !p.values.empty() && (p.values[0] == "-1" || p.values[0] == "-2") &&
          (s_ == Solution::Statics || s_ == Solution::Buckling)) {
        report_.add(Kind::Refused, "PARAM INREL", p.ref, "inertia relief (INREL = " + p.values[0] + ") is not supported");
        continue;
      }
      if (p.name == "GRDPNT" && !p.values.empty() && p.values[0] != "0" && p.values[0] != "-1" &&
          !m_.grid_index.count(std::atoi(p.values[0].c_str())))
        report_.add(Kind::Unused, "PARAM GRDPNT", p.ref,
                    "grid " + p.values[0] + " is not defined; the mass properties (seflex info) use the basic origin, as Nastran does");
      if (kUsed.count(p.name) || p.name == "QUAD4TYP") continue;
      // the shear factors of MYSTRAN's plate elements, used with QUAD4TYP MIN4T only
      if ((p.name == "CBMIN3" || p.name == "CBMIN4T") && fem::mystran_plate_elements(m_)) continue;
      ++count;
      if (std::tie(p.ref.file, p.ref.line) < std::tie(first.file, first.line)) first = p.ref;
      if (seen.insert(p.name).second && seen.size() <= 12) names += (seen.size() > 1 ? ", " : "") + p.name;
    }
    if (count == 0) return;
    if (seen.size() > 12) names += ", ...";
    report_.add(Kind::Unused, "PARAM", first, "parameters seflex does not use: " + names, count);
  }

  // ------------------------------------------------------------------------------------------
  /// The table's row, or for an element or property fem::finalize left out ("CHEXA on PCOMPS (left
  /// out)") a structural card seflex does not model.
  static const CardRole* role_of(const std::string& name) {
    static const CardRole kLeftOut{"", Role::Structure, false, nullptr};
    static const std::string kSuffix = " (left out)";
    static const std::string kPart = "part superelement: ";  // a part's card fem::assemble_parts does not merge
    if (name.size() > kSuffix.size() && name.compare(name.size() - kSuffix.size(), kSuffix.size(), kSuffix) == 0)
      return &kLeftOut;
    if (name.compare(0, kPart.size(), kPart) == 0) return &kLeftOut;
    return detail::find_card_role(name);
  }

  void unsupported() {
    for (const auto& u : m_.unsupported) {
      const CardRole* r = role_of(u.name);
      if (r == nullptr && u.name.find(' ') != std::string::npos) continue;  // a feature note (notes())
      if (s_ == Solution::Convert) {
        report_.add(Kind::Unused, u.name, u.first, "not written: seflex does not model it", u.count);
        continue;
      }
      if (detail::is_unknown_card(u.name)) {
        unknown_card(u);
        continue;
      }
      if (r == nullptr) {  // a line of punctuation ('&'): the reader's note, not a card
        report_.add(Kind::Unused, u.name, u.first, "a line of punctuation, not a card; ignored", u.count);
        continue;
      }
      switch (r->role) {
        case Role::Load: load_cards(u); break;
        case Role::TemperatureLoad:
          temperature_cards(u);
          break;
        case Role::Geometry:
        case Role::Structure:
          if (s_ == Solution::Convert)
            report_.add(Kind::Unused, u.name, u.first, "not written: seflex does not model it", u.count);
          else if (runs(s_))
            report_.add(Kind::Refused, u.name, u.first,
                        "seflex does not model " + u.name + " (" + sol() + " needs every element, property and material of the structure)",
                        u.count);
          else
            report_.add(Kind::Unused, u.name, u.first, "seflex does not model it: a solution would refuse the deck", u.count);
          break;
        case Role::Superelement:
          report_.add(runs(s_) ? Kind::Refused : Kind::Unused, u.name, u.first,
                      "superelement partitioning of the bulk data is not supported", u.count);
          break;
        case Role::SpcSet:
        case Role::MpcSet:
          report_.add(runs(s_) && s_ != Solution::Convert ? Kind::Refused : Kind::Unused, u.name, u.first,
                      "axisymmetric constraints are not supported", u.count);
          break;
        default: report_.add(Kind::Unused, u.name, u.first, role_phrase(r->role), u.count); break;
      }
    }
  }

  /// A card seflex does not know: a solution refuses the deck unless asked to go on without it.
  void unknown_card(const fem::UnsupportedCard& u) {
    if (runs(s_) && !ignore_unknown_)
      report_.add(Kind::Refused, u.name, u.first, "a card seflex does not know", u.count);
    else if (runs(s_))
      report_.add(Kind::Unused, u.name, u.first, "a card seflex does not know; ignored (--ignore-unknown)", u.count);
    else
      report_.add(Kind::Unused, u.name, u.first,
                  "a card seflex does not know: static, modes, buckling and reduce refuse the deck (--ignore-unknown "
                  "runs them without it)",
                  u.count);
    report_.mark_unknown();
  }

  void temperature_cards(const fem::UnsupportedCard& u) {
    std::size_t counted = 0;
    for (const Member& mb : u.members) {
      ++counted;
      if (used_temp_.count(mb.sid))
        report_.add_set(
            Kind::Refused, u.name, mb.ref, "thermal load set", mb.sid,
            " selected by TEMPERATURE(LOAD) holds them, and seflex does not apply " + u.name + " temperatures");
      else
        unused_temperature(u.name, mb.sid, mb.ref);
    }
    if (counted < u.count)
      report_.add(Kind::Unused, u.name, u.first, "cards without a set id in field 2; not used", u.count - counted);
  }

  void load_cards(const fem::UnsupportedCard& u) {
    std::size_t counted = 0;
    for (const Member& mb : u.members) {
      ++counted;
      if (uses_loads() && used_load_.count(mb.sid))
        report_.add_set(Kind::Refused, u.name, mb.ref, "load set", mb.sid,
                        " selected by the case control holds them, and seflex does not apply " + u.name + " loads");
      else
        unused_load(u.name, mb.sid, mb.ref);
    }
    if (counted < u.count)
      report_.add(Kind::Unused, u.name, u.first, "cards without a set id in field 2; not used", u.count - counted);
  }

  std::string role_phrase(Role r) const {
    const std::string by = std::string(" by ") + sol();
    switch (r) {
      case Role::Damping: return "damping is not used" + by;
      case Role::Nonlinear: return "nonlinear material and property data are not used" + by;
      case Role::TempMaterial: return "temperature-dependent material data are not used" + by;
      case Role::Bset: return "c-set/q-set (component modes of superelements) are not used" + by;
      case Role::BucklingMethod:
        return s_ == Solution::Buckling ? "buckling method not selected by METHOD" : "buckling methods are not used" + by;
      case Role::ComplexMethod: return "complex eigenvalue methods are not used" + by;
      case Role::Dynamics: return "dynamic-response data are not used" + by;
      case Role::OtherMatrix: return "direct matrix input other than DMIG (K2GG/M2GG) is not used" + by;
      case Role::Output: return "output requests: seflex writes its own results";
      case Role::Optimization: return "design optimisation data are not used" + by;
      case Role::Aero: return "aeroelastic data are not used" + by;
      case Role::Heat: return "heat-transfer data are not used" + by;
      case Role::Contact: return "contact is not modelled" + by;
      case Role::Solver: return "another solver's control or numbering card; not used" + by;
      default: return "not used" + by;
    }
  }

  /// Features of supported cards that seflex reads with an approximation (reader notes) and rigid-
  /// element fields it ignores.
  void notes() {
    const Kind k = runs(s_) ? Kind::Approximated : Kind::Unused;
    for (const auto& u : m_.unsupported)
      if (u.name.find(' ') != std::string::npos && role_of(u.name) == nullptr)
        report_.add(k, u.name, u.first, "read with the approximation stated", u.count);
    auto alpha = [&](const char* card, double value, const fem::CardRef& ref) {
      if (value != 0.0)
        report_.add(k, std::string(card) + " ALPHA", ref,
                    "thermal expansion coefficient of the element: read, not used (rigid elements do not expand)");
    };
    for (const auto& r : m_.rbe3) alpha("RBE3", r.has_alpha ? r.alpha : 0.0, r.ref);
    for (const auto& r : m_.rbars) alpha("RBAR", r.alpha, r.ref);
    for (const auto& r : m_.rigid_bodies) alpha(fem::rigid_body_card(r), r.alpha, r.ref);
    for (const auto& r : m_.rigid_rods) alpha(fem::rigid_rod_card(r), r.alpha, r.ref);
    if (s_ == Solution::Convert)
      for (const auto& x : m_.external_parts)
        report_.add(Kind::Unused, "SEBULK EXTOP4", x.ref,
                    "not written: the external superelement's matrices (" + x.source + ") stay in its OP4 file", 1);
    drilling();
  }

  /// What the deck asks for and seflex computes as written, with a consequence to be told
  /// (modelling_cautions.hpp): in every solution that builds the structure (and seflex info), bars
  /// without torsional stiffness and thick plates; in statics and buckling, the RFORCE cards of
  /// the load sets the subcases select.
  void cautions() {
    if (!runs(s_) && s_ != Solution::Info) return;
    std::vector<detail::Caution> found = detail::torsionless_bars(m_, s_ == Solution::Buckling);
    for (auto& c : detail::thick_shells(m_)) found.push_back(std::move(c));
    if (uses_loads())
      for (auto& c : detail::rforce_units(m_, used_load_)) found.push_back(std::move(c));
    for (const auto& c : found) report_.add(Kind::Caution, c.card, c.first, c.reason, c.count);
  }

  /// CONM2 rotary inertia about a flat shell's normal that only the drilling penalty holds: spurious
  /// modes in every solution that uses mass unless K6ROT is large (1e4 and up leaves a flat shell's
  /// other modes unchanged: docs/fem.md, "Shell sections").
  void drilling() {
    if (s_ != Solution::NormalModes && s_ != Solution::CraigBampton && s_ != Solution::Info) return;
    const double k6rot = fem::param_number(m_, "K6ROT");
    if (k6rot >= 1e4) return;
    const detail::DrillingInertia d = detail::drilling_inertia(m_);
    if (d.count == 0) return;
    char buf[96];
    std::snprintf(buf, sizeof buf, "%.4g", d.first_inertia);
    char k6[32];
    std::snprintf(k6, sizeof k6, "%g", k6rot);
    report_.add(Kind::Approximated, "CONM2", d.first,
                "rotary inertia about the normal of the flat shells at grid " + std::to_string(d.first_grid) + " (" + buf +
                    ") rests on the drilling penalty alone (PARAM K6ROT = " + k6 +
                    "): it makes spurious low modes; set PARAM K6ROT to 1e4 or more, or leave that inertia out",
                d.count);
  }

  const fem::Model& m_;
  Solution s_;
  const std::vector<CaseSelection>& cases_;
  unsigned interface_;
  bool ignore_unknown_;
  Report report_;
  std::multimap<int, const fem::LoadCombination*> load_combos_;
  std::set<int> spc_defined_, mpc_defined_, load_defined_, temp_defined_;
  std::set<int> used_spc_, used_mpc_, used_load_, used_method_, used_temp_;
  std::vector<std::pair<const CardRole*, std::vector<Member>>> supported_loads_, supported_temps_;
};

}  // namespace

Solution solution_of_deck(const fem::Model& model) {
  if (!model.case_control.sol) return Solution::Info;
  const std::string& s = *model.case_control.sol;
  if (s == "101" || s == "1" || s == "STATIC" || s == "STATICS" || s == "SESTATIC" || s == "SESTATICS") return Solution::Statics;
  if (s == "103" || s == "3" || s == "MODES" || s == "SEMODES") return Solution::NormalModes;
  if (s == "105" || s == "5" || s == "BUCKLING" || s == "SEBUCKL") return Solution::Buckling;
  return Solution::Info;
}

const char* solution_name(Solution s) {
  switch (s) {
    case Solution::Info: return "seflex info";
    case Solution::Statics: return "linear statics (SOL 101)";
    case Solution::NormalModes: return "normal modes (SOL 103)";
    case Solution::Buckling: return "buckling (SOL 105)";
    case Solution::CraigBampton: return "the Craig-Bampton reduction";
    case Solution::Convert: return "seflex convert";
  }
  return "?";
}

bool CardUsage::refused() const { return count(CardUse::Kind::Refused) > 0; }

std::size_t CardUsage::count(CardUse::Kind kind) const {
  std::size_t n = 0;
  for (const CardUse& u : uses) n += u.kind == kind;
  return n;
}

CardUsage check_card_usage(const fem::Model& model, Solution solution, const std::vector<CaseSelection>& cases,
                           unsigned interface, bool ignore_unknown_cards) {
  CardUsage out;
  out.solution = solution;
  out.cases = cases;
  out.uses = Classifier(model, solution, out.cases, interface, ignore_unknown_cards).run();
  return out;
}

std::string describe(const fem::Model& model, const CardUse& use) {
  if (use.card.rfind("case control", 0) == 0 || use.card.rfind("executive control", 0) == 0) return use.card + " (" + fem::where(model, use.first).str() + "): " + use.reason;
  return use.card + ": " + std::to_string(use.count) + (use.count == 1 ? " card" : " cards") + ", first at " +
         fem::where(model, use.first).str() + ": " + use.reason;
}

void require_usable(const fem::Model& model, const CardUsage& usage) {
  const std::size_t n = usage.count(CardUse::Kind::Refused);
  if (n == 0) return;
  std::vector<const CardUse*> unknown;
  for (const CardUse& u : usage.uses)
    if (u.kind == CardUse::Kind::Refused && u.unknown_card) unknown.push_back(&u);
  if (!unknown.empty()) {
    constexpr std::size_t kListed = 12;
    std::string list;
    for (std::size_t k = 0; k < unknown.size() && k < kListed; ++k)
      list += (k ? ", " : "") + unknown[k]->card + " (" + std::to_string(unknown[k]->count) +
              (unknown[k]->count == 1 ? " card, at " : " cards, first at ") + fem::where(model, unknown[k]->first).str() + ")";
    if (unknown.size() > kListed) list += " and " + std::to_string(unknown.size() - kListed) + " more (seflex info lists them)";
    const std::size_t others = n - unknown.size();
    throw InputError(fem::where(model, unknown.front()->first),
                     (unknown.size() == 1 ? std::string("a card seflex does not know: ")
                                          : std::to_string(unknown.size()) + " kinds of card seflex does not know: ") +
                         list + "; " + solution_name(usage.solution) +
                         " does not run on a deck with cards it does not know (MSC Nastran stops on them too): correct "
                         "or remove them, or give --ignore-unknown to run without them" +
                         (others ? " (and " + std::to_string(others) + " more problem" + (others > 1 ? "s" : "") +
                                       ": seflex info lists them)"
                                 : std::string()));
  }
  const CardUse& u = usage.uses.front();  // Refused entries come first
  std::string more;
  if (n > 1) more = " (and " + std::to_string(n - 1) + " more problem" + (n > 2 ? "s" : "") + ": seflex info lists them)";
  std::string what = u.card;
  if (u.count > 1) what += " (" + std::to_string(u.count) + " cards)";
  throw InputError(fem::where(model, u.first),
                   what + ": " + u.reason + "; " + solution_name(usage.solution) + " cannot run without it" + more);
}

}  // namespace seflex::solutions
