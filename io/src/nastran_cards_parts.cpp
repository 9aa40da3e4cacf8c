// The cards that place and connect part superelements: POINT, SELOC, SEBULK, SECONCT, SELABEL
// (fem/parts.hpp assembles the parts; MSC Nastran QRG for the fields).
#include <string>

#include "seflex/io/nastran_cards.hpp"
#include "seflex/io/nastran_lines.hpp"

namespace seflex::io::nastran {
namespace {

/// TOL (a real >= 0, blank: QRG's 1.0E-5) and LOC (YES, NO, blank: YES) in data fields i and i + 1
/// of SEBULK and SECONCT.
void tolerance_and_location(const Card& card, std::size_t i, double& tol, bool& loc) {
  tol = card.real_or(i, "TOL", 1e-5);
  if (tol < 0) card.fail(i, "TOL", card.got(i) + "; expected a tolerance >= 0");
  const std::string yes_no = upper(card.text_or(i + 1, "LOC", "YES"));
  if (yes_no != "YES" && yes_no != "NO") card.fail(i + 1, "LOC", card.got(i + 1) + "; expected YES, NO or blank");
  loc = yes_no == "YES";
}

}  // namespace

// POINT ID CP X1 X2 X3
void parse_point(const Card& card, ReaderState& st) {
  fem::GeometricPoint p;
  p.id = card.id(0, "ID");
  p.cp = card.integer_or(1, "CP", 0);
  if (p.cp < 0) card.fail(1, "CP", card.got(1) + "; expected a coordinate system id >= 0 or blank");
  p.x = {card.real_or(2, "X1", 0.0), card.real_or(3, "X2", 0.0), card.real_or(4, "X3", 0.0)};
  p.ref = card.ref();
  st.model.points.push_back(p);
}

// SELOC SEID PA1 PA2 PA3 PB1 PB2 PB3
void parse_seloc(const Card& card, ReaderState& st) {
  fem::PartLocation l;
  l.seid = card.id(0, "SEID");
  static const char* names[6] = {"PA1", "PA2", "PA3", "PB1", "PB2", "PB3"};
  for (std::size_t k = 0; k < 3; ++k) {
    l.pa[k] = card.id(1 + k, names[k]);
    l.pb[k] = card.id(4 + k, names[3 + k]);
  }
  l.ref = card.ref();
  st.model.part_locations.push_back(l);
}

// SEMPLN SEID PLANE P1 P2 P3
void parse_sempln(const Card& card, ReaderState& st) {
  fem::MirrorPlane p;
  p.seid = card.id(0, "SEID");
  if (upper(card.text_or(1, "PLANE", "")) != "PLANE") card.fail(1, "PLANE", card.got(1) + "; expected PLANE");
  static const char* names[3] = {"P1", "P2", "P3"};
  for (std::size_t k = 0; k < 3; ++k) p.p[k] = card.id(2 + k, names[k]);
  p.ref = card.ref();
  st.model.mirror_planes.push_back(p);
}

// EXTRN GID1 C1 GID2 C2 ... (C = 0: a scalar point)
void parse_extrn(const Card& card, ReaderState& st) {
  fem::ExternalBoundary b;
  std::size_t last = card.size();
  while (last > 0 && card.blank(last - 1)) --last;
  if (last == 0) card.fail_card("no points; expected GID1 C1 GID2 C2 ...");
  if (last % 2) card.fail(last, "Ci", "blank after " + card.got(last - 1) + "; expected grid or scalar point ids and components in pairs");
  for (std::size_t i = 0; i < last; i += 2) {
    const int id = card.id(i, "GIDi");
    b.points.emplace_back(id, card.components(i + 1, "Ci", false, true));
  }
  b.ref = card.ref();
  st.model.external_points.push_back(b);
}

// SEBULK SEID TYPE RSEID METHOD TOL LOC UNITNO
void parse_sebulk(const Card& card, ReaderState& st) {
  fem::PartBulk b;
  b.seid = card.id(0, "SEID");
  b.type = upper(card.text_or(1, "TYPE", "PRIMARY"));
  static const char* types[] = {"PRIMARY", "REPEAT", "MIRROR", "COLLCTR", "EXTERNAL", "EXTOP2", "EXTOP4", "FRFOP2", "MANUAL", "AUTO"};
  bool known = false;
  for (const char* t : types) known = known || b.type == t;
  if (!known || b.type == "MANUAL" || b.type == "AUTO")
    card.fail(1, "TYPE", card.got(1) + "; expected PRIMARY, REPEAT, MIRROR, COLLCTR, EXTERNAL, EXTOP2, EXTOP4 or FRFOP2");
  b.rseid = card.integer_or(2, "RSEID", 0);
  const std::string method = upper(card.text_or(3, "METHOD", "AUTO"));
  if (method != "AUTO" && method != "MANUAL") card.fail(3, "METHOD", card.got(3) + "; expected AUTO, MANUAL or blank");
  b.manual = method == "MANUAL";
  tolerance_and_location(card, 4, b.tol, b.loc);
  b.unit = card.integer_or(6, "UNITNO", 0);
  if (b.type == "EXTOP4" && b.unit <= 0)
    card.fail(6, "UNITNO", card.got(6) + "; expected the Fortran unit (> 0) of an ASSIGN INPUTT4 holding the part's matrices");
  if ((b.type == "MIRROR" || b.type == "REPEAT") && b.rseid <= 0)
    card.fail(2, "RSEID", card.got(2) + "; expected the id of the part that TYPE = " + b.type + " copies");
  b.ref = card.ref();
  st.model.part_bulks.push_back(b);
}

// SECONCT SEIDA SEIDB TOL LOC / GIDA1 GIDB1 GIDA2 GIDB2 ... (or GIDA1 THRU GIDA2 GIDB1 THRU GIDB2)
void parse_seconct(const Card& card, ReaderState& st) {
  fem::PartConnection c;
  c.seid_a = card.integer(0, "SEIDA");
  c.seid_b = card.integer(1, "SEIDB");
  if (c.seid_a < 0) card.fail(0, "SEIDA", card.got(0) + "; expected a part id (0 = the residual)");
  if (c.seid_b < 0 || c.seid_b == c.seid_a)
    card.fail(1, "SEIDB", card.got(1) + "; expected a part id (0 = the residual) other than SEIDA");
  tolerance_and_location(card, 2, c.tol, c.loc);
  for (std::size_t i = 4; i < 8; ++i)
    if (!card.blank(i)) card.fail(i, "(blank)", card.got(i) + "; expected a blank field (the grid pairs start on the continuation)");
  std::vector<std::size_t> f;  // the filled fields after the first line
  for (std::size_t i = 8; i < card.size(); ++i)
    if (!card.blank(i)) f.push_back(i);
  // pairs GIDAi GIDBi, or ranges GIDA1 THRU GIDA2 GIDB1 THRU GIDB2, in any mix
  const auto is_thru = [&](std::size_t k) { return k < f.size() && upper(card.raw(f[k])) == "THRU"; };
  for (std::size_t k = 0; k < f.size();) {
    if (is_thru(k + 1)) {
      if (k + 5 >= f.size() || !is_thru(k + 4))
        card.fail(f[k + 1], "THRU", "expected 'GIDA1 THRU GIDA2 GIDB1 THRU GIDB2'");
      const int a1 = card.id(f[k], "GIDA1"), a2 = card.id(f[k + 2], "GIDA2"), b1 = card.id(f[k + 3], "GIDB1"),
                b2 = card.id(f[k + 5], "GIDB2");
      if (a2 < a1) card.fail(f[k + 2], "GIDA2", card.got(f[k + 2]) + "; expected an id >= GIDA1");
      if (b2 - b1 != a2 - a1) card.fail(f[k + 5], "GIDB2", card.got(f[k + 5]) + "; expected as many ids as GIDA1 THRU GIDA2");
      if (a2 - a1 > kMaxThru) card.fail(f[k + 2], "GIDA2", "a range of more than " + std::to_string(kMaxThru) + " ids; expected fewer");
      for (int j = 0; j <= a2 - a1; ++j) c.pairs.emplace_back(a1 + j, b1 + j);
      k += 6;
    } else {
      if (k + 1 >= f.size()) card.fail(f[k], "GIDBi", "missing after " + card.got(f[k]) + "; expected grid ids in pairs GIDAi GIDBi");
      c.pairs.emplace_back(card.id(f[k], "GIDAi"), card.id(f[k + 1], "GIDBi"));
      k += 2;
    }
  }
  if (c.pairs.empty()) card.fail_card("no grid pairs; expected GIDA1 GIDB1 ... on the continuation");
  c.ref = card.ref();
  st.model.part_connections.push_back(c);
}

// SELABEL SEID LABEL: a name for output only (read, not kept).
void parse_selabel(const Card& card, ReaderState&) { card.id(0, "SEID"); }

}  // namespace seflex::io::nastran
