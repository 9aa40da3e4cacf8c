// CBUSH, PBUSH, CBUSH1D, PBUSH1D, CELAS3, CELAS4, CMASS1-4, PMASS, CONM1, TABLEM1-4. Field layouts: MSC Nastran Quick Reference
// Guide (docs/nastran-support.md).
#include <string>

#include "seflex/io/nastran_cards.hpp"
#include "seflex/io/nastran_lines.hpp"

namespace seflex::io::nastran {
namespace {

/// A grid or scalar point id (0 = blank, grounded) and, unless scalar_only, its component 0..6.
void scalar_end(const Card& card, std::size_t i, bool scalar_only, const char* gname, const char* cname, int& g, int& c) {
  g = card.integer_or(i, gname, 0);
  if (g < 0) card.fail(i, gname, card.got(i) + "; expected a grid or scalar point id, or blank (grounded)");
  c = 0;
  if (scalar_only) return;
  c = card.integer_or(i + 1, cname, 0);
  if (c < 0 || c > 6) card.fail(i + 1, cname, card.got(i + 1) + "; expected one component 1-6 (0 or blank for a scalar point)");
}

/// Both ends of a CELASi/CMASSi: fields 4-7 (G1 C1 G2 C2) or 4-5 (S1 S2, scalar points).
template <class E>
void scalar_ends(const Card& card, bool scalar_only, E& s) {
  if (scalar_only) {
    scalar_end(card, 2, true, "S1", "", s.g1, s.c1);
    scalar_end(card, 3, true, "S2", "", s.g2, s.c2);
  } else {
    scalar_end(card, 2, false, "G1", "C1", s.g1, s.c1);
    scalar_end(card, 4, false, "G2", "C2", s.g2, s.c2);
  }
  if (s.g1 == 0 && s.g2 == 0) card.fail(2, scalar_only ? "S1" : "G1", "both ends are blank; expected at least one grid or scalar point");
  if (s.g1 == s.g2 && s.c1 == s.c2)
    card.fail(scalar_only ? 3 : 4, scalar_only ? "S2" : "G2", "both ends are the same degree of freedom; expected two different ones");
  s.ref = card.ref();
}

}  // namespace

// CELAS3 EID PID S1 S2
void parse_celas3(const Card& card, ReaderState& st) {
  fem::Spring s;
  s.id = card.id(0, "EID");
  s.pid = card.id_or(1, "PID", s.id);
  s.scalar_points = true;
  scalar_ends(card, true, s);
  st.model.springs.push_back(s);
}

// CELAS4 EID K S1 S2
void parse_celas4(const Card& card, ReaderState& st) {
  fem::Spring s;
  s.id = card.id(0, "EID");
  s.inline_property = true;
  s.scalar_points = true;
  s.k = card.real(1, "K");
  scalar_ends(card, true, s);
  st.model.springs.push_back(s);
}

// CMASS1 EID PID G1 C1 G2 C2 / CMASS3 EID PID S1 S2
void parse_cmass1(const Card& card, ReaderState& st) {
  fem::ScalarMass s;
  s.id = card.id(0, "EID");
  s.pid = card.id_or(1, "PID", s.id);
  s.scalar_points = card.name() == "CMASS3";
  scalar_ends(card, s.scalar_points, s);
  st.model.scalar_masses.push_back(s);
}

// CMASS2 EID M G1 C1 G2 C2 / CMASS4 EID M S1 S2
void parse_cmass2(const Card& card, ReaderState& st) {
  fem::ScalarMass s;
  s.id = card.id(0, "EID");
  s.inline_property = true;
  s.m = card.real_or(1, "M", 0.0);
  s.scalar_points = card.name() == "CMASS4";
  scalar_ends(card, s.scalar_points, s);
  st.model.scalar_masses.push_back(s);
}

// PMASS PID1 M1 PID2 M2 PID3 M3 PID4 M4
void parse_pmass(const Card& card, ReaderState& st) {
  static const char* names[4][2] = {{"PID1", "M1"}, {"PID2", "M2"}, {"PID3", "M3"}, {"PID4", "M4"}};
  for (std::size_t k = 0; k < 4; ++k) {
    if (k > 0 && card.blank(2 * k) && card.blank(2 * k + 1)) continue;
    fem::MassProperty p;
    p.id = card.id(2 * k, names[k][0]);
    p.m = card.real_or(2 * k + 1, names[k][1], 0.0);
    p.ref = card.ref();
    st.model.mass_props.push_back(p);
  }
}

// CONM1 EID G CID M11 M21 M22 M31 M32 / M33 M41 M42 M43 M44 M51 M52 M53 / M54 M55 M61 M62 M63 M64 M65 M66
void parse_conm1(const Card& card, ReaderState& st) {
  fem::Conm1 c;
  c.id = card.id(0, "EID");
  c.grid = card.id(1, "G");
  c.cid = card.integer_or(2, "CID", 0);
  if (c.cid < 0) card.fail(2, "CID", card.got(2) + "; expected a coordinate system id >= 0 or blank");
  std::size_t i = 3;
  for (int r = 0; r < 6; ++r)
    for (int col = 0; col <= r; ++col, ++i) {
      const std::string name = "M" + std::to_string(r + 1) + std::to_string(col + 1);
      c.M(r, col) = c.M(col, r) = card.real_or(i, name.c_str(), 0.0);
    }
  for (int r = 0; r < 6; ++r)
    if (c.M(r, r) < 0.0) {
      const std::size_t i_rr = 3 + static_cast<std::size_t>(r * (r + 3) / 2);  // Mrr follows the r terms of row r
      const std::string name = "M" + std::to_string(r + 1) + std::to_string(r + 1);
      card.fail(i_rr, name.c_str(), card.got(i_rr) + "; expected a diagonal term >= 0");
    }
  c.ref = card.ref();
  st.model.conm1.push_back(c);
}

namespace {
/// EID PID GA GB of CBUSH and CBUSH1D (blank PID = EID; blank GB = grounded).
fem::Bush bush_ends(const Card& card) {
  fem::Bush b;
  b.id = card.id(0, "EID");
  b.pid = card.id_or(1, "PID", b.id);
  b.ga = card.id(2, "GA");
  b.gb = card.integer_or(3, "GB", 0);
  if (b.gb < 0) card.fail(3, "GB", card.got(3) + "; expected a grid id or blank (grounded)");
  if (b.gb == b.ga) card.fail(3, "GB", "GB is GA; expected a second grid or blank (grounded)");
  return b;
}
}  // namespace

// CBUSH EID PID GA GB GO/X1 X2 X3 CID / S OCID S1 S2 S3
void parse_cbush(const Card& card, ReaderState& st) {
  fem::Bush b = bush_ends(card);
  switch (card.kind(4)) {
    case FieldKind::Integer:
      b.g0 = card.id(4, "GO");
      b.has_g0 = true;
      if (!card.blank(5) || !card.blank(6)) card.fail(5, "X2", card.got(5) + " after GO; expected blank fields after an orientation grid");
      if (b.g0 == b.ga || b.g0 == b.gb) card.fail(4, "GO", "GO is an end of the element; expected a third grid");
      break;
    case FieldKind::Blank:
      if (card.blank(5) && card.blank(6)) break;
      [[fallthrough]];
    case FieldKind::Real:
      b.v = {card.real_or(4, "X1", 0.0), card.real_or(5, "X2", 0.0), card.real_or(6, "X3", 0.0)};
      b.has_v = b.v.squaredNorm() > 0.0;
      break;
    default: card.fail(4, "GO/X1", card.got(4) + "; expected an orientation grid id (integer) or X1 (real)");
  }
  b.cid = card.integer_or(7, "CID", -1);
  if (b.cid < -1) card.fail(7, "CID", card.got(7) + "; expected a coordinate system id >= 0 or blank");
  b.s = card.real_or(8, "S", 0.5);
  b.ocid = card.integer_or(9, "OCID", -1);
  if (b.ocid < -1) card.fail(9, "OCID", card.got(9) + "; expected -1, a coordinate system id >= 0 or blank");
  b.s_ocid = {card.real_or(10, "S1", 0.0), card.real_or(11, "S2", 0.0), card.real_or(12, "S3", 0.0)};
  if (b.ocid == -1 && !(b.s >= 0.0 && b.s <= 1.0)) card.fail(8, "S", card.got(8) + "; expected 0 <= S <= 1");
  if (card.used() > 13) card.fail(13, "", card.got(13) + " after S3; expected nothing more");
  b.ref = card.ref();
  st.model.bushes.push_back(b);
}

// PBUSH PID "K" K1 K2 K3 K4 K5 K6 / - "B" B1 ... B6 / - "GE" GE1 ... / - "RCV" SA ST EA ET / - "M" MASS
// Each line starts with its keyword (field 3); lines may come in any order.
void parse_pbush(const Card& card, ReaderState& st) {
  fem::BushProperty p;
  p.id = card.id(0, "PID");
  for (std::size_t line = 0; 8 * line < card.size(); ++line) {
    const std::size_t k = 8 * line + 1;
    if (line > 0 && !card.blank(k - 1))
      card.fail(k - 1, "blank", card.got(k - 1) + "; expected a blank field 2 on a continuation line (the keyword K, B, GE, RCV or M goes in field 3)");
    const std::string key = card.text_or(k, "keyword", "");
    if (key.empty()) {
      for (std::size_t i = k; i < k + 7; ++i)
        if (!card.blank(i)) card.fail(k, "keyword", "blank before values; expected K, B, GE, RCV or M");
      continue;
    }
    if (key == "K" || key == "B" || key == "GE") {
      auto& v = key == "K" ? p.k : key == "B" ? p.b : p.ge;
      for (std::size_t c = 0; c < 6; ++c) {
        const std::string name = key + std::to_string(c + 1);
        v[c] = card.real_or(k + 1 + c, name.c_str(), 0.0);
        if (key == "K" && v[c] < 0.0) card.fail(k + 1 + c, name.c_str(), card.got(k + 1 + c) + "; expected a stiffness >= 0");
        if (key == "B" && v[c] != 0.0) p.has_b = true;
        if (key == "GE" && v[c] != 0.0) p.has_ge = true;
      }
    } else if (key == "RCV" || key == "M") {
      bool any = false;
      for (std::size_t c = 0; c < 6; ++c) any = any || !card.blank(k + 1 + c);
      if (any) st.note_unsupported(key == "RCV" ? "PBUSH RCV (stress recovery coefficients ignored)" : "PBUSH M (mass ignored)", card.ref());
    } else {
      card.fail(k, "keyword", card.got(k) + "; expected K, B, GE, RCV or M");
    }
  }
  if (p.has_b) st.note_unsupported("PBUSH B (viscous damping ignored: statics and real modes)", card.ref());
  if (p.has_ge) st.note_unsupported("PBUSH GE (structural damping ignored: statics and real modes)", card.ref());
  p.ref = card.ref();
  st.model.bush_props.push_back(p);
}

// CBUSH1D EID PID GA GB CID (QRG CBUSH1D): the rod-type spring, a CBUSH along the element axis.
void parse_cbush1d(const Card& card, ReaderState& st) {
  fem::Bush b = bush_ends(card);
  b.one_d = true;
  b.cid = card.integer_or(4, "CID", -1);
  if (b.cid < -1) card.fail(4, "CID", card.got(4) + "; expected a coordinate system id >= 0 or blank");
  if (card.used() > 5) card.fail(5, "", card.got(5) + " after CID; expected nothing more");
  b.ref = card.ref();
  st.model.bushes.push_back(b);
}

// PBUSH1D PID K C M - SA SE / SHOCKA|SPRING|DAMPER|GENER ... (QRG PBUSH1D). The continuation lines
// are used by nonlinear solutions only (QRG remark 3): listed. C is ignored by statics (remark 2) and
// real modes: listed as damping.
void parse_pbush1d(const Card& card, ReaderState& st) {
  fem::BushProperty p;
  p.one_d = true;
  p.id = card.id(0, "PID");
  if (card.blank(1) && card.blank(2)) card.fail(1, "K", "K and C blank; expected a stiffness K or a damping C (QRG PBUSH1D remark 1)");
  p.k[0] = card.real_or(1, "K", 0.0);
  if (p.k[0] < 0.0) card.fail(1, "K", card.got(1) + "; expected a stiffness >= 0");
  p.b[0] = card.real_or(2, "C", 0.0);
  p.has_b = p.b[0] != 0.0;
  p.mass = card.real_or(3, "M", 0.0);
  if (p.mass < 0.0) card.fail(3, "M", card.got(3) + "; expected a mass >= 0");
  if (!card.blank(4)) card.fail(4, "blank", card.got(4) + "; expected a blank field 6 (SA is field 7)");
  p.sa = card.real_or(5, "SA", 1.0);
  p.se = card.real_or(6, "SE", 1.0);
  for (std::size_t k = 8; k < card.size(); k += 8) {
    const std::string key = card.text_or(k, "keyword", "");
    if (key != "SHOCKA" && key != "SPRING" && key != "DAMPER" && key != "GENER")
      card.fail(k, "keyword", card.got(k) + "; expected SHOCKA, SPRING, DAMPER or GENER on a continuation line");
    st.note_unsupported("PBUSH1D " + key + " (nonlinear: linear solutions use K and C)", card.ref());
  }
  if (p.has_b) st.note_unsupported("PBUSH1D C (viscous damping ignored: statics and real modes)", card.ref());
  p.ref = card.ref();
  st.model.bush_props.push_back(p);
}

// TABLEM1 ID XAXIS YAXIS / x1 y1 x2 y2 ... ENDT; TABLEM2 ID X1; TABLEM3 ID X1 X2; TABLEM4 ID X1 X2 X3
// X4 / A0 A1 ... ENDT (QRG TABLEM1-4). Checked (x in ascending or descending order, SKIP pairs,
// X2 != 0, X3 < X4, ENDT) and kept; no solution uses them (fem::MaterialTable).
void parse_tablem(const Card& card, ReaderState& st) {
  fem::MaterialTable t;
  t.type = card.name().back() - '0';
  t.id = card.id(0, "ID");
  if (t.type == 1) {
    for (std::size_t i : {std::size_t{1}, std::size_t{2}}) {
      const std::string a = card.text_or(i, i == 1 ? "XAXIS" : "YAXIS", "");
      if (!a.empty() && a != "LINEAR" && a != "LOG") card.fail(i, i == 1 ? "XAXIS" : "YAXIS", card.got(i) + "; expected LINEAR, LOG or blank");
      (i == 1 ? t.xaxis : t.yaxis) = a;
    }
  } else {
    static const char* names[4] = {"X1", "X2", "X3", "X4"};
    const int n = t.type == 2 ? 1 : t.type == 3 ? 2 : 4;
    for (int i = 0; i < n; ++i) t.x[static_cast<std::size_t>(i)] = card.real_or(static_cast<std::size_t>(1 + i), names[i], 0.0);
    if (t.type >= 3 && t.x[1] == 0.0) card.fail(2, "X2", card.got(2) + "; expected a real other than 0 (it divides x)");
    if (t.type == 4 && !(t.x[2] < t.x[3])) card.fail(3, "X3", card.got(3) + " and X4 " + card.got(4) + "; expected X3 < X4 (the range of x)");
  }
  std::size_t i = 8;
  bool ended = false;
  for (; i < card.size(); ++i) {
    if (card.blank(i)) continue;
    if (card.kind(i) == FieldKind::Text && card.text_or(i, "value", "") == "ENDT") { ended = true; break; }
    if (t.type == 4) {
      t.values.push_back(card.real(i, "A"));
      continue;
    }
    const bool skip = card.kind(i) == FieldKind::Text && card.text_or(i, "x", "") == "SKIP";
    if (skip) {  // a SKIP pair: both of its fields SKIP (QRG)
      if (card.kind(i + 1) != FieldKind::Text || card.text_or(i + 1, "y", "") != "SKIP")
        card.fail(i + 1, "y", card.got(i + 1) + " after x SKIP; expected SKIP");
      ++i;
      continue;
    }
    const double x = card.real(i, "x");
    if (i + 1 >= card.size() || card.blank(i + 1)) card.fail(i + 1, "y", "blank after x; expected a y value");
    t.values.push_back(x);
    t.values.push_back(card.real(i + 1, "y"));
    ++i;
  }
  if (!ended) card.fail_card("has no ENDT; expected its table to end with ENDT");
  if (t.values.empty()) card.fail_card(t.type == 4 ? "has no coefficient; expected A0 ... before ENDT" : "has no (x, y) pair; expected at least one before ENDT");
  if (t.type != 4) {  // x in ascending or descending order (QRG TABLEM1 remark 2)
    int order = 0;
    for (std::size_t k = 2; k < t.values.size(); k += 2) {
      const double d = t.values[k] - t.values[k - 2];
      const int s = d > 0 ? 1 : d < 0 ? -1 : 0;
      if (s != 0 && order != 0 && s != order)
        card.fail_card("x values " + std::to_string(t.values[k - 2]) + ", " + std::to_string(t.values[k]) + " change direction; expected x in ascending or descending order");
      if (s != 0) order = s;
    }
  }
  t.ref = card.ref();
  st.model.material_tables.push_back(std::move(t));
}

}  // namespace seflex::io::nastran
