// EIGRL, EIGR, EIGB, PARAM, DMIG.
#include <charconv>
#include <string>

#include "seflex/io/nastran_cards.hpp"
#include "seflex/io/nastran_lines.hpp"
#include "seflex/fem/finalize.hpp"

namespace seflex::io::nastran {
namespace {

std::optional<double> optional_real(const Card& card, std::size_t i, const char* what) {
  if (card.blank(i)) return std::nullopt;
  return card.real(i, what);
}

std::optional<int> optional_count(const Card& card, std::size_t i, const char* what) {
  if (card.blank(i)) return std::nullopt;
  const int n = card.integer(i, what);
  if (n <= 0) card.fail(i, what, card.got(i) + "; expected a number of roots > 0 or blank");
  return n;
}

/// G and C of NORM = POINT (EIGR, EIGB: fields 9 and 10 of the card, the continuation's 2 and 3).
void norm_point(const Card& card, fem::EigenMethod& m) {
  m.norm_grid = card.id(9, "G");
  m.norm_component = card.integer(10, "C");
  if (m.norm_component < 0 || m.norm_component > 6)
    card.fail(10, "C", card.got(10) + "; expected one component 1-6 (0 for a scalar point)");
}

/// The DMIG of this name, created on first sight.
fem::Dmig& dmig_named(ReaderState& st, const std::string& name, const fem::CardRef& ref) {
  auto [it, inserted] = st.dmig_index.try_emplace(name, st.model.dmigs.size());
  if (inserted) {
    fem::Dmig d;
    d.name = name;
    d.ref = ref;
    st.model.dmigs.push_back(std::move(d));
    st.dmig_has_header.push_back(false);
  }
  return st.model.dmigs[it->second];
}

}  // namespace

std::string param_value(std::string_view f) {
  switch (classify(f)) {
    case FieldKind::Text: return upper(f);
    case FieldKind::Real: {
      double x = 0;
      parse_real(f, x);
      char buf[64];
      const auto r = std::to_chars(buf, buf + sizeof buf, x);
      std::string s(buf, r.ptr);
      if (s.find_first_of(".e") == std::string::npos) s += ".";
      return s;
    }
    case FieldKind::Integer: {
      int i = 0;
      parse_int(f, i);
      return std::to_string(i);
    }
    default: return std::string(f);
  }
}


// EIGRL SID V1 V2 ND MSGLVL MAXSET SHFSCL NORM / option=value ...
void parse_eigrl(const Card& card, ReaderState& st) {
  fem::EigenMethod m;
  m.sid = card.id(0, "SID");
  m.method = "LAN";
  m.f1 = optional_real(card, 1, "V1");
  m.f2 = optional_real(card, 2, "V2");
  if (m.f1 && m.f2 && *m.f2 < *m.f1) card.fail(2, "V2", card.got(2) + "; expected V2 >= V1");
  m.nd = optional_count(card, 3, "ND");
  card.integer_or(4, "MSGLVL", 0);
  card.integer_or(5, "MAXSET", 0);
  card.real_or(6, "SHFSCL", 0.0);
  m.norm = card.text_or(7, "NORM", "MASS");
  if (m.norm != "MASS" && m.norm != "MAX") card.fail(7, "NORM", card.got(7) + "; expected MASS, MAX or blank");
  if (card.used() > 8) st.note_unsupported("EIGRL options (continuation ignored)", card.ref());
  m.ref = card.ref();
  st.model.eigen_methods.push_back(std::move(m));
}

// EIGR SID METHOD F1 F2 NE ND - - / NORM G C
void parse_eigr(const Card& card, ReaderState& st) {
  fem::EigenMethod m;
  m.sid = card.id(0, "SID");
  m.is_eigr = true;
  m.method = card.text_or(1, "METHOD", "LAN");
  m.f1 = optional_real(card, 2, "F1");
  m.f2 = optional_real(card, 3, "F2");
  if (m.f1 && m.f2 && *m.f2 < *m.f1) card.fail(3, "F2", card.got(3) + "; expected F2 >= F1");
  card.integer_or(4, "NE", 0);
  m.nd = optional_count(card, 5, "ND");
  m.norm = card.text_or(8, "NORM", "MASS");
  if (m.norm != "MASS" && m.norm != "MAX" && m.norm != "POINT")
    card.fail(8, "NORM", card.got(8) + "; expected MASS, MAX, POINT or blank");
  if (m.norm == "POINT") norm_point(card, m);
  m.ref = card.ref();
  st.model.eigen_methods.push_back(std::move(m));
}

// EIGB SID METHOD L1 L2 NEP NDP NDN - / NORM G C (MSC QRG EIGB: the load factors in [L1, L2]; NDP
// and NDN default to 3 NEP; NORM MAX (default) or POINT). seflex's eigensolver finds the positive
// roots whatever METHOD (INV or SINV) names; NDN (negative roots) is read for its type.
void parse_eigb(const Card& card, ReaderState& st) {
  fem::EigenMethod m;
  m.sid = card.id(0, "SID");
  m.is_eigb = true;
  m.method = card.text_or(1, "METHOD", "");
  if (m.method != "INV" && m.method != "SINV") card.fail(1, "METHOD", card.got(1) + "; expected INV or SINV");
  m.f1 = card.real(2, "L1");
  m.f2 = card.real(3, "L2");
  if (!(*m.f2 > *m.f1)) card.fail(3, "L2", card.got(3) + "; expected L2 > L1 (L1 = " + card.got(2) + ")");
  const int nep = card.integer_or(4, "NEP", 0);
  if (nep < 0) card.fail(4, "NEP", card.got(4) + "; expected an estimated number of roots >= 0 or blank");
  m.nd = optional_count(card, 5, "NDP");
  if (!m.nd && nep > 0) m.nd = 3 * nep;
  if (!card.blank(6)) optional_count(card, 6, "NDN");
  m.norm = card.text_or(8, "NORM", "MAX");
  if (m.norm != "MAX" && m.norm != "POINT") card.fail(8, "NORM", card.got(8) + "; expected MAX, POINT or blank");
  if (m.norm == "POINT") norm_point(card, m);
  m.ref = card.ref();
  st.model.eigen_methods.push_back(std::move(m));
}

// PARAM N V1 V2
void parse_param(const Card& card, ReaderState& st) {
  fem::Param p;
  if (card.kind(0) != FieldKind::Text) card.fail(0, "N", card.got(0) + "; expected a parameter name");
  p.name = upper(card.raw(0));
  const std::size_t used = card.used();
  if (used < 2) card.fail(1, "V1", "blank; expected the parameter's value");
  for (std::size_t i = 1; i < used; ++i) {
    const std::string_view f = card.raw(i);
    if (classify(f) == FieldKind::Invalid)
      card.fail(i, "V", card.got(i) + "; expected a number or a character value");
    p.values.push_back(param_value(f));
  }
  p.ref = card.ref();
  // A parameter the case control sets: its value takes precedence over the bulk data's (MSC Nastran
  // QRG, "Parameter Applicability Tables"). seflex does as Nastran does: the bulk data value is left
  // out, with a warning when it differs.
  for (std::size_t i = 0; i < st.case_control_params && i < st.model.params.size(); ++i)
    if (const fem::Param& cc = st.model.params[i]; cc.name == p.name) {
      if (cc.values != p.values) {
        auto joined = [](const std::vector<std::string>& v) {
          std::string out;
          for (const auto& x : v) out += (out.empty() ? "" : " ") + x;
          return out;
        };
        st.model.read_warnings.push_back(fem::where(st.model, p.ref).str() + ": PARAM " + p.name + " " + joined(p.values) +
                                         " in the bulk data not used: the case control's PARAM " + p.name + " " +
                                         joined(cc.values) + " (" + fem::where(st.model, cc.ref).str() +
                                         ") takes precedence, as in Nastran");
      }
      return;
    }
  st.model.params.push_back(std::move(p));
}

// Header:  DMIG NAME 0 IFO TIN TOUT POLAR - NCOL
// Column:  DMIG NAME GJ CJ - G1 C1 A1 B1 / G2 C2 A2 B2 ...
void parse_dmig(const Card& card, ReaderState& st) {
  if (card.kind(0) != FieldKind::Text) card.fail(0, "NAME", card.got(0) + "; expected a matrix name");
  const std::string name = upper(card.raw(0));
  if (card.raw(1) == "0") {
    fem::Dmig& d = dmig_named(st, name, card.ref());
    const std::size_t index = st.dmig_index[name];
    if (st.dmig_has_header[index]) card.fail(1, "0", "a second header for DMIG " + name + "; expected one");
    st.dmig_has_header[index] = true;
    d.ref = card.ref();
    d.form = card.integer(2, "IFO");
    if (d.form != 1 && d.form != 2 && d.form != 6 && d.form != 9)
      card.fail(2, "IFO", card.got(2) + "; expected 1 (square), 2 or 9 (rectangular) or 6 (symmetric)");
    d.tin = card.integer(3, "TIN");
    if (d.tin != 1 && d.tin != 2)
      card.fail(3, "TIN", card.got(3) + "; expected 1 or 2 (real; complex matrices are not supported)");
    d.tout = card.integer_or(4, "TOUT", 0);
    if (card.integer_or(5, "POLAR", 0) != 0) card.fail(5, "POLAR", card.got(5) + "; expected 0 or blank");
    card.integer_or(7, "NCOL", 0);
    return;
  }
  fem::Dmig& d = dmig_named(st, name, card.ref());
  const int gj = card.id(1, "GJ");
  const int cj = card.integer_or(2, "CJ", 0);
  if (cj < 0 || cj > 6) card.fail(2, "CJ", card.got(2) + "; expected one component 1-6 (0 or blank for a scalar point)");
  bool any = false;
  for (std::size_t i = 4; i < card.size(); i += 4) {
    if (card.blank(i) && card.blank(i + 1) && card.blank(i + 2) && card.blank(i + 3)) continue;
    fem::DmigEntry e;
    e.gj = gj;
    e.cj = cj;
    e.gi = card.id(i, "G");
    e.ci = card.integer_or(i + 1, "C", 0);
    if (e.ci < 0 || e.ci > 6) card.fail(i + 1, "C", card.got(i + 1) + "; expected one component 1-6 (0 or blank for a scalar point)");
    e.value = card.real(i + 2, "A");
    if (!card.blank(i + 3) && card.real(i + 3, "B") != 0.0)
      card.fail(i + 3, "B", card.got(i + 3) + "; expected blank (complex matrices are not supported)");
    d.entries.push_back(e);
    any = true;
  }
  if (!any) card.fail(4, "G1", "blank; expected at least one matrix term (G1 C1 A1)");
}

// MDLPRM NAME1 VAL1 NAME2 VAL2 ...: MSC's model parameters. HDF5 (the output database) is output
// and listed as such; every other one is listed by name (seflex models none of them).
void parse_mdlprm(const Card& card, ReaderState& st) {
  bool any = false;
  for (std::size_t i = 0; i < card.size(); i += 2) {
    if (card.blank(i)) continue;
    const std::string name = card.text_or(i, "PARAMi", "");
    any = true;
    st.note_unsupported(name == "HDF5" ? std::string(kMdlprmHdf5) : "MDLPRM " + name + " (model parameter not used)", card.ref());
  }
  if (!any) card.fail(0, "PARAM1", "blank; expected model parameter names and values");
}

}  // namespace seflex::io::nastran
