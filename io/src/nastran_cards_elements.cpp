// CBAR, CBEAM, BAROR, BEAMOR, CROD, CONROD, CQUAD4, CTRIA3, CONM2, CELAS1, CELAS2, RBE2.
#include <string>

#include "seflex/io/nastran_cards.hpp"

namespace seflex::io::nastran {
namespace {

/// OFFT: three letters, B or G for the orientation vector, then G or O for each end's offset.
/// An integer there is COSMIC NASTRAN's orientation flag F (COSMIC NASTRAN User's Manual, CBAR: 1:
/// X1-X3 is a vector, 2: X1 is G0, both in GA's displacement system; offsets at the grids in their
/// displacement systems): exactly MSC's GGG, the default, so read as blank; F must agree with field 6.
std::string offt(const Card& card, std::size_t i, ReaderState&) {
  if (card.kind(i) == FieldKind::Integer) {
    const int f = card.integer(i, "OFFT");
    const bool g0 = card.kind(i - 3) == FieldKind::Integer;
    if ((f == 1 && !g0) || (f == 2 && g0)) return "";
    card.fail(i, "OFFT", card.got(i) + "; expected one of GGG, BGG, GGO, BGO, GOG, BOG, GOO, BOO (or COSMIC's flag F: 1 with a vector X1-X3, 2 with G0)");
  }
  std::string s = card.text_or(i, "OFFT", "");
  if (s.empty()) return s;
  if (s.size() != 3 || (s[0] != 'G' && s[0] != 'B') || (s[1] != 'G' && s[1] != 'O') || (s[2] != 'G' && s[2] != 'O'))
    card.fail(i, "OFFT", card.got(i) + "; expected one of GGG, BGG, GGO, BGO, GOG, BOG, GOO, BOO");
  return s;
}

/// Orientation in fields i..i+2: G0 (integer) or the vector X1 X2 X3 (reals). Returns false if all blank.
bool orientation(const Card& card, std::size_t i, bool& has_g0, int& g0, Eigen::Vector3d& v) {
  switch (card.kind(i)) {
    case FieldKind::Integer:
      g0 = card.id(i, "G0");
      has_g0 = true;
      if (!card.blank(i + 1) || !card.blank(i + 2))
        card.fail(i + 1, "X2", card.got(i + 1) + " after G0 in field " + std::to_string(i % 8 + 2) +
                                   "; expected blank fields after an orientation grid");
      return true;
    case FieldKind::Blank:
      if (card.blank(i + 1) && card.blank(i + 2)) return false;
      [[fallthrough]];
    case FieldKind::Real:
      has_g0 = false;
      v = {card.real_or(i, "X1", 0.0), card.real_or(i + 1, "X2", 0.0), card.real_or(i + 2, "X3", 0.0)};
      if (v.squaredNorm() == 0.0)
        card.fail(i, "X1", "the orientation vector (X1, X2, X3) is zero; expected a non-zero vector or a grid G0");
      return true;
    default:
      card.fail(i, "X1/G0", card.got(i) + "; expected an orientation grid id (integer) or X1 (real)");
  }
}

void check_distinct(const Card& card, const int* g, std::size_t n, std::size_t first, const char* const* names) {
  for (std::size_t a = 0; a < n; ++a)
    for (std::size_t b = a + 1; b < n; ++b)
      if (g[a] == g[b])
        card.fail(first + b, names[b], "grid " + std::to_string(g[b]) + " repeats " + names[a] +
                                           "; expected distinct grids");
}

// The two distinct end grids of a line element, in fields first and first + 1.
void line_ends(const Card& card, std::size_t first, const char* na, const char* nb, int& ga, int& gb) {
  ga = card.id(first, na);
  gb = card.id(first + 1, nb);
  const char* names[2] = {na, nb};
  const int ends[2] = {ga, gb};
  check_distinct(card, ends, 2, first, names);
}

void parse_bar_like(const Card& card, ReaderState& st, bool beam) {
  fem::Bar b;
  b.is_beam = beam;
  b.id = card.id(0, "EID");
  b.pid = card.id_or(1, "PID", 0);  // blank: BAROR/BEAMOR PID, else EID (applied after reading)
  line_ends(card, 2, "GA", "GB", b.ga, b.gb);
  orientation(card, 4, b.has_g0, b.g0, b.v);
  if (beam && card.kind(7) == FieldKind::Real)
    st.note_unsupported("CBEAM BIT (built-in twist ignored)", card.ref());
  else
    b.offt = offt(card, 7, st);
  // 0: no pin flags, as blank (MSC's test decks dbxdra2, d200obus write it)
  b.pa = card.raw(8) == "0" ? fem::ComponentMask{0} : card.components(8, "PA", true);
  b.pb = card.raw(9) == "0" ? fem::ComponentMask{0} : card.components(9, "PB", true);
  b.wa = {card.real_or(10, "W1A", 0.0), card.real_or(11, "W2A", 0.0), card.real_or(12, "W3A", 0.0)};
  b.wb = {card.real_or(13, "W1B", 0.0), card.real_or(14, "W2B", 0.0), card.real_or(15, "W3B", 0.0)};
  if (beam && (card.integer_or(16, "SA", 0) != 0 || card.integer_or(17, "SB", 0) != 0))
    st.note_unsupported("CBEAM SA/SB (warping scalar points and PBEAM CW ignored)", card.ref());
  b.ref = card.ref();
  st.model.bars.push_back(b);
}

void parse_bar_defaults(const Card& card, ReaderState& st, fem::BarDefaults& d) {
  if (d.present) {
    card.fail_card("a second " + std::string(card.name()) + " (the first is at " + st.where(d.ref) + "); expected at most one");
  }
  d.present = true;
  d.ref = card.ref();
  d.pid = card.id_or(1, "PID", 0);
  orientation(card, 4, d.has_g0, d.g0, d.v);
  if (card.name() == "BEAMOR" && card.kind(7) == FieldKind::Real)
    st.note_unsupported("BEAMOR BIT (built-in twist ignored)", card.ref());
  else
    d.offt = offt(card, 7, st);
  if (d.offt.empty()) d.offt = "GGG";
}

/// THETA (real, degrees) or MCID (integer >= 0) in field i.
void theta_mcid(const Card& card, std::size_t i, fem::Shell& s) {
  switch (card.kind(i)) {
    case FieldKind::Blank: return;
    case FieldKind::Real: s.theta_deg = card.real(i, "THETA"); return;
    case FieldKind::Integer:
      s.mcid = card.integer(i, "MCID");
      if (s.mcid < 0) card.fail(i, "MCID", card.got(i) + "; expected a coordinate system id >= 0");
      s.theta_is_mcid = true;
      return;
    default: card.fail(i, "THETA/MCID", card.got(i) + "; expected THETA (real, degrees) or MCID (integer)");
  }
}

void parse_shell(const Card& card, ReaderState& st, std::uint8_t nnode) {
  static const char* gnames[4] = {"G1", "G2", "G3", "G4"};
  static const char* tnames[4] = {"T1", "T2", "T3", "T4"};
  fem::Shell s;
  s.nnode = nnode;
  s.drilling = card.name() == "CQUADR" || card.name() == "CTRIAR";  // the same fields as CQUAD4 / CTRIA3
  s.id = card.id(0, "EID");
  s.pid = card.id_or(1, "PID", s.id);
  for (std::size_t k = 0; k < nnode; ++k) s.g[k] = card.id(2 + k, gnames[k]);
  check_distinct(card, s.g.data(), nnode, 2, gnames);
  theta_mcid(card, 2 + nnode, s);
  s.zoffs = card.real_or(3 + nnode, "ZOFFS", 0.0);
  if (card.size() > 8) {
    if (card.kind(10) == FieldKind::Real) {
      // TFLAG written as a real: 0. and 1. are read as 0 and 1 (listed); a fraction such as .63 is
      // likely a thickness one column to the left of T1 (an older layout): read as 0 and listed as
      // refused, since which thickness is meant is not known.
      const double t = card.real(10, "TFLAG");
      if (t == 0.0 || t == 1.0) {
        s.tflag = static_cast<int>(t);
        st.note_unsupported("CQUAD4/CTRIA3 TFLAG written as a real (0. or 1.)", card.ref());
      } else {
        s.tflag = 0;
        st.note_unsupported(kShellTflagFraction, card.ref());
      }
    } else {
      s.tflag = card.integer_or(10, "TFLAG", 0);
      if (s.tflag != 0 && s.tflag != 1) card.fail(10, "TFLAG", card.got(10) + "; expected 0, 1 or blank");
    }
    for (std::size_t k = 0; k < nnode; ++k) {
      s.t[k] = card.real_or(11 + k, tnames[k], 0.0);
      if (s.t[k] < 0.0) card.fail(11 + k, tnames[k], card.got(11 + k) + "; expected a thickness >= 0 or blank");
    }
  }
  s.ref = card.ref();
  st.model.shells.push_back(s);
}

/// A spring's grid or scalar point and its component (0..6; 0 or blank for a scalar point).
void spring_end(const Card& card, std::size_t i, const char* gname, const char* cname, int& g, int& c) {
  g = card.integer_or(i, gname, 0);
  if (g < 0) card.fail(i, gname, card.got(i) + "; expected a grid or scalar point id, or blank (grounded)");
  c = card.integer_or(i + 1, cname, 0);
  if (c < 0 || c > 6) card.fail(i + 1, cname, card.got(i + 1) + "; expected one component 1-6 (0 or blank for a scalar point)");
}

/// G1 C1 G2 C2 in fields 4-7 of CELAS1/CELAS2, and the card's location.
void spring_ends(const Card& card, fem::Spring& s) {
  spring_end(card, 2, "G1", "C1", s.g1, s.c1);
  spring_end(card, 4, "G2", "C2", s.g2, s.c2);
  if (s.g1 == 0 && s.g2 == 0) card.fail(2, "G1", "G1 and G2 are both blank; expected at least one grid or scalar point");
  if (s.g1 == s.g2 && s.c1 == s.c2) card.fail(4, "G2", "both ends are the same degree of freedom; expected two different ones");
  s.ref = card.ref();
}

}  // namespace

// CBAR EID PID GA GB X1/G0 X2 X3 OFFT / PA PB W1A W2A W3A W1B W2B W3B
void parse_cbar(const Card& card, ReaderState& st) { parse_bar_like(card, st, false); }
// CBEAM EID PID GA GB X1/G0 X2 X3 OFFT/BIT / PA PB W1A W2A W3A W1B W2B W3B / SA SB
void parse_cbeam(const Card& card, ReaderState& st) { parse_bar_like(card, st, true); }
// BAROR - PID - - X1/G0 X2 X3 OFFT
void parse_baror(const Card& card, ReaderState& st) { parse_bar_defaults(card, st, st.model.baror); }
void parse_beamor(const Card& card, ReaderState& st) { parse_bar_defaults(card, st, st.model.beamor); }

// CROD EID PID G1 G2
void parse_crod(const Card& card, ReaderState& st) {
  fem::Rod r;
  r.tube = card.name() == "CTUBE";  // CTUBE EID PID G1 G2: a CROD on a PTUBE
  r.id = card.id(0, "EID");
  r.pid = card.id_or(1, "PID", r.id);
  line_ends(card, 2, "G1", "G2", r.ga, r.gb);
  if (r.tube && card.used() > 4) card.fail(4, "", card.got(4) + " after G2; expected one tube per CTUBE card");
  r.ref = card.ref();
  st.model.rods.push_back(r);
}

// CONROD EID G1 G2 MID A J C NSM
void parse_conrod(const Card& card, ReaderState& st) {
  fem::Rod r;
  r.id = card.id(0, "EID");
  line_ends(card, 1, "G1", "G2", r.ga, r.gb);
  r.inline_property = true;
  r.mid = card.id(3, "MID");
  r.A = card.real(4, "A");
  r.J = card.real_or(5, "J", 0.0);
  r.C = card.real_or(6, "C", 0.0);
  r.nsm = card.real_or(7, "NSM", 0.0);
  if (r.A < 0.0) card.fail(4, "A", card.got(4) + "; expected an area >= 0");
  r.ref = card.ref();
  st.model.rods.push_back(r);
}

// CQUAD4 EID PID G1 G2 G3 G4 THETA/MCID ZOFFS / - - TFLAG T1 T2 T3 T4
void parse_cquad4(const Card& card, ReaderState& st) { parse_shell(card, st, 4); }
// CTRIA3 EID PID G1 G2 G3 THETA/MCID ZOFFS - / - - TFLAG T1 T2 T3
void parse_ctria3(const Card& card, ReaderState& st) { parse_shell(card, st, 3); }

// CONM2 EID G CID M X1 X2 X3 - / I11 I21 I22 I31 I32 I33
void parse_conm2(const Card& card, ReaderState& st) {
  fem::Conm2 m;
  m.id = card.id(0, "EID");
  m.grid = card.id(1, "G");
  m.cid = card.integer_or(2, "CID", 0);
  if (m.cid < -1) card.fail(2, "CID", card.got(2) + "; expected -1, 0, a coordinate system id or blank");
  m.m = card.real_or(3, "M", 0.0);
  m.x = {card.real_or(4, "X1", 0.0), card.real_or(5, "X2", 0.0), card.real_or(6, "X3", 0.0)};
  m.I11 = card.real_or(8, "I11", 0.0);
  m.I21 = card.real_or(9, "I21", 0.0);
  m.I22 = card.real_or(10, "I22", 0.0);
  m.I31 = card.real_or(11, "I31", 0.0);
  m.I32 = card.real_or(12, "I32", 0.0);
  m.I33 = card.real_or(13, "I33", 0.0);
  if (m.I11 < 0.0) card.fail(8, "I11", card.got(8) + "; expected a moment of inertia >= 0");
  if (m.I22 < 0.0) card.fail(10, "I22", card.got(10) + "; expected a moment of inertia >= 0");
  if (m.I33 < 0.0) card.fail(13, "I33", card.got(13) + "; expected a moment of inertia >= 0");
  m.ref = card.ref();
  st.model.conm2.push_back(m);
}

// CELAS1 EID PID G1 C1 G2 C2
void parse_celas1(const Card& card, ReaderState& st) {
  fem::Spring s;
  s.id = card.id(0, "EID");
  s.pid = card.id_or(1, "PID", s.id);
  spring_ends(card, s);
  st.model.springs.push_back(s);
}

// CELAS2 EID K G1 C1 G2 C2 GE S
void parse_celas2(const Card& card, ReaderState& st) {
  fem::Spring s;
  s.id = card.id(0, "EID");
  s.inline_property = true;
  s.k = card.real(1, "K");
  spring_ends(card, s);
  s.ge = card.real_or(6, "GE", 0.0);
  s.s = card.real_or(7, "S", 0.0);
  st.model.springs.push_back(s);
}

// RBE2 EID GN CM GM1 GM2 ... [ALPHA]
void parse_rbe2(const Card& card, ReaderState& st) {
  fem::Rbe2 r;
  r.id = card.id(0, "EID");
  r.gn = card.id(1, "GN");
  r.cm = card.components(2, "CM", false);
  std::size_t stop = 0;
  r.gm = id_list(card, 3, "GM", true, &stop);
  if (stop < card.size()) {
    card.real(stop, "ALPHA");  // thermal expansion coefficient: checked, not used
    for (std::size_t i = stop + 1; i < card.size(); ++i)
      if (!card.blank(i)) card.fail(i, "GM", card.got(i) + " after ALPHA; expected nothing after ALPHA");
  }
  if (r.gm.empty()) card.fail(3, "GM1", "blank; expected at least one dependent grid");
  for (const int g : r.gm)
    if (g == r.gn) card.fail(3, "GM", "the independent grid " + std::to_string(g) + " is also dependent; expected GMi different from GN");
  r.ref = card.ref();
  st.model.rbe2.push_back(std::move(r));
}

// CSHEAR EID PID G1 G2 G3 G4 (PID blank: EID)
void parse_cshear(const Card& card, ReaderState& st) {
  fem::ShearPanel e;
  e.id = card.id(0, "EID");
  e.pid = card.id_or(1, "PID", e.id);
  static const char* names[4] = {"G1", "G2", "G3", "G4"};
  for (std::size_t k = 0; k < 4; ++k) e.g[k] = card.id(2 + k, names[k]);
  check_distinct(card, e.g.data(), 4, 2, names);
  if (card.used() > 6) card.fail(6, "", card.got(6) + " after G4; expected nothing more");
  e.ref = card.ref();
  st.model.shear_panels.push_back(e);
}

// CBEND EID PID GA GB X1 X2 X3 GEOM, or G0 in field 6 (PID blank: EID)
void parse_cbend(const Card& card, ReaderState& st) {
  fem::Bend b;
  b.id = card.id(0, "EID");
  b.pid = card.id_or(1, "PID", b.id);
  line_ends(card, 2, "GA", "GB", b.ga, b.gb);
  if (!orientation(card, 4, b.has_g0, b.g0, b.v))
    card.fail(4, "X1/G0", "blank; expected an orientation grid G0 or vector X1 X2 X3 (the plane of the bend)");
  if (b.has_g0 && (b.g0 == b.ga || b.g0 == b.gb)) card.fail(4, "G0", "G0 is an end of the element; expected a third grid");
  b.geom = card.integer(7, "GEOM");
  if (b.geom < 1 || b.geom > 4) card.fail(7, "GEOM", card.got(7) + "; expected 1, 2, 3 or 4 (QRG CBEND)");
  if (card.used() > 8) card.fail(8, "", card.got(8) + " after GEOM; expected nothing more");
  b.ref = card.ref();
  st.model.bends.push_back(b);
}

// CQUAD8 EID PID G1 G2 G3 G4 G5 G6 / G7 G8 T1 T2 T3 T4 THETA/MCID ZOFFS / TFLAG
// CTRIA6 EID PID G1 G2 G3 G4 G5 G6 / THETA/MCID ZOFFS T1 T2 T3 TFLAG
// Mid-side grids (G5-G8, G4-G6) may be blank: that edge is straight (QRG CQUAD8, CTRIA6).
void parse_shell8(const Card& card, ReaderState& st) {
  const bool quad = card.name() == "CQUAD8";
  const std::size_t nc = quad ? 4 : 3;
  static const char* gnames[8] = {"G1", "G2", "G3", "G4", "G5", "G6", "G7", "G8"};
  static const char* tnames[4] = {"T1", "T2", "T3", "T4"};
  fem::QuadraticShell q;
  fem::Shell& s = q.shell;
  s.nnode = static_cast<std::uint8_t>(nc);
  s.id = card.id(0, "EID");
  s.pid = card.id_or(1, "PID", s.id);
  for (std::size_t k = 0; k < nc; ++k) s.g[k] = card.id(2 + k, gnames[k]);
  check_distinct(card, s.g.data(), nc, 2, gnames);
  int all[8] = {s.g[0], s.g[1], s.g[2], s.g[3]};
  for (std::size_t k = 0; k < nc; ++k) {
    q.mid[k] = card.integer_or(2 + nc + k, gnames[nc + k], 0);
    if (q.mid[k] < 0) card.fail(2 + nc + k, gnames[nc + k], card.got(2 + nc + k) + "; expected a grid id or blank (a straight edge)");
    all[nc + k] = q.mid[k];
  }
  for (std::size_t a = 0; a < 2 * nc; ++a)
    for (std::size_t b = a + 1; b < 2 * nc; ++b)
      if (all[b] != 0 && all[a] == all[b])
        card.fail(2 + b, gnames[b], "grid " + std::to_string(all[b]) + " repeats " + gnames[a] + "; expected distinct grids");
  const std::size_t t0 = 10;  // T1: field 4 of the second line of both
  const std::size_t theta = quad ? 14 : 8, zoffs = quad ? 15 : 9, tflag = quad ? 16 : 13;
  for (std::size_t k = 0; k < nc; ++k) {
    s.t[k] = card.real_or(t0 + k, tnames[k], 0.0);
    if (s.t[k] < 0.0) card.fail(t0 + k, tnames[k], card.got(t0 + k) + "; expected a thickness >= 0 or blank");
  }
  theta_mcid(card, theta, s);
  s.zoffs = card.real_or(zoffs, "ZOFFS", 0.0);
  s.tflag = card.integer_or(tflag, "TFLAG", 0);
  if (s.tflag != 0 && s.tflag != 1) card.fail(tflag, "TFLAG", card.got(tflag) + "; expected 0, 1 or blank");
  if (card.used() > tflag + 1) card.fail(tflag + 1, "", card.got(tflag + 1) + " after TFLAG; expected nothing more");
  s.ref = card.ref();
  st.model.shells8.push_back(q);
}

}  // namespace seflex::io::nastran
