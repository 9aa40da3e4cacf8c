// PLOAD1 (distributed and concentrated loads on CBAR/CBEAM) and SPCD (enforced motion). Field
// layouts: MSC Nastran Quick Reference Guide (docs/nastran-support.md).
#include <string>

#include "seflex/io/nastran_cards.hpp"

namespace seflex::io::nastran {

// PLOAD1 SID EID TYPE SCALE X1 P1 X2 P2
void parse_pload1(const Card& card, ReaderState& st) {
  fem::BarLineLoad l;
  l.sid = card.id(0, "SID");
  l.element = card.id(1, "EID");
  l.type = card.text_or(2, "TYPE", "");
  static const char* types[] = {"FX", "FY", "FZ", "FXE", "FYE", "FZE", "MX", "MY", "MZ", "MXE", "MYE", "MZE"};
  bool known = false;
  for (const char* t : types) known = known || l.type == t;
  if (!known) card.fail(2, "TYPE", card.got(2) + "; expected FX, FY, FZ, FXE, FYE, FZE, MX, MY, MZ, MXE, MYE or MZE");
  const std::string scale = card.text_or(3, "SCALE", "");
  if (scale == "LE") l.scale = fem::BarLineLoad::Scale::LE;
  else if (scale == "FR") l.scale = fem::BarLineLoad::Scale::FR;
  else if (scale == "LEPR") l.scale = fem::BarLineLoad::Scale::LEPR;
  else if (scale == "FRPR") l.scale = fem::BarLineLoad::Scale::FRPR;
  else card.fail(3, "SCALE", card.got(3) + "; expected LE, FR, LEPR or FRPR");
  l.x1 = card.real(4, "X1");
  l.p1 = card.real_or(5, "P1", 0.0);
  l.x2 = card.real_or(6, "X2", l.x1);
  l.p2 = card.real_or(7, "P2", card.blank(6) ? l.p1 : 0.0);
  if (!(l.x1 >= 0.0)) card.fail(4, "X1", card.got(4) + "; expected X1 >= 0");
  if (!(l.x2 >= l.x1)) card.fail(6, "X2", card.got(6) + "; expected X2 >= X1 (or blank: a concentrated load at X1)");
  const bool fraction = l.scale == fem::BarLineLoad::Scale::FR || l.scale == fem::BarLineLoad::Scale::FRPR;
  if (fraction && !(l.x2 <= 1.0)) card.fail(6, "X2", card.got(6) + "; expected a fraction of the length <= 1 with SCALE " + scale);
  l.ref = card.ref();
  st.model.bar_line_loads.push_back(l);
}

// SPCD SID G1 C1 D1 G2 C2 D2
void parse_spcd(const Card& card, ReaderState& st) {
  static const char* names[2][3] = {{"G1", "C1", "D1"}, {"G2", "C2", "D2"}};
  const int sid = card.id(0, "SID");
  for (std::size_t s = 0; s < 2; ++s) {
    const std::size_t b = 1 + 3 * s;
    if (s == 1 && card.blank(b) && card.blank(b + 1) && card.blank(b + 2)) break;
    fem::EnforcedMotion e;
    e.sid = sid;
    e.grid = card.id(b, names[s][0]);
    e.c = card.components(b + 1, names[s][1], false, true);
    e.d = card.real_or(b + 2, names[s][2], 0.0);
    e.ref = card.ref();
    st.model.enforced_motions.push_back(e);
  }
}

}  // namespace seflex::io::nastran
