// fem::finalize: id maps, duplicate ids, coordinate systems, references, PARAM values.
#include "seflex/fem/finalize.hpp"

#include "seflex/fem/components.hpp"
#include "seflex/common/error.hpp"
#include "finalize_unsupported.hpp"

#include <algorithm>
#include <cctype>
#include <charconv>
#include <set>
#include <string>
#include <tuple>
#include <sstream>
#include <unordered_map>
#include <unordered_set>

namespace seflex::fem {
namespace {


/// One id space shared by several card types; a duplicate is reported on the card read later.
struct IdSpace {
  struct Entry {
    CardRef ref;
    const char* card = nullptr;  ///< nullptr: no id (dense)
  };
  std::unordered_map<int, Entry> map;
  /// Ids 1..max in a table instead of the map when they are dense (use_dense): a 1M-element deck
  /// spends less in one table than in a million hash nodes.
  std::vector<Entry> dense;
  const Model* model = nullptr;
  void use_dense(int max_id, std::size_t count) {
    if (max_id > 0 && static_cast<std::size_t>(max_id) <= 4 * count + 1024) dense.assign(static_cast<std::size_t>(max_id) + 1, Entry{});
  }
  void add(int id, const CardRef& ref, const char* card, const char* field, const char* what, const char* expected);
};

const char* spring_card(const Spring& s) {
  return s.scalar_points ? (s.inline_property ? "CELAS4" : "CELAS3") : (s.inline_property ? "CELAS2" : "CELAS1");
}
const char* scalar_mass_card(const ScalarMass& s) {
  return s.scalar_points ? (s.inline_property ? "CMASS4" : "CMASS3") : (s.inline_property ? "CMASS2" : "CMASS1");
}

class Finalizer {
 public:
  explicit Finalizer(Model& m) : m_(m) {}

  void run() {
    m_.finalized = false;
    detail::leave_out_unsupported(m_);
    index_grids();
    index_coords();
    index_materials_and_properties();
    index_elements();
    resolve_coordinates(m_);
    check_elements();
    offset_definition_without_offsets();
    material_tables();
    check_constraints_and_loads();
    check_solution_control();
    m_.finalized = true;
  }

 private:
  [[noreturn]] void fail(const CardRef& ref, const std::string& card, int id, std::string_view field,
                         const std::string& problem) const {
    std::string msg = card + " " + std::to_string(id);
    if (!field.empty()) {
      msg += ", ";
      msg += field;
    }
    throw InputError(where(m_, ref), msg + ": " + problem);
  }

  std::string at(const CardRef& ref) const { return where(m_, ref).str(); }

  template <class Vec>
  void index(const Vec& items, std::unordered_map<int, std::uint32_t>& map, const char* card, const char* what) {
    map.clear();
    map.reserve(items.size());
    for (std::size_t i = 0; i < items.size(); ++i) {
      const auto [it, inserted] = map.emplace(items[i].id, static_cast<std::uint32_t>(i));
      if (!inserted)
        fail(items[i].ref, card, items[i].id, "field 2 (ID)",
             std::string("duplicate ") + what + " id, first defined at " + at(items[it->second].ref) +
                 "; expected unique ids");
    }
  }

  void index_grids() {
    index(m_.grids, m_.grid_index, "GRID", "grid");
    // Grid ids are usually dense: then a bitmap answers the many "is this a grid" questions of the
    // element checks faster than the hash map.
    int max_id = 0;
    for (const auto& g : m_.grids) max_id = std::max(max_id, g.id);
    dense_grids_.clear();
    if (static_cast<std::size_t>(max_id) <= 4 * m_.grids.size() + 1024) {
      dense_grids_.assign(static_cast<std::size_t>(max_id) + 1, false);
      for (const auto& g : m_.grids) dense_grids_[static_cast<std::size_t>(g.id)] = true;
    }
    // An SPOINT listed twice defines the same scalar point twice: one is kept, as Nastran does
    // (pyNastran's freq_sine/good_sine.dat lists SPOINT 1000 twice and carries the results Nastran
    // computed from it, good_sine.op2; a scalar point carries no data that could differ). Said in a
    // warning, not listed as unsupported: nothing is approximated.
    {
      std::unordered_set<int> seen;
      std::size_t repeats = 0;
      int first_repeat_id = 0;
      CardRef first_repeat_ref;
      auto& sp = m_.spoints;
      std::unordered_map<int, CardRef> first_at;
      for (const ScalarPoint& s : sp) first_at.emplace(s.id, s.ref);
      sp.erase(std::remove_if(sp.begin(), sp.end(),
                              [&](const ScalarPoint& s) {
                                if (seen.insert(s.id).second) return false;
                                if (repeats++ == 0) {
                                  first_repeat_id = s.id;
                                  first_repeat_ref = s.ref;
                                }
                                return true;
                              }),
               sp.end());
      if (repeats > 0)
        warn_once(at(first_repeat_ref) + ": SPOINT " + std::to_string(first_repeat_id) +
                                   " given again (first at " + at(first_at.at(first_repeat_id)) + ")" +
                                   (repeats > 1 ? " and " + std::to_string(repeats - 1) + " more repeated ids" : "") +
                                   ": one scalar point kept, as Nastran does");
      // A scalar point that appears on a scalar element (CELAS3/4, CMASS3/4, or CELAS1/2, CMASS1/2
      // with component 0 and no GRID of that id) needs no SPOINT (MSC QRG, SPOINT remarks).
      auto implicit = [&](int g, int c, bool scalar_points, const CardRef& ref) {
        if (g <= 0 || (!scalar_points && c != 0) || is_grid(g)) return;
        if (seen.insert(g).second) sp.push_back({g, ref});
      };
      for (const auto& e : m_.springs) {
        implicit(e.g1, e.c1, e.scalar_points, e.ref);
        implicit(e.g2, e.c2, e.scalar_points, e.ref);
      }
      for (const auto& e : m_.scalar_masses) {
        implicit(e.g1, e.c1, e.scalar_points, e.ref);
        implicit(e.g2, e.c2, e.scalar_points, e.ref);
      }
    }
    index(m_.spoints, m_.spoint_index, "SPOINT", "scalar point");
    for (const auto& s : m_.spoints)
      if (const auto it = m_.grid_index.find(s.id); it != m_.grid_index.end())
        fail(s.ref, "SPOINT", s.id, "", "the id is also a GRID (at " + at(m_.grids[it->second].ref) +
                                            "); expected grid and scalar point ids to be distinct");
  }

  void index_coords() {
    for (const auto& c : m_.coords)
      if (c.id <= 0) fail(c.ref, "CORD", c.id, "field 2 (CID)", "expected a coordinate system id > 0 (0 is basic)");
    index(m_.coords, m_.coord_index, "CORD", "coordinate system");
  }

  /// Map id -> position without a duplicate check (the shared IdSpace reports duplicates, naming
  /// the card types).
  template <class Vec>
  static void index_unchecked(const Vec& items, std::unordered_map<int, std::uint32_t>& map) {
    map.clear();
    map.reserve(items.size());
    for (std::size_t i = 0; i < items.size(); ++i) map.emplace(items[i].id, static_cast<std::uint32_t>(i));
  }

  void index_materials_and_properties() {
    // one id space for the structural materials
    IdSpace mats;
    mats.model = &m_;
    auto add_mat = [&](int id, const CardRef& ref, const char* card) {
      mats.add(id, ref, card, "field 2 (MID)", "material", "expected unique material ids across MAT1, MAT2, MAT8, MAT9");
    };
    index(m_.mat1, m_.mat1_index, "MAT1", "material");
    for (const auto& m : m_.mat1) add_mat(m.id, m.ref, "MAT1");
    for (const auto& m : m_.mat2) add_mat(m.id, m.ref, "MAT2");
    for (const auto& m : m_.mat8) add_mat(m.id, m.ref, "MAT8");
    for (const auto& m : m_.mat9) add_mat(m.id, m.ref, "MAT9");
    index_unchecked(m_.mat2, m_.mat2_index);
    index_unchecked(m_.mat8, m_.mat8_index);
    index_unchecked(m_.mat9, m_.mat9_index);
    index(m_.bar_props, m_.bar_prop_index, "PBAR", "property");
    index_unchecked(m_.rod_props, m_.rod_prop_index);  // PROD and PTUBE: checked in the shared id space below
    index(m_.shell_props, m_.shell_prop_index, "PSHELL", "property");
    index(m_.spring_props, m_.spring_prop_index, "PELAS", "property");
    index_unchecked(m_.bush_props, m_.bush_prop_index);
    index_unchecked(m_.mass_props, m_.mass_prop_index);
    index_unchecked(m_.shear_props, m_.shear_prop_index);
    index_unchecked(m_.bend_props, m_.bend_prop_index);
    index(m_.solid_props, m_.solid_prop_index, "PSOLID", "property");
    // one id space for all properties
    IdSpace seen;
    seen.model = &m_;
    auto add = [&](int id, const CardRef& ref, const char* card) {
      seen.add(id, ref, card, "field 2 (PID)", "property",
               "expected unique property ids across PBAR, PBARL, PBEAM, PBEAML, PROD, PTUBE, PSHEAR, PBEND, PSHELL, PCOMP, PCOMPG, PELAS, PBUSH, PBUSH1D, PMASS, PSOLID");
    };
    for (const auto& p : m_.bar_props) add(p.id, p.ref, card_name(p.source));
    for (const auto& p : m_.rod_props) add(p.id, p.ref, rod_property_card(p));
    for (const auto& p : m_.shell_props) add(p.id, p.ref, "PSHELL");
    for (const auto& p : m_.composite_props) add(p.id, p.ref, p.global ? "PCOMPG" : "PCOMP");
    for (const auto& p : m_.spring_props) add(p.id, p.ref, "PELAS");
    for (const auto& p : m_.bush_props) add(p.id, p.ref, p.one_d ? "PBUSH1D" : "PBUSH");
    for (const auto& p : m_.mass_props) add(p.id, p.ref, "PMASS");
    for (const auto& p : m_.shear_props) add(p.id, p.ref, "PSHEAR");
    for (const auto& p : m_.bend_props) add(p.id, p.ref, "PBEND");
    for (const auto& p : m_.solid_props) add(p.id, p.ref, "PSOLID");
    index_unchecked(m_.composite_props, m_.composite_prop_index);
    for (const auto& p : m_.bar_props) need_material(p.mid, p.ref, card_name(p.source), p.id, "field 3 (MID)");
    for (const auto& p : m_.rod_props) need_material(p.mid, p.ref, rod_property_card(p), p.id, "field 3 (MID)");
    for (const auto& p : m_.shear_props) need_material(p.mid, p.ref, "PSHEAR", p.id, "field 3 (MID)");
    for (const auto& p : m_.bend_props) need_material(p.mid, p.ref, "PBEND", p.id, "field 3 (MID)");
    for (const auto& p : m_.solid_props)
      if (!m_.mat9_index.count(p.mid)) need_material(p.mid, p.ref, "PSOLID", p.id, "field 3 (MID)", true);
    for (const auto& p : m_.shell_props) {
      if (p.mid1) need_shell_material(p.mid1, p.ref, "PSHELL", p.id, "field 3 (MID1)");
      if (p.mid2) need_shell_material(p.mid2, p.ref, "PSHELL", p.id, "field 5 (MID2)");
      if (p.mid3) need_shell_material(p.mid3, p.ref, "PSHELL", p.id, "field 7 (MID3)");
      if (p.mid4) need_shell_material(p.mid4, p.ref, "PSHELL", p.id, "field 4 of continuation 1 (MID4)");
    }
    std::size_t mat2_plies = 0;
    CardRef first_mat2_ply;
    for (const auto& p : m_.composite_props)
      for (std::size_t k = 0; k < p.plies.size(); ++k) {
        const std::string field = "MID" + std::to_string(k + 1) +
                                  (p.global ? " (GPLYID " + std::to_string(p.plies[k].gplyid) + ")" : std::string());
        need_shell_material(p.plies[k].mid, p.ref, p.global ? "PCOMPG" : "PCOMP", p.id, field);
        if (m_.mat2_index.count(p.plies[k].mid) && mat2_plies++ == 0) first_mat2_ply = p.ref;
      }
    if (mat2_plies > 0) note("PCOMP ply of MAT2 (rigid in transverse shear: a MAT2 gives no transverse shear moduli)",
                             first_mat2_ply, mat2_plies);
    poisson_ratio_above_half();
  }

  /// MDLPRM OFFDEF (MSC: how element offsets behave) with no offset anywhere in the deck (CBAR/CBEAM
  /// WA/WB, shell ZOFFS, CBUSH OCID/S1-S3, CONM2 X1-X3): there is nothing it could change, so the note
  /// is replaced by a warning (pyNastran's rigid_rbe2.bdf, cbush_test.bdf: OFFDEF LROFF, no offsets).
  /// With offsets it stays listed (as a model parameter seflex does not use).
  void offset_definition_without_offsets() {
    const std::string name = "MDLPRM OFFDEF (model parameter not used)";
    const auto it = std::find_if(m_.unsupported.begin(), m_.unsupported.end(), [&](const UnsupportedCard& u) { return u.name == name; });
    if (it == m_.unsupported.end()) return;
    for (const auto& b : m_.bars)
      if (!b.wa.isZero(0.0) || !b.wb.isZero(0.0)) return;
    for (const auto& e : m_.shells)
      if (e.zoffs != 0.0) return;
    for (const auto& e : m_.bushes)
      if (e.ocid >= 0) return;
    for (const auto& e : m_.conm2)
      if (e.cid < 0 || !e.x.isZero(0.0)) return;
    warn_once(at(it->first) + ": MDLPRM OFFDEF: no element of the deck has an offset (CBAR/CBEAM WA/WB, shell ZOFFS, "
                              "CBUSH OCID, CONM2 X): nothing for it to define; not used");
    m_.unsupported.erase(it);
  }

  /// MAT1 NU above 0.5 (the QRG's range is -1 < NU <= 0.5; decks with E, G and NU = E/2G - 1 of an
  /// "equivalent" plate material have it, e.g. pyNastran's freedlm.bdf). Rods, bars, beams, tubes and
  /// bends use E and G only, so a MAT1 that only they use is read with a warning, as Nastran warns of
  /// an inconsistent E, G, NU; a shell, composite ply, shear panel or solid would use NU: listed (every
  /// solution refuses the deck, naming the MAT1 card).
  /// TABLEM1-4: ids unique among them (QRG); kept but used by no solution (the MATTi that would use
  /// them are not modelled, and are listed when present): one warning.
  void material_tables() {
    if (m_.material_tables.empty()) return;
    std::unordered_map<int, std::uint32_t> ids;
    index(m_.material_tables, ids, "TABLEM", "TABLEMi");
    const MaterialTable& t = m_.material_tables.front();
    warn_once(at(t.ref) + ": TABLEM" + std::to_string(t.type) + " " + std::to_string(t.id) +
              (m_.material_tables.size() > 1 ? " and " + std::to_string(m_.material_tables.size() - 1) + " more TABLEMi" : std::string()) +
              ": read; seflex models no temperature-dependent material (MATTi), so no card uses them");
  }

  void poisson_ratio_above_half() {
    std::unordered_map<int, std::string> needs_nu;  // MID -> the first property that uses its NU
    auto uses = [&](int mid, const char* card, int pid) {
      if (mid > 0) needs_nu.emplace(mid, std::string(card) + " " + std::to_string(pid));
    };
    for (const auto& p : m_.shell_props)
      for (const int mid : {p.mid1, p.mid2, p.mid3, p.mid4}) uses(mid, "PSHELL", p.id);
    for (const auto& p : m_.composite_props)
      for (const auto& ply : p.plies) uses(ply.mid, p.global ? "PCOMPG" : "PCOMP", p.id);
    for (const auto& p : m_.shear_props) uses(p.mid, "PSHEAR", p.id);
    for (const auto& p : m_.solid_props) uses(p.mid, "PSOLID", p.id);
    std::size_t refused = 0;
    CardRef first;
    for (const auto& m : m_.mat1) {
      if (!(m.nu > 0.5)) continue;
      const std::string what = at(m.ref) + ": MAT1 " + std::to_string(m.id) + " NU = " + number(m.nu) +
                               " is above 0.5 (the QRG's range is -1 < NU <= 0.5)";
      if (const auto it = needs_nu.find(m.id); it != needs_nu.end()) {
        if (refused++ == 0 || std::tie(m.ref.file, m.ref.line) < std::tie(first.file, first.line)) first = m.ref;
        warn_once(what + " and " + it->second + " uses it: seflex does not model such a material on shells or solids");
      } else {
        warn_once(what + "; only rods, bars and beams use it, which take E and G, not NU: read as given");
      }
    }
    if (refused > 0) note("MAT1 NU above 0.5", first, refused);
  }

  static std::string number(double x) {
    std::ostringstream os;
    os << x;
    return os.str();
  }

  /// A warning every command prints (Model::read_warnings), once however often finalize runs.
  void warn_once(const std::string& text) {
    if (std::find(m_.read_warnings.begin(), m_.read_warnings.end(), text) == m_.read_warnings.end())
      m_.read_warnings.push_back(text);
  }

  /// A note of a feature read with an approximation (listed with the unsupported cards, as the
  /// reader's notes; card usage reports it as approximated). Replaces an earlier note of this name.
  void note(const std::string& name, const CardRef& first, std::size_t count) {
    UnsupportedCard& u = UnsupportedNotes(m_.unsupported).add(name, first, 0);  // at most twice per finalize
    u.count = count;
    u.first = first;
  }

  /// The elements share one id space (CBAR, CBEAM, CROD, CONROD, CQUAD4, CTRIA3, CONM2, CONM1,
  /// CELASi, CMASSi, CBUSH, solids); the rigid elements RBE2, RBAR, RBE3 another.
  void index_elements() {
    const std::size_t total = m_.bars.size() + m_.rods.size() + m_.shells.size() + m_.conm2.size() +
                              m_.springs.size() + m_.rbe2.size() + m_.rbars.size() + m_.rbe3.size() +
                              m_.bushes.size() + m_.scalar_masses.size() + m_.conm1.size() +
                              m_.solids.size() + m_.genels.size() + m_.shear_panels.size() + m_.bends.size() +
                              m_.shells8.size();
    IdSpace seen;
    seen.model = &m_;
    int max_id = 0;
    auto max_of = [&](const auto& v) {
      for (const auto& e : v) max_id = std::max(max_id, e.id);
    };
    max_of(m_.bars), max_of(m_.rods), max_of(m_.shells), max_of(m_.conm2), max_of(m_.springs), max_of(m_.bushes);
    max_of(m_.scalar_masses), max_of(m_.conm1), max_of(m_.solids), max_of(m_.genels), max_of(m_.shear_panels), max_of(m_.bends);
    for (const auto& e : m_.shells8) max_id = std::max(max_id, e.shell.id);
    seen.use_dense(max_id, total);
    if (seen.dense.empty()) seen.map.reserve(total);
    auto add = [&](int id, const CardRef& ref, const char* card) {
      seen.add(id, ref, card, "field 2 (EID)", "element", "expected unique ids across all elements (incl. CONM2, CELASi, CBUSH)");
    };
    // Rigid elements are numbered apart: MSC's own decks (aerobeam, dbxdra7) give an RBAR the id of a
    // CONM2 or a CBEAM, and pyNastran keeps them apart too. Unique among themselves.
    IdSpace rigid;
    rigid.model = &m_;
    auto add_rigid = [&](int id, const CardRef& ref, const char* card) {
      rigid.add(id, ref, card, "field 2 (EID)", "rigid element",
                "expected unique ids across the rigid elements (RBE1, RBE2, RBE3, RBAR, RROD, CRIGD1-3, CRIGDR)");
    };
    for (const auto& e : m_.bars) add(e.id, e.ref, e.is_beam ? "CBEAM" : "CBAR");
    for (const auto& e : m_.rods) add(e.id, e.ref, rod_card(e));
    for (const auto& e : m_.shells) add(e.id, e.ref, shell_card(e));
    for (const auto& e : m_.conm2) add(e.id, e.ref, "CONM2");
    for (const auto& e : m_.springs) add(e.id, e.ref, spring_card(e));
    for (const auto& e : m_.bushes) add(e.id, e.ref, bush_card(e));
    for (const auto& e : m_.scalar_masses) add(e.id, e.ref, scalar_mass_card(e));
    for (const auto& e : m_.conm1) add(e.id, e.ref, "CONM1");
    for (const auto& e : m_.genels) add(e.id, e.ref, "GENEL");
    for (const auto& e : m_.shear_panels) add(e.id, e.ref, "CSHEAR");
    for (const auto& e : m_.bends) add(e.id, e.ref, "CBEND");
    for (const auto& e : m_.shells8) add(e.shell.id, e.shell.ref, quadratic_shell_card(e));
    for (const auto& e : m_.rbe2) add_rigid(e.id, e.ref, "RBE2");
    for (const auto& e : m_.rbars) add_rigid(e.id, e.ref, "RBAR");
    for (const auto& e : m_.rbe3) add_rigid(e.id, e.ref, "RBE3");
    for (const auto& e : m_.rigid_bodies) add_rigid(e.id, e.ref, rigid_body_card(e));
    for (const auto& e : m_.rigid_rods) add_rigid(e.id, e.ref, rigid_rod_card(e));
    for (const auto& e : m_.solids) add(e.id, e.ref, e.card());
  }

  /// An isotropic MAT1 (or, with solid, a MAT9: the caller checks that one first).
  void need_material(int mid, const CardRef& ref, const char* card, int id, const char* field, bool solid = false) {
    if (m_.mat1_index.count(mid)) return;
    const std::string expected = solid ? "; expected the id of a MAT1 or MAT9 card" : "; expected the id of a MAT1 card";
    const char* other = m_.mat2_index.count(mid) ? "MAT2 (a shell material)"
                        : m_.mat8_index.count(mid) ? "MAT8 (a shell material)"
                        : m_.mat9_index.count(mid) ? "MAT9 (an anisotropic solid material, for PSOLID only)"
                                                   : nullptr;
    if (other) fail(ref, card, id, field, "references material " + std::to_string(mid) + ", a " + other + expected);
    fail(ref, card, id, field, "references MAT1 " + std::to_string(mid) + undefined(mid) + expected);
  }

  void need_shell_material(int mid, const CardRef& ref, const char* card, int id, const std::string& field) {
    if (m_.mat9_index.count(mid))
      fail(ref, card, id, field, "references material " + std::to_string(mid) +
                                     ", a MAT9 (an anisotropic solid material, for PSOLID only); expected the id of a MAT1, MAT2 or MAT8 card");
    if (!m_.mat1_index.count(mid) && !m_.mat2_index.count(mid) && !m_.mat8_index.count(mid))
      fail(ref, card, id, field, "references material " + std::to_string(mid) + undefined(mid) +
                                     "; expected the id of a MAT1, MAT2 or MAT8 card");
  }

  /// ", which is not defined", or ", a PCOMP card, which seflex does not support" when a card seflex
  /// lists as unsupported has this id (field 2): the user's property or material is there.
  std::string undefined(int id) const {
    for (const auto& u : m_.unsupported) {
      if (!(u.name[0] == 'P' || u.name.rfind("MAT", 0) == 0)) continue;  // properties and materials only
      for (const auto& mb : u.members)
        if (mb.sid == id) return ", a " + u.name + " card (" + at(mb.ref) + "), which seflex does not support";
    }
    return ", which is not defined";
  }

  bool is_grid(int g) const {
    if (!dense_grids_.empty()) return g > 0 && static_cast<std::size_t>(g) < dense_grids_.size() && dense_grids_[static_cast<std::size_t>(g)];
    return m_.grid_index.count(g) > 0;
  }

  void need_grid(int g, const CardRef& ref, const char* card, int id, std::string_view field) {
    if (!is_grid(g))
      fail(ref, card, id, field, "references grid " + std::to_string(g) + ", which is not defined; expected the id of a GRID" +
                                     (m_.spoint_index.count(g) ? " (it is a scalar point)" : ""));
  }

  void need_coord(int cid, const CardRef& ref, const char* card, int id, std::string_view field) {
    if (cid != 0 && !m_.coord_index.count(cid))
      fail(ref, card, id, field, "references coordinate system " + std::to_string(cid) +
                                     ", which is not defined; expected the id of a CORD1x or CORD2x card (or 0)");
  }

  /// A grid with components 1-6 or a scalar point with component 0.
  void need_dof(int g, int mask_or_component, bool is_mask, const CardRef& ref, const char* card, int id,
                std::string_view field) {
    const bool grid = is_grid(g), spoint = m_.spoint_index.count(g) > 0;
    if (!grid && !spoint)
      fail(ref, card, id, field, "references point " + std::to_string(g) +
                                     ", which is not defined; expected the id of a GRID or SPOINT");
    if (grid && mask_or_component == 0)
      fail(ref, card, id, field, "grid " + std::to_string(g) + " with component 0 or blank; expected components 1-6 for a grid");
    if (spoint && mask_or_component != 0)
      fail(ref, card, id, field, "scalar point " + std::to_string(g) + " with component " +
                                     (is_mask ? component_string(static_cast<ComponentMask>(mask_or_component))
                                              : std::to_string(mask_or_component)) +
                                     "; expected 0 or blank for a scalar point");
  }

  /// Ends of CELAS1-4 / CMASS1-4: grid components or scalar points (CELAS3/4, CMASS3/4: scalar points only).
  template <class E>
  void check_scalar_ends(const E& s, const char* card) {
    const int g[2] = {s.g1, s.g2}, c[2] = {s.c1, s.c2};
    const char* fields[2][2] = {{"field 4 (G1)", "field 6 (G2)"}, {"field 4 (S1)", "field 5 (S2)"}};
    for (int k = 0; k < 2; ++k) {
      if (g[k] == 0) continue;
      const char* field = fields[s.scalar_points ? 1 : 0][k];
      if (s.scalar_points && !m_.spoint_index.count(g[k]))
        fail(s.ref, card, s.id, field, "references point " + std::to_string(g[k]) + ", which is not an SPOINT; expected a scalar point" +
                                           (is_grid(g[k]) ? " (it is a GRID: use " + std::string(card, 5) + "1 or " + std::string(card, 5) + "2)"
                                                          : std::string()));
      need_dof(g[k], c[k], false, s.ref, card, s.id, field);
    }
  }

  void check_elements() {
    for (const auto& b : m_.bars) {
      const char* card = b.is_beam ? "CBEAM" : "CBAR";
      need_grid(b.ga, b.ref, card, b.id, "field 4 (GA)");
      need_grid(b.gb, b.ref, card, b.id, "field 5 (GB)");
      if (b.has_g0) {
        need_grid(b.g0, b.ref, card, b.id, "field 6 (G0)");
        if (b.g0 == b.ga || b.g0 == b.gb)
          fail(b.ref, card, b.id, "field 6 (G0)", "orientation grid " + std::to_string(b.g0) +
                                                      " is an end of the element; expected a third grid");
      } else if (b.v.squaredNorm() == 0.0) {
        fail(b.ref, card, b.id, "field 6 (X1/G0)", std::string("blank and no ") + (b.is_beam ? "BEAMOR" : "BAROR") +
                                                       " gives a default; expected an orientation vector X1 X2 X3 or a grid G0");
      }
      const auto it = m_.bar_prop_index.find(b.pid);
      if (it == m_.bar_prop_index.end())
        fail(b.ref, card, b.id, "field 3 (PID)", "references property " + std::to_string(b.pid) + undefined(b.pid) + "; expected the id of a " +
                                                     (b.is_beam ? "PBEAM or PBEAML" : "PBAR or PBARL") + " card");
      const BarProperty& p = m_.bar_props[it->second];
      const bool beam_prop = p.source == BarProperty::Source::PBEAM || p.source == BarProperty::Source::PBEAML;
      if (beam_prop != b.is_beam)
        fail(b.ref, card, b.id, "field 3 (PID)", "references " + std::string(card_name(p.source)) + " " + std::to_string(p.id) +
                                                     "; expected a " + (b.is_beam ? "PBEAM or PBEAML" : "PBAR or PBARL"));
    }
    for (const auto& r : m_.rods) {
      const char* card = rod_card(r);
      need_grid(r.ga, r.ref, card, r.id, r.inline_property ? "field 3 (G1)" : "field 4 (G1)");
      need_grid(r.gb, r.ref, card, r.id, r.inline_property ? "field 4 (G2)" : "field 5 (G2)");
      if (r.inline_property)
        need_material(r.mid, r.ref, card, r.id, "field 5 (MID)");
      else if (!m_.rod_prop_index.count(r.pid))
        fail(r.ref, card, r.id, "field 3 (PID)", "references property " + std::to_string(r.pid) + undefined(r.pid) +
                                                     "; expected the id of a " + (r.tube ? "PTUBE" : "PROD") + " card");
      else if (const RodProperty& p = m_.rod_props[m_.rod_prop_index.at(r.pid)]; p.tube != r.tube)
        fail(r.ref, card, r.id, "field 3 (PID)", "references " + std::string(rod_property_card(p)) + " " + std::to_string(p.id) +
                                                     "; expected a " + (r.tube ? "PTUBE" : "PROD"));
    }
    for (const auto& s : m_.shells) {
      const char* card = shell_card(s);
      static const char* gfields[4] = {"field 4 (G1)", "field 5 (G2)", "field 6 (G3)", "field 7 (G4)"};
      for (int k = 0; k < s.nnode; ++k) need_grid(s.g[k], s.ref, card, s.id, gfields[k]);
      if (!m_.shell_prop_index.count(s.pid) && !m_.composite_prop_index.count(s.pid))
        fail(s.ref, card, s.id, "field 3 (PID)", "references property " + std::to_string(s.pid) + undefined(s.pid) +
                                                   "; expected the id of a PSHELL, PCOMP or PCOMPG card");
      if (s.theta_is_mcid) need_coord(s.mcid, s.ref, card, s.id, s.nnode == 4 ? "field 8 (MCID)" : "field 7 (MCID)");
    }
    for (const auto& c : m_.conm2) {
      need_grid(c.grid, c.ref, "CONM2", c.id, "field 3 (G)");
      if (c.cid > 0) need_coord(c.cid, c.ref, "CONM2", c.id, "field 4 (CID)");
    }
    for (const auto& s : m_.springs) {
      const char* card = spring_card(s);
      check_scalar_ends(s, card);
      if (!s.inline_property && !m_.spring_prop_index.count(s.pid))
        fail(s.ref, card, s.id, "field 3 (PID)", "references property " + std::to_string(s.pid) + undefined(s.pid) + "; expected the id of a PELAS card");
    }
    for (const auto& s : m_.scalar_masses) {
      const char* card = scalar_mass_card(s);
      check_scalar_ends(s, card);
      if (!s.inline_property && !m_.mass_prop_index.count(s.pid))
        fail(s.ref, card, s.id, "field 3 (PID)", "references property " + std::to_string(s.pid) + undefined(s.pid) + "; expected the id of a PMASS card");
    }
    for (const auto& b : m_.bushes) {
      const char* card = bush_card(b);
      const char* prop_card = b.one_d ? "PBUSH1D" : "PBUSH";
      need_grid(b.ga, b.ref, card, b.id, "field 4 (GA)");
      if (b.gb != 0) need_grid(b.gb, b.ref, card, b.id, "field 5 (GB)");
      if (b.has_g0) need_grid(b.g0, b.ref, card, b.id, "field 6 (GO)");
      if (b.cid > 0) need_coord(b.cid, b.ref, card, b.id, b.one_d ? "field 6 (CID)" : "field 9 (CID)");
      if (b.ocid > 0) need_coord(b.ocid, b.ref, card, b.id, "field 3 of continuation 1 (OCID)");
      const auto it = m_.bush_prop_index.find(b.pid);
      if (it == m_.bush_prop_index.end())
        fail(b.ref, card, b.id, "field 3 (PID)",
             "references property " + std::to_string(b.pid) + undefined(b.pid) + "; expected the id of a " + prop_card + " card");
      if (const BushProperty& p = m_.bush_props[it->second]; p.one_d != b.one_d)
        fail(b.ref, card, b.id, "field 3 (PID)",
             "references property " + std::to_string(b.pid) + ", a " + (p.one_d ? "PBUSH1D" : "PBUSH") + " card (" + at(p.ref) +
                 "); expected the id of a " + prop_card + " card");
    }
    for (const auto& e : m_.shear_panels) {
      static const char* gfields[4] = {"field 4 (G1)", "field 5 (G2)", "field 6 (G3)", "field 7 (G4)"};
      for (int k = 0; k < 4; ++k) need_grid(e.g[static_cast<std::size_t>(k)], e.ref, "CSHEAR", e.id, gfields[k]);
      if (!m_.shear_prop_index.count(e.pid))
        fail(e.ref, "CSHEAR", e.id, "field 3 (PID)", "references property " + std::to_string(e.pid) + undefined(e.pid) + "; expected the id of a PSHEAR card");
    }
    for (const auto& q : m_.shells8) {
      const Shell& s = q.shell;
      const char* card = quadratic_shell_card(q);
      for (int k = 0; k < s.nnode; ++k) need_grid(s.g[static_cast<std::size_t>(k)], s.ref, card, s.id, "G" + std::to_string(k + 1));
      for (int k = 0; k < s.nnode; ++k)
        if (q.mid[static_cast<std::size_t>(k)] != 0)
          need_grid(q.mid[static_cast<std::size_t>(k)], s.ref, card, s.id, "G" + std::to_string(s.nnode + k + 1));
      if (!m_.shell_prop_index.count(s.pid) && !m_.composite_prop_index.count(s.pid))
        fail(s.ref, card, s.id, "field 3 (PID)", "references property " + std::to_string(s.pid) + undefined(s.pid) +
                                                   "; expected the id of a PSHELL, PCOMP or PCOMPG card");
      if (s.theta_is_mcid) need_coord(s.mcid, s.ref, card, s.id, "MCID");
    }
    for (const auto& e : m_.bends) {
      need_grid(e.ga, e.ref, "CBEND", e.id, "field 4 (GA)");
      need_grid(e.gb, e.ref, "CBEND", e.id, "field 5 (GB)");
      if (e.has_g0) need_grid(e.g0, e.ref, "CBEND", e.id, "field 6 (G0)");
      if (!m_.bend_prop_index.count(e.pid))
        fail(e.ref, "CBEND", e.id, "field 3 (PID)", "references property " + std::to_string(e.pid) + undefined(e.pid) + "; expected the id of a PBEND card");
    }
    for (const auto& e : m_.genels)
      for (const auto* list : {&e.ui, &e.ud})
        for (const auto& d : *list) need_dof(d.point, d.c, false, e.ref, "GENEL", e.id, list == &e.ui ? "field UIi" : "field UDi");
    for (const auto& c : m_.conm1) {
      need_grid(c.grid, c.ref, "CONM1", c.id, "field 3 (G)");
      if (c.cid > 0) need_coord(c.cid, c.ref, "CONM1", c.id, "field 4 (CID)");
    }
    for (const auto& e : m_.solids) {
      for (int k = 0; k < e.nnode; ++k)
        need_grid(e.g[static_cast<std::size_t>(k)], e.ref, e.card(), e.id, "G" + std::to_string(e.grid_number(k)));
      if (!m_.solid_prop_index.count(e.pid))
        fail(e.ref, e.card(), e.id, "field 3 (PID)", "references property " + std::to_string(e.pid) + undefined(e.pid) + "; expected the id of a PSOLID card");
    }
    for (const auto& r : m_.rbe2) {
      need_grid(r.gn, r.ref, "RBE2", r.id, "field 3 (GN)");
      for (const int g : r.gm) need_grid(g, r.ref, "RBE2", r.id, "GM " + std::to_string(g));
    }
    for (const auto& r : m_.rbars) {
      need_grid(r.ga, r.ref, "RBAR", r.id, "field 3 (GA)");
      need_grid(r.gb, r.ref, "RBAR", r.id, "field 4 (GB)");
    }
    for (const auto& r : m_.rigid_bodies) {
      const RigidBodyFields f = rigid_body_fields(r);
      for (const auto& g : r.independent) need_grid(g.grid, r.ref, rigid_body_card(r), r.id, "field " + f.independent);
      for (const auto& g : r.dependent) need_grid(g.grid, r.ref, rigid_body_card(r), r.id, "field " + f.dependent);
    }
    for (const auto& r : m_.rigid_rods) {
      const RigidRodFields f = rigid_rod_fields(r);
      need_grid(r.ga, r.ref, rigid_rod_card(r), r.id, std::string("field ") + f.ga);
      need_grid(r.gb, r.ref, rigid_rod_card(r), r.id, std::string("field ") + f.gb);
    }
    for (const auto& r : m_.rbe3) {
      need_grid(r.refgrid, r.ref, "RBE3", r.id, "field 4 (REFGRID)");
      for (const auto& group : r.groups)
        for (const int g : group.grids) need_grid(g, r.ref, "RBE3", r.id, "Gi,j " + std::to_string(g));
      for (const auto& d : r.um) need_grid(d.grid, r.ref, "RBE3", r.id, "GMi (UM) " + std::to_string(d.grid));
    }
  }

  /// Set cards (SPC, MPC, loads) are checked where a solution selects them (fem::spc_set_dofs,
  /// fem::load_vector, the MPC elimination; solutions::check_card_usage warns about the unselected
  /// ones, as Nastran does): here only what makes the deck itself ambiguous - duplicate and clashing
  /// set ids - and the dof sets that are not selected by case control (ASET, OMIT, BSET, SUPORT).
  void check_constraints_and_loads() {
    std::set<int> spc_sets, mpc_sets, load_sets;
    for (const auto& s : m_.spcs) spc_sets.insert(s.sid);
    for (const auto& e : m_.mpcs) mpc_sets.insert(e.sid);
    for (const auto& l : m_.point_loads) load_sets.insert(l.sid);
    std::unordered_map<int, CardRef> spcadd_ids, mpcadd_ids, load_ids;
    for (const auto& a : m_.spcadds) check_combination(spcadd_ids, spc_sets, "SPCADD", a.sid, a.ref, "SPC set", "SPC or SPC1");
    for (const auto& a : m_.mpcadds) check_combination(mpcadd_ids, mpc_sets, "MPCADD", a.sid, a.ref, "MPC set", "MPC");
    for (const auto& l : m_.load_combinations) check_combination(load_ids, load_sets, "LOAD", l.sid, l.ref, "load set", "FORCE, MOMENT, FORCE1/2 or MOMENT1/2");
    for (const auto& e : m_.aset) need_dof(e.grid, e.c, true, e.ref, "ASET/ASET1", e.grid, "");
    for (const auto& e : m_.omit) need_dof(e.grid, e.c, true, e.ref, "OMIT/OMIT1", e.grid, "");
    for (const auto& e : m_.bset) need_dof(e.grid, e.c, true, e.ref, "BSET/BSET1", e.grid, "");
    for (const auto& e : m_.suport) need_dof(e.grid, e.c, true, e.ref, "SUPORT", e.grid, "");
    for (const auto& e : m_.suport1) need_dof(e.dofs.grid, e.dofs.c, true, e.dofs.ref, "SUPORT1", e.sid, "");
  }

  /// SPCADD / MPCADD / LOAD: a unique id, not also a set id of the cards it combines. (Whether the
  /// combined sets exist is checked when the combination is selected.)
  void check_combination(std::unordered_map<int, CardRef>& ids, const std::set<int>& sets, const char* card, int sid,
                         const CardRef& ref, const char* set_kind, const char* set_cards) {
    if (const auto [it, inserted] = ids.emplace(sid, ref); !inserted)
      fail(ref, card, sid, "field 2 (SID)", std::string("duplicate ") + card + " id, first defined at " + at(it->second) + "; expected unique ids");
    if (sets.count(sid))
      fail(ref, card, sid, "field 2 (SID)", std::string("the id is also used by ") + set_cards + " cards; expected a " + card +
                                                " id different from every " + set_kind + " id");
  }

  /// EIGR/EIGRL ids must be unique; what a method references (NORM = POINT grid) and what the case
  /// control selects are checked when a solution uses them (solutions::check_card_usage).
  void check_solution_control() {
    std::unordered_map<int, CardRef> methods;
    for (const auto& e : m_.eigen_methods) {
      const char* card = e.is_eigr ? "EIGR" : "EIGRL";
      if (const auto [it, inserted] = methods.emplace(e.sid, e.ref); !inserted)
        fail(e.ref, card, e.sid, "field 2 (SID)", "duplicate method id, first defined at " + at(it->second) + "; expected unique EIGR/EIGRL ids");
    }
    check_params();
  }

  /// The parameters seflex reads (param_number and the AUTOSPC / INREL lookups).
  static const std::set<std::string>& used_params() {
    static const std::set<std::string> names = {"WTMASS", "COUPMASS", "K6ROT", "GRDPNT", "AUTOSPC", "CK2", "CM2", "INREL",
                                                   "QUAD4TYP"};
    return names;
  }

  void check_params() {
    // MYSTRAN's plate elements: QUAD4TYP MIN4T (other values refused here) and then its shear factors
    const bool mystran = mystran_plate_elements(m_);
    auto used = [&](const std::string& name) {
      return used_params().count(name) || (mystran && (name == "CBMIN3" || name == "CBMIN4T"));
    };
    std::unordered_map<std::string, const Param*> first;
    for (const auto& p : m_.params) {
      const auto [it, inserted] = first.emplace(p.name, &p);
      // Two values of a parameter seflex does not use are Nastran's business (subcase-level PARAMs
      // in the case control, e.g.); of one it uses, ambiguous.
      if (!inserted && it->second->values != p.values && used(p.name))
        throw InputError(where(m_, p.ref), "PARAM " + p.name + ": a second value (the first, at " + at(it->second->ref) +
                                               ", differs); expected one value per parameter");
    }
    auto number = [&](const char* name, double fallback, bool integer) {
      const double v = param_number(m_, name, fallback);
      if (integer && v != static_cast<double>(static_cast<long long>(v))) {
        const Param* p = first.at(name);
        throw InputError(where(m_, p->ref), std::string("PARAM ") + name + ", field 3 (V1): got " + p->values[0] + "; expected an integer");
      }
      return v;
    };
    auto bad = [&](const char* name, const std::string& expected) {
      const Param* p = first.at(name);
      throw InputError(where(m_, p->ref), std::string("PARAM ") + name + ", field 3 (V1): got " + p->values[0] + "; expected " + expected);
    };
    if (first.count("WTMASS") && !(number("WTMASS", 1.0, false) > 0.0)) bad("WTMASS", "a mass factor > 0");
    if (first.count("K6ROT") && !(number("K6ROT", 0.0, false) >= 0.0)) bad("K6ROT", "a stiffness factor >= 0");
    if (first.count("COUPMASS")) number("COUPMASS", -1.0, true);
    if (mystran && first.count("CBMIN3") && !(number("CBMIN3", 2.0, false) > 0.0)) bad("CBMIN3", "a shear factor > 0");
    if (mystran && first.count("CBMIN4T") && !(number("CBMIN4T", 3.6, false) > 0.0)) bad("CBMIN4T", "a shear factor > 0");
  }

  Model& m_;
  std::vector<bool> dense_grids_;  ///< by grid id, when the ids are dense enough
};

void IdSpace::add(int id, const CardRef& ref, const char* card, const char* field, const char* what,
                  const char* expected) {
  Entry* present = nullptr;
  if (id > 0 && static_cast<std::size_t>(id) < dense.size()) {
    Entry& e = dense[static_cast<std::size_t>(id)];
    if (e.card == nullptr) {
      e = Entry{ref, card};
      return;
    }
    present = &e;
  } else {
    const auto [it, inserted] = map.emplace(id, Entry{ref, card});
    if (inserted) return;
    present = &it->second;
  }
  Entry first = *present, later{ref, card};
  if (std::tie(later.ref.file, later.ref.line) < std::tie(first.ref.file, first.ref.line)) std::swap(first, later);
  throw InputError(where(*model, later.ref), std::string(later.card) + " " + std::to_string(id) + ", " + field +
                                                 ": duplicate " + what + " id, first defined at " +
                                                 where(*model, first.ref).str() + " (" + first.card + "); " + expected);
}

}  // namespace

SourceRef where(const Model& model, const CardRef& ref) {
  SourceRef s;
  s.file = ref.file < model.files.size() ? model.files[ref.file] : std::string("<model>");
  s.line = static_cast<int>(ref.line);
  return s;
}

namespace {
/// The first value of PARAM p as a number; throws InputError naming the card if it is not one.
double param_value_number(const Model& model, const Param& p) {
  if (p.values.empty() || p.values[0].empty())
    throw InputError(where(model, p.ref), "PARAM " + p.name + ", field 3 (V1): blank; expected a number");
  const std::string& v = p.values[0];
  double x = 0;
  const auto [ptr, ec] = std::from_chars(v.data(), v.data() + v.size(), x);
  if (ec != std::errc() || ptr != v.data() + v.size())
    throw InputError(where(model, p.ref), "PARAM " + p.name + ", field 3 (V1): got '" + v + "'; expected a number");
  return x;
}
}  // namespace

double param_number(const Model& model, const std::string& name, double fallback) {
  for (const auto& p : model.params)
    if (p.name == name) return param_value_number(model, p);
  return fallback;
}

namespace {
/// The numeric parameters seflex reads and their defaults when absent (MSC Nastran QRG,
/// "Parameters"; CBMIN3/CBMIN4T: MYSTRAN's user manual).
const std::pair<const char*, double> kNumericParams[] = {
    {"WTMASS", 1.0}, {"COUPMASS", -1.0}, {"K6ROT", 100.0}, {"GRDPNT", -1.0},
    {"CK2", 1.0},    {"CM2", 1.0},       {"CBMIN3", 2.0},  {"CBMIN4T", 3.6},
};

const double* numeric_default(const std::string& name) {
  for (const auto& [n, v] : kNumericParams)
    if (name == n) return &v;
  return nullptr;
}
}  // namespace

double param_number(const Model& model, const std::string& name) {
  const double* fallback = numeric_default(name);
  SEFLEX_DEMAND(fallback != nullptr, "param_number: no default for this parameter");
  return param_number(model, name, *fallback);
}

bool param_at_default(const Model& model, const Param& p) {
  if (p.name == "AUTOSPC") return !p.values.empty() && p.values[0] == "YES";
  const double* fallback = numeric_default(p.name);
  return fallback && param_value_number(model, p) == *fallback;
}

bool mystran_plate_elements(const Model& model) {
  for (const auto& p : model.params) {
    if (p.name != "QUAD4TYP") continue;
    std::string v = p.values.empty() ? std::string() : p.values[0];
    for (char& c : v) c = static_cast<char>(std::toupper(static_cast<unsigned char>(c)));
    if (v == "MIN4T") return true;
    if (v == "MIN4")
      throw InputError(where(model, p.ref), "PARAM QUAD4TYP, field 3 (V1): MIN4 (Tessler's MIN4 quadrilateral) is not "
                                            "available in seflex; expected MIN4T (MYSTRAN's default: CQUAD4 = 4 MIN3 "
                                            "triangles, CTRIA3 = MIN3)");
    throw InputError(where(model, p.ref), "PARAM QUAD4TYP, field 3 (V1): got '" + v +
                                              "'; expected MIN4T (MYSTRAN's plate elements; without the PARAM seflex "
                                              "uses MITC4/MITC3)");
  }
  return false;
}

void finalize(Model& model) { Finalizer(model).run(); }

}  // namespace seflex::fem
