// Elements on properties or materials seflex does not model: left out and listed (finalize_unsupported.hpp).
#include "finalize_unsupported.hpp"

#include "seflex/fem/finalize.hpp"

#include <algorithm>
#include <string>
#include <unordered_map>
#include <unordered_set>

namespace seflex::fem::detail {

namespace {

class LeaveOut {
 public:
  explicit LeaveOut(Model& m) : m_(m), notes_(m.unsupported) {}

  void run() {
    for (const auto& u : m_.unsupported) {
      if (u.name.rfind("MAT", 0) == 0)
        for (const auto& mb : u.members) unsupported_mat_.emplace(mb.sid, u.name);
      else if (!u.name.empty() && u.name[0] == 'P')
        for (const auto& mb : u.members) unsupported_prop_.emplace(mb.sid, u.name);
    }
    if (unsupported_mat_.empty() && unsupported_prop_.empty() && m_.mat2.empty() && m_.mat8.empty()) return;
    // the properties some element references (one id space for all properties)
    for (const auto& e : m_.bars) used_pids_.insert(e.pid);
    for (const auto& e : m_.rods)
      if (!e.inline_property) used_pids_.insert(e.pid);
    for (const auto& e : m_.bends) used_pids_.insert(e.pid);
    for (const auto& e : m_.shear_panels) used_pids_.insert(e.pid);
    for (const auto& e : m_.solids) used_pids_.insert(e.pid);
    for (const auto& e : m_.shells) used_pids_.insert(e.pid);
    for (const auto& e : m_.shells8) used_pids_.insert(e.shell.pid);
    for (const auto& x : m_.mat1) mat1_.insert(x.id);
    for (const auto& x : m_.mat2) other_mat_.emplace(x.id, "MAT2");
    for (const auto& x : m_.mat8) other_mat_.emplace(x.id, "MAT8");
    properties();
    elements();
  }

 private:
  /// Why a property with material `mid` that needs a MAT1 (isotropic) is left out, or "" if it stays.
  std::string isotropic_problem(int mid) const {
    if (mid == 0 || mat1_.count(mid)) return "";
    if (const auto it = other_mat_.find(mid); it != other_mat_.end()) return it->second;
    if (const auto it = unsupported_mat_.find(mid); it != unsupported_mat_.end()) return it->second;
    return "";  // not defined at all: finalize's error
  }
  /// Same for a shell material (MAT1, MAT2 or MAT8 accepted).
  std::string shell_problem(int mid) const {
    if (mid == 0 || mat1_.count(mid) || other_mat_.count(mid)) return "";
    if (const auto it = unsupported_mat_.find(mid); it != unsupported_mat_.end()) return it->second;
    return "";
  }

  template <class Vec, class Why>
  void drop_properties(Vec& props, const char* kind, Why why) {
    auto& dropped = dropped_[kind];
    props.erase(std::remove_if(props.begin(), props.end(),
                               [&](const auto& p) {
                                 const std::string reason = why(p);
                                 if (reason.empty()) return false;
                                 // a property no element uses changes nothing: Nastran runs such decks
                                 // (pyNastran's bwb_saero_trim.f06: PBEAML 5 and 999 on MAT8, no CBEAM
                                 // on them); a warning, not a note that solutions refuse
                                 if (used_pids_.count(p.id))
                                   note(reason + " (left out)", p.ref);
                                 else
                                   unused_property(reason, p.id, p.ref);
                                 dropped.emplace(p.id, reason);
                                 return true;
                               }),
                props.end());
  }

  void properties() {
    drop_properties(m_.bar_props, "bar", [&](const BarProperty& p) {
      const std::string mat = isotropic_problem(p.mid);
      return mat.empty() ? mat : std::string(card_name(p.source)) + " on " + mat;
    });
    drop_properties(m_.rod_props, "rod", [&](const RodProperty& p) {
      const std::string mat = isotropic_problem(p.mid);
      return mat.empty() ? mat : std::string(rod_property_card(p)) + " on " + mat;
    });
    drop_properties(m_.bend_props, "bend", [&](const BendProperty& p) {
      const std::string mat = isotropic_problem(p.mid);
      return mat.empty() ? mat : "PBEND on " + mat;
    });
    drop_properties(m_.shear_props, "shear", [&](const ShearProperty& p) {
      const std::string mat = isotropic_problem(p.mid);
      return mat.empty() ? mat : "PSHEAR on " + mat;
    });
    drop_properties(m_.solid_props, "solid", [&](const SolidProperty& p) {
      const std::string mat = isotropic_problem(p.mid);
      return mat.empty() ? mat : "PSOLID on " + mat;
    });
    drop_properties(m_.shell_props, "shell", [&](const ShellProperty& p) {
      for (const int mid : {p.mid1, p.mid2, p.mid3, p.mid4})
        if (const std::string mat = shell_problem(mid); !mat.empty()) return "PSHELL on " + mat;
      return std::string();
    });
    drop_properties(m_.composite_props, "shell", [&](const CompositeProperty& p) {
      for (const auto& ply : p.plies)
        if (const std::string mat = shell_problem(ply.mid); !mat.empty())
          return std::string(p.global ? "PCOMPG" : "PCOMP") + " on " + mat;
      return std::string();
    });
  }

  /// Why an element on property `pid` of kind `kind` is left out, or "" if it stays. `kept` tells
  /// whether a supported property of that id remains.
  std::string element_problem(int pid, const char* kind, const std::unordered_set<int>& kept) const {
    if (kept.count(pid)) return "";
    const auto& dropped = dropped_.at(kind);
    if (const auto it = dropped.find(pid); it != dropped.end()) return it->second;
    if (const auto it = unsupported_prop_.find(pid); it != unsupported_prop_.end()) return it->second;
    return "";  // not defined: finalize's error
  }

  /// Leave out the elements (with their shell(e) giving pid and ref: the element itself, or the
  /// corner data of a CTRIA6/CQUAD8) whose property of kind `kind` is left out or unsupported.
  template <class Vec, class Kept, class Card, class ShellOf>
  void drop_elements(Vec& elements, const char* kind, Kept kept_of, Card card_of, ShellOf shell) {
    const auto& dropped = dropped_[kind];
    if (dropped.empty() && unsupported_prop_.empty()) return;
    const std::unordered_set<int> kept = kept_of();
    elements.erase(std::remove_if(elements.begin(), elements.end(),
                                  [&](const auto& e) {
                                    if (shell(e).pid == 0) return false;
                                    const std::string reason = element_problem(shell(e).pid, kind, kept);
                                    if (reason.empty()) return false;
                                    note(std::string(card_of(e)) + " on " + reason + " (left out)", shell(e).ref);
                                    return true;
                                  }),
                   elements.end());
  }
  template <class Vec, class Kept, class Card>
  void drop_elements(Vec& elements, const char* kind, Kept kept_of, Card card_of) {
    drop_elements(elements, kind, kept_of, card_of, [](const auto& e) -> const auto& { return e; });
  }

  template <class Vec>
  static std::unordered_set<int> ids(const Vec& v) {
    std::unordered_set<int> s;
    for (const auto& x : v) s.insert(x.id);
    return s;
  }

  void elements() {
    drop_elements(m_.bars, "bar", [&] { return ids(m_.bar_props); },
                  [](const Bar& b) { return b.is_beam ? "CBEAM" : "CBAR"; });
    drop_elements(m_.rods, "rod", [&] { return ids(m_.rod_props); }, [](const Rod& r) { return rod_card(r); });
    drop_elements(m_.bends, "bend", [&] { return ids(m_.bend_props); }, [](const Bend&) { return "CBEND"; });
    drop_elements(m_.shear_panels, "shear", [&] { return ids(m_.shear_props); }, [](const ShearPanel&) { return "CSHEAR"; });
    drop_elements(m_.solids, "solid", [&] { return ids(m_.solid_props); }, [](const Solid& s) { return s.card(); });
    const auto shell_ids = [&] {
      std::unordered_set<int> s = ids(m_.shell_props);
      for (const auto& p : m_.composite_props) s.insert(p.id);
      return s;
    };
    drop_elements(m_.shells, "shell", shell_ids, [](const Shell& s) { return shell_card(s); });
    drop_elements(m_.shells8, "shell", shell_ids, quadratic_shell_card, [](const QuadraticShell& q) -> const Shell& { return q.shell; });
    // CONROD: its own material
    m_.rods.erase(std::remove_if(m_.rods.begin(), m_.rods.end(),
                                 [&](const Rod& r) {
                                   if (!r.inline_property) return false;
                                   const std::string mat = isotropic_problem(r.mid);
                                   if (mat.empty()) return false;
                                   note("CONROD on " + mat + " (left out)", r.ref);
                                   return true;
                                 }),
                  m_.rods.end());
  }

  void note(const std::string& name, const CardRef& ref) { notes_.add(name, ref); }

  /// "deck.bdf:12: PBEAML 5 on MAT8: no element uses it; ..." (reason: "PBEAML on MAT8").
  void unused_property(const std::string& reason, int pid, const CardRef& ref) {
    const std::size_t card_end = reason.find(' ');
    m_.read_warnings.push_back(where(m_, ref).str() + ": " + reason.substr(0, card_end) + " " + std::to_string(pid) +
                               reason.substr(card_end) + ": no element uses it; left out (seflex does not model it)");
  }

  Model& m_;
  std::unordered_set<int> used_pids_;  ///< properties some element references
  std::unordered_map<int, std::string> unsupported_mat_, unsupported_prop_, other_mat_;
  std::unordered_set<int> mat1_;
  std::unordered_map<std::string, std::unordered_map<int, std::string>> dropped_;  ///< kind -> pid -> reason
  UnsupportedNotes notes_;  ///< adds to m_.unsupported
};

}  // namespace

void leave_out_unsupported(Model& model) { LeaveOut(model).run(); }

}  // namespace seflex::fem::detail
