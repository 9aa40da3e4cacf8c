#include "seflex/io/nastran_writer.hpp"

#include <charconv>
#include <cstdio>
#include <fstream>

#include "seflex/common/error.hpp"
#include "seflex/fem/finalize.hpp"
#include "seflex/io/results_csv.hpp"

namespace seflex::io {
namespace {

/// Builds one card's fields and appends it, free field, to a text buffer.
class CardWriter {
 public:
  explicit CardWriter(std::string& out) : out_(out) {}

  CardWriter& start(const char* name) {
    name_ = name;
    fields_.clear();
    return *this;
  }
  CardWriter& i(long long v) {
    char buf[24];
    const auto r = std::to_chars(buf, buf + sizeof buf, v);
    fields_.emplace_back(buf, r.ptr);
    return *this;
  }
  /// Shortest text that reads back to the same double, always with '.' or an exponent.
  CardWriter& r(double v) {
    char buf[40];
    const auto res = std::to_chars(buf, buf + sizeof buf, v);
    std::string s(buf, res.ptr);
    if (s.find_first_of(".e") == std::string::npos) s += '.';
    fields_.push_back(std::move(s));
    return *this;
  }
  CardWriter& t(std::string s) {
    fields_.push_back(std::move(s));
    return *this;
  }
  CardWriter& blank(std::size_t n = 1) {
    for (std::size_t k = 0; k < n; ++k) fields_.emplace_back();
    return *this;
  }
  /// Id or blank when 0.
  CardWriter& id0(int v) { return v ? i(v) : blank(); }
  CardWriter& components(fem::ComponentMask c, bool zero_is_blank = true) {
    if (c == 0) return zero_is_blank ? blank() : i(0);
    std::string s;
    for (int k = 0; k < 6; ++k)
      if (c & (1u << k)) s += static_cast<char>('1' + k);
    return t(std::move(s));
  }
  /// Pad to the start of the next continuation line.
  CardWriter& next_line() {
    while (fields_.size() % 8) fields_.emplace_back();
    return *this;
  }
  void end() {
    std::size_t n = fields_.size();
    while (n > 0 && fields_[n - 1].empty()) --n;
    out_ += name_;
    for (std::size_t k = 0; k < n; ++k) {
      if (k > 0 && k % 8 == 0) out_ += "\n";
      out_ += ',';
      out_ += fields_[k];
    }
    if (n == 0) out_ += ',';
    out_ += '\n';
  }

 private:
  std::string& out_;
  const char* name_ = "";
  std::vector<std::string> fields_;
};

const char* coord_name(const fem::CoordSys& c) {
  static const char* names[2][3] = {{"CORD2R", "CORD2C", "CORD2S"}, {"CORD1R", "CORD1C", "CORD1S"}};
  return names[c.by_grids ? 1 : 0][static_cast<int>(c.type)];
}

/// Name or quoted name for a `$seflex set` line.
std::string set_name(const std::string& s) {
  return s.find_first_of(" \t") == std::string::npos && !s.empty() ? s : "\"" + s + "\"";
}

void write_case_control(const fem::Model& m, std::string& out) {
  const fem::CaseControl& cc = m.case_control;
  auto selections = [&](const fem::Subcase& s, const char* indent) {
    if (!s.label.empty()) out += std::string(indent) + "LABEL = " + s.label + "\n";
    if (s.spc) out += std::string(indent) + "SPC = " + std::to_string(*s.spc) + "\n";
    if (s.mpc) out += std::string(indent) + "MPC = " + std::to_string(*s.mpc) + "\n";
    if (s.load) out += std::string(indent) + "LOAD = " + std::to_string(*s.load) + "\n";
    if (s.method) out += std::string(indent) + "METHOD = " + std::to_string(*s.method) + "\n";
    if (s.temperature) out += std::string(indent) + "TEMPERATURE(LOAD) = " + std::to_string(*s.temperature) + "\n";
    for (const auto* names : {&s.k2gg, &s.m2gg}) {
      if (names->empty()) continue;
      out += std::string(indent) + (names == &s.k2gg ? "K2GG = " : "M2GG = ");
      for (std::size_t k = 0; k < names->size(); ++k) out += (k ? ", " : "") + (*names)[k];
      out += "\n";
    }
  };
  const fem::Subcase& g = cc.global;
  const bool any = cc.sol || !cc.title.empty() || !cc.subtitle.empty() || !cc.subcases.empty() || !g.label.empty() ||
                   g.spc || g.mpc || g.load || g.method || g.temperature || !g.k2gg.empty() || !g.m2gg.empty();
  if (!any) return;
  if (cc.sol) out += "SOL " + *cc.sol + "\n";
  out += "CEND\n";
  if (!cc.title.empty()) out += "TITLE = " + cc.title + "\n";
  if (!cc.subtitle.empty()) out += "SUBTITLE = " + cc.subtitle + "\n";
  selections(g, "");
  for (const auto& s : cc.subcases) {
    out += "SUBCASE " + std::to_string(s.id) + "\n";
    selections(s, "  ");
  }
}

/// MAT1 with the one of E, G, NU blank that the reader's completion rule gives back exactly. A NU
/// outside (-1, 0.5] can only have been computed (the reader checks a given NU): it stays blank.
void write_mat1(CardWriter& w, const fem::Mat1& m) {
  const bool nu_computed = m.G != 0.0 && m.nu == m.E / (2.0 * m.G) - 1.0;
  const bool nu_blank = nu_computed && !(m.nu > -1.0 && m.nu <= 0.5);
  const bool g_blank = !nu_blank && m.G == m.E / (2.0 * (1.0 + m.nu));
  const bool nu_blank2 = nu_blank || (!g_blank && nu_computed);
  const bool e_blank = !g_blank && !nu_blank2 && m.E == 2.0 * (1.0 + m.nu) * m.G;
  w.start("MAT1").i(m.id);
  e_blank ? w.blank() : w.r(m.E);
  g_blank ? w.blank() : w.r(m.G);
  nu_blank2 ? w.blank() : w.r(m.nu);
  w.r(m.rho).r(m.alpha).r(m.tref).r(m.ge).end();
}

void write_composite(CardWriter& w, const fem::CompositeProperty& p) {
  using Lam = fem::CompositeProperty::Lam;
  static const char* lam[] = {"", "SYM", "MEM", "BEND", "SMEAR", "SMCORE"};
  w.start(p.global ? "PCOMPG" : "PCOMP").i(p.id);
  p.has_z0 ? w.r(p.z0) : w.blank();
  w.r(p.nsm).r(p.sb);
  p.ft.empty() ? w.blank() : w.t(p.ft);
  w.r(p.tref).r(p.ge);
  p.lam == Lam::Blank ? w.blank() : w.t(lam[static_cast<int>(p.lam)]);
  for (const auto& ply : p.plies) {
    if (p.global) w.next_line().i(ply.gplyid);
    w.i(ply.mid).r(ply.t).r(ply.theta_deg).t(ply.sout ? "YES" : "NO");
  }
  w.end();
}

void write_bar_property(CardWriter& w, const fem::BarProperty& p) {
  using Source = fem::BarProperty::Source;
  w.start(fem::card_name(p.source)).i(p.id).i(p.mid);
  switch (p.source) {
    case Source::PBAR:
      w.r(p.A).r(p.I1).r(p.I2).r(p.J).r(p.nsm).next_line().blank(8).r(p.K1).r(p.K2).r(p.I12);
      break;
    case Source::PBEAM:
      w.r(p.A).r(p.I1).r(p.I2).r(p.I12).r(p.J).r(p.nsm).next_line();
      if (p.stations.empty())
        w.blank(8);
      for (std::size_t k = 1; k < p.stations.size(); ++k) {  // a taper: each station (end B last), no stress points
        const auto& s = p.stations[k];
        w.t("NO").r(s.x).r(s.A).r(s.I1).r(s.I2).r(s.I12).r(s.J).r(s.nsm);
      }
      w.r(p.K1).r(p.K2).blank(2).r(p.nsi).r(p.stations.empty() ? p.nsi : p.stations.back().nsi);
      if (p.m_A != p.m_B || p.n_A != p.n_B || p.m_A != std::array<double, 2>{} || p.n_A != std::array<double, 2>{}) {
        w.blank(2);  // CW(A), CW(B): no effect without a CBEAM's SA/SB (see parse_pbeam)
        for (const auto& yz : {p.m_A, p.m_B, p.n_A, p.n_B}) w.r(yz[0]).r(yz[1]);
      }
      break;
    case Source::PBARL:
    case Source::PBEAML:
      w.t("MSCBML0").t(p.section_type).next_line();
      for (const double d : p.dims) w.r(d);
      w.r(p.nsm);
      for (std::size_t k = 1; k < p.stations.size(); ++k) {  // a taper: the stations' dimensions (end B last)
        w.t("NO").r(p.stations[k].x);
        for (const double d : p.stations[k].dims) w.r(d);
        w.r(p.stations[k].nsm);
      }
      break;
  }
  w.end();
}

void write_bar(CardWriter& w, const fem::Bar& b) {
  w.start(b.is_beam ? "CBEAM" : "CBAR").i(b.id).i(b.pid).i(b.ga).i(b.gb);
  if (b.has_g0)
    w.i(b.g0).blank(2);
  else if (b.v.squaredNorm() > 0.0)
    w.r(b.v.x()).r(b.v.y()).r(b.v.z());
  else
    w.blank(3);
  w.t(b.offt.empty() ? "GGG" : b.offt);
  if (b.pa || b.pb || b.wa.squaredNorm() > 0.0 || b.wb.squaredNorm() > 0.0) {
    w.components(b.pa).components(b.pb);
    for (int k = 0; k < 3; ++k) w.r(b.wa(k));
    for (int k = 0; k < 3; ++k) w.r(b.wb(k));
  }
  w.end();
}

void write_shell(CardWriter& w, const fem::Shell& s) {
  w.start(fem::shell_card(s)).i(s.id).i(s.pid);
  for (int k = 0; k < s.nnode; ++k) w.i(s.g[k]);
  if (s.theta_is_mcid)
    w.i(s.mcid);
  else
    w.r(s.theta_deg);
  w.r(s.zoffs);
  const bool corner = s.tflag != 0 || s.t[0] != 0.0 || s.t[1] != 0.0 || s.t[2] != 0.0 || s.t[3] != 0.0;
  if (corner) {
    w.next_line().blank(2).i(s.tflag);
    for (int k = 0; k < s.nnode; ++k) s.t[k] != 0.0 ? w.r(s.t[k]) : w.blank();
  }
  w.end();
}


/// CQUAD8 EID PID G1-G6 / G7 G8 T1-T4 THETA/MCID ZOFFS / TFLAG; CTRIA6 EID PID G1-G6 / THETA/MCID
/// ZOFFS T1-T3 TFLAG (blank mid-side grids and thicknesses stay blank).
void write_quadratic_shell(const fem::QuadraticShell& q, CardWriter& w) {
  const fem::Shell& s = q.shell;
  const bool quad = s.nnode == 4;
  w.start(fem::quadratic_shell_card(q)).i(s.id).i(s.pid);
  for (int k = 0; k < s.nnode; ++k) w.i(s.g[static_cast<std::size_t>(k)]);
  for (int k = 0; k < s.nnode; ++k) w.id0(q.mid[static_cast<std::size_t>(k)]);
  auto theta = [&] { s.theta_is_mcid ? w.i(s.mcid) : w.r(s.theta_deg); };
  auto thicknesses = [&] {
    for (int k = 0; k < s.nnode; ++k) s.t[static_cast<std::size_t>(k)] != 0.0 ? w.r(s.t[static_cast<std::size_t>(k)]) : w.blank();
  };
  if (quad) {
    thicknesses();
    theta();
    w.r(s.zoffs).i(s.tflag);
  } else {
    theta();
    w.r(s.zoffs);
    thicknesses();
    w.i(s.tflag);
  }
  w.end();
}

/// GENEL as the reader reads it (nastran_cards_genel.cpp): the lists and matrices each from a new line.
void write_genel(const fem::Genel& g, CardWriter& w) {
  w.start("GENEL").i(g.id).blank();
  for (const auto& d : g.ui) w.i(d.point).i(d.c);
  if (!g.ud.empty()) {
    w.next_line().t("UD").blank();
    for (const auto& d : g.ud) w.i(d.point).i(d.c);
  }
  w.next_line().t(g.flexibility ? "Z" : "K");
  for (const double v : g.kz) w.r(v);
  if (!g.s.empty()) {
    w.next_line().t("S");
    for (const double v : g.s) w.r(v);
  }
  w.end();
}

/// RBE1, CRIGD1, CRIGD2, CRIGD3 as the reader reads them (nastran_cards_rigid.cpp).
void write_rigid_body(const fem::RigidBody& r, CardWriter& w) {
  w.start(fem::rigid_body_card(r)).i(r.id);
  if (r.card == fem::RigidBody::Card::Crigd1 || r.card == fem::RigidBody::Card::Crigd2) {
    w.i(r.independent.front().grid);
    for (const auto& g : r.dependent) {
      w.i(g.grid);
      if (r.card == fem::RigidBody::Card::Crigd2) w.components(g.c);
    }
    w.end();
    return;
  }
  // RBE1, CRIGD3: three pairs per line in fields 3-8; the dependent pairs after UM (MSET)
  auto pairs = [&](const std::vector<fem::RigidBody::GridComponents>& list) {
    for (std::size_t k = 0; k < list.size(); ++k) {
      if (k > 0 && k % 3 == 0) w.blank().next_line().blank();
      w.i(list[k].grid).components(list[k].c);
    }
  };
  pairs(r.independent);
  w.next_line().t(r.card == fem::RigidBody::Card::Rbe1 ? "UM" : "MSET");
  pairs(r.dependent);
  if (r.alpha != 0.0) w.r(r.alpha);
  w.end();
}

void write_elements(const fem::Model& m, CardWriter& w) {
  for (const auto& b : m.bars) write_bar(w, b);
  for (const auto& r : m.rods) {
    if (r.inline_property)
      w.start("CONROD").i(r.id).i(r.ga).i(r.gb).i(r.mid).r(r.A).r(r.J).r(r.C).r(r.nsm).end();
    else
      w.start(fem::rod_card(r)).i(r.id).i(r.pid).i(r.ga).i(r.gb).end();
  }
  for (const auto& s : m.shells) write_shell(w, s);
  for (const auto& s : m.solids) {
    w.start(s.card()).i(s.id).i(s.pid);
    for (int k = 0; k < s.corners(); ++k) w.i(s.g[static_cast<std::size_t>(k)]);
    if (s.quadratic())
      for (int e = 0, k = s.corners(); e < s.edges(); ++e)  // a blank mid-edge grid: a straight edge
        (s.missing_mid >> e & 1u) ? w.blank() : w.i(s.g[static_cast<std::size_t>(k++)]);
    w.end();
  }
  for (const auto& s : m.springs) {
    if (s.scalar_points)
      s.inline_property ? w.start("CELAS4").i(s.id).r(s.k).id0(s.g1).id0(s.g2).end()
                        : w.start("CELAS3").i(s.id).i(s.pid).id0(s.g1).id0(s.g2).end();
    else if (s.inline_property)
      w.start("CELAS2").i(s.id).r(s.k).id0(s.g1).i(s.c1).id0(s.g2).i(s.c2).r(s.ge).r(s.s).end();
    else
      w.start("CELAS1").i(s.id).i(s.pid).id0(s.g1).i(s.c1).id0(s.g2).i(s.c2).end();
  }
  for (const auto& r : m.rbe2) {
    w.start("RBE2").i(r.id).i(r.gn).components(r.cm);
    for (const int g : r.gm) w.i(g);
    w.end();
  }
  for (const auto& r : m.rbars)
    w.start("RBAR").i(r.id).i(r.ga).i(r.gb).components(r.cna).components(r.cnb).components(r.cma).components(r.cmb)
        .r(r.alpha).end();
  for (const auto& q : m.shells8) write_quadratic_shell(q, w);
  for (const auto& s : m.shear_panels) w.start("CSHEAR").i(s.id).i(s.pid).i(s.g[0]).i(s.g[1]).i(s.g[2]).i(s.g[3]).end();
  for (const auto& b : m.bends) {
    w.start("CBEND").i(b.id).i(b.pid).i(b.ga).i(b.gb);
    if (b.has_g0)
      w.i(b.g0).blank(2);
    else
      w.r(b.v.x()).r(b.v.y()).r(b.v.z());
    w.i(b.geom).end();
  }
  for (const auto& r : m.rigid_bodies) write_rigid_body(r, w);
  for (const auto& g : m.genels) write_genel(g, w);
  for (const auto& r : m.rigid_rods) {
    if (r.card == fem::RigidRod::Card::Crigdr)
      w.start("CRIGDR").i(r.id).i(r.ga).i(r.gb).i(r.cmb).end();
    else
      w.start("RROD").i(r.id).i(r.ga).i(r.gb).id0(r.cma).id0(r.cmb).r(r.alpha).end();
  }
  for (const auto& r : m.rbe3) {
    w.start("RBE3").i(r.id).blank().i(r.refgrid).components(r.refc);
    for (const auto& g : r.groups) {
      w.r(g.weight).components(g.c);
      for (const int id : g.grids) w.i(id);
    }
    if (!r.um.empty()) {
      w.next_line().t("UM");
      for (std::size_t k = 0; k < r.um.size(); ++k) {
        if (k > 0 && k % 3 == 0) w.blank().next_line().blank();  // three pairs per line, fields 3-8
        w.i(r.um[k].grid).components(r.um[k].c);
      }
    }
    if (r.has_alpha) w.next_line().t("ALPHA").r(r.alpha);
    w.end();
  }
  for (const auto& c : m.conm2)
    w.start("CONM2").i(c.id).i(c.grid).i(c.cid).r(c.m).r(c.x.x()).r(c.x.y()).r(c.x.z()).blank()
        .r(c.I11).r(c.I21).r(c.I22).r(c.I31).r(c.I32).r(c.I33).end();
}

void write_constraints_and_loads(const fem::Model& m, CardWriter& w) {
  for (const auto& s : m.spcs) {
    // grids of an SPC1 THRU range that do not exist are not part of the model (QRG SPC1)
    if (s.from_thru && !m.grid_index.count(s.grid) && !m.spoint_index.count(s.grid)) continue;
    w.start("SPC").i(s.sid).i(s.grid).components(s.c, false).r(s.d).end();
  }
  for (const auto& a : m.spcadds) {
    w.start("SPCADD").i(a.sid);
    for (const int s : a.sets) w.i(s);
    w.end();
  }
  for (const auto& e : m.mpcs) {
    w.start("MPC").i(e.sid);
    for (std::size_t k = 0; k < e.terms.size(); ++k) {
      if (k > 0 && k % 2 == 0) w.blank().next_line().blank();  // two terms per line, fields 3-8
      w.i(e.terms[k].grid).i(e.terms[k].component).r(e.terms[k].a);
    }
    w.end();
  }
  for (const auto& a : m.mpcadds) {
    w.start("MPCADD").i(a.sid);
    for (const int s : a.sets) w.i(s);
    w.end();
  }
  const std::pair<const char*, const std::vector<fem::DofSetEntry>*> sets[] = {
      {"ASET", &m.aset}, {"OMIT", &m.omit}, {"BSET", &m.bset}, {"SUPORT", &m.suport}};
  for (const auto& [name, entries] : sets)
    for (const auto& e : *entries) w.start(name).i(e.grid).components(e.c, false).end();
  for (const auto& l : m.point_loads) {
    w.start(fem::point_load_card(l)).i(l.sid).i(l.grid);
    if (l.direction == fem::PointLoad::Direction::Vector) {
      w.i(l.cid).r(l.scale).r(l.n.x()).r(l.n.y()).r(l.n.z()).end();
      continue;
    }
    w.r(l.scale).i(l.g[0]).i(l.g[1]);
    if (l.direction == fem::PointLoad::Direction::FourGrids) w.i(l.g[2]).i(l.g[3]);
    w.end();
  }
  for (const auto& l : m.scalar_loads) w.start("SLOAD").i(l.sid).i(l.point).r(l.f).end();
  for (const auto& l : m.grid_pressure_loads) w.start("PLOAD").i(l.sid).r(l.p).i(l.g[0]).i(l.g[1]).i(l.g[2]).id0(l.g[3]).end();
  for (const auto& l : m.pressure_loads) {
    w.start("PLOAD2").i(l.sid).r(l.p);
    if (l.thru)
      w.i(l.elements[0]).t("THRU").i(l.elements[1]);
    else
      for (const int e : l.elements) w.i(e);  // continued after six ids (the reader accepts it)
    w.end();
  }
  for (const auto& l : m.face_loads) {
    w.start("PLOAD4").i(l.sid).i(l.eid);
    for (const double p : l.p) w.r(p);
    if (l.eid_last > 0)
      w.t("THRU").i(l.eid_last);
    else
      w.id0(l.g1).id0(l.g34);
    if (l.n.squaredNorm() > 0) w.next_line().i(l.cid).r(l.n.x()).r(l.n.y()).r(l.n.z());
    w.end();
  }
  for (const auto& g : m.gravity_loads)
    w.start("GRAV").i(g.sid).id0(g.cid).r(g.a).r(g.n.x()).r(g.n.y()).r(g.n.z()).end();
  for (const auto& r : m.rotational_loads) {
    w.start("RFORCE").i(r.sid).id0(r.grid).id0(r.cid).r(r.a).r(r.r.x()).r(r.r.y()).r(r.r.z()).i(r.method);
    if (r.racc != 0.0) w.r(r.racc);
    w.end();
  }
  for (const auto& t : m.grid_temperatures) w.start("TEMP").i(t.sid).i(t.grid).r(t.t).end();
  for (const auto& t : m.default_temperatures) w.start("TEMPD").i(t.sid).r(t.t).end();
  for (const auto& t : m.bar_temperatures)
    w.start("TEMPRB").i(t.sid).i(t.element).r(t.ta).r(t.tb).r(t.tp1a).r(t.tp1b).r(t.tp2a).r(t.tp2b).end();
  for (const auto& l : m.load_combinations) {
    w.start("LOAD").i(l.sid).r(l.s);
    for (const auto& [s, id] : l.terms) w.r(s).i(id);
    w.end();
  }
}

/// PBUSH, PBUSH1D, PMASS, TABLEM1-4, CBUSH, CBUSH1D, CMASS1-4, CONM1, PLOAD1, SPCD.
void write_bush_mass_cards(const fem::Model& m, CardWriter& w) {
  for (const auto& p : m.bush_props) {
    if (p.one_d) {
      w.start("PBUSH1D").i(p.id).r(p.k[0]).r(p.b[0]).r(p.mass).blank().r(p.sa).r(p.se).end();
      continue;
    }
    w.start("PBUSH").i(p.id).t("K");
    for (const double k : p.k) w.r(k);
    if (p.has_b) {
      w.blank().t("B");
      for (const double b : p.b) w.r(b);
    }
    if (p.has_ge) {
      w.blank().t("GE");
      for (const double g : p.ge) w.r(g);
    }
    w.end();
  }
  for (std::size_t k = 0; k < m.mass_props.size(); k += 4) {
    w.start("PMASS");
    for (std::size_t j = k; j < m.mass_props.size() && j < k + 4; ++j) w.i(m.mass_props[j].id).r(m.mass_props[j].m);
    w.end();
  }
  for (const auto& t : m.material_tables) {
    static const char* names[4] = {"TABLEM1", "TABLEM2", "TABLEM3", "TABLEM4"};
    w.start(names[t.type - 1]).i(t.id);
    if (t.type == 1) {
      t.xaxis.empty() ? w.blank() : w.t(t.xaxis);
      t.yaxis.empty() ? w.blank() : w.t(t.yaxis);
      w.blank(5);
    } else {
      const int n = t.type == 2 ? 1 : t.type == 3 ? 2 : 4;
      for (int i = 0; i < n; ++i) w.r(t.x[static_cast<std::size_t>(i)]);
      w.blank(7 - n);
    }
    for (const double v : t.values) w.r(v);
    w.t("ENDT").end();
  }
  for (const auto& b : m.bushes) {
    if (b.one_d) {
      w.start("CBUSH1D").i(b.id).i(b.pid).i(b.ga).id0(b.gb);
      b.cid >= 0 ? w.i(b.cid) : w.blank();
      w.end();
      continue;
    }
    w.start("CBUSH").i(b.id).i(b.pid).i(b.ga).id0(b.gb);
    if (b.has_g0)
      w.i(b.g0).blank(2);
    else if (b.has_v)
      w.r(b.v.x()).r(b.v.y()).r(b.v.z());
    else
      w.blank(3);
    b.cid >= 0 ? w.i(b.cid) : w.blank();
    w.r(b.s).i(b.ocid);
    if (b.ocid >= 0) w.r(b.s_ocid.x()).r(b.s_ocid.y()).r(b.s_ocid.z());
    w.end();
  }
  for (const auto& s : m.scalar_masses) {
    const char* name = s.scalar_points ? (s.inline_property ? "CMASS4" : "CMASS3") : (s.inline_property ? "CMASS2" : "CMASS1");
    w.start(name).i(s.id);
    s.inline_property ? w.r(s.m) : w.i(s.pid);
    if (s.scalar_points)
      w.id0(s.g1).id0(s.g2);
    else
      w.id0(s.g1).i(s.c1).id0(s.g2).i(s.c2);
    w.end();
  }
  for (const auto& c : m.conm1) {
    w.start("CONM1").i(c.id).i(c.grid).i(c.cid);
    for (int r = 0; r < 6; ++r)
      for (int col = 0; col <= r; ++col) w.r(c.M(r, col));
    w.end();
  }
  static const char* scales[] = {"LE", "FR", "LEPR", "FRPR"};
  for (const auto& l : m.bar_line_loads)
    w.start("PLOAD1").i(l.sid).i(l.element).t(l.type).t(scales[static_cast<int>(l.scale)]).r(l.x1).r(l.p1).r(l.x2).r(l.p2).end();
  for (const auto& e : m.enforced_motions) w.start("SPCD").i(e.sid).i(e.grid).components(e.c, false).r(e.d).end();
}

void write_solution_cards(const fem::Model& m, CardWriter& w) {
  for (const auto& e : m.eigen_methods) {
    auto opt_r = [&](const std::optional<double>& v) { v ? w.r(*v) : w.blank(); };
    if (e.is_eigr || e.is_eigb) {  // EIGR F1 F2 NE ND, EIGB L1 L2 NEP NDP: the same fields
      w.start(fem::method_card(e)).i(e.sid).t(e.method);
      opt_r(e.f1);
      opt_r(e.f2);
      w.blank();
      e.nd ? w.i(*e.nd) : w.blank();
      w.next_line().t(e.norm);
      if (e.norm == "POINT") w.i(e.norm_grid).i(e.norm_component);
    } else {
      w.start("EIGRL").i(e.sid);
      opt_r(e.f1);
      opt_r(e.f2);
      e.nd ? w.i(*e.nd) : w.blank();
      w.blank(3).t(e.norm);
    }
    w.end();
  }
  for (const auto& d : m.dmigs) {
    w.start("DMIG").t(d.name).i(0).i(d.form).i(d.tin).i(d.tout).end();
    for (std::size_t k = 0; k < d.entries.size();) {
      const fem::DmigEntry& head = d.entries[k];
      w.start("DMIG").t(d.name).i(head.gj).i(head.cj).blank();
      for (; k < d.entries.size() && d.entries[k].gj == head.gj && d.entries[k].cj == head.cj; ++k)
        w.i(d.entries[k].gi).i(d.entries[k].ci).r(d.entries[k].value).blank();
      w.end();
    }
  }
}

}  // namespace

std::vector<std::string> unwritten_cards(const fem::Model& model) {
  std::vector<std::string> out;
  for (const auto& u : model.unsupported)
    out.push_back(u.name + " (" + std::to_string(u.count) + ", first at " + fem::where(model, u.first).str() + ")");
  return out;
}

void write_nastran(const fem::Model& m, std::ostream& stream, const NastranWriteOptions& options) {
  std::string out;
  out.reserve(256 + 64 * (m.grids.size() + m.shells.size() + m.bars.size() + m.conm2.size()));
  for (const auto& c : options.comments) out += "$ " + c + "\n";
  for (const auto& u : unwritten_cards(m)) out += "$ not written (seflex does not model it): " + u + "\n";
  write_case_control(m, out);
  out += "BEGIN BULK\n";
  CardWriter w(out);
  for (const auto& [name, ids] : m.node_sets)
    for (std::size_t k = 0; k < ids.size(); k += 10) {
      out += "$seflex set " + set_name(name);
      for (std::size_t j = k; j < ids.size() && j < k + 10; ++j) {
        out += ' ';
        out += std::to_string(ids[j]);
      }
      out += "\n";
    }
  for (const auto& p : m.params) {
    w.start("PARAM").t(p.name);
    for (const auto& v : p.values) w.t(v);
    w.end();
  }
  for (const auto& c : m.coords) {
    w.start(coord_name(c)).i(c.id);
    if (c.by_grids) {
      w.i(c.grids[0]).i(c.grids[1]).i(c.grids[2]);
    } else {
      w.i(c.rid);
      for (const double x : c.abc) w.r(x);
    }
    w.end();
  }
  for (const auto& g : m.grids)
    w.start("GRID").i(g.id).i(g.cp).r(g.x.x()).r(g.x.y()).r(g.x.z()).i(g.cd).components(g.ps).end();
  for (std::size_t k = 0; k < m.spoints.size(); k += 8) {
    w.start("SPOINT");
    for (std::size_t j = k; j < m.spoints.size() && j < k + 8; ++j) w.i(m.spoints[j].id);
    w.end();
  }
  for (const auto& mat : m.mat1) write_mat1(w, mat);
  for (const auto& mat : m.mat2)
    w.start("MAT2").i(mat.id).r(mat.G11).r(mat.G12).r(mat.G13).r(mat.G22).r(mat.G23).r(mat.G33).r(mat.rho)
        .next_line().r(mat.a1).r(mat.a2).r(mat.a3).r(mat.tref).r(mat.ge).end();
  for (const auto& mat : m.mat8) {
    w.start("MAT8").i(mat.id).r(mat.E1).r(mat.E2).r(mat.nu12).r(mat.G12);
    mat.G1z > 0.0 ? w.r(mat.G1z) : w.blank();  // blank = rigid in transverse shear
    mat.G2z > 0.0 ? w.r(mat.G2z) : w.blank();
    w.r(mat.rho).next_line().r(mat.a1).r(mat.a2).r(mat.tref).blank(5).r(mat.ge).end();
  }
  for (const auto& mat : m.mat9) {
    w.start("MAT9").i(mat.id);
    for (const double g : mat.g) w.r(g);
    w.r(mat.rho);
    for (const double a : mat.a) w.r(a);
    w.r(mat.tref).r(mat.ge).end();
  }
  for (const auto& p : m.bar_props) write_bar_property(w, p);
  for (const auto& p : m.rod_props)
    if (p.tube)
      w.start("PTUBE").i(p.id).i(p.mid).r(p.od).r(p.t).r(p.nsm).r(p.od2).end();
    else
      w.start("PROD").i(p.id).i(p.mid).r(p.A).r(p.J).r(p.C).r(p.nsm).end();
  for (const auto& p : m.shear_props) w.start("PSHEAR").i(p.id).i(p.mid).r(p.t).r(p.nsm).r(p.f1).r(p.f2).end();
  for (const auto& p : m.bend_props) {
    w.start("PBEND").i(p.id).i(p.mid);
    if (p.pipe)
      w.i(p.fsi).r(p.rm).r(p.t).r(p.p).r(p.rb).r(p.thetab_deg).next_line().blank(2).r(p.nsm).r(p.rc).r(p.zc);
    else {
      w.r(p.A).r(p.I1).r(p.I2).r(p.J).r(p.rb).r(p.thetab_deg).next_line().blank(8).r(p.K1).r(p.K2).r(p.nsm).r(p.rc).r(p.zc);
      if (p.has_deltan) w.r(p.deltan);
    }
    w.end();
  }
  for (const auto& p : m.shell_props)
    w.start("PSHELL").i(p.id).id0(p.mid1).r(p.t).id0(p.mid2).r(p.bend_ratio).id0(p.mid3).r(p.ts_t).r(p.nsm)
        .r(p.z1).r(p.z2).id0(p.mid4).end();
  for (const auto& p : m.composite_props) write_composite(w, p);
  for (const auto& p : m.spring_props) w.start("PELAS").i(p.id).r(p.k).r(p.ge).r(p.s).end();
  for (const auto& p : m.solid_props) {
    static const char* in[] = {"", "BUBBLE", "TWO", "THREE"};
    static const char* isop[] = {"", "REDUCED", "FULL"};
    w.start("PSOLID").i(p.id).i(p.mid).i(p.cordm).t(in[static_cast<int>(p.in)]).t(p.stress)
        .t(isop[static_cast<int>(p.isop)]).t(p.fctn).end();
  }
  stream << out;
  out.clear();
  write_elements(m, w);
  write_constraints_and_loads(m, w);
  write_bush_mass_cards(m, w);
  write_solution_cards(m, w);
  out += "ENDDATA\n";
  stream << out;
}

void write_nastran_file(const fem::Model& model, const std::filesystem::path& path, bool overwrite,
                        const NastranWriteOptions& options) {
  std::error_code ec;
  if (std::filesystem::is_directory(path, ec))
    throw InputError(path.string() + ": is a folder; expected the name of the deck to write");
  check_writable(path, overwrite);
  std::filesystem::path tmp = path;
  tmp += ".seflex-tmp";
  {
    std::ofstream out(tmp, std::ios::binary | std::ios::trunc);
    if (!out) throw InputError(path.string() + ": cannot create it (" + tmp.string() + " not writable); expected a writable folder");
    write_nastran(model, out, options);
    out.flush();
    if (!out) {
      out.close();
      std::filesystem::remove(tmp, ec);
      throw InputError(path.string() + ": writing failed (disk full?)");
    }
  }
  std::filesystem::rename(tmp, path, ec);
  if (ec) {
    std::filesystem::remove(tmp, ec);
    throw InputError(path.string() + ": cannot write it (" + ec.message() + ")");
  }
}

}  // namespace seflex::io
