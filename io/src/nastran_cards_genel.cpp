// GENEL (MSC QRG): EID - UI1 CI1 UI2 CI2 ... / "UD" - UD1 CD1 ... / "K" or "Z" KZ11 KZ21 ... / "S" S11 ...
// Field by field: the UI pairs from field 4, then the keyword UD followed by a blank field and the
// UD pairs, the keyword K or Z followed by the lower triangle by columns, the keyword S followed by S
// by rows. Blank fields between values (line padding) are skipped.
#include <string>

#include "seflex/io/nastran_cards.hpp"

namespace seflex::io::nastran {

void parse_genel(const Card& card, ReaderState& st) {
  fem::Genel g;
  g.id = card.id(0, "EID");
  if (!card.blank(1)) card.fail(1, "blank", card.got(1) + "; expected field 3 blank (UI1 starts in field 4)");
  enum class Part { Ui, Ud, Kz, S } part = Part::Ui;
  bool has_kz = false, has_s = false;
  const std::size_t n = card.size();
  for (std::size_t i = 2; i < n; ++i) {
    if (card.blank(i)) continue;
    if (card.kind(i) == FieldKind::Text) {
      const std::string word = card.text_or(i, "keyword", "");
      if (word == "UD" && part == Part::Ui) {
        part = Part::Ud;
        if (!card.blank(i + 1)) card.fail(i + 1, "blank", card.got(i + 1) + " after UD; expected a blank field, then UD1 CD1");
        ++i;
      } else if ((word == "K" || word == "Z") && !has_kz) {
        part = Part::Kz;
        has_kz = true;
        g.flexibility = word == "Z";
      } else if (word == "S" && has_kz && !has_s) {
        part = Part::S;
        has_s = true;
      } else {
        card.fail(i, "keyword", card.got(i) + (has_kz ? "; expected S (once) after the K or Z values"
                                                       : "; expected UD, K or Z (each once, in this order)"));
      }
      continue;
    }
    if (part == Part::Ui || part == Part::Ud) {
      const bool ui = part == Part::Ui;
      fem::Genel::Dof d;
      d.point = card.id(i, ui ? "UIi" : "UDi");
      std::size_t j = i + 1;
      while (j < n && card.blank(j)) ++j;
      d.c = card.integer(j < n ? j : i + 1, ui ? "CIi" : "CDi");
      if (d.c < 0 || d.c > 6)
        card.fail(j, ui ? "CIi" : "CDi", card.got(j) + "; expected one component 1-6 (grid) or 0 (scalar point)");
      (ui ? g.ui : g.ud).push_back(d);
      i = j;
      continue;
    }
    const double v = card.real(i, part == Part::S ? "Sij" : g.flexibility ? "Zij" : "Kij");
    (part == Part::S ? g.s : g.kz).push_back(v);
  }
  if (g.ui.empty()) card.fail(2, "UI1", "blank; expected the dofs UI1 CI1 ... of the element");
  if (!has_kz) card.fail_card("no K or Z; expected the keyword K (stiffness) or Z (flexibility) followed by the matrix's lower triangle");
  const std::size_t ni = g.ui.size(), nd = g.ud.size();
  if (g.kz.size() != ni * (ni + 1) / 2)
    card.fail_card(std::to_string(g.kz.size()) + (g.flexibility ? " Z" : " K") + " values for " + std::to_string(ni) +
                   " UI dofs; expected the lower triangle, " + std::to_string(ni * (ni + 1) / 2) + " values");
  if (has_s && nd == 0) card.fail_card("S without UD; expected S only with UD dofs");
  if (has_s && g.s.size() != ni * nd)
    card.fail_card(std::to_string(g.s.size()) + " S values for " + std::to_string(ni) + " UI and " + std::to_string(nd) +
                   " UD dofs; expected " + std::to_string(ni * nd) + " (UI rows of UD columns)");
  if (!has_s && nd != 0 && nd != 6)
    card.fail_card(std::to_string(nd) + " UD dofs and no S; expected S, or six UD dofs that fix the rigid-body motion (S is then "
                                        "computed from the geometry)");
  g.ref = card.ref();
  st.model.genels.push_back(std::move(g));
}

}  // namespace seflex::io::nastran
