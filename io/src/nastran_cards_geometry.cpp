// GRID, GRDSET, CORD2R/C/S, CORD1R/C/S, SPOINT.
#include "seflex/io/nastran_cards.hpp"

namespace seflex::io::nastran {
namespace {

fem::CoordType coord_type(const Card& card) {
  switch (card.name().back()) {
    case 'C': return fem::CoordType::Cylindrical;
    case 'S': return fem::CoordType::Spherical;
    default: return fem::CoordType::Rectangular;
  }
}

}  // namespace

// GRID ID CP X1 X2 X3 CD PS SEID
void parse_grid(const Card& card, ReaderState& st) {
  fem::Grid g;
  g.id = card.id(0, "ID");
  std::uint8_t blank = 0;
  if (card.blank(1)) {
    blank |= 1;
  } else {
    g.cp = card.integer(1, "CP");
    if (g.cp < 0) card.fail(1, "CP", card.got(1) + "; expected a coordinate system id >= 0 or blank");
  }
  g.x = {card.real_or(2, "X1", 0.0), card.real_or(3, "X2", 0.0), card.real_or(4, "X3", 0.0)};
  if (card.blank(5)) {
    blank |= 2;
  } else {
    g.cd = card.integer(5, "CD");
    if (g.cd == -1) {
      // A fluid grid (acoustic pressure, one degree of freedom): read with CD = 0 and listed; every
      // solution refuses the deck (seflex has no fluid elements).
      g.cd = 0;
      st.note_unsupported(kFluidGrid, card.ref());
    } else if (g.cd < 0) {
      card.fail(5, "CD", card.got(5) + "; expected a coordinate system id >= 0, blank or -1 (a fluid grid)");
    }
  }
  if (card.blank(6))
    blank |= 4;
  else
    g.ps = card.raw(6) == "0" ? fem::ComponentMask{0} : card.components(6, "PS", false);  // 0: none (MSC's dbxdra2)
  if (card.integer_or(7, "SEID", 0) != 0) st.note_unsupported("GRID SEID (superelement id ignored)", card.ref());
  g.ref = card.ref();
  st.model.grids.push_back(g);
  st.grid_blank.push_back(blank);
}

// GRDSET - CP - - - CD PS SEID
void parse_grdset(const Card& card, ReaderState& st) {
  auto& d = st.model.grdset;
  if (d.present) {
    card.fail_card("a second GRDSET (the first is at " + st.where(d.ref) + "); expected at most one");
  }
  d.present = true;
  d.ref = card.ref();
  d.cp = card.integer_or(1, "CP", 0);
  if (d.cp < 0) card.fail(1, "CP", card.got(1) + "; expected a coordinate system id >= 0 or blank");
  d.cd = card.integer_or(5, "CD", 0);
  if (d.cd == -1) {  // fluid grids by default: as on GRID
    d.cd = 0;
    st.note_unsupported(kFluidGrid, card.ref());
  } else if (d.cd < 0) {
    card.fail(5, "CD", card.got(5) + "; expected a coordinate system id >= 0, blank or -1 (fluid grids)");
  }
  d.ps = card.components(6, "PS", true);
}

// CORD2R CID RID A1 A2 A3 B1 B2 B3 / C1 C2 C3
void parse_cord2(const Card& card, ReaderState& st) {
  fem::CoordSys c;
  c.id = card.id(0, "CID");
  c.type = coord_type(card);
  c.rid = card.integer_or(1, "RID", 0);
  if (c.rid < 0) card.fail(1, "RID", card.got(1) + "; expected a coordinate system id >= 0 or blank");
  static const char* names[9] = {"A1", "A2", "A3", "B1", "B2", "B3", "C1", "C2", "C3"};
  for (std::size_t k = 0; k < 9; ++k) c.abc[k] = card.real_or(2 + k, names[k], 0.0);
  c.ref = card.ref();
  st.model.coords.push_back(c);
}

// CORD1R CIDA G1A G2A G3A CIDB G1B G2B G3B
void parse_cord1(const Card& card, ReaderState& st) {
  static const char* cid_names[2] = {"CIDA", "CIDB"};
  static const char* grid_names[2][3] = {{"G1A", "G2A", "G3A"}, {"G1B", "G2B", "G3B"}};
  for (std::size_t s = 0; s < 2; ++s) {
    const std::size_t base = 4 * s;
    if (s == 1 && card.blank(4) && card.blank(5) && card.blank(6) && card.blank(7)) break;
    fem::CoordSys c;
    c.id = card.id(base, cid_names[s]);
    c.type = coord_type(card);
    c.by_grids = true;
    for (std::size_t k = 0; k < 3; ++k) c.grids[k] = card.id(base + 1 + k, grid_names[s][k]);
    if (c.grids[0] == c.grids[1] || c.grids[0] == c.grids[2] || c.grids[1] == c.grids[2])
      card.fail(base + 1, grid_names[s][0], "the three grids " + std::to_string(c.grids[0]) + ", " +
                                                std::to_string(c.grids[1]) + ", " + std::to_string(c.grids[2]) +
                                                " are not distinct; expected three different grids");
    c.ref = card.ref();
    st.model.coords.push_back(c);
  }
}

// SPOINT ID1 ID2 ... or SPOINT ID1 THRU ID2
void parse_spoint(const Card& card, ReaderState& st) {
  const std::vector<int> ids = id_list(card, 0, "ID");
  if (ids.empty()) card.fail(0, "ID1", "blank; expected scalar point ids");
  for (const int id : ids) st.model.spoints.push_back({id, card.ref()});
}

}  // namespace seflex::io::nastran
