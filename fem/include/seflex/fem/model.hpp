#pragma once
// The FE model as data: what a Nastran bulk-data deck (or a gmsh mesh with its property file)
// describes, card by card, with the source location of every card for error messages.
// Readers in io/ fill it; fem/ resolves and consumes it. No parsing and no numerics here.
//
// Conventions
// - Ids are the user's (Nastran) ids. After fem::finalize(model) the maps `*_index` give the
//   position of an id in its vector, coordinate systems are resolved to the basic system, and every
//   GRID has its basic position.
// - Units are whatever the deck uses (seflex does not rescale); PARAM WTMASS multiplies every mass
//   when matrices are built. Angles on cards (e.g. CQUAD4 THETA) are in degrees as Nastran writes
//   them; fem converts to radians.
// - Component lists ("123456", "12 456") are stored as bit masks: bit (c-1) set for component c.
#include <Eigen/Core>
#include <array>
#include <cstdint>
#include <map>
#include <optional>
#include <string>
#include <unordered_map>
#include <vector>

#include "seflex/fem/card_ref.hpp"
#include "seflex/fem/model_solids.hpp"

namespace seflex::fem {


using ComponentMask = std::uint8_t;  ///< bit (c-1) for component c = 1..6

// ---------------------------------------------------------------------------------------------
// Coordinate systems
enum class CoordType : std::uint8_t { Rectangular, Cylindrical, Spherical };

/// CORD2R/C/S (defined by points A, B, C in system rid) or CORD1R/C/S (by three grids).
struct CoordSys {
  int id = 0;
  CoordType type = CoordType::Rectangular;
  bool by_grids = false;            ///< CORD1x
  int rid = 0;                      ///< CORD2x reference system
  std::array<double, 9> abc{};      ///< CORD2x: A(3), B(3), C(3) in rid
  std::array<int, 3> grids{};       ///< CORD1x: G1, G2, G3
  CardRef ref;
  // Resolved by fem::finalize: origin and axes (columns) in the basic system.
  bool resolved = false;
  Eigen::Vector3d origin = Eigen::Vector3d::Zero();
  Eigen::Matrix3d axes = Eigen::Matrix3d::Identity();  ///< columns e1, e2, e3 in basic
};

// ---------------------------------------------------------------------------------------------
// Grids and scalar points
struct Grid {
  int id = 0;
  int cp = 0;                       ///< system of x
  Eigen::Vector3d x = Eigen::Vector3d::Zero();  ///< coordinates in cp (r, theta_deg, z for cylindrical ...)
  int cd = 0;                       ///< displacement (global) system
  ComponentMask ps = 0;             ///< permanent single-point constraints
  CardRef ref;
  Eigen::Vector3d x_basic = Eigen::Vector3d::Zero();  ///< resolved by finalize
};

struct ScalarPoint {  ///< SPOINT: one degree of freedom, used by DMIG matrices
  int id = 0;
  CardRef ref;
};

struct GridDefaults {  ///< GRDSET (blank = 0)
  int cp = 0, cd = 0;
  ComponentMask ps = 0;
  bool present = false;
  CardRef ref;
};

// ---------------------------------------------------------------------------------------------
// Materials and properties
struct Mat1 {
  int id = 0;
  double E = 0, G = 0, nu = 0;  ///< completed with Nastran's rule when one is blank
  double rho = 0, alpha = 0, tref = 0, ge = 0;
  CardRef ref;
};

/// MAT2: anisotropic plane-stress material, G = [G11 G12 G13; G12 G22 G23; G13 G23 G33] (Voigt xx,
/// yy, xy with engineering shear strain). As a PSHELL MID3 (transverse shear), [G11 G12; G12 G22] is
/// the 2 x 2 transverse shear matrix (QRG MAT2).
struct Mat2 {
  int id = 0;
  double G11 = 0, G12 = 0, G13 = 0, G22 = 0, G23 = 0, G33 = 0;
  double rho = 0, ge = 0;
  double a1 = 0, a2 = 0, a3 = 0;  ///< thermal expansion (xx, yy, xy engineering), material axes
  double tref = 0;
  CardRef ref;
};

/// MAT8: orthotropic plane-stress material in its axes 1 (fibre), 2. G1Z, G2Z: transverse shear
/// moduli; 0 (blank) = infinite (rigid in transverse shear), as the QRG says for MAT8.
struct Mat8 {
  int id = 0;
  double E1 = 0, E2 = 0, nu12 = 0, G12 = 0, G1z = 0, G2z = 0;
  double rho = 0, ge = 0;
  double a1 = 0, a2 = 0;          ///< thermal expansion along axes 1 and 2
  double tref = 0;
  CardRef ref;
};

/// PCOMP or PCOMPG: a laminate of plies listed from the bottom (most negative z) up.
struct CompositeProperty {
  enum class Lam : std::uint8_t { Blank, Sym, Mem, Bend, Smear, SmCore };
  struct Ply {
    int gplyid = 0;                 ///< PCOMPG global ply id (0 for PCOMP)
    int mid = 0;
    double t = 0;
    double theta_deg = 0;           ///< ply angle from the element's material x axis, degrees
    bool sout = false;
  };
  int id = 0;
  bool global = false;              ///< PCOMPG
  bool has_z0 = false;
  double z0 = 0;                    ///< bottom surface from the reference plane (blank: -T/2)
  double nsm = 0, sb = 0, tref = 0, ge = 0;
  std::string ft;                   ///< failure theory (not used)
  Lam lam = Lam::Blank;
  std::vector<Ply> plies;           ///< as written (LAM = SYM: the lower half only)
  CardRef ref;
};

/// Bar/beam section, from PBAR, PBARL, PBEAM (end A) or PBEAML (end A), in element axes.
struct BarProperty {
  enum class Source : std::uint8_t { PBAR, PBARL, PBEAM, PBEAML };
  int id = 0;
  int mid = 0;
  Source source = Source::PBAR;
  double A = 0, I1 = 0, I2 = 0, I12 = 0, J = 0, nsm = 0;
  double nsi = 0;                   ///< PBEAM NSI(A): non-structural mass moment of inertia per length
  double K1 = 0, K2 = 0;            ///< shear factors; 0 (blank) = no transverse shear flexibility
  std::string section_type;         ///< PBARL/PBEAML TYPE (ROD, TUBE, BAR, BOX, I, ...)
  std::vector<double> dims;         ///< PBARL/PBEAML DIMi
  CardRef ref;
};

struct RodProperty {  ///< PROD (CONROD stores its own inline copy, id = 0)
  int id = 0, mid = 0;
  double A = 0, J = 0, C = 0, nsm = 0;
  CardRef ref;
};

struct ShellProperty {  ///< PSHELL
  int id = 0;
  int mid1 = 0;                     ///< membrane (0 = none)
  double t = 0;
  int mid2 = 0;                     ///< bending (0 = none)
  double bend_ratio = 1.0;          ///< 12I/T^3 (blank = 1)
  int mid3 = 0;                     ///< transverse shear (0 = none)
  double ts_t = 0.833333;           ///< TS/T (blank = .833333)
  double nsm = 0;
  double z1 = 0, z2 = 0;            ///< fibre distances (stress only)
  int mid4 = 0;                     ///< membrane-bending coupling (0 = none): B = T^2 G4
  CardRef ref;
};

struct SpringProperty {  ///< PELAS
  int id = 0;
  double k = 0, ge = 0, s = 0;
  CardRef ref;
};

// ---------------------------------------------------------------------------------------------
// Elements
struct BarDefaults {  ///< BAROR (and BEAMOR for CBEAM)
  bool present = false;
  int pid = 0;
  bool has_g0 = false;
  int g0 = 0;
  Eigen::Vector3d v = Eigen::Vector3d::Zero();
  std::string offt = "GGG";
  CardRef ref;
};

/// CBAR or CBEAM (a CBEAM is treated as a prismatic bar with its end-A section).
struct Bar {
  int id = 0, pid = 0;
  int ga = 0, gb = 0;
  bool has_g0 = false;
  int g0 = 0;                                   ///< orientation grid (has_g0)
  Eigen::Vector3d v = Eigen::Vector3d::Zero();  ///< orientation vector (in GA's CD system for OFFT G..)
  std::string offt = "GGG";
  ComponentMask pa = 0, pb = 0;                 ///< pin flags (released element dofs)
  Eigen::Vector3d wa = Eigen::Vector3d::Zero(), wb = Eigen::Vector3d::Zero();  ///< offsets
  bool is_beam = false;                         ///< came from CBEAM
  CardRef ref;
};

struct Rod {  ///< CROD (pid -> PROD) or CONROD (inline property, pid = 0)
  int id = 0, pid = 0;
  int ga = 0, gb = 0;
  bool inline_property = false;
  int mid = 0;                                  ///< CONROD only
  double A = 0, J = 0, C = 0, nsm = 0;          ///< CONROD only
  CardRef ref;
};

/// CQUAD4 (4 grids) or CTRIA3 (3 grids; g[3] = 0).
struct Shell {
  int id = 0, pid = 0;
  std::array<int, 4> g{};
  std::uint8_t nnode = 4;
  bool theta_is_mcid = false;
  double theta_deg = 0;                         ///< material angle (degrees) or MCID
  int mcid = -1;
  double zoffs = 0;
  int tflag = 0;
  std::array<double, 4> t{};                    ///< corner thicknesses, 0 = blank (use PSHELL T)
  CardRef ref;
};

/// CONM2: concentrated mass with offset and inertia.
struct Conm2 {
  int id = 0, grid = 0;
  int cid = 0;                                  ///< 0 basic, -1 offset in basic from the grid, >0 system
  double m = 0;
  Eigen::Vector3d x = Eigen::Vector3d::Zero();  ///< offset (cid >= 0: in cid; cid = -1: absolute basic position)
  double I11 = 0, I21 = 0, I22 = 0, I31 = 0, I32 = 0, I33 = 0;  ///< about the CG, in cid axes
  CardRef ref;
};

/// CELAS1 (pid -> PELAS) or CELAS2 (inline k). g2 = 0 means grounded.
struct Spring {
  int id = 0, pid = 0;
  bool inline_property = false;
  double k = 0, ge = 0, s = 0;                  ///< CELAS2 only
  int g1 = 0, c1 = 0, g2 = 0, c2 = 0;           ///< components 0..6 (0 for scalar points)
  bool scalar_points = false;                   ///< CELAS3 (pid) / CELAS4 (inline k): S1 S2 scalar points only
  CardRef ref;
};

/// PBUSH: stiffness K1-K6 in the CBUSH element axes (T1 T2 T3 R1 R2 R3; blank = 0). B (damping),
/// GE, RCV and M are read and kept for `seflex convert`; statics and modes do not use them.
struct BushProperty {
  int id = 0;
  std::array<double, 6> k{}, b{}, ge{};
  bool has_b = false, has_ge = false;
  CardRef ref;
};

/// CBUSH: generalized spring between GA and GB (gb = 0: grounded) at the point S of the line GA-GB
/// (OCID = -1) or at GA + (S1, S2, S3) in system OCID. Element axes: system CID (cid >= 0) or x along
/// GA -> GB, y in the plane of x and the orientation vector (GO or X1-X3 in GA's CD system).
struct Bush {
  int id = 0, pid = 0, ga = 0, gb = 0;
  bool has_g0 = false, has_v = false;
  int g0 = 0;
  Eigen::Vector3d v = Eigen::Vector3d::Zero();
  int cid = -1;                                 ///< -1 = blank
  double s = 0.5;
  int ocid = -1;
  Eigen::Vector3d s_ocid = Eigen::Vector3d::Zero();  ///< S1 S2 S3 (OCID >= 0)
  CardRef ref;
};

/// PMASS: scalar mass value of CMASS1/CMASS3.
struct MassProperty {
  int id = 0;
  double m = 0;
  CardRef ref;
};

/// CMASS1 (pid -> PMASS), CMASS2 (inline m): grid components or scalar points; CMASS3 (pid), CMASS4
/// (inline m): scalar points only. g2 = 0 means grounded:
///   M = m [1 -1; -1 1] on (dof1, dof2), or m on dof1 alone.
struct ScalarMass {
  int id = 0, pid = 0;
  bool inline_property = false;
  bool scalar_points = false;                   ///< CMASS3 / CMASS4
  double m = 0;                                 ///< CMASS2/CMASS4 only
  int g1 = 0, c1 = 0, g2 = 0, c2 = 0;
  CardRef ref;
};

/// CONM1: a 6 x 6 symmetric mass matrix on grid G, in the axes of system CID (0 = basic).
struct Conm1 {
  int id = 0, grid = 0, cid = 0;
  Eigen::Matrix<double, 6, 6> M = Eigen::Matrix<double, 6, 6>::Zero();
  CardRef ref;
};

/// RBE2: the dependent components cm of every grid in gm follow the independent grid gn rigidly.
struct Rbe2 {
  int id = 0, gn = 0;
  ComponentMask cm = 0;
  std::vector<int> gm;
  CardRef ref;
};

/// RBAR: a rigid bar between GA and GB. CNA/CNB: independent components (six in all, able to
/// describe any rigid motion); CMA/CMB: dependent ones (both blank: every component not independent).
struct Rbar {
  int id = 0, ga = 0, gb = 0;
  ComponentMask cna = 0, cnb = 0, cma = 0, cmb = 0;
  double alpha = 0;                             ///< thermal expansion: read, not used
  CardRef ref;
};

/// RBE3: the REFC components of REFGRID are the weighted least-squares average of the motions of
/// the groups' grids (WTi on components Ci of grids Gi,j). UM: the dependent set redefined.
struct Rbe3 {
  struct Group {
    double weight = 0;
    ComponentMask c = 0;
    std::vector<int> grids;
  };
  struct Dependent {                            ///< one UM pair GMi CMi
    int grid = 0;
    ComponentMask c = 0;
  };
  int id = 0, refgrid = 0;
  ComponentMask refc = 0;
  std::vector<Group> groups;
  std::vector<Dependent> um;                    ///< empty: REFC of REFGRID are the dependents
  bool has_alpha = false;
  double alpha = 0;                             ///< thermal expansion: read, not used
  CardRef ref;
};

// ---------------------------------------------------------------------------------------------
// Constraints, sets and loads
struct SpcEntry {  ///< one SPC/SPC1 grid-component entry (d = enforced value, SPC only)
  int sid = 0, grid = 0;
  ComponentMask c = 0;
  double d = 0;
  bool from_thru = false;           ///< SPC1 "G1 THRU G2": a missing grid is skipped (QRG SPC1 remark)
  CardRef ref;
};

/// SPCADD / MPCADD: set SID is the union of sets S1, S2, ...
struct SetCombination {
  int sid = 0;
  std::vector<int> sets;
  CardRef ref;
};
using SpcAdd = SetCombination;

/// MPC: one equation sum_j A_j u(G_j, C_j) = 0 (components in the grids' CD systems, 0 for a
/// scalar point); the first term's dof is the dependent one.
struct MpcTerm {
  int grid = 0, component = 0;
  double a = 0;
};
struct MpcEquation {
  int sid = 0;
  std::vector<MpcTerm> terms;
  CardRef ref;
};

using MpcAdd = SetCombination;

struct DofSetEntry {  ///< ASET/ASET1/OMIT/OMIT1/BSET/BSET1/SUPORT entries (grid or scalar point + components)
  int grid = 0;
  ComponentMask c = 0;
  CardRef ref;
};

struct PointLoad {  ///< FORCE or MOMENT: value = scale * (n1, n2, n3) in system cid
  enum class Kind : std::uint8_t { Force, Moment };
  Kind kind = Kind::Force;
  int sid = 0, grid = 0, cid = 0;
  double scale = 0;
  Eigen::Vector3d n = Eigen::Vector3d::Zero();
  CardRef ref;
};

/// PLOAD2: uniform pressure p on CQUAD4/CTRIA3 elements, positive along the element normal (right-hand
/// rule on the grid order). `thru`: elements = {EID1, EID2} of "EID1 THRU EID2", whose ids that are
/// not shells are skipped (QRG PLOAD2 remark); otherwise the ids listed, which must be shells.
struct PressureLoad {
  int sid = 0;
  double p = 0;
  std::vector<int> elements;
  bool thru = false;
  CardRef ref;
};

/// PLOAD1: a load on CBAR/CBEAM EID distributed from X1 (P1) to X2 (P2), linearly (X1 = X2: a
/// concentrated load P1 at X1). TYPE: FX FY FZ (force per length along basic x, y, z), FXE FYE FZE
/// (along the element axes), MX MY MZ, MXE MYE MZE (moments). SCALE: LE (X1, X2 lengths along the
/// bar, P per length), FR (X fractions of the length), LEPR, FRPR (P per projected length: basic
/// types only).
struct BarLineLoad {
  enum class Scale : std::uint8_t { LE, FR, LEPR, FRPR };
  int sid = 0, element = 0;
  std::string type;                 ///< FX, FY, FZ, FXE, FYE, FZE, MX, MY, MZ, MXE, MYE, MZE
  Scale scale = Scale::LE;
  double x1 = 0, p1 = 0, x2 = 0, p2 = 0;
  CardRef ref;
};

/// SPCD: enforced value D of components C of grid G (a load set: selected by the subcase LOAD,
/// its dofs must be in the subcase's SPC set).
struct EnforcedMotion {
  int sid = 0, grid = 0;
  ComponentMask c = 0;
  double d = 0;
  CardRef ref;
};

/// GRAV: acceleration A (N1, N2, N3) in rectangular system CID applied to every mass: p = M a.
struct GravityLoad {
  int sid = 0, cid = 0;
  double a = 0;
  Eigen::Vector3d n = Eigen::Vector3d::Zero();
  CardRef ref;
};

/// RFORCE: steady rotation omega = 2 pi A (R1, R2, R3)/|R| (A in revolutions per unit time) and
/// angular acceleration 2 pi RACC (same axis) about the axis through grid G (0: basic origin),
/// components in rectangular system CID. METHOD 1 and 2 are computed alike (mass matrix times the
/// acceleration of every grid).
struct RotationalLoad {
  int sid = 0, grid = 0, cid = 0;
  double a = 0, racc = 0;
  Eigen::Vector3d r = Eigen::Vector3d::Zero();
  int method = 1;
  CardRef ref;
};

/// Temperatures of a thermal load set (selected by case control TEMPERATURE(LOAD)):
/// TEMP SID G1 T1 G2 T2 G3 T3 (grid temperatures) ...
struct GridTemperature {
  int sid = 0, grid = 0;
  double t = 0;
  CardRef ref;
};
/// ... TEMPD SID1 T1 ... (the temperature of every grid set SID does not give) ...
struct DefaultTemperature {
  int sid = 0;
  double t = 0;
  CardRef ref;
};
/// ... and TEMPRB SID EID1 TA TB TP1A TP1B TP2A TP2B / TCA ... / EID2 ... (line elements: mean
/// temperatures at ends A and B, effective linear gradients in the element's y (1) and z (2)
/// directions; the stress-point temperatures TCA ... are read and not used).
struct BarTemperature {
  int sid = 0, element = 0;
  double ta = 0, tb = 0, tp1a = 0, tp1b = 0, tp2a = 0, tp2b = 0;
  CardRef ref;
};

struct LoadCombination {  ///< LOAD: overall scale s, then (si, li) pairs
  int sid = 0;
  double s = 1;
  std::vector<std::pair<double, int>> terms;
  CardRef ref;
};

/// EIGRL (Lanczos) or EIGR (other methods; seflex honours F1, F2, ND and NORM of both).
struct EigenMethod {
  int sid = 0;
  bool is_eigr = false;
  std::string method = "LAN";
  std::optional<double> f1, f2;     ///< frequency range (Hz); EIGRL V1/V2
  std::optional<int> nd;            ///< number of roots
  std::string norm = "MASS";        ///< MASS, MAX or POINT
  int norm_grid = 0, norm_component = 0;
  CardRef ref;
};

/// DMIG matrix (direct matrix input at grid/scalar-point dofs).
struct DmigEntry {
  int gj = 0, cj = 0, gi = 0, ci = 0;
  double value = 0;
};
struct Dmig {
  std::string name;
  int form = 6;                     ///< 1 square, 6 symmetric, 9 rectangular
  int tin = 1, tout = 0;
  std::vector<DmigEntry> entries;
  CardRef ref;
};

struct Param {
  std::string name;
  std::vector<std::string> values;  ///< raw field text after the name
  CardRef ref;
};

// ---------------------------------------------------------------------------------------------
// Executive and case control (what seflex keeps of it)
/// A case-control command that selects analysis input seflex does not use (TEMPERATURE(INIT),
/// DLOAD, DEFORM, SUPORT1, ...): kept so that a solution that would need it can refuse the deck.
struct CaseCommand {
  std::string name;                 ///< upper case, with its describer: "TEMPERATURE(LOAD)", "DLOAD"
  std::string value;                ///< the text after '='
  CardRef ref;
};

struct Subcase {
  int id = 0;                       ///< 0 = the global (above any SUBCASE) selections
  std::string label;
  std::optional<int> spc, load, method, mpc;
  std::optional<int> temperature;   ///< TEMPERATURE(LOAD), (BOTH) or bare: the thermal load set
  std::vector<std::string> k2gg, m2gg;
  std::vector<CaseCommand> other;   ///< selections seflex does not use (global ones are inherited)
  CardRef ref;                      ///< the SUBCASE line (file 0, line 0 for the global level)
};

struct CaseControl {
  std::optional<std::string> sol;   ///< e.g. "103", "SEMODES", "3"
  std::string title, subtitle;
  Subcase global;
  std::vector<Subcase> subcases;
};

/// Cards the reader recognised but seflex does not model, or did not recognise at all. `members`
/// holds field 2 (the SID of a load, a method or a set; an element's id) of each card whose field 2
/// is an integer, so that the cards of a selected set can be told from those of unselected sets.
struct UnsupportedCard {
  struct Member {
    int sid = 0;
    CardRef ref;
  };
  std::string name;
  std::size_t count = 0;
  CardRef first;
  std::vector<Member> members;
};

// ---------------------------------------------------------------------------------------------
struct Model {
  std::vector<std::string> files;   ///< files[CardRef::file]; files[0] is the main deck

  CaseControl case_control;

  std::vector<CoordSys> coords;
  std::vector<Grid> grids;
  std::vector<ScalarPoint> spoints;
  GridDefaults grdset;

  std::vector<Mat1> mat1;
  std::vector<Mat2> mat2;
  std::vector<Mat8> mat8;
  std::vector<BarProperty> bar_props;
  std::vector<RodProperty> rod_props;
  std::vector<ShellProperty> shell_props;
  std::vector<CompositeProperty> composite_props;  ///< PCOMP, PCOMPG
  std::vector<SpringProperty> spring_props;
  std::vector<BushProperty> bush_props;        ///< PBUSH
  std::vector<MassProperty> mass_props;        ///< PMASS

  BarDefaults baror, beamor;
  std::vector<Bar> bars;
  std::vector<Rod> rods;
  std::vector<Shell> shells;
  std::vector<Conm2> conm2;
  std::vector<Spring> springs;
  std::vector<Bush> bushes;                    ///< CBUSH
  std::vector<ScalarMass> scalar_masses;       ///< CMASS1-4
  std::vector<Conm1> conm1;
  std::vector<SolidProperty> solid_props;   ///< PSOLID
  std::vector<Solid> solids;                ///< CHEXA, CPENTA, CTETRA
  std::vector<Rbe2> rbe2;
  std::vector<Rbar> rbars;
  std::vector<Rbe3> rbe3;

  std::vector<SpcEntry> spcs;
  std::vector<SpcAdd> spcadds;
  std::vector<MpcEquation> mpcs;
  std::vector<MpcAdd> mpcadds;
  std::vector<DofSetEntry> aset, omit, bset, suport;
  std::vector<PointLoad> point_loads;
  std::vector<PressureLoad> pressure_loads;
  std::vector<BarLineLoad> bar_line_loads;         ///< PLOAD1
  std::vector<EnforcedMotion> enforced_motions;    ///< SPCD
  std::vector<FaceLoad> face_loads;         ///< PLOAD4
  std::vector<GravityLoad> gravity_loads;
  std::vector<RotationalLoad> rotational_loads;
  std::vector<LoadCombination> load_combinations;
  std::vector<GridTemperature> grid_temperatures;
  std::vector<DefaultTemperature> default_temperatures;
  std::vector<BarTemperature> bar_temperatures;
  std::vector<EigenMethod> eigen_methods;
  std::vector<Dmig> dmigs;
  std::vector<Param> params;

  std::vector<UnsupportedCard> unsupported;  ///< in order of first appearance
  /// Number of cards of each name the reader accepted (e.g. "GRID" -> 18), for reports.
  std::map<std::string, std::size_t> card_counts;

  /// Named node sets (from gmsh physical groups of points, or user definitions): name -> grid ids.
  std::map<std::string, std::vector<int>> node_sets;

  // Lookups, built by fem::finalize (id -> position in the vector above).
  std::unordered_map<int, std::uint32_t> grid_index, coord_index, mat1_index, mat2_index, mat8_index,
      bar_prop_index, rod_prop_index, shell_prop_index, composite_prop_index, spring_prop_index, spoint_index,
      bush_prop_index, mass_prop_index, solid_prop_index;
  bool finalized = false;
};

}  // namespace seflex::fem
