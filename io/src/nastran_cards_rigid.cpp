// RBE1, CRIGD1, CRIGD2, CRIGD3 (fem::RigidBody) and RROD, CRIGDR (fem::RigidRod): the rigid
// elements besides RBE2, RBAR (nastran_cards_elements.cpp, nastran_cards_constraints.cpp). Field
// layouts: MSC QRG (RBE1, RROD); COSMIC NASTRAN User's Manual (CRIGD1, CRIGD2, CRIGD3, CRIGDR).
#include <string>
#include <tuple>

#include "seflex/io/nastran_cards.hpp"

namespace seflex::io::nastran {
namespace {

using GridComponents = fem::RigidBody::GridComponents;

/// No component of a dependent grid is also independent on that grid; no grid is dependent twice.
void check_sets(const Card& card, const fem::RigidBody& r, std::size_t dependent_field, const char* what) {
  for (std::size_t a = 0; a < r.dependent.size(); ++a) {
    const GridComponents& d = r.dependent[a];
    for (const GridComponents& n : r.independent)
      if (n.grid == d.grid && (n.c & d.c))
        card.fail(dependent_field, what, "grid " + std::to_string(d.grid) +
                                             " has a component both independent and dependent; expected none in both");
    for (std::size_t b = 0; b < a; ++b)
      if (r.dependent[b].grid == d.grid)
        card.fail(dependent_field, what, "grid " + std::to_string(d.grid) +
                                             " is dependent twice; expected each dependent grid once");
  }
}

/// The independent components of RBE1/CRIGD3: six in all.
void check_six(const Card& card, const fem::RigidBody& r, const char* what) {
  int n = 0;
  for (const GridComponents& g : r.independent)
    for (int k = 0; k < 6; ++k) n += (g.c >> k) & 1;
  if (n != 6)
    card.fail(2, what, std::to_string(n) + " independent components; expected six in all, able to describe any "
                                           "rigid-body motion of the element");
}

/// RBE1 EID GN1 CN1 GN2 CN2 GN3 CN3 / - GN4 CN4 GN5 CN5 GN6 CN6 / "UM" GM1 CM1 GM2 CM2 GM3 CM3 /
/// - GM4 CM4 ... ALPHA; CRIGD3 alike with "MSET" for "UM" and no ALPHA. Pairs sit in fields 3-8 of
/// every line; field 2 of a continuation is blank or the keyword that starts the dependent pairs.
void parse_general_rigid(const Card& card, ReaderState& st, fem::RigidBody::Card kind, const char* keyword) {
  fem::RigidBody r;
  r.card = kind;
  r.id = card.id(0, "EID");
  const bool rbe1 = kind == fem::RigidBody::Card::Rbe1;
  const char* gn = rbe1 ? "GNi" : "IGi";
  const char* cn = rbe1 ? "CNi" : "ICi";
  const char* gm = rbe1 ? "GMi" : "DGi";
  const char* cm = rbe1 ? "CMi" : "DCi";
  bool dependent = false, alpha = false;
  std::size_t first_dependent = 0;
  for (std::size_t line = 0; 8 * line < card.size(); ++line) {
    const std::size_t b = 8 * line;
    if (line > 0 && !card.blank(b)) {
      if (card.kind(b) != FieldKind::Text || card.text_or(b, "keyword", "") != keyword || dependent)
        card.fail(b, "keyword", card.got(b) + "; expected blank or " + keyword + " (once) before the dependent grids");
      dependent = true;
      first_dependent = b + 1;
    }
    for (std::size_t i = b + 1; i < b + 7; i += 2) {
      if (card.blank(i) && card.blank(i + 1)) continue;
      if (alpha) card.fail(i, "ALPHA", card.got(i) + " after ALPHA; expected nothing more");
      if (rbe1 && dependent && card.kind(i) == FieldKind::Real) {  // ALPHA ends the card
        r.alpha = card.real(i, "ALPHA");
        alpha = true;
        if (!card.blank(i + 1)) card.fail(i + 1, "ALPHA", card.got(i + 1) + " after ALPHA; expected nothing more");
        continue;
      }
      GridComponents g;
      g.grid = card.id(i, dependent ? gm : gn);
      g.c = card.components(i + 1, dependent ? cm : cn, false);
      (dependent ? r.dependent : r.independent).push_back(g);
    }
    if (!card.blank(b + 7)) {
      if (!(rbe1 && dependent && !alpha && card.kind(b + 7) == FieldKind::Real))
        card.fail(b + 7, "", card.got(b + 7) + "; expected field 9 blank (grid and component pairs sit in fields 3-8)");
      r.alpha = card.real(b + 7, "ALPHA");
      alpha = true;
    }
  }
  if (r.independent.empty()) card.fail(1, gn, "blank; expected the independent grids and their components");
  if (!dependent) card.fail_card(std::string("no ") + keyword + " continuation; expected " + keyword +
                                 " in field 2 of a continuation line, followed by the dependent grids and components");
  if (r.dependent.empty()) card.fail(first_dependent, gm, std::string("blank; expected at least one dependent grid and its components after ") + keyword);
  check_six(card, r, cn);
  check_sets(card, r, first_dependent, gm);
  r.ref = card.ref();
  st.model.rigid_bodies.push_back(std::move(r));
}

}  // namespace

void parse_rbe1(const Card& card, ReaderState& st) { parse_general_rigid(card, st, fem::RigidBody::Card::Rbe1, "UM"); }
void parse_crigd3(const Card& card, ReaderState& st) { parse_general_rigid(card, st, fem::RigidBody::Card::Crigd3, "MSET"); }

// CRIGD1 EID IG G1 G2 G3 ... (or IG GID1 THRU GID2): all six components of each Gi follow IG.
void parse_crigd1(const Card& card, ReaderState& st) {
  fem::RigidBody r;
  r.card = fem::RigidBody::Card::Crigd1;
  r.id = card.id(0, "EID");
  const int ig = card.id(1, "IG");
  r.independent.push_back({ig, 0x3F});
  for (const int g : id_list(card, 2, "Gi")) r.dependent.push_back({g, 0x3F});
  if (r.dependent.empty()) card.fail(2, "G1", "blank; expected at least one dependent grid");
  check_sets(card, r, 2, "Gi");
  r.ref = card.ref();
  st.model.rigid_bodies.push_back(std::move(r));
}

// CRIGD2 EID IG G1 C1 G2 C2 G3 C3 / G4 C4 ...: components Ci of each Gi follow IG.
void parse_crigd2(const Card& card, ReaderState& st) {
  fem::RigidBody r;
  r.card = fem::RigidBody::Card::Crigd2;
  r.id = card.id(0, "EID");
  r.independent.push_back({card.id(1, "IG"), 0x3F});
  for (std::size_t i = 2; i < card.size(); i += 2) {
    if (card.blank(i) && card.blank(i + 1)) continue;
    r.dependent.push_back({card.id(i, "Gi"), card.components(i + 1, "Ci", false)});
  }
  if (r.dependent.empty()) card.fail(2, "G1", "blank; expected at least one dependent grid and its components");
  check_sets(card, r, 2, "Gi");
  r.ref = card.ref();
  st.model.rigid_bodies.push_back(std::move(r));
}

// CRIGDR EID G G1 C1 [EID G G1 C1]: translation C1 (1-3) of G1 follows G along the rod G -> G1.
void parse_crigdr(const Card& card, ReaderState& st) {
  for (std::size_t b = 0; b < 8; b += 4) {
    if (b > 0 && card.blank(b) && card.blank(b + 1) && card.blank(b + 2) && card.blank(b + 3)) break;
    fem::RigidRod r;
    r.card = fem::RigidRod::Card::Crigdr;
    r.id = card.id(b, "EID");
    r.ga = card.id(b + 1, "G");
    r.gb = card.id(b + 2, "G1");
    if (r.gb == r.ga) card.fail(b + 2, "G1", "the same grid as G; expected a dependent grid other than the reference grid");
    r.cmb = card.integer(b + 3, "C1");
    if (r.cmb < 1 || r.cmb > 3) card.fail(b + 3, "C1", card.got(b + 3) + "; expected a translation component 1, 2 or 3");
    r.ref = card.ref();
    st.model.rigid_rods.push_back(r);
  }
  if (card.used() > 8) card.fail(8, "", card.got(8) + "; expected at most two rigid rods on one CRIGDR card");
}

// RROD EID GA GB CMA CMB ALPHA: one of CMA, CMB (1-3) or both blank.
void parse_rrod(const Card& card, ReaderState& st) {
  fem::RigidRod r;
  r.id = card.id(0, "EID");
  r.ga = card.id(1, "GA");
  r.gb = card.id(2, "GB");
  if (r.gb == r.ga) card.fail(2, "GB", "the same grid as GA; expected two different grids");
  r.cma = card.integer_or(3, "CMA", 0);
  r.cmb = card.integer_or(4, "CMB", 0);
  for (const auto& [i, c, name] : {std::tuple{std::size_t{3}, r.cma, "CMA"}, std::tuple{std::size_t{4}, r.cmb, "CMB"}})
    if (c < 0 || c > 3) card.fail(i, name, card.got(i) + "; expected a translation component 1, 2 or 3, or blank");
  if (r.cma != 0 && r.cmb != 0)
    card.fail(4, "CMB", card.got(4) + " with CMA " + std::to_string(r.cma) + "; expected one dependent translation, CMA or CMB");
  r.alpha = card.real_or(5, "ALPHA", 0.0);
  if (card.used() > 6) card.fail(6, "", card.got(6) + " after ALPHA; expected nothing more");
  r.ref = card.ref();
  st.model.rigid_rods.push_back(r);
}

}  // namespace seflex::io::nastran
