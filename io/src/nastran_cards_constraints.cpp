// SPC, SPC1, SPCADD, ASET, ASET1, BSET, BSET1, SUPORT, FORCE, MOMENT, LOAD; the id-list helper.
#include <string>

#include "seflex/io/nastran_cards.hpp"
#include "seflex/io/nastran_lines.hpp"

namespace seflex::io::nastran {

std::vector<int> id_list(const Card& card, std::size_t first, const char* what, bool stop_at_real, std::size_t* stopped_at) {
  std::vector<int> ids;
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
      for (int id = from + 1; id <= last; ++id) ids.push_back(id);
      i = j;
      continue;
    }
    card.fail(i, what, card.got(i) + "; expected an id (integer > 0) or THRU");
  }
  return ids;
}

namespace {

void dof_pairs(const Card& card, std::vector<fem::DofSetEntry>& out) {
  static const char* ids[4] = {"ID1", "ID2", "ID3", "ID4"};
  static const char* comps[4] = {"C1", "C2", "C3", "C4"};
  bool any = false;
  for (std::size_t i = 0; i + 1 < card.size() || i == 0; i += 2) {
    const std::size_t k = (i / 2) % 4;
    if (card.blank(i) && card.blank(i + 1)) continue;
    fem::DofSetEntry e;
    e.grid = card.id(i, ids[k]);
    e.c = card.components(i + 1, comps[k], true, true);
    e.ref = card.ref();
    out.push_back(e);
    any = true;
  }
  if (!any) card.fail(0, "ID1", "blank; expected grid or scalar point ids with components");
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

// SPC1 SID C G1 G2 ... (or G1 THRU G2)
void parse_spc1(const Card& card, ReaderState& st) {
  const int sid = card.id(0, "SID");
  const fem::ComponentMask c = card.components(1, "C", false, true);
  const std::vector<int> grids = id_list(card, 2, "G");
  if (grids.empty()) card.fail(2, "G1", "blank; expected grid or scalar point ids");
  for (const int g : grids) st.model.spcs.push_back({sid, g, c, 0.0, card.ref()});
}

// SPCADD SID S1 S2 ...
void parse_spcadd(const Card& card, ReaderState& st) {
  fem::SpcAdd a;
  a.sid = card.id(0, "SID");
  a.sets = id_list(card, 1, "S");
  if (a.sets.empty()) card.fail(1, "S1", "blank; expected SPC set ids");
  a.ref = card.ref();
  st.model.spcadds.push_back(std::move(a));
}

// ASET ID1 C1 ID2 C2 ...; ASET1 C ID1 ID2 ... (THRU); same for BSET/BSET1; SUPORT ID1 C1 ...
void parse_aset(const Card& card, ReaderState& st) { dof_pairs(card, st.model.aset); }
void parse_aset1(const Card& card, ReaderState& st) { dof_list(card, st.model.aset); }
void parse_bset(const Card& card, ReaderState& st) { dof_pairs(card, st.model.bset); }
void parse_bset1(const Card& card, ReaderState& st) { dof_list(card, st.model.bset); }
void parse_suport(const Card& card, ReaderState& st) { dof_pairs(card, st.model.suport); }

// FORCE SID G CID F N1 N2 N3; MOMENT SID G CID M N1 N2 N3
void parse_force(const Card& card, ReaderState& st) { point_load(card, st, fem::PointLoad::Kind::Force); }
void parse_moment(const Card& card, ReaderState& st) { point_load(card, st, fem::PointLoad::Kind::Moment); }

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

}  // namespace seflex::io::nastran
