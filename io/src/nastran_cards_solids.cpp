// Solid elements and face pressures: CHEXA, CPENTA, CTETRA, CPYRAM, PSOLID, PLOAD4. Field layouts: MSC
// Nastran Quick Reference Guide (docs/nastran-support.md).
#include <cstdint>
#include <string>

#include "seflex/io/nastran_cards.hpp"
#include "seflex/io/nastran_lines.hpp"

namespace seflex::io::nastran {
namespace {

const char* const kGridNames[20] = {"G1",  "G2",  "G3",  "G4",  "G5",  "G6",  "G7",  "G8",  "G9",  "G10",
                                    "G11", "G12", "G13", "G14", "G15", "G16", "G17", "G18", "G19", "G20"};

/// EID PID G1 ... : `corners` grids required, then any of the `total - corners` mid-edge grids (a
/// blank or 0 one makes its edge straight, QRG CHEXA/CPENTA/CTETRA/CPYRAM): stored as fem::Solid says.
void parse_solid(const Card& card, ReaderState& st, fem::Solid::Shape shape, int corners, int total) {
  fem::Solid s;
  s.shape = shape;
  s.id = card.id(0, "EID");
  s.pid = card.id(1, "PID");
  for (int k = 0; k < corners; ++k) s.g[static_cast<std::size_t>(k)] = card.id(2 + static_cast<std::size_t>(k), kGridNames[k]);
  int n = corners;
  std::uint16_t missing = 0;
  int qrg[20];  // QRG grid index (0-based) of each stored grid
  for (int k = 0; k < corners; ++k) qrg[k] = k;
  for (int k = corners; k < total; ++k) {
    const std::size_t i = 2 + static_cast<std::size_t>(k);
    if (card.blank(i) || (card.kind(i) == FieldKind::Integer && card.integer(i, kGridNames[k]) == 0)) {
      missing = static_cast<std::uint16_t>(missing | 1u << (k - corners));
      continue;
    }
    qrg[n] = k;
    s.g[static_cast<std::size_t>(n++)] = card.id(i, kGridNames[k]);
  }
  if (card.used() > 2 + static_cast<std::size_t>(total))
    card.fail(2 + static_cast<std::size_t>(total), "G", card.got(2 + static_cast<std::size_t>(total)) +
                                                       "; expected at most " + std::to_string(total) + " grids");
  s.ref = card.ref();
  s.nnode = static_cast<std::uint8_t>(n);
  s.missing_mid = n > corners ? missing : 0;
  for (int a = 0; a < s.nnode; ++a)
    for (int b = a + 1; b < s.nnode; ++b)
      if (s.g[static_cast<std::size_t>(a)] == s.g[static_cast<std::size_t>(b)])
        card.fail(2 + static_cast<std::size_t>(qrg[b]), kGridNames[qrg[b]],
                  "grid " + std::to_string(s.g[static_cast<std::size_t>(b)]) + " repeats " + kGridNames[qrg[a]] +
                      "; expected distinct grids");
  st.model.solids.push_back(s);
}

}  // namespace

// CHEXA EID PID G1 G2 G3 G4 G5 G6 / G7 ... G14 / G15 ... G20
void parse_chexa(const Card& card, ReaderState& st) { parse_solid(card, st, fem::Solid::Shape::Hexa, 8, 20); }
// CPENTA EID PID G1 G2 G3 G4 G5 G6 / G7 ... G14 / G15
void parse_cpenta(const Card& card, ReaderState& st) { parse_solid(card, st, fem::Solid::Shape::Penta, 6, 15); }
// CTETRA EID PID G1 G2 G3 G4 G5 G6 / G7 ... G10
void parse_ctetra(const Card& card, ReaderState& st) { parse_solid(card, st, fem::Solid::Shape::Tetra, 4, 10); }
// CPYRAM EID PID G1 G2 G3 G4 G5 G6 / G7 ... G13 (G1-G4 the base, G5 the apex)
void parse_cpyram(const Card& card, ReaderState& st) { parse_solid(card, st, fem::Solid::Shape::Pyram, 5, 13); }

// PSOLID PID MID CORDM IN STRESS ISOP FCTN
void parse_psolid(const Card& card, ReaderState& st) {
  fem::SolidProperty p;
  p.id = card.id(0, "PID");
  p.mid = card.id(1, "MID");
  p.cordm = card.integer_or(2, "CORDM", 0);
  if (p.cordm < -1) card.fail(2, "CORDM", card.got(2) + "; expected -1, 0, a coordinate system id or blank");
  using In = fem::SolidProperty::Integration;
  const std::string in = card.kind(3) == FieldKind::Integer ? std::to_string(card.integer(3, "IN")) : card.text_or(3, "IN", "");
  if (in.empty()) p.in = In::Default;
  else if (in == "0" || in == "BUBBLE") p.in = In::Bubble;
  else if (in == "2" || in == "TWO") p.in = In::Two;
  else if (in == "3" || in == "THREE") p.in = In::Three;
  else card.fail(3, "IN", card.got(3) + "; expected 0/BUBBLE, 2/TWO, 3/THREE or blank");
  // STRESS: 0 or GRID, 1 or GAUSS (integers as in IN and ISOP; gpst17, an MSC test deck, has 1)
  p.stress = card.kind(4) == FieldKind::Integer ? std::to_string(card.integer(4, "STRESS")) : card.text_or(4, "STRESS", "");
  if (card.kind(4) == FieldKind::Integer && p.stress != "0" && p.stress != "1")
    card.fail(4, "STRESS", card.got(4) + "; expected 0/GRID, 1/GAUSS or blank");
  using Isop = fem::SolidProperty::Isop;
  const std::string isop = card.kind(5) == FieldKind::Integer ? std::to_string(card.integer(5, "ISOP")) : card.text_or(5, "ISOP", "");
  if (isop.empty()) p.isop = Isop::Default;
  else if (isop == "0" || isop == "REDUCED") p.isop = Isop::Reduced;
  else if (isop == "1" || isop == "FULL") p.isop = Isop::Full;
  else card.fail(5, "ISOP", card.got(5) + "; expected 0/REDUCED, 1/FULL or blank (other schemes are not modelled)");
  p.fctn = card.text_or(6, "FCTN", "");
  if (card.used() > 7) card.fail_card("fields after FCTN (field 8); expected none");
  if (p.fctn == "PFLUID") {
    // A fluid (acoustic) property: not kept; its elements are left out by fem::finalize and every
    // solution refuses the deck.
    st.note_unsupported_member(kFluidSolid, p.id, card.ref());
    return;
  }
  if (!p.fctn.empty() && p.fctn != "SMECH")
    card.fail(6, "FCTN", card.got(6) + "; expected SMECH, PFLUID (a fluid, listed as unsupported) or blank");
  if (!p.stress.empty()) st.note_unsupported("PSOLID STRESS (stress output system; seflex gives no stresses)", card.ref());
  if (p.cordm != 0) st.note_unsupported("PSOLID CORDM (material axes: no effect with an isotropic MAT1)", card.ref());
  p.ref = card.ref();
  st.model.solid_props.push_back(p);
}

// PLOAD4 SID EID P1 P2 P3 P4 G1 G3/G4 / CID N1 N2 N3 SORL LDIR
// PLOAD4 SID EID1 P1 P2 P3 P4 THRU EID2 / CID N1 N2 N3 SORL LDIR
void parse_pload4(const Card& card, ReaderState& st) {
  fem::FaceLoad l;
  l.sid = card.id(0, "SID");
  l.eid = card.id(1, "EID");
  l.p[0] = card.real_or(2, "P1", 0.0);
  static const char* pn[4] = {"P1", "P2", "P3", "P4"};
  for (std::size_t k = 1; k < 4; ++k) l.p[k] = card.real_or(2 + k, pn[k], l.p[0]);
  if (card.kind(6) == FieldKind::Text) {
    if (upper(card.raw(6)) != "THRU") card.fail(6, "G1/THRU", card.got(6) + "; expected a grid id, THRU or blank");
    l.eid_last = card.id(7, "EID2");
    if (l.eid_last <= l.eid)
      card.fail(7, "EID2", card.got(7) + " after THRU; expected an id greater than " + std::to_string(l.eid));
    if (l.eid_last - l.eid > kMaxThru)
      card.fail(7, "EID2", "a range of more than " + std::to_string(kMaxThru) + " ids; expected a smaller range");
  } else {
    l.g1 = card.integer_or(6, "G1", 0);
    l.g34 = card.integer_or(7, "G3/G4", 0);
    if (l.g1 < 0) card.fail(6, "G1", card.got(6) + "; expected a grid id or blank");
    if (l.g34 < 0) card.fail(7, "G3/G4", card.got(7) + "; expected a grid id or blank");
  }
  l.cid = card.integer_or(8, "CID", 0);
  if (l.cid < 0) card.fail(8, "CID", card.got(8) + "; expected a coordinate system id >= 0 or blank");
  l.n = {card.real_or(9, "N1", 0.0), card.real_or(10, "N2", 0.0), card.real_or(11, "N3", 0.0)};
  const std::string sorl = card.text_or(12, "SORL", "SURF"), ldir = card.text_or(13, "LDIR", "NORM");
  if (sorl != "SURF")
    card.fail(12, "SORL", card.got(12) + "; expected SURF or blank (edge line loads are not supported)");
  if (ldir != "NORM")
    card.fail(13, "LDIR", card.got(13) + "; expected NORM or blank (edge line loads are not supported)");
  if (card.used() > 14) card.fail_card("fields after LDIR (field 7 of the continuation); expected none");
  l.ref = card.ref();
  st.model.face_loads.push_back(l);
}

}  // namespace seflex::io::nastran
