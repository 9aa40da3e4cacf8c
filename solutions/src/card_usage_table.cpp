// The card table of check_card_usage (card_usage_table.hpp).
//
// TO SUPPORT A CARD: parse it into fem::Model (io/), make the solutions use it, then set `supported`
// on its row here. A supported Load or TemperatureLoad card also needs `members`: a function listing
// each card's set id (SID) and location, so that the cards of selected and unselected load sets can
// be told apart (see force_members below).
#include "card_usage_table.hpp"

#include <unordered_map>

namespace seflex::solutions::detail {
namespace {

template <fem::PointLoad::Kind K, fem::PointLoad::Direction D>
void point_load_members(const fem::Model& m, MemberList& out) {
  for (const auto& l : m.point_loads)
    if (l.kind == K && l.direction == D) out.push_back({l.sid, l.ref});
}
using PK = fem::PointLoad::Kind;
using PD = fem::PointLoad::Direction;
constexpr MembersFn force_members = point_load_members<PK::Force, PD::Vector>;
constexpr MembersFn moment_members = point_load_members<PK::Moment, PD::Vector>;
constexpr MembersFn force1_members = point_load_members<PK::Force, PD::TwoGrids>;
constexpr MembersFn moment1_members = point_load_members<PK::Moment, PD::TwoGrids>;
constexpr MembersFn force2_members = point_load_members<PK::Force, PD::FourGrids>;
constexpr MembersFn moment2_members = point_load_members<PK::Moment, PD::FourGrids>;

void sload_members(const fem::Model& m, MemberList& out) {
  for (const auto& l : m.scalar_loads) out.push_back({l.sid, l.ref});
}
void pload_members(const fem::Model& m, MemberList& out) {
  for (const auto& l : m.grid_pressure_loads) out.push_back({l.sid, l.ref});
}
void pload2_members(const fem::Model& m, MemberList& out) {
  for (const auto& l : m.pressure_loads) out.push_back({l.sid, l.ref});
}
void pload1_members(const fem::Model& m, MemberList& out) {
  for (const auto& l : m.bar_line_loads) out.push_back({l.sid, l.ref});
}
void spcd_members(const fem::Model& m, MemberList& out) {
  for (const auto& e : m.enforced_motions) out.push_back({e.sid, e.ref});
}
void pload4_members(const fem::Model& m, MemberList& out) {
  for (const auto& l : m.face_loads) out.push_back({l.sid, l.ref});
}
void grav_members(const fem::Model& m, MemberList& out) {
  for (const auto& l : m.gravity_loads) out.push_back({l.sid, l.ref});
}
void rforce_members(const fem::Model& m, MemberList& out) {
  for (const auto& l : m.rotational_loads) out.push_back({l.sid, l.ref});
}
void temp_members(const fem::Model& m, MemberList& out) {
  for (const auto& t : m.grid_temperatures) out.push_back({t.sid, t.ref});
}
void tempd_members(const fem::Model& m, MemberList& out) {
  for (const auto& t : m.default_temperatures) out.push_back({t.sid, t.ref});
}
void temprb_members(const fem::Model& m, MemberList& out) {
  for (const auto& t : m.bar_temperatures) out.push_back({t.sid, t.ref});
}

using R = Role;
constexpr bool Y = true, N = false;

// clang-format off
const CardRole kRows[] = {
    // geometry
    {"GRID", R::Geometry, Y, nullptr}, {"GRDSET", R::Geometry, Y, nullptr}, {"SPOINT", R::Geometry, Y, nullptr},
    {"CORD1R", R::Geometry, Y, nullptr}, {"CORD1C", R::Geometry, Y, nullptr}, {"CORD1S", R::Geometry, Y, nullptr},
    {"CORD2R", R::Geometry, Y, nullptr}, {"CORD2C", R::Geometry, Y, nullptr}, {"CORD2S", R::Geometry, Y, nullptr},
    {"CORD3G", R::Geometry, N, nullptr}, {"EPOINT", R::Dynamics, N, nullptr}, {"BAROR", R::Geometry, Y, nullptr},
    {"BEAMOR", R::Geometry, Y, nullptr}, {"SEQGP", R::Solver, N, nullptr}, {"SEQEP", R::Solver, N, nullptr},
    // elements
    {"CBAR", R::Structure, Y, nullptr}, {"CBEAM", R::Structure, Y, nullptr}, {"CROD", R::Structure, Y, nullptr},
    {"CONROD", R::Structure, Y, nullptr}, {"CQUAD4", R::Structure, Y, nullptr}, {"CTRIA3", R::Structure, Y, nullptr},
    {"CONM2", R::Structure, Y, nullptr}, {"CELAS1", R::Structure, Y, nullptr}, {"CELAS2", R::Structure, Y, nullptr},
    {"CELAS3", R::Structure, Y, nullptr}, {"CELAS4", R::Structure, Y, nullptr}, {"CMASS1", R::Structure, Y, nullptr},
    {"CMASS2", R::Structure, Y, nullptr}, {"CMASS3", R::Structure, Y, nullptr}, {"CMASS4", R::Structure, Y, nullptr},
    {"CONM1", R::Structure, Y, nullptr}, {"CBUSH", R::Structure, Y, nullptr}, {"CBUSH1D", R::Structure, Y, nullptr},
    {"CBUSH2D", R::Structure, N, nullptr}, {"CHEXA", R::Structure, Y, nullptr}, {"CPENTA", R::Structure, Y, nullptr},
    {"CTETRA", R::Structure, Y, nullptr}, {"CPYRAM", R::Structure, Y, nullptr}, {"CQUAD8", R::Structure, Y, nullptr},
    {"CTRIA6", R::Structure, Y, nullptr}, {"CQUADR", R::Structure, Y, nullptr}, {"CTRIAR", R::Structure, Y, nullptr},
    {"CQUAD", R::Structure, N, nullptr}, {"CSHEAR", R::Structure, Y, nullptr}, {"CTUBE", R::Structure, Y, nullptr},
    {"CBEND", R::Structure, Y, nullptr}, {"CBEAM3", R::Structure, N, nullptr}, {"CGAP", R::Structure, N, nullptr},
    {"CFAST", R::Structure, N, nullptr}, {"CWELD", R::Structure, N, nullptr}, {"CSEAM", R::Structure, N, nullptr},
    {"GENEL", R::Structure, Y, nullptr}, {"CQUADX", R::Structure, N, nullptr}, {"CTRIAX", R::Structure, N, nullptr},
    {"CTRIAX6", R::Structure, N, nullptr}, {"CCONEAX", R::Structure, N, nullptr}, {"CRAC2D", R::Structure, N, nullptr},
    {"CRAC3D", R::Structure, N, nullptr}, {"CSPRING", R::Structure, N, nullptr}, {"CDAMP1", R::Damping, N, nullptr},
    {"CDAMP2", R::Damping, N, nullptr}, {"CDAMP3", R::Damping, N, nullptr}, {"CDAMP4", R::Damping, N, nullptr},
    {"CDAMP5", R::Damping, N, nullptr}, {"CVISC", R::Damping, N, nullptr}, {"PLOTEL", R::Output, N, nullptr},
    // rigid and interpolation elements
    {"RBE2", R::Structure, Y, nullptr}, {"RBAR", R::Structure, Y, nullptr}, {"RBE3", R::Structure, Y, nullptr},
    {"RBE1", R::Structure, Y, nullptr}, {"RROD", R::Structure, Y, nullptr}, {"CRIGD1", R::Structure, Y, nullptr},
    {"CRIGD2", R::Structure, Y, nullptr}, {"CRIGD3", R::Structure, Y, nullptr}, {"CRIGDR", R::Structure, Y, nullptr},
    // features of supported cards the reader keeps for `seflex info` but no solution may use (the
    // names the reader gives them: io/include/seflex/io/nastran_cards.hpp, io/src/nastran_deck.cpp)
    {"MAT1 NU above 0.5", R::Structure, N, nullptr}, {"CQUAD4/CTRIA3 TFLAG a fraction", R::Structure, N, nullptr},
    {"GRID CD = -1 (fluid)", R::Structure, N, nullptr}, {"PSOLID FCTN = PFLUID", R::Structure, N, nullptr},
    {"PSHELL MID2 = -1 (plane strain)", R::Structure, N, nullptr},
    {"RBAR1", R::Structure, N, nullptr}, {"RTRPLT", R::Structure, N, nullptr}, {"RTRPLT1", R::Structure, N, nullptr}, {"RSPLINE", R::Structure, N, nullptr},
    {"RJOINT", R::Structure, N, nullptr}, {"RBE2A", R::Structure, N, nullptr},
    // properties
    {"PBAR", R::Structure, Y, nullptr}, {"PBARL", R::Structure, Y, nullptr}, {"PBEAM", R::Structure, Y, nullptr},
    {"PBEAML", R::Structure, Y, nullptr}, {"PROD", R::Structure, Y, nullptr}, {"PSHELL", R::Structure, Y, nullptr},
    {"PELAS", R::Structure, Y, nullptr}, {"PCOMP", R::Structure, Y, nullptr}, {"PCOMPG", R::Structure, Y, nullptr},
    {"PSOLID", R::Structure, Y, nullptr}, {"PLSOLID", R::Structure, N, nullptr}, {"PBUSH", R::Structure, Y, nullptr},
    {"PBUSH1D", R::Structure, Y, nullptr}, {"PBUSH2D", R::Structure, N, nullptr}, {"PBUSHT", R::Nonlinear, N, nullptr},
    {"PMASS", R::Structure, Y, nullptr}, {"PSHEAR", R::Structure, Y, nullptr}, {"PTUBE", R::Structure, Y, nullptr},
    {"PBEND", R::Structure, Y, nullptr}, {"PBCOMP", R::Structure, N, nullptr}, {"PBRSECT", R::Structure, N, nullptr},
    {"PBMSECT", R::Structure, N, nullptr}, {"PGAP", R::Structure, N, nullptr}, {"PFAST", R::Structure, N, nullptr},
    {"PWELD", R::Structure, N, nullptr}, {"PSEAM", R::Structure, N, nullptr}, {"PCONEAX", R::Structure, N, nullptr},
    {"PLPLANE", R::Structure, N, nullptr}, {"PRAC2D", R::Structure, N, nullptr}, {"PRAC3D", R::Structure, N, nullptr},
    {"PDAMP", R::Damping, N, nullptr}, {"PDAMP5", R::Damping, N, nullptr}, {"PVISC", R::Damping, N, nullptr},
    {"PELAST", R::Nonlinear, N, nullptr}, {"PDAMPT", R::Damping, N, nullptr}, {"PSHELL1", R::Structure, N, nullptr},
    // materials
    {"MAT1", R::Structure, Y, nullptr}, {"MAT2", R::Structure, Y, nullptr}, {"MAT3", R::Structure, N, nullptr},
    {"MAT8", R::Structure, Y, nullptr}, {"MAT9", R::Structure, Y, nullptr}, {"MAT10", R::Structure, N, nullptr},
    {"MAT11", R::Structure, N, nullptr}, {"MATS1", R::Nonlinear, N, nullptr}, {"MATS3", R::Nonlinear, N, nullptr},
    {"MATS8", R::Nonlinear, N, nullptr}, {"MATHP", R::Nonlinear, N, nullptr}, {"MATHE", R::Nonlinear, N, nullptr},
    {"CREEP", R::Nonlinear, N, nullptr}, {"MATT1", R::TempMaterial, N, nullptr}, {"MATT2", R::TempMaterial, N, nullptr},
    {"MATT3", R::TempMaterial, N, nullptr}, {"MATT8", R::TempMaterial, N, nullptr}, {"MATT9", R::TempMaterial, N, nullptr},
    {"MAT4", R::Heat, N, nullptr}, {"MAT5", R::Heat, N, nullptr},
    // static loads (selected by LOAD)
    {"FORCE", R::Load, Y, force_members}, {"MOMENT", R::Load, Y, moment_members}, {"LOAD", R::LoadCombination, Y, nullptr},
    {"FORCE1", R::Load, Y, force1_members}, {"FORCE2", R::Load, Y, force2_members}, {"MOMENT1", R::Load, Y, moment1_members},
    {"MOMENT2", R::Load, Y, moment2_members}, {"PLOAD", R::Load, Y, pload_members}, {"PLOAD1", R::Load, Y, pload1_members},
    {"PLOAD2", R::Load, Y, pload2_members}, {"PLOAD4", R::Load, Y, pload4_members}, {"PLOADX1", R::Load, N, nullptr},
    {"GRAV", R::Load, Y, grav_members}, {"RFORCE", R::Load, Y, rforce_members}, {"RFORCE1", R::Load, N, nullptr},
    {"ACCEL", R::Load, N, nullptr}, {"ACCEL1", R::Load, N, nullptr}, {"SPCD", R::Load, Y, spcd_members},
    {"SLOAD", R::Load, Y, sload_members}, {"PLOADB3", R::Load, N, nullptr}, {"PRESAX", R::Load, N, nullptr},
    {"LSEQ", R::Load, N, nullptr}, {"DEFORM", R::Load, N, nullptr},
    // temperatures (selected by TEMPERATURE)
    {"TEMP", R::TemperatureLoad, Y, temp_members}, {"TEMPD", R::TemperatureLoad, Y, tempd_members},
    {"TEMPP1", R::TemperatureLoad, N, nullptr}, {"TEMPRB", R::TemperatureLoad, Y, temprb_members},
    {"TEMPF", R::TemperatureLoad, N, nullptr}, {"TEMPAX", R::TemperatureLoad, N, nullptr},
    {"TEMPB3", R::TemperatureLoad, N, nullptr},
    // constraints and dof sets
    {"SPC", R::SpcSet, Y, nullptr}, {"SPC1", R::SpcSet, Y, nullptr}, {"SPCADD", R::SpcSet, Y, nullptr},
    {"SPCAX", R::SpcSet, N, nullptr}, {"MPC", R::MpcSet, Y, nullptr}, {"MPCADD", R::MpcSet, Y, nullptr},
    {"MPCAX", R::MpcSet, N, nullptr}, {"ASET", R::Omit, Y, nullptr}, {"ASET1", R::Omit, Y, nullptr},
    {"OMIT", R::Omit, Y, nullptr}, {"OMIT1", R::Omit, Y, nullptr}, {"BSET", R::Bset, Y, nullptr},
    {"BSET1", R::Bset, Y, nullptr}, {"CSET", R::Bset, N, nullptr}, {"CSET1", R::Bset, N, nullptr},
    {"QSET", R::Bset, N, nullptr}, {"QSET1", R::Bset, N, nullptr}, {"SUPORT", R::Suport, Y, nullptr},
    {"SUPORT1", R::Suport1, Y, nullptr},
    // eigenvalue methods
    {"EIGR", R::EigenMethod, Y, nullptr}, {"EIGRL", R::EigenMethod, Y, nullptr}, {"EIGB", R::BucklingMethod, Y, nullptr},
    {"EIGC", R::ComplexMethod, N, nullptr}, {"EIGP", R::ComplexMethod, N, nullptr},
    // dynamics
    {"DLOAD", R::Dynamics, N, nullptr}, {"RLOAD1", R::Dynamics, N, nullptr}, {"RLOAD2", R::Dynamics, N, nullptr},
    {"TLOAD1", R::Dynamics, N, nullptr}, {"TLOAD2", R::Dynamics, N, nullptr}, {"DAREA", R::Dynamics, N, nullptr},
    {"DELAY", R::Dynamics, N, nullptr}, {"DPHASE", R::Dynamics, N, nullptr}, {"FREQ", R::Dynamics, N, nullptr},
    {"FREQ1", R::Dynamics, N, nullptr}, {"FREQ2", R::Dynamics, N, nullptr}, {"FREQ3", R::Dynamics, N, nullptr},
    {"FREQ4", R::Dynamics, N, nullptr}, {"FREQ5", R::Dynamics, N, nullptr}, {"TSTEP", R::Dynamics, N, nullptr},
    {"TSTEPNL", R::Dynamics, N, nullptr}, {"NLPARM", R::Dynamics, N, nullptr}, {"NLPCI", R::Dynamics, N, nullptr},
    {"TABLED1", R::Dynamics, N, nullptr}, {"TABLED2", R::Dynamics, N, nullptr}, {"TABLED3", R::Dynamics, N, nullptr},
    {"TABLED4", R::Dynamics, N, nullptr}, {"TABLEM1", R::TempMaterial, Y, nullptr}, {"TABLEM2", R::TempMaterial, Y, nullptr},
    {"TABLEM3", R::TempMaterial, Y, nullptr}, {"TABLEM4", R::TempMaterial, Y, nullptr}, {"TABLES1", R::Nonlinear, N, nullptr},
    {"TABDMP1", R::Dynamics, N, nullptr}, {"TABRND1", R::Dynamics, N, nullptr}, {"RANDPS", R::Dynamics, N, nullptr},
    {"TIC", R::Dynamics, N, nullptr}, {"NOLIN1", R::Dynamics, N, nullptr}, {"TF", R::Dynamics, N, nullptr},
    {"USET", R::Dynamics, N, nullptr}, {"USET1", R::Dynamics, N, nullptr},
    // matrices
    {"DMIG", R::Dmig, Y, nullptr}, {"DMI", R::OtherMatrix, N, nullptr}, {"DMIJ", R::OtherMatrix, N, nullptr},
    {"DMIJI", R::OtherMatrix, N, nullptr}, {"DMIK", R::OtherMatrix, N, nullptr}, {"DMIAX", R::OtherMatrix, N, nullptr},
    {"PARAM", R::Param, Y, nullptr},
    // output
    {"MONPNT1", R::Output, N, nullptr}, {"MONPNT2", R::Output, N, nullptr}, {"MONPNT3", R::Output, N, nullptr},
    {"MONSUM", R::Output, N, nullptr}, {"PARVEC", R::Output, N, nullptr}, {"MDLPRM HDF5 (output format)", R::Output, N, nullptr},
    {"ECHOON", R::Output, N, nullptr}, {"ECHOOFF", R::Output, N, nullptr}, {"DTI", R::OtherMatrix, N, nullptr},
    // optimisation
    {"DESVAR", R::Optimization, N, nullptr}, {"DRESP1", R::Optimization, N, nullptr}, {"DRESP2", R::Optimization, N, nullptr},
    {"DRESP3", R::Optimization, N, nullptr}, {"DCONSTR", R::Optimization, N, nullptr}, {"DCONADD", R::Optimization, N, nullptr},
    {"DVPREL1", R::Optimization, N, nullptr}, {"DVPREL2", R::Optimization, N, nullptr}, {"DVMREL1", R::Optimization, N, nullptr},
    {"DVMREL2", R::Optimization, N, nullptr}, {"DVCREL1", R::Optimization, N, nullptr}, {"DVCREL2", R::Optimization, N, nullptr},
    {"DVGRID", R::Optimization, N, nullptr}, {"DOPTPRM", R::Optimization, N, nullptr}, {"DTABLE", R::Optimization, N, nullptr},
    {"DEQATN", R::Optimization, N, nullptr}, {"DLINK", R::Optimization, N, nullptr}, {"DSCREEN", R::Optimization, N, nullptr},
    {"DRESP", R::Optimization, N, nullptr}, {"TOPVAR", R::Optimization, N, nullptr}, {"DVSHAP", R::Optimization, N, nullptr},
    // aeroelasticity
    {"AERO", R::Aero, N, nullptr}, {"AEROS", R::Aero, N, nullptr}, {"CAERO1", R::Aero, N, nullptr},
    {"CAERO2", R::Aero, N, nullptr}, {"CAERO3", R::Aero, N, nullptr}, {"CAERO4", R::Aero, N, nullptr},
    {"CAERO5", R::Aero, N, nullptr}, {"PAERO1", R::Aero, N, nullptr}, {"PAERO2", R::Aero, N, nullptr},
    {"PAERO3", R::Aero, N, nullptr}, {"PAERO4", R::Aero, N, nullptr}, {"PAERO5", R::Aero, N, nullptr},
    {"SPLINE1", R::Aero, N, nullptr}, {"SPLINE2", R::Aero, N, nullptr}, {"SPLINE3", R::Aero, N, nullptr},
    {"SPLINE4", R::Aero, N, nullptr}, {"SPLINE5", R::Aero, N, nullptr}, {"SPLINE6", R::Aero, N, nullptr},
    {"SPLINE7", R::Aero, N, nullptr}, {"SET1", R::Aero, N, nullptr}, {"SET2", R::Aero, N, nullptr},
    {"SET3", R::Aero, N, nullptr}, {"AESTAT", R::Aero, N, nullptr}, {"AESURF", R::Aero, N, nullptr},
    {"AESURFS", R::Aero, N, nullptr}, {"AELIST", R::Aero, N, nullptr}, {"AEPARM", R::Aero, N, nullptr},
    {"AELINK", R::Aero, N, nullptr}, {"TRIM", R::Aero, N, nullptr}, {"FLUTTER", R::Aero, N, nullptr},
    {"FLFACT", R::Aero, N, nullptr}, {"MKAERO1", R::Aero, N, nullptr}, {"MKAERO2", R::Aero, N, nullptr},
    {"GUST", R::Aero, N, nullptr}, {"DIVERG", R::Aero, N, nullptr}, {"CSSCHD", R::Aero, N, nullptr},
    {"AECOMP", R::Aero, N, nullptr}, {"AEFORCE", R::Aero, N, nullptr}, {"AEPRESS", R::Aero, N, nullptr},
    {"UXVEC", R::Aero, N, nullptr},
    // heat transfer
    {"CHBDYE", R::Heat, N, nullptr}, {"CHBDYG", R::Heat, N, nullptr}, {"CHBDYP", R::Heat, N, nullptr},
    {"PHBDY", R::Heat, N, nullptr}, {"CONV", R::Heat, N, nullptr}, {"CONVM", R::Heat, N, nullptr},
    {"PCONV", R::Heat, N, nullptr}, {"RADBC", R::Heat, N, nullptr}, {"RADM", R::Heat, N, nullptr},
    {"QBDY1", R::Heat, N, nullptr}, {"QBDY2", R::Heat, N, nullptr}, {"QBDY3", R::Heat, N, nullptr},
    {"QHBDY", R::Heat, N, nullptr}, {"QVOL", R::Heat, N, nullptr}, {"QVECT", R::Heat, N, nullptr},
    {"TEMPBC", R::Heat, N, nullptr},
    // superelements, contact, other solvers
    {"BEGIN SUPER", R::Superelement, N, nullptr}, {"SESET", R::Superelement, N, nullptr}, {"SEBSET", R::Superelement, N, nullptr}, {"SEBSET1", R::Superelement, N, nullptr},
    {"SECONCT", R::Superelement, N, nullptr}, {"SEELT", R::Superelement, N, nullptr}, {"SELOC", R::Superelement, N, nullptr},
    {"SEMPLN", R::Superelement, N, nullptr}, {"SELABEL", R::Superelement, N, nullptr}, {"BCTSET", R::Contact, N, nullptr},
    {"BCTPARA", R::Contact, N, nullptr}, {"BSURF", R::Contact, N, nullptr}, {"BSURFS", R::Contact, N, nullptr},
    {"BCPROP", R::Contact, N, nullptr}, {"BCBODY", R::Contact, N, nullptr}, {"BCONP", R::Contact, N, nullptr},
    {"BLSEG", R::Contact, N, nullptr}, {"BFRIC", R::Contact, N, nullptr}, {"DEBUG", R::Solver, N, nullptr},
    {"YPARAM", R::Solver, N, nullptr},
};
// clang-format on

}  // namespace

const CardRole* find_card_role(std::string_view name) {
  static const std::unordered_map<std::string_view, const CardRole*> index = [] {
    std::unordered_map<std::string_view, const CardRole*> m;
    for (const CardRole& r : kRows) m.emplace(r.name, &r);
    return m;
  }();
  const auto it = index.find(name);
  return it == index.end() ? nullptr : it->second;
}

bool is_unknown_card(std::string_view name) {
  return !name.empty() && name.front() != '\'' && name.find(' ') == std::string_view::npos && find_card_role(name) == nullptr;
}

std::vector<const CardRole*> supported_set_cards() {
  std::vector<const CardRole*> out;
  for (const CardRole& r : kRows)
    if (r.supported && r.members != nullptr) out.push_back(&r);
  return out;
}

}  // namespace seflex::solutions::detail
