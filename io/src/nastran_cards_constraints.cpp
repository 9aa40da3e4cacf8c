// SPC, SPC1, SPCADD, MPC, MPCADD, ASET, ASET1, OMIT, OMIT1, BSET, BSET1, SUPORT, FORCE, MOMENT, LOAD;
// the rigid and interpolation elements RBAR and RBE3; the id-list helper.
#include <string>

#include "seflex/io/nastran_cards.hpp"
#include "seflex/io/nastran_lines.hpp"

namespace seflex::io::nastran {

std::vector<int> id_list(const Card& card, std::size_t first, const char* what, bool stop_at_real, std::size_t* stopped_at,
                         std::vector<bool>* from_thru) {
  std::vector<int> ids;
  auto mark = [&](bool thru) {
    if (from_thru) from_thru->resize(ids.size(), thru);
  };
  std::size_t i = first;
  const std::size_t n = card.size();
  if (stopped_at) *stopped_at = n;
  for (; i < n; ++i) {
    const std::string_view f = card.raw(i);
    if (f.empty()) continue;
    const FieldKind kind = classify(f);
    if (kind == FieldKind::Integer) {
      const int id = card.id(i, what);
      ids.push_back(id);
      mark(false);
      continue;
    }
    if (kind == FieldKind::Real && stop_at_real) {
      if (stopped_at) *stopped_at = i;
      return ids;
    }
    if (kind == FieldKind::Text && upper(f) == "THRU") {
      if (ids.empty()) card.fail(i, what, "THRU without an id before it; expected 'ID1 THRU ID2'");
      std::size_t j = i + 1;
      while (j < n && card.blank(j)) ++j;
      const int last = card.id(j < n ? j : i + 1, what);
      const int from = ids.back();
      if (last <= from)
        card.fail(j, what, card.got(j) + " after THRU; expected an id greater than " + std::to_string(from));
      if (last - from > kMaxThru || ids.size() + static_cast<std::size_t>(last - from) > std::size_t(kMaxThru))
        card.fail(j, what, std::to_string(from) + " THRU " + std::to_string(last) + " is more than " +
                               std::to_string(kMaxThru) + " ids; expected a smaller range");
      if (from_thru && !from_thru->empty()) from_thru->back() = true;  // G1 of "G1 THRU G2"
      for (int id = from + 1; id <= last; ++id) ids.push_back(id);
      mark(true);
      i = j;
      continue;
    }
    card.fail(i, what, card.got(i) + "; expected an id (integer > 0) or THRU");
  }
  return ids;
}

namespace {

void dof_pairs(const Card& card, std::vector<fem::DofSetEntry>& out, std::size_t first = 0) {
  static const char* ids[4] = {"ID1", "ID2", "ID3", "ID4"};
  static const char* comps[4] = {"C1", "C2", "C3", "C4"};
  bool any = false;
  for (std::size_t i = first; i + 1 < card.size() || i == first; i += 2) {
    const std::size_t k = ((i - first) / 2) % 4;
    if (card.blank(i) && card.blank(i + 1)) continue;
    fem::DofSetEntry e;
    e.grid = card.id(i, ids[k]);
    e.c = card.components(i + 1, comps[k], true, true);
    e.ref = card.ref();
    out.push_back(e);
    any = true;
  }
  if (!any) card.fail(first, "ID1", "blank; expected grid or scalar point ids with components");
}

void dof_list(const Card& card, std::vector<fem::DofSetEntry>& out) {
  const fem::ComponentMask c = card.components(0, "C", false, true);
  const std::vector<int> ids = id_list(card, 1, "ID");
  if (ids.empty()) card.fail(1, "ID1", "blank; expected grid or scalar point ids");
  for (const int id : ids) out.push_back({id, c, card.ref()});
}

void point_load(const Card& card, ReaderState& st, fem::PointLoad::Kind kind) {
  fem::PointLoad l;
  l.kind = kind;
  l.sid = card.id(0, "SID");
  l.grid = card.id(1, "G");
  l.cid = card.integer_or(2, "CID", 0);
  if (l.cid < 0) card.fail(2, "CID", card.got(2) + "; expected a coordinate system id >= 0 or blank");
  l.scale = card.real(3, kind == fem::PointLoad::Kind::Force ? "F" : "M");
  l.n = {card.real_or(4, "N1", 0.0), card.real_or(5, "N2", 0.0), card.real_or(6, "N3", 0.0)};
  l.ref = card.ref();
  st.model.point_loads.push_back(l);
}

}  // namespace

// SPC SID G1 C1 D1 G2 C2 D2
void parse_spc(const Card& card, ReaderState& st) {
  static const char* names[2][3] = {{"G1", "C1", "D1"}, {"G2", "C2", "D2"}};
  const int sid = card.id(0, "SID");
  for (std::size_t s = 0; s < 2; ++s) {
    const std::size_t b = 1 + 3 * s;
    if (s == 1 && card.blank(b) && card.blank(b + 1) && card.blank(b + 2)) break;
    fem::SpcEntry e;
    e.sid = sid;
    e.grid = card.id(b, names[s][0]);
    e.c = card.components(b + 1, names[s][1], true, true);
    e.d = card.real_or(b + 2, names[s][2], 0.0);
    e.ref = card.ref();
    st.model.spcs.push_back(e);
  }
}

// SPC1 SID C G1 G2 ... (or G1 THRU G2: grids of the range need not exist, QRG SPC1 remark)
void parse_spc1(const Card& card, ReaderState& st) {
  const int sid = card.id(0, "SID");
  const fem::ComponentMask c = card.components(1, "C", false, true);
  std::vector<bool> thru;
  const std::vector<int> grids = id_list(card, 2, "G", false, nullptr, &thru);
  if (grids.empty()) card.fail(2, "G1", "blank; expected grid or scalar point ids");
  for (std::size_t k = 0; k < grids.size(); ++k) st.model.spcs.push_back({sid, grids[k], c, 0.0, thru[k], card.ref()});
}

// SPCADD / MPCADD SID S1 S2 ...
static void set_combination(const Card& card, const char* sets, std::vector<fem::SetCombination>& out) {
  fem::SetCombination a;
  a.sid = card.id(0, "SID");
  a.sets = id_list(card, 1, "S");
  if (a.sets.empty()) card.fail(1, "S1", std::string("blank; expected ") + sets + " set ids");
  a.ref = card.ref();
  out.push_back(std::move(a));
}
void parse_spcadd(const Card& card, ReaderState& st) { set_combination(card, "SPC", st.model.spcadds); }

// MPC SID G1 C1 A1 G2 C2 A2 / - G3 C3 A3 G4 C4 A4 / ...: sum Ai u(Gi, Ci) = 0, (G1, C1) dependent.
void parse_mpc(const Card& card, ReaderState& st) {
  static const char* names[2][3] = {{"G1", "C1", "A1"}, {"G2", "C2", "A2"}};
  fem::MpcEquation e;
  e.sid = card.id(0, "SID");
  for (std::size_t line = 0; 8 * line < card.size(); ++line)
    for (std::size_t half = 0; half < 2; ++half) {
      const std::size_t b = 8 * line + 1 + 3 * half;
      if (card.blank(b) && card.blank(b + 1) && card.blank(b + 2)) continue;
      std::string g = "G", c = "C", a = "A";
      const std::string k = std::to_string(2 * line + half + 1);
      const bool first = e.terms.empty();
      fem::MpcTerm t;
      t.grid = card.id(b, first ? names[0][0] : (g + k).c_str());
      t.component = card.integer_or(b + 1, first ? names[0][1] : (c + k).c_str(), 0);
      if (t.component < 0 || t.component > 6)
        card.fail(b + 1, first ? "C1" : (c + k).c_str(),
                  card.got(b + 1) + "; expected one component 1-6 (grid), or 0 or blank (scalar point)");
      t.a = card.real(b + 2, first ? names[0][2] : (a + k).c_str());
      if (first && t.a == 0.0)
        card.fail(b + 2, "A1", "0.0; expected a nonzero coefficient for the dependent dof (G1, C1)");
      e.terms.push_back(t);
    }
  if (e.terms.empty()) card.fail(1, "G1", "blank; expected the dependent grid, component and coefficient");
  e.ref = card.ref();
  st.model.mpcs.push_back(std::move(e));
}

void parse_mpcadd(const Card& card, ReaderState& st) { set_combination(card, "MPC", st.model.mpcadds); }

// ASET ID1 C1 ID2 C2 ...; ASET1 C ID1 ID2 ... (THRU); same for OMIT/OMIT1, BSET/BSET1; SUPORT ID1 C1 ...
void parse_aset(const Card& card, ReaderState& st) { dof_pairs(card, st.model.aset); }
void parse_aset1(const Card& card, ReaderState& st) { dof_list(card, st.model.aset); }
void parse_omit(const Card& card, ReaderState& st) { dof_pairs(card, st.model.omit); }
void parse_omit1(const Card& card, ReaderState& st) { dof_list(card, st.model.omit); }
void parse_bset(const Card& card, ReaderState& st) { dof_pairs(card, st.model.bset); }
void parse_bset1(const Card& card, ReaderState& st) { dof_list(card, st.model.bset); }
void parse_suport(const Card& card, ReaderState& st) { dof_pairs(card, st.model.suport); }

// SUPORT1 SID ID1 C1 ID2 C2 ID3 C3: SUPORT's supports, used by the subcases whose case control selects
// SUPORT1 = SID (MSC QRG SUPORT1; several cards may share a SID)
void parse_suport1(const Card& card, ReaderState& st) {
  const int sid = card.id(0, "SID");
  std::vector<fem::DofSetEntry> pairs;
  dof_pairs(card, pairs, 1);
  for (const fem::DofSetEntry& e : pairs) st.model.suport1.push_back({sid, e});
}

// FORCE SID G CID F N1 N2 N3; MOMENT SID G CID M N1 N2 N3
void parse_force(const Card& card, ReaderState& st) { point_load(card, st, fem::PointLoad::Kind::Force); }
void parse_moment(const Card& card, ReaderState& st) { point_load(card, st, fem::PointLoad::Kind::Moment); }

// FORCE1 SID G F G1 G2 (MOMENT1: M); FORCE2 SID G F G1 G2 G3 G4 (MOMENT2: M). The direction, G1 -> G2
// or (G1 -> G2) x (G3 -> G4), is taken from the grids' positions when the load is applied.
void parse_force12(const Card& card, ReaderState& st) {
  const std::string_view name = card.name();
  fem::PointLoad l;
  l.kind = name[0] == 'F' ? fem::PointLoad::Kind::Force : fem::PointLoad::Kind::Moment;
  const bool four = name.back() == '2';
  l.direction = four ? fem::PointLoad::Direction::FourGrids : fem::PointLoad::Direction::TwoGrids;
  l.sid = card.id(0, "SID");
  l.grid = card.id(1, "G");
  l.scale = card.real(2, l.kind == fem::PointLoad::Kind::Force ? "F" : "M");
  static const char* names[4] = {"G1", "G2", "G3", "G4"};
  const std::size_t n = four ? 4 : 2;
  for (std::size_t k = 0; k < n; ++k) l.g[k] = card.id(3 + k, names[k]);
  for (std::size_t k = 0; k < n; k += 2)
    if (l.g[k] == l.g[k + 1])
      card.fail(4 + k, names[k + 1], "grid " + std::to_string(l.g[k]) + " is also " + names[k] +
                                         "; expected two distinct grids to give a direction");
  if (card.used() > 3 + n) card.fail(3 + n, "", card.got(3 + n) + " after " + names[n - 1] + "; expected nothing more");
  l.ref = card.ref();
  st.model.point_loads.push_back(l);
}

// SLOAD SID S1 F1 S2 F2 S3 F3
void parse_sload(const Card& card, ReaderState& st) {
  const int sid = card.id(0, "SID");
  static const char* names[3][2] = {{"S1", "F1"}, {"S2", "F2"}, {"S3", "F3"}};
  for (std::size_t k = 0; k < 3; ++k) {
    const std::size_t b = 1 + 2 * k;
    if (k > 0 && card.blank(b) && card.blank(b + 1)) continue;
    st.model.scalar_loads.push_back({sid, card.id(b, names[k][0]), card.real(b + 1, names[k][1]), card.ref()});
  }
  if (card.used() > 7) card.fail(7, "", card.got(7) + " after F3; expected at most three scalar loads per SLOAD");
}

// PLOAD SID P G1 G2 G3 G4 (G4 blank or 0: a triangle)
void parse_pload(const Card& card, ReaderState& st) {
  fem::GridPressureLoad l;
  l.sid = card.id(0, "SID");
  l.p = card.real(1, "P");
  static const char* names[4] = {"G1", "G2", "G3", "G4"};
  for (std::size_t k = 0; k < 3; ++k) l.g[k] = card.id(2 + k, names[k]);
  l.g[3] = card.integer_or(5, "G4", 0);
  if (l.g[3] < 0) card.fail(5, "G4", card.got(5) + "; expected a grid id, or 0 or blank (a triangle)");
  for (std::size_t a = 0; a < 4; ++a)
    for (std::size_t b = a + 1; b < 4; ++b)
      if (l.g[b] != 0 && l.g[a] == l.g[b])
        card.fail(2 + b, names[b], "grid " + std::to_string(l.g[b]) + " repeats " + names[a] + "; expected distinct grids");
  if (card.used() > 6) card.fail(6, "", card.got(6) + " after G4; expected nothing more");
  l.ref = card.ref();
  st.model.grid_pressure_loads.push_back(l);
}

// LOAD SID S S1 L1 S2 L2 ...
void parse_load(const Card& card, ReaderState& st) {
  fem::LoadCombination l;
  l.sid = card.id(0, "SID");
  l.s = card.real(1, "S");
  for (std::size_t i = 2; i < card.size(); i += 2) {
    if (card.blank(i) && card.blank(i + 1)) continue;
    const std::size_t k = i / 2;
    std::string si = "S", li = "L";
    si += std::to_string(k);
    li += std::to_string(k);
    const double s = card.real(i, si.c_str());
    const int set = card.id(i + 1, li.c_str());
    l.terms.emplace_back(s, set);
  }
  if (l.terms.empty()) card.fail(2, "S1", "blank; expected scale factor and load set pairs");
  l.ref = card.ref();
  st.model.load_combinations.push_back(std::move(l));
}

// RBAR EID GA GB CNA CNB CMA CMB ALPHA
void parse_rbar(const Card& card, ReaderState& st) {
  fem::Rbar r;
  r.id = card.id(0, "EID");
  r.ga = card.id(1, "GA");
  r.gb = card.id(2, "GB");
  if (r.ga == r.gb) card.fail(2, "GB", "the same grid as GA; expected two different grids");
  r.cna = card.components(3, "CNA", true);
  r.cnb = card.components(4, "CNB", true);
  r.cma = card.components(5, "CMA", true);
  r.cmb = card.components(6, "CMB", true);
  r.alpha = card.real_or(7, "ALPHA", 0.0);
  int n = 0;
  for (int k = 0; k < 6; ++k) n += ((r.cna >> k) & 1) + ((r.cnb >> k) & 1);
  if (n != 6)
    card.fail(3, "CNA", std::to_string(n) + " independent components in CNA and CNB; expected six in all, able to "
                            "describe any rigid-body motion of the bar");
  if (r.cma == 0 && r.cmb == 0) {  // QRG: both blank -> all components not independent are dependent
    r.cma = static_cast<fem::ComponentMask>(0x3F & ~r.cna);
    r.cmb = static_cast<fem::ComponentMask>(0x3F & ~r.cnb);
  }
  if (r.cma & r.cna) card.fail(5, "CMA", "a component is both independent (CNA) and dependent (CMA); expected none in both");
  if (r.cmb & r.cnb) card.fail(6, "CMB", "a component is both independent (CNB) and dependent (CMB); expected none in both");
  r.ref = card.ref();
  st.model.rbars.push_back(r);
}

// RBE3 EID - REFGRID REFC WT1 C1 G1,1 G1,2 / G1,3 WT2 C2 G2,1 ... / "UM" GM1 CM1 ... / "ALPHA" ALPHA
void parse_rbe3(const Card& card, ReaderState& st) {
  fem::Rbe3 r;
  r.id = card.id(0, "EID");
  r.refgrid = card.id(2, "REFGRID");
  r.refc = card.components(3, "REFC", false);
  const std::size_t n = card.size();
  std::size_t i = 4;
  enum class Part { Groups, Um, Alpha } part = Part::Groups;
  while (i < n) {
    if (card.blank(i)) {
      ++i;
      continue;
    }
    const FieldKind kind = card.kind(i);
    if (kind == FieldKind::Text) {
      const std::string word = upper(card.raw(i));
      if (word == "UM" && part == Part::Groups) {
        part = Part::Um;
        ++i;
        continue;
      }
      if (word == "ALPHA" && part != Part::Alpha) {
        part = Part::Alpha;
        ++i;
        std::size_t j = i;
        while (j < n && card.blank(j)) ++j;
        if (j < n) {
          r.has_alpha = true;
          r.alpha = card.real(j, "ALPHA");
          i = j + 1;
        }
        continue;
      }
      card.fail(i, part == Part::Groups ? "Gi,j" : "GMi",
                card.got(i) + "; expected a weight, components and grids, or the flags UM or ALPHA");
    }
    if (part == Part::Alpha) card.fail(i, "ALPHA", card.got(i) + " after ALPHA; expected nothing more (TREF is not read)");
    if (part == Part::Um) {
      fem::Rbe3::Dependent d;
      d.grid = card.id(i, "GMi");
      std::size_t j = i + 1;
      while (j < n && card.blank(j)) ++j;
      d.c = card.components(j < n ? j : i + 1, "CMi", false);
      r.um.push_back(d);
      i = j + 1;
      continue;
    }
    // a group: WTi Ci Gi,1 Gi,2 ...
    if (kind != FieldKind::Real)
      card.fail(i, r.groups.empty() ? "WT1" : "Gi,j",
                card.got(i) + (r.groups.empty() ? "; expected a weighting factor (real)"
                                                : "; expected a grid id, a new weighting factor (real), UM or ALPHA"));
    fem::Rbe3::Group g;
    g.weight = card.real(i, "WTi");
    if (!(g.weight >= 0.0)) card.fail(i, "WTi", card.got(i) + "; expected a weighting factor >= 0");
    std::size_t j = i + 1;
    while (j < n && card.blank(j)) ++j;
    g.c = card.components(j < n ? j : i + 1, "Ci", false);
    i = j + 1;
    while (i < n && (card.blank(i) || card.kind(i) == FieldKind::Integer)) {
      if (!card.blank(i)) g.grids.push_back(card.id(i, "Gi,j"));
      ++i;
    }
    if (g.grids.empty()) card.fail(j, "Ci", "no grid after the components; expected at least one grid Gi,j per weight");
    r.groups.push_back(std::move(g));
  }
  if (r.groups.empty()) card.fail(4, "WT1", "blank; expected at least one weight, components and grids");
  r.ref = card.ref();
  st.model.rbe3.push_back(std::move(r));
}

}  // namespace seflex::io::nastran
