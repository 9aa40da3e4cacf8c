// MAT1, MAT2, MAT8, PBAR, PBARL, PBEAM, PBEAML, PROD, PSHELL, PCOMP, PCOMPG, PELAS.
#include <cmath>
#include <string>

#include "seflex/common/error.hpp"
#include "seflex/fem/beam_section.hpp"
#include "seflex/io/nastran_cards.hpp"
#include "seflex/io/nastran_lines.hpp"

namespace seflex::io::nastran {
namespace {

bool is_station_flag(std::string_view f) { return f == "YES" || f == "YESA" || f == "NO"; }

void check_inertia(const Card& card, const fem::BarProperty& p, std::size_t i1, std::size_t i2, std::size_t i12) {
  if (p.A < 0.0) card.fail(2, "A", card.got(2) + "; expected an area >= 0");
  if (p.I1 < 0.0) card.fail(i1, "I1", card.got(i1) + "; expected I1 >= 0");
  if (p.I2 < 0.0) card.fail(i2, "I2", card.got(i2) + "; expected I2 >= 0");
  if (p.I12 != 0.0 && !(p.I1 * p.I2 > p.I12 * p.I12))
    card.fail(i12, "I12", card.got(i12) + "; expected I1 * I2 > I12^2");
}

/// DIMs of a PBARL/PBEAML section starting at data field `first`; sets A, I1, I2, J, K1, K2.
void section_from_dims(const Card& card, fem::BarProperty& p, std::size_t first) {
  const int ndim = fem::section_dimension_count(p.section_type);
  if (ndim == 0)
    card.fail(3, "TYPE", card.got(3) + "; expected one of the section types seflex computes: " +
                             fem::supported_section_types());
  p.dims.clear();
  for (int k = 0; k < ndim; ++k) {
    const std::string name = "DIM" + std::to_string(k + 1);
    p.dims.push_back(card.real(first + static_cast<std::size_t>(k), name.c_str()));
  }
  fem::BeamSection s;
  try {
    s = fem::beam_section(p.section_type, p.dims);
  } catch (const InputError& e) {
    card.fail(first, "DIM1", std::string(e.what()));
  }
  p.A = s.A;
  p.I1 = s.I1;
  p.I2 = s.I2;
  p.I12 = s.I12;
  p.J = s.J;
  p.K1 = s.K1;
  p.K2 = s.K2;
}

/// PID MID GROUP TYPE / DIM1.. of PBARL and PBEAML (end A): the section computed from its dimensions.
fem::BarProperty section_property(const Card& card, fem::BarProperty::Source source) {
  fem::BarProperty p;
  p.source = source;
  p.id = card.id(0, "PID");
  p.mid = card.id(1, "MID");
  const std::string group = card.text_or(2, "GROUP", "MSCBML0");
  if (group != "MSCBML0")
    card.fail(2, "GROUP", card.got(2) + "; expected MSCBML0 or blank (user section libraries are not supported)");
  p.section_type = card.text_or(3, "TYPE", "");
  if (p.section_type.empty()) card.fail(3, "TYPE", "blank; expected a section type (" + fem::supported_section_types() + ")");
  section_from_dims(card, p, 8);
  return p;
}

}  // namespace

// MAT1 MID E G NU RHO A TREF GE / ST SC SS MCSID
void parse_mat1(const Card& card, ReaderState& st) {
  fem::Mat1 m;
  m.id = card.id(0, "MID");
  const bool has_e = !card.blank(1), has_g = !card.blank(2), has_nu = !card.blank(3);
  m.E = card.real_or(1, "E", 0.0);
  m.G = card.real_or(2, "G", 0.0);
  m.nu = card.real_or(3, "NU", 0.0);
  if (m.E < 0.0) card.fail(1, "E", card.got(1) + "; expected E >= 0");
  if (m.G < 0.0) card.fail(2, "G", card.got(2) + "; expected G >= 0");
  if (has_nu && !(m.nu > -1.0)) card.fail(3, "NU", card.got(3) + "; expected -1 < NU <= 0.5");
  // NU above 0.5 (the QRG's range is -1 < NU <= 0.5): read; fem::finalize warns, or lists it when a
  // shell or solid would use NU.
  // Nastran's rules (QRG MAT1, remarks 2-4): E or G must be given; if E and NU, or G and NU, are
  // both blank they are both 0 (e.g. an E-only truss material); otherwise a single blank one follows
  // from E = 2 (1 + NU) G.
  if (!has_e && !has_g)
    card.fail(1, "E", "blank, and G is blank too; expected E or G (or both)");
  if (has_e && !has_g && !has_nu) {
    m.G = 0.0;
    m.nu = 0.0;
  } else if (!has_e && has_g && !has_nu) {
    m.E = 0.0;
    m.nu = 0.0;
  } else {
    if (!has_g) m.G = m.E / (2.0 * (1.0 + m.nu));
    if (!has_nu) {
      if (m.G == 0.0) card.fail(2, "G", "G = 0 with NU blank; expected G > 0 to compute NU = E / (2 G) - 1");
      m.nu = m.E / (2.0 * m.G) - 1.0;
    }
    if (!has_e) m.E = 2.0 * (1.0 + m.nu) * m.G;
  }
  m.rho = card.real_or(4, "RHO", 0.0);
  m.alpha = card.real_or(5, "A", 0.0);
  m.tref = card.real_or(6, "TREF", 0.0);
  m.ge = card.real_or(7, "GE", 0.0);
  // ST, SC, SS (stress limits) and MCSID are read for their types only.
  card.real_or(8, "ST", 0.0);
  card.real_or(9, "SC", 0.0);
  card.real_or(10, "SS", 0.0);
  card.integer_or(11, "MCSID", 0);
  m.ref = card.ref();
  st.model.mat1.push_back(m);
}

// PBAR PID MID A I1 I2 J NSM - / C1 C2 D1 D2 E1 E2 F1 F2 / K1 K2 I12
void parse_pbar(const Card& card, ReaderState& st) {
  fem::BarProperty p;
  p.source = fem::BarProperty::Source::PBAR;
  p.id = card.id(0, "PID");
  p.mid = card.id(1, "MID");
  p.A = card.real_or(2, "A", 0.0);
  p.I1 = card.real_or(3, "I1", 0.0);
  p.I2 = card.real_or(4, "I2", 0.0);
  p.J = card.real_or(5, "J", 0.0);
  p.nsm = card.real_or(6, "NSM", 0.0);
  static const char* stress[8] = {"C1", "C2", "D1", "D2", "E1", "E2", "F1", "F2"};
  for (std::size_t k = 0; k < 8; ++k) card.real_or(8 + k, stress[k], 0.0);
  p.K1 = card.real_or(16, "K1", 0.0);
  p.K2 = card.real_or(17, "K2", 0.0);
  p.I12 = card.real_or(18, "I12", 0.0);
  if (p.K1 < 0.0) card.fail(16, "K1", card.got(16) + "; expected K1 >= 0 or blank");
  if (p.K2 < 0.0) card.fail(17, "K2", card.got(17) + "; expected K2 >= 0 or blank");
  check_inertia(card, p, 3, 4, 18);
  p.ref = card.ref();
  st.model.bar_props.push_back(std::move(p));
}

// PBARL PID MID GROUP TYPE / DIM1 DIM2 ... DIMn NSM
void parse_pbarl(const Card& card, ReaderState& st) {
  fem::BarProperty p = section_property(card, fem::BarProperty::Source::PBARL);
  const std::size_t nsm_at = 8 + p.dims.size();
  p.nsm = card.real_or(nsm_at, "NSM", 0.0);
  for (std::size_t i = nsm_at + 1; i < card.size(); ++i)
    if (!card.blank(i)) card.fail(i, "NSM", card.got(i) + " after NSM; expected " + std::to_string(p.dims.size()) + " dimensions then NSM");
  p.ref = card.ref();
  st.model.bar_props.push_back(std::move(p));
}

// PBEAM PID MID A(A) I1(A) I2(A) I12(A) J(A) NSM(A) / C1(A) .. F2(A) / [SO X/XB A I1 I2 I12 J NSM /
//   C1 .. F2]... / K1 K2 S1 S2 NSI(A) NSI(B) CW(A) CW(B) / M1(A) M2(A) M1(B) M2(B) N1(A) N2(A) N1(B) N2(B)
// A taper (stations or end B differing from end A, NSI(B) differing from NSI(A)) keeps every station
// (BarProperty::stations); NSI, the non-structural mass moment of inertia per length, goes into the
// beam's polar inertia; M1/M2 (NSM centre of gravity) and N1/N2 (neutral axis) are kept for the CBEAM.
void parse_pbeam(const Card& card, ReaderState& st) {
  fem::BarProperty p;
  p.source = fem::BarProperty::Source::PBEAM;
  p.id = card.id(0, "PID");
  p.mid = card.id(1, "MID");
  p.A = card.real_or(2, "A", 0.0);
  p.I1 = card.real_or(3, "I1", 0.0);
  p.I2 = card.real_or(4, "I2", 0.0);
  p.I12 = card.real_or(5, "I12", 0.0);
  p.J = card.real_or(6, "J", 0.0);
  p.nsm = card.real_or(7, "NSM", 0.0);
  check_inertia(card, p, 3, 4, 5);
  const std::size_t nlines = (card.used() + 7) / 8;
  std::size_t line = 1;
  // stress recovery points of end A (optional when a station follows directly)
  if (line < nlines && !is_station_flag(upper(card.raw(8)))) ++line;
  bool tapered = false;
  static const char* names[6] = {"A", "I1", "I2", "I12", "J", "NSM"};
  const double end_a[6] = {p.A, p.I1, p.I2, p.I12, p.J, p.nsm};
  std::vector<fem::BarProperty::Station> stations{{0.0, p.A, p.I1, p.I2, p.I12, p.J, p.nsm, 0.0, {}}};
  while (line < nlines && is_station_flag(upper(card.raw(8 * line)))) {
    const std::size_t b = 8 * line;
    const double x = card.real(b + 1, "X/XB");
    if (x < 0.0 || x > 1.0) card.fail(b + 1, "X/XB", card.got(b + 1) + "; expected 0 <= X/XB <= 1");
    if (!(x > stations.back().x))
      card.fail(b + 1, "X/XB", card.got(b + 1) + "; expected stations in increasing X/XB after end A (0)");
    double v[6];
    for (std::size_t k = 0; k < 6; ++k) {
      v[k] = card.real_or(b + 2 + k, names[k], end_a[k]);
      if (std::abs(v[k] - end_a[k]) > 1e-9 * std::max(std::abs(end_a[k]), std::abs(v[k]))) tapered = true;
    }
    stations.push_back({x, v[0], v[1], v[2], v[3], v[4], v[5], 0.0, {}});
    const bool has_stress_line = upper(card.raw(b)) == "YES";
    line += has_stress_line ? 2 : 1;
  }
  if (stations.back().x < 1.0) {  // end B as the last station given (QRG: the last one is end B)
    stations.push_back(stations.back());
    stations.back().x = 1.0;
  }
  if (line < nlines) {  // K1 K2 S1 S2 NSI(A) NSI(B) CW(A) CW(B)
    const std::size_t b = 8 * line;
    p.K1 = card.real_or(b, "K1", 1.0);
    p.K2 = card.real_or(b + 1, "K2", 1.0);
    if (p.K1 < 0.0) card.fail(b, "K1", card.got(b) + "; expected K1 >= 0 or blank");
    if (p.K2 < 0.0) card.fail(b + 1, "K2", card.got(b + 1) + "; expected K2 >= 0 or blank");
    p.nsi = card.real_or(b + 4, "NSI(A)", 0.0);
    if (p.nsi < 0.0) card.fail(b + 4, "NSI(A)", card.got(b + 4) + "; expected a mass moment of inertia per length >= 0 or blank");
    const double nsi_b = card.real_or(b + 5, "NSI(B)", p.nsi);
    if (std::abs(nsi_b - p.nsi) > 1e-9 * std::max(std::abs(p.nsi), std::abs(nsi_b))) tapered = true;
    for (auto& s : stations) s.nsi = p.nsi + s.x * (nsi_b - p.nsi);
    // S1/S2, the shear relief of a tapered beam's flanges (QRG: "shear relief coefficient due to
    // taper"), are not modelled. CW(A)/CW(B), the warping coefficient, acts only through the warping
    // degrees of freedom SA/SB of a CBEAM (MSC Nastran QRG, CBEAM remarks 5 and 6: without them
    // "torsional stiffness due to warping of the cross section will not be considered"; MSC Nastran
    // 2014.1 runs pyNastran's cantilever_2014.1.bdf, CW = 10.9761 and no SA/SB, with warping torque 0
    // and the twist TL/GJ), so it is read and has no effect; a CBEAM with SA/SB is listed by its reader.
    if (card.real_or(b + 2, "S1", 0.0) != 0.0 || card.real_or(b + 3, "S2", 0.0) != 0.0)
      st.note_unsupported("PBEAM S1/S2 (shear relief of a tapered beam ignored)", card.ref());
    const double cw_a = card.real_or(b + 6, "CW(A)", 0.0);
    card.real_or(b + 7, "CW(B)", cw_a);
    ++line;
  } else {
    p.K1 = p.K2 = 1.0;  // QRG PBEAM: K1, K2 default to 1.0
  }
  if (line < nlines) {  // M1(A) M2(A) M1(B) M2(B) N1(A) N2(A) N1(B) N2(B); end B defaults to end A (QRG)
    const std::size_t b = 8 * line;
    p.m_A = {card.real_or(b, "M1(A)", 0.0), card.real_or(b + 1, "M2(A)", 0.0)};
    p.m_B = {card.real_or(b + 2, "M1(B)", p.m_A[0]), card.real_or(b + 3, "M2(B)", p.m_A[1])};
    p.n_A = {card.real_or(b + 4, "N1(A)", 0.0), card.real_or(b + 5, "N2(A)", 0.0)};
    p.n_B = {card.real_or(b + 6, "N1(B)", p.n_A[0]), card.real_or(b + 7, "N2(B)", p.n_A[1])};
    ++line;
  }
  if (line < nlines)
    card.fail(8 * line, "SO", card.got(8 * line) + "; expected YES, YESA or NO starting a station, or the K1 line and the M1 line at the end");
  if (tapered) p.stations = std::move(stations);
  p.ref = card.ref();
  st.model.bar_props.push_back(std::move(p));
}

// PBEAML PID MID GROUP TYPE / DIM1(A) .. DIMn(A) NSM(A) SO(1) X(1)/XB DIM1(1) .. DIMn(1) NSM(1) ...
void parse_pbeaml(const Card& card, ReaderState& st) {
  fem::BarProperty p = section_property(card, fem::BarProperty::Source::PBEAML);
  const std::size_t n = p.dims.size();
  p.nsm = card.real_or(8 + n, "NSM", 0.0);
  bool tapered = false;
  std::size_t i = 9 + n;
  const std::size_t used = card.used();
  std::vector<fem::BarProperty::Station> stations{{0.0, p.A, p.I1, p.I2, p.I12, p.J, p.nsm, 0.0, p.dims}};
  while (i < used) {
    const std::string so = card.text_or(i, "SO", "YES");
    if (!is_station_flag(so)) card.fail(i, "SO", card.got(i) + "; expected YES, YESA or NO");
    const double x = card.real(i + 1, "X/XB");
    if (x < 0.0 || x > 1.0) card.fail(i + 1, "X/XB", card.got(i + 1) + "; expected 0 <= X/XB <= 1");
    if (!(x > stations.back().x))
      card.fail(i + 1, "X/XB", card.got(i + 1) + "; expected stations in increasing X/XB after end A (0)");
    fem::BarProperty::Station s;
    s.x = x;
    for (std::size_t k = 0; k < n; ++k) {
      const std::string name = "DIM" + std::to_string(k + 1);
      s.dims.push_back(card.real_or(i + 2 + k, name.c_str(), p.dims[k]));
      if (std::abs(s.dims[k] - p.dims[k]) > 1e-9 * std::max(std::abs(p.dims[k]), std::abs(s.dims[k]))) tapered = true;
    }
    s.nsm = card.real_or(i + 2 + n, "NSM", p.nsm);
    if (s.nsm != p.nsm) tapered = true;
    try {
      const fem::BeamSection b = fem::beam_section(p.section_type, s.dims);
      s.A = b.A, s.I1 = b.I1, s.I2 = b.I2, s.I12 = b.I12, s.J = b.J;
    } catch (const InputError& e) {
      card.fail(i + 2, "DIMi", std::string(e.what()) + " (station X/XB = " + std::string(card.raw(i + 1)) + ")");
    }
    stations.push_back(std::move(s));
    i += n + 3;
  }
  if (stations.back().x < 1.0) {
    stations.push_back(stations.back());
    stations.back().x = 1.0;
  }
  if (tapered) p.stations = std::move(stations);
  p.ref = card.ref();
  st.model.bar_props.push_back(std::move(p));
}

// PROD PID MID A J C NSM
void parse_prod(const Card& card, ReaderState& st) {
  fem::RodProperty p;
  p.id = card.id(0, "PID");
  p.mid = card.id(1, "MID");
  p.A = card.real(2, "A");
  if (p.A < 0.0) card.fail(2, "A", card.got(2) + "; expected an area >= 0");
  p.J = card.real_or(3, "J", 0.0);
  p.C = card.real_or(4, "C", 0.0);
  p.nsm = card.real_or(5, "NSM", 0.0);
  p.ref = card.ref();
  st.model.rod_props.push_back(p);
}

// PTUBE PID MID OD T NSM OD2: a PROD of the tube's section (T = 0 or blank: a solid rod; QRG PTUBE).
// OD2 tapers the tube in heat transfer only (QRG remark 5): the structure has the section of OD,
// as MSC Nastran's; an OD2 other than OD is listed.
void parse_ptube(const Card& card, ReaderState& st) {
  fem::RodProperty p;
  p.tube = true;
  p.id = card.id(0, "PID");
  p.mid = card.id(1, "MID");
  p.od = card.real(2, "OD");
  if (!(p.od > 0.0)) card.fail(2, "OD", card.got(2) + "; expected an outside diameter > 0");
  p.t = card.real_or(3, "T", 0.0);
  if (!(p.t >= 0.0 && p.t <= 0.5 * p.od))
    card.fail(3, "T", card.got(3) + "; expected a wall thickness 0 <= T <= OD/2 (0 or blank: a solid rod)");
  p.nsm = card.real_or(4, "NSM", 0.0);
  p.od2 = card.real_or(5, "OD2", p.od);
  if (!(p.od2 > 0.0)) card.fail(5, "OD2", card.got(5) + "; expected a diameter at G2 > 0 or blank (OD)");
  if (p.od2 != p.od) st.note_unsupported("PTUBE OD2 (tapered; MSC Nastran tapers tubes in heat transfer only: the structure uses OD)", card.ref());
  if (card.used() > 6) card.fail(6, "", card.got(6) + " after OD2; expected nothing more");
  const double r_in = p.t == 0.0 ? 0.0 : 0.5 * p.od - p.t;  // T = 0 or OD/2: the solid rod
  const fem::BeamSection s = r_in > 0.0 ? fem::beam_section("TUBE", {0.5 * p.od, r_in}) : fem::beam_section("ROD", {0.5 * p.od});
  p.A = s.A;
  p.J = s.J;
  p.C = 0.5 * p.od;
  p.ref = card.ref();
  st.model.rod_props.push_back(p);
}

// PBEND PID MID A I1 I2 J RB THETAB / C1 C2 D1 D2 E1 E2 F1 F2 / K1 K2 NSM RC ZC DELTAN, or the pipe
// format PID MID FSI RM T P RB THETAB / - - NSM RC ZC (FSI an integer in field 4).
void parse_pbend(const Card& card, ReaderState& st) {
  fem::BendProperty p;
  p.id = card.id(0, "PID");
  p.mid = card.id(1, "MID");
  p.pipe = card.kind(2) == FieldKind::Integer;
  if (p.pipe) {
    p.fsi = card.integer(2, "FSI");
    if (p.fsi < 1 || p.fsi > 3) card.fail(2, "FSI", card.got(2) + "; expected 1, 2 or 3 (pipe format), or the area A (real)");
    p.rm = card.real(3, "RM");
    if (!(p.rm > 0.0)) card.fail(3, "RM", card.got(3) + "; expected a mean pipe radius > 0");
    p.t = card.real_or(4, "T", 0.0);
    if (!(p.t >= 0.0 && p.t <= 2.0 * p.rm)) card.fail(4, "T", card.got(4) + "; expected a wall thickness 0 <= T <= 2 RM (0: a solid section of radius RM)");
    p.p = card.real_or(5, "P", 0.0);
    p.nsm = card.real_or(10, "NSM", 0.0);
    p.rc = card.real_or(11, "RC", 0.0);
    p.zc = card.real_or(12, "ZC", 0.0);
    // a circular tube of mean radius RM and wall T (T = 0: solid of radius RM, QRG PBEND remark 6)
    const double ro = p.t == 0.0 ? p.rm : p.rm + 0.5 * p.t, ri = p.t == 0.0 ? 0.0 : p.rm - 0.5 * p.t;
    const fem::BeamSection s = ri > 0.0 ? fem::beam_section("TUBE", {ro, ri}) : fem::beam_section("ROD", {ro});
    p.A = s.A, p.I1 = p.I2 = s.I1, p.J = s.J;
    st.note_unsupported("PBEND pipe format (flexibility factors FSI, pressure P and transverse shear not applied: a circular tube)", card.ref());
  } else {
    static const char* names[4] = {"A", "I1", "I2", "J"};
    double* v[4] = {&p.A, &p.I1, &p.I2, &p.J};
    for (std::size_t k = 0; k < 4; ++k) {
      *v[k] = card.real(2 + k, names[k]);
      if (!(*v[k] > 0.0)) card.fail(2 + k, names[k], card.got(2 + k) + "; expected a section property > 0");
    }
    for (std::size_t i = 8; i < 16; ++i) card.real_or(i, "Ci/Di/Ei/Fi", 0.0);  // stress recovery points: not used
    p.K1 = card.real_or(16, "K1", 0.0);
    p.K2 = card.real_or(17, "K2", 0.0);
    if (!(p.K1 >= 0.0)) card.fail(16, "K1", card.got(16) + "; expected a shear factor >= 0 (0 or blank: rigid in shear)");
    if (!(p.K2 >= 0.0)) card.fail(17, "K2", card.got(17) + "; expected a shear factor >= 0 (0 or blank: rigid in shear)");
    p.nsm = card.real_or(18, "NSM", 0.0);
    p.rc = card.real_or(19, "RC", 0.0);
    p.zc = card.real_or(20, "ZC", 0.0);
    p.has_deltan = !card.blank(21);
    p.deltan = card.real_or(21, "DELTAN", 0.0);
  }
  p.rb = card.real_or(6, "RB", 0.0);
  p.thetab_deg = card.real_or(7, "THETAB", 0.0);
  if (p.rc != 0.0 || p.zc != 0.0) st.note_unsupported("PBEND RC/ZC (centroid offsets ignored)", card.ref());
  if (p.deltan != 0.0) st.note_unsupported("PBEND DELTAN (neutral-axis offset ignored: a thin curved beam)", card.ref());
  p.ref = card.ref();
  st.model.bend_props.push_back(p);
}

// PSHEAR PID MID T NSM F1 F2 (F1, F2 blank: 0, no extensional stiffness)
void parse_pshear(const Card& card, ReaderState& st) {
  fem::ShearProperty p;
  p.id = card.id(0, "PID");
  p.mid = card.id(1, "MID");
  p.t = card.real(2, "T");
  if (!(p.t > 0.0)) card.fail(2, "T", card.got(2) + "; expected a thickness > 0");
  p.nsm = card.real_or(3, "NSM", 0.0);
  p.f1 = card.real_or(4, "F1", 0.0);
  p.f2 = card.real_or(5, "F2", 0.0);
  if (!(p.f1 >= 0.0)) card.fail(4, "F1", card.got(4) + "; expected an effectiveness factor >= 0 (0 or blank: none)");
  if (!(p.f2 >= 0.0)) card.fail(5, "F2", card.got(5) + "; expected an effectiveness factor >= 0 (0 or blank: none)");
  if (card.used() > 6) card.fail(6, "", card.got(6) + " after F2; expected nothing more");
  p.ref = card.ref();
  st.model.shear_props.push_back(p);
}

// PSHELL PID MID1 T MID2 12I/T**3 MID3 TS/T NSM / Z1 Z2 MID4
void parse_pshell(const Card& card, ReaderState& st) {
  fem::ShellProperty p;
  p.id = card.id(0, "PID");
  p.mid1 = card.id_or(1, "MID1", 0);
  p.t = card.real_or(2, "T", 0.0);
  if (p.t < 0.0) card.fail(2, "T", card.got(2) + "; expected a thickness >= 0 or blank");
  p.mid2 = card.integer_or(3, "MID2", 0);
  const bool plane_strain = p.mid2 == -1;
  if (p.mid2 < -1) card.fail(3, "MID2", card.got(3) + "; expected a material id, -1 (plane strain) or blank");
  p.bend_ratio = card.real_or(4, "12I/T**3", 1.0);
  if (p.bend_ratio < 0.0) card.fail(4, "12I/T**3", card.got(4) + "; expected a ratio >= 0 or blank");
  p.mid3 = card.id_or(5, "MID3", 0);
  p.ts_t = card.real_or(6, "TS/T", 0.833333);
  if (p.ts_t < 0.0) card.fail(6, "TS/T", card.got(6) + "; expected a ratio >= 0 or blank");
  p.nsm = card.real_or(7, "NSM", 0.0);
  p.z1 = card.real_or(8, "Z1", -0.5 * p.t);
  p.z2 = card.real_or(9, "Z2", 0.5 * p.t);
  p.mid4 = card.id_or(10, "MID4", 0);
  // Z1/Z2 only place the fibres of stress recovery, which seflex does not do: said when they differ
  // from the defaults.
  if ((!card.blank(8) && p.z1 != -0.5 * p.t) || (!card.blank(9) && p.z2 != 0.5 * p.t))
    st.note_unsupported("PSHELL Z1/Z2 (fibre distances for stresses, which seflex does not compute: not used)", card.ref());
  if (p.mid1 == 0 && p.mid2 == 0 && p.mid3 == 0)
    card.fail(1, "MID1", "MID1, MID2 and MID3 are all blank; expected at least one material");
  p.ref = card.ref();
  if (plane_strain) {
    // MID2 = -1: a plane-strain membrane (MSC QRG PSHELL), which seflex does not model: the property
    // is not kept, its elements are left out by fem::finalize and every solution refuses the deck.
    st.note_unsupported_member(kPlaneStrainShell, p.id, p.ref);
    return;
  }
  st.model.shell_props.push_back(p);
}

// MAT2 MID G11 G12 G13 G22 G23 G33 RHO / A1 A2 A3 TREF GE ST SC SS / MCSID
void parse_mat2(const Card& card, ReaderState& st) {
  fem::Mat2 m;
  m.id = card.id(0, "MID");
  m.G11 = card.real_or(1, "G11", 0.0);
  m.G12 = card.real_or(2, "G12", 0.0);
  m.G13 = card.real_or(3, "G13", 0.0);
  m.G22 = card.real_or(4, "G22", 0.0);
  m.G23 = card.real_or(5, "G23", 0.0);
  m.G33 = card.real_or(6, "G33", 0.0);
  m.rho = card.real_or(7, "RHO", 0.0);
  m.a1 = card.real_or(8, "A1", 0.0);
  m.a2 = card.real_or(9, "A2", 0.0);
  m.a3 = card.real_or(10, "A3", 0.0);
  m.tref = card.real_or(11, "TREF", 0.0);
  static const char* rest[3] = {"ST", "SC", "SS"};
  for (std::size_t k = 0; k < 3; ++k) card.real_or(13 + k, rest[k], 0.0);  // read for their types
  m.ge = card.real_or(12, "GE", 0.0);
  card.integer_or(16, "MCSID", 0);
  m.ref = card.ref();
  st.model.mat2.push_back(m);
}

// MAT8 MID E1 E2 NU12 G12 G1Z G2Z RHO / A1 A2 TREF Xt Xc Yt Yc S / GE F12 STRN
void parse_mat8(const Card& card, ReaderState& st) {
  fem::Mat8 m;
  m.id = card.id(0, "MID");
  m.E1 = card.real(1, "E1");
  m.E2 = card.real(2, "E2");
  m.nu12 = card.real(3, "NU12");
  if (!(m.E1 > 0.0)) card.fail(1, "E1", card.got(1) + "; expected a modulus > 0");
  if (!(m.E2 > 0.0)) card.fail(2, "E2", card.got(2) + "; expected a modulus > 0");
  if (!(m.nu12 * m.nu12 < m.E1 / m.E2))
    card.fail(3, "NU12", card.got(3) + "; expected NU12^2 < E1/E2 (1 - NU12 NU21 > 0, a positive definite material)");
  m.G12 = card.real_or(4, "G12", 0.0);
  m.G1z = card.real_or(5, "G1Z", 0.0);
  m.G2z = card.real_or(6, "G2Z", 0.0);
  if (m.G12 < 0.0) card.fail(4, "G12", card.got(4) + "; expected a modulus >= 0 or blank");
  if (m.G1z < 0.0) card.fail(5, "G1Z", card.got(5) + "; expected a modulus > 0, or blank (rigid in transverse shear)");
  if (m.G2z < 0.0) card.fail(6, "G2Z", card.got(6) + "; expected a modulus > 0, or blank (rigid in transverse shear)");
  m.rho = card.real_or(7, "RHO", 0.0);
  m.a1 = card.real_or(8, "A1", 0.0);
  m.a2 = card.real_or(9, "A2", 0.0);
  m.tref = card.real_or(10, "TREF", 0.0);
  static const char* rest[5] = {"Xt", "Xc", "Yt", "Yc", "S"};
  for (std::size_t k = 0; k < 5; ++k) card.real_or(11 + k, rest[k], 0.0);  // read for their types
  m.ge = card.real_or(16, "GE", 0.0);
  card.real_or(17, "F12", 0.0);
  card.real_or(18, "STRN", 0.0);
  m.ref = card.ref();
  st.model.mat8.push_back(m);
}

// MAT9 MID G11 G12 G13 G14 G15 G16 G22 / G23 G24 G25 G26 G33 G34 G35 G36 / G44 G45 G46 G55 G56 G66 RHO A1 /
//      A2 A3 A4 A5 A6 TREF GE
void parse_mat9(const Card& card, ReaderState& st) {
  static const char* const names[21] = {"G11", "G12", "G13", "G14", "G15", "G16", "G22", "G23", "G24", "G25", "G26",
                                        "G33", "G34", "G35", "G36", "G44", "G45", "G46", "G55", "G56", "G66"};
  static const char* const a_names[6] = {"A1", "A2", "A3", "A4", "A5", "A6"};
  fem::Mat9 m;
  m.id = card.id(0, "MID");
  for (std::size_t k = 0; k < 21; ++k) m.g[k] = card.real_or(1 + k, names[k], 0.0);
  // diagonal terms: positions of G11 G22 G33 G44 G55 G66 in the upper triangle
  static const std::size_t diagonal[6] = {0, 6, 11, 15, 18, 20};
  for (std::size_t i = 0; i < 6; ++i)
    if (!(m.g[diagonal[i]] > 0.0))
      card.fail(1 + diagonal[i], names[diagonal[i]], card.got(1 + diagonal[i]) + "; expected a diagonal modulus > 0");
  m.rho = card.real_or(22, "RHO", 0.0);
  for (std::size_t k = 0; k < 6; ++k) m.a[k] = card.real_or(23 + k, a_names[k], 0.0);
  m.tref = card.real_or(29, "TREF", 0.0);
  m.ge = card.real_or(30, "GE", 0.0);
  if (card.used() > 31) card.fail_card("has data after GE (field 8 of continuation 3); expected at most MID, G11-G66, RHO, A1-A6, TREF, GE");
  m.ref = card.ref();
  st.model.mat9.push_back(m);
}

namespace {

using Lam = fem::CompositeProperty::Lam;

/// PID Z0 NSM SB FT TREF GE LAM: the fields PCOMP and PCOMPG share.
fem::CompositeProperty composite_header(const Card& card, bool global) {
  fem::CompositeProperty p;
  p.global = global;
  p.id = card.id(0, "PID");
  p.has_z0 = !card.blank(1);
  p.z0 = card.real_or(1, "Z0", 0.0);
  p.nsm = card.real_or(2, "NSM", 0.0);
  p.sb = card.real_or(3, "SB", 0.0);
  p.ft = card.text_or(4, "FT", "");
  p.tref = card.real_or(5, "TREF", 0.0);
  p.ge = card.real_or(6, "GE", 0.0);
  const std::string lam = card.text_or(7, "LAM", "");
  if (lam.empty()) p.lam = Lam::Blank;
  else if (lam == "SYM" && !global) p.lam = Lam::Sym;
  else if (lam == "MEM") p.lam = Lam::Mem;
  else if (lam == "BEND") p.lam = Lam::Bend;
  else if (lam == "SMEAR") p.lam = Lam::Smear;
  else if (lam == "SMCORE") p.lam = Lam::SmCore;
  else
    card.fail(7, "LAM", card.got(7) + (global ? "; expected blank, MEM, BEND, SMEAR or SMCORE (PCOMPG lists every ply)"
                                              : "; expected blank, SYM, MEM, BEND, SMEAR or SMCORE"));
  return p;
}

/// MIDi Ti THETAi SOUTi of ply k (1-based) at data fields b..b+3; a blank MID or T is the previous
/// ply's (QRG PCOMP remark 1).
fem::CompositeProperty::Ply composite_ply(const Card& card, std::size_t b, std::size_t k,
                                          const fem::CompositeProperty& p) {
  const std::string n = std::to_string(k);
  const std::string mid = "MID" + n, t = "T" + n, theta = "THETA" + n, sout = "SOUT" + n;
  fem::CompositeProperty::Ply ply;
  const bool first = p.plies.empty();
  if (first && card.blank(b)) card.fail(b, mid.c_str(), "blank; expected the material of the first ply");
  if (first && card.blank(b + 1)) card.fail(b + 1, t.c_str(), "blank; expected the thickness of the first ply");
  ply.mid = card.id_or(b, mid.c_str(), first ? 0 : p.plies.back().mid);
  ply.t = card.real_or(b + 1, t.c_str(), first ? 0.0 : p.plies.back().t);
  if (!(ply.t > 0.0)) card.fail(b + 1, t.c_str(), card.got(b + 1) + "; expected a ply thickness > 0");
  ply.theta_deg = card.real_or(b + 2, theta.c_str(), 0.0);
  const std::string so = card.text_or(b + 3, sout.c_str(), "NO");
  if (so != "YES" && so != "NO") card.fail(b + 3, sout.c_str(), card.got(b + 3) + "; expected YES, NO or blank");
  ply.sout = so == "YES";
  return ply;
}

void check_composite(const Card& card, const fem::CompositeProperty& p) {
  if (p.plies.empty())
    card.fail_card(std::string("no plies; expected at least one ply (") + (p.global ? "GPLYID1 MID1 T1" : "MID1 T1") +
                   " ... on a continuation line)");
  if (p.lam == Lam::SmCore && p.plies.size() < 2)
    card.fail(7, "LAM", "SMCORE with one ply; expected the face-sheet plies, then the core ply last");
}

}  // namespace

// PCOMP PID Z0 NSM SB FT TREF GE LAM / MID1 T1 THETA1 SOUT1 MID2 T2 THETA2 SOUT2 / ...
void parse_pcomp(const Card& card, ReaderState& st) {
  fem::CompositeProperty p = composite_header(card, false);
  const std::size_t used = card.used();
  for (std::size_t b = 8, k = 1; b < used; b += 4) {
    if (card.blank(b) && card.blank(b + 1) && card.blank(b + 2) && card.blank(b + 3)) continue;  // an empty slot
    p.plies.push_back(composite_ply(card, b, k++, p));
  }
  check_composite(card, p);
  p.ref = card.ref();
  st.model.composite_props.push_back(std::move(p));
}

// PCOMPG PID Z0 NSM SB FT TREF GE LAM / GPLYID1 MID1 T1 THETA1 SOUT1 / GPLYID2 ... (one ply per line)
void parse_pcompg(const Card& card, ReaderState& st) {
  fem::CompositeProperty p = composite_header(card, true);
  const std::size_t used = card.used();
  for (std::size_t b = 8, k = 1; b < used; b += 8, ++k) {
    const std::string g = "GPLYID" + std::to_string(k);
    const int gplyid = card.id(b, g.c_str());
    for (const auto& q : p.plies)
      if (q.gplyid == gplyid) card.fail(b, g.c_str(), card.got(b) + ", a repeated global ply id; expected unique GPLYIDs");
    fem::CompositeProperty::Ply ply = composite_ply(card, b + 1, k, p);
    ply.gplyid = gplyid;
    for (std::size_t i = b + 5; i < b + 8; ++i)
      if (!card.blank(i)) card.fail(i, "(blank)", card.got(i) + "; expected blank (PCOMPG takes one ply per line: GPLYID MID T THETA SOUT)");
    p.plies.push_back(ply);
  }
  check_composite(card, p);
  p.ref = card.ref();
  st.model.composite_props.push_back(std::move(p));
}

// PELAS PID1 K1 GE1 S1 PID2 K2 GE2 S2
void parse_pelas(const Card& card, ReaderState& st) {
  static const char* names[2][4] = {{"PID1", "K1", "GE1", "S1"}, {"PID2", "K2", "GE2", "S2"}};
  for (std::size_t s = 0; s < 2; ++s) {
    const std::size_t b = 4 * s;
    if (s == 1 && card.blank(4) && card.blank(5) && card.blank(6) && card.blank(7)) break;
    fem::SpringProperty p;
    p.id = card.id(b, names[s][0]);
    p.k = card.real(b + 1, names[s][1]);
    p.ge = card.real_or(b + 2, names[s][2], 0.0);
    p.s = card.real_or(b + 3, names[s][3], 0.0);
    p.ref = card.ref();
    st.model.spring_props.push_back(p);
  }
}

}  // namespace seflex::io::nastran
