// CBUSH, PBUSH, CELAS3, CELAS4, CMASS1-4, PMASS, CONM1. Field layouts: MSC Nastran Quick Reference
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

// CBUSH EID PID GA GB GO/X1 X2 X3 CID / S OCID S1 S2 S3
void parse_cbush(const Card& card, ReaderState& st) {
  fem::Bush b;
  b.id = card.id(0, "EID");
  b.pid = card.id_or(1, "PID", b.id);
  b.ga = card.id(2, "GA");
  b.gb = card.integer_or(3, "GB", 0);
  if (b.gb < 0) card.fail(3, "GB", card.got(3) + "; expected a grid id or blank (grounded)");
  if (b.gb == b.ga) card.fail(3, "GB", "GB is GA; expected a second grid or blank (grounded)");
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

}  // namespace seflex::io::nastran
