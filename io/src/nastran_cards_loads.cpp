// Static loads besides FORCE/MOMENT/LOAD: PLOAD2, GRAV, RFORCE; thermal load sets TEMP, TEMPD,
// TEMPRB. Field layouts: MSC Nastran Quick Reference Guide (docs/nastran-support.md).
#include <string>

#include "seflex/io/nastran_cards.hpp"
#include "seflex/io/nastran_lines.hpp"

namespace seflex::io::nastran {
namespace {

/// Field index of the first non-blank field at or after i (card.size() if none).
std::size_t next_filled(const Card& card, std::size_t i) {
  while (i < card.size() && card.blank(i)) ++i;
  return i;
}

}  // namespace

// PLOAD2 SID P EID1 EID2 ... (any number, continuation lines tolerated) or PLOAD2 SID P EID1 THRU EID2.
void parse_pload2(const Card& card, ReaderState& st) {
  fem::PressureLoad l;
  l.sid = card.id(0, "SID");
  l.p = card.real(1, "P");
  const std::size_t n = card.size();
  std::size_t i = next_filled(card, 2);
  if (i >= n) card.fail(2, "EID1", "blank; expected at least one element id (CQUAD4 or CTRIA3)");
  const std::size_t thru = next_filled(card, i + 1);
  if (thru < n && card.kind(thru) == FieldKind::Text) {
    if (upper(card.raw(thru)) != "THRU") card.fail(thru, "EID2", card.got(thru) + "; expected an element id or THRU");
    const int first = card.id(i, "EID1");
    const std::size_t j = next_filled(card, thru + 1);
    const int last = card.id(j < n ? j : thru + 1, "EID2");
    if (last <= first)
      card.fail(j, "EID2", card.got(j) + " after THRU; expected an id greater than " + std::to_string(first));
    if (last - first > kMaxThru)
      card.fail(j, "EID2",
                std::to_string(first) + " THRU " + std::to_string(last) + " is more than " + std::to_string(kMaxThru) +
                    " ids; expected a smaller range");
    if (next_filled(card, j + 1) < n)
      card.fail(next_filled(card, j + 1), "EID",
                card.got(next_filled(card, j + 1)) + " after 'EID1 THRU EID2'; expected nothing more");
    l.thru = true;
    l.elements = {first, last};
  } else {
    for (; i < n; i = next_filled(card, i + 1)) {
      if (card.kind(i) == FieldKind::Text && upper(card.raw(i)) == "THRU")
        card.fail(i, "EID", "THRU after more than one element id; expected 'EID1 THRU EID2' alone");
      l.elements.push_back(card.id(i, "EIDi"));
    }
  }
  l.ref = card.ref();
  st.model.pressure_loads.push_back(std::move(l));
}

// GRAV SID CID A N1 N2 N3 MB
void parse_grav(const Card& card, ReaderState& st) {
  fem::GravityLoad g;
  g.sid = card.id(0, "SID");
  g.cid = card.integer_or(1, "CID", 0);
  if (g.cid < 0) card.fail(1, "CID", card.got(1) + "; expected a coordinate system id >= 0 or blank");
  g.a = card.real(2, "A");
  g.n = {card.real_or(3, "N1", 0.0), card.real_or(4, "N2", 0.0), card.real_or(5, "N3", 0.0)};
  if (g.n.squaredNorm() == 0.0)
    card.fail(3, "N1", "N1 = N2 = N3 = 0; expected an acceleration direction with a nonzero component");
  const int mb = card.integer_or(6, "MB", 0);
  if (mb != 0 && mb != -1)
    card.fail(6, "MB", card.got(6) + "; expected 0, -1 or blank (superelements are not supported)");
  if (card.used() > 7) card.fail_card("fields after MB (field 8); expected none");
  g.ref = card.ref();
  st.model.gravity_loads.push_back(g);
}

// RFORCE SID G CID A R1 R2 R3 METHOD / RACC MB IDRF
void parse_rforce(const Card& card, ReaderState& st) {
  fem::RotationalLoad r;
  r.sid = card.id(0, "SID");
  r.grid = card.integer_or(1, "G", 0);
  if (r.grid < 0) card.fail(1, "G", card.got(1) + "; expected a grid id, or 0 or blank for the basic origin");
  r.cid = card.integer_or(2, "CID", 0);
  if (r.cid < 0) card.fail(2, "CID", card.got(2) + "; expected a coordinate system id >= 0 or blank");
  r.a = card.real_or(3, "A", 0.0);
  r.r = {card.real_or(4, "R1", 0.0), card.real_or(5, "R2", 0.0), card.real_or(6, "R3", 0.0)};
  if (r.r.squaredNorm() == 0.0)
    card.fail(4, "R1", "R1 = R2 = R3 = 0; expected a rotation axis with a nonzero component");
  r.method = card.integer_or(7, "METHOD", 1);
  if (r.method != 1 && r.method != 2) card.fail(7, "METHOD", card.got(7) + "; expected 1, 2 or blank");
  if (r.method == 2)
    st.note_unsupported("RFORCE METHOD 2 (computed as METHOD 1: mass matrix times grid accelerations)", card.ref());
  r.racc = card.real_or(8, "RACC", 0.0);
  const int mb = card.integer_or(9, "MB", 0);
  if (mb != 0 && mb != -1)
    card.fail(9, "MB", card.got(9) + "; expected 0, -1 or blank (superelements are not supported)");
  if (card.integer_or(10, "IDRF", 0) != 0)
    card.fail(10, "IDRF", card.got(10) + "; expected 0 or blank (RFORCE on an element set is not supported)");
  if (card.used() > 11) card.fail_card("fields after IDRF; expected none");
  r.ref = card.ref();
  st.model.rotational_loads.push_back(r);
}

// TEMP SID G1 T1 G2 T2 G3 T3
void parse_temp(const Card& card, ReaderState& st) {
  static const char* names[3][2] = {{"G1", "T1"}, {"G2", "T2"}, {"G3", "T3"}};
  const int sid = card.id(0, "SID");
  for (std::size_t k = 0; k < 3; ++k) {
    const std::size_t b = 1 + 2 * k;
    if (k > 0 && card.blank(b) && card.blank(b + 1)) continue;
    fem::GridTemperature t;
    t.sid = sid;
    t.grid = card.id(b, names[k][0]);
    t.t = card.real(b + 1, names[k][1]);
    t.ref = card.ref();
    st.model.grid_temperatures.push_back(t);
  }
  if (card.used() > 7) card.fail_card("fields after T3; expected at most three grid-temperature pairs per TEMP card");
}

// TEMPD SID1 T1 SID2 T2 SID3 T3 SID4 T4
void parse_tempd(const Card& card, ReaderState& st) {
  static const char* names[4][2] = {{"SID1", "T1"}, {"SID2", "T2"}, {"SID3", "T3"}, {"SID4", "T4"}};
  for (std::size_t k = 0; k < 4; ++k) {
    const std::size_t b = 2 * k;
    if (k > 0 && card.blank(b) && card.blank(b + 1)) continue;
    fem::DefaultTemperature t;
    t.sid = card.id(b, names[k][0]);
    t.t = card.real(b + 1, names[k][1]);
    t.ref = card.ref();
    st.model.default_temperatures.push_back(t);
  }
  if (card.used() > 8) card.fail_card("fields after T4; expected at most four set-temperature pairs per TEMPD card");
}

// TEMPRB SID EID1 TA TB TP1A TP1B TP2A TP2B / TCA TDA TEA TFA TCB TDB TEB TFB / EID2 EID3 ... (THRU)
void parse_temprb(const Card& card, ReaderState& st) {
  fem::BarTemperature t;
  t.sid = card.id(0, "SID");
  t.element = card.id(1, "EID1");
  t.ta = card.real(2, "TA");
  t.tb = card.real(3, "TB");
  t.tp1a = card.real_or(4, "TP1A", 0.0);
  t.tp1b = card.real_or(5, "TP1B", 0.0);
  t.tp2a = card.real_or(6, "TP2A", 0.0);
  t.tp2b = card.real_or(7, "TP2B", 0.0);
  static const char* stress[8] = {"TCA", "TDA", "TEA", "TFA", "TCB", "TDB", "TEB", "TFB"};
  for (std::size_t k = 0; k < 8; ++k) card.real_or(8 + k, stress[k], 0.0);  // stress points: checked, not used
  t.ref = card.ref();
  st.model.bar_temperatures.push_back(t);
  for (const int eid : id_list(card, 16, "EIDi")) {
    fem::BarTemperature more = t;
    more.element = eid;
    st.model.bar_temperatures.push_back(more);
  }
}

}  // namespace seflex::io::nastran
