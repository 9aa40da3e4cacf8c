#pragma once
// Part of model.hpp (the FE model as data; conventions there), kept apart to keep headers short:
// line, shell, spring, bush and mass elements (CBAR/CBEAM with BAROR/BEAMOR, CROD/CONROD,
// CQUAD4/CTRIA3, CONM1/CONM2, CELAS1-4, CBUSH, CMASS1-4) and DMIG matrices. Solids: model_solids.hpp.
// No parsing and no numerics here.
#include <Eigen/Core>
#include <array>
#include <cstdint>
#include <string>
#include <vector>

#include "seflex/fem/card_ref.hpp"
#include "seflex/fem/model_geometry.hpp"

namespace seflex::fem {

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

/// CBAR or CBEAM (a CBEAM on a tapered PBEAM/PBEAML: BarProperty::stations).
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

struct Rod {  ///< CROD (pid -> PROD), CTUBE (pid -> PTUBE) or CONROD (inline property, pid = 0)
  int id = 0, pid = 0;
  int ga = 0, gb = 0;
  bool inline_property = false;
  bool tube = false;                            ///< CTUBE
  int mid = 0;                                  ///< CONROD only
  double A = 0, J = 0, C = 0, nsm = 0;          ///< CONROD only
  CardRef ref;
};

/// "CROD", "CTUBE" or "CONROD".
inline const char* rod_card(const Rod& r) { return r.tube ? "CTUBE" : r.inline_property ? "CONROD" : "CROD"; }

/// CQUAD4 or CQUADR (4 grids), CTRIA3 or CTRIAR (3 grids; g[3] = 0).
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
  bool drilling = false;                        ///< CQUADR / CTRIAR (MSC's shells with drilling stiffness)
  CardRef ref;
};

/// CSHEAR: shear panel on G1-G4 (consecutive around the perimeter), pid -> PSHEAR.
struct ShearPanel {
  int id = 0, pid = 0;
  std::array<int, 4> g{};
  CardRef ref;
};

/// CBEND: curved beam or pipe from GA to GB along a circular arc (pid -> PBEND). The arc's plane and
/// centre come from the orientation (grid G0 or vector X1-X3 in GA's displacement system) and GEOM
/// (QRG CBEND): 1 centre on the line from GA along the orientation; 2 tangent at GA along the
/// orientation (the arc on its side of the chord); 3 radius RB, 4 arc angle THETAB of the PBEND, the
/// centre on the side of the chord away from the orientation.
struct Bend {
  int id = 0, pid = 0, ga = 0, gb = 0;
  bool has_g0 = false;
  int g0 = 0;
  Eigen::Vector3d v = Eigen::Vector3d::Zero();
  int geom = 0;                                 ///< 1-4
  CardRef ref;
};

/// "CQUAD4", "CTRIA3", "CQUADR" or "CTRIAR".
inline const char* shell_card(const Shell& s) {
  return s.nnode == 4 ? (s.drilling ? "CQUADR" : "CQUAD4") : (s.drilling ? "CTRIAR" : "CTRIA3");
}

/// CTRIA6 (3 corners) or CQUAD8 (4 corners) with their mid-side grids: the corner data as a Shell
/// (PID, THETA/MCID, ZOFFS, TFLAG, corner thicknesses; shell.nnode = 3 or 4) and mid[k] the grid
/// on the edge from corner k to corner k + 1, 0 = blank (that edge straight, its field linear).
struct QuadraticShell {
  Shell shell;
  std::array<int, 4> mid{};
};

inline const char* quadratic_shell_card(const QuadraticShell& q) { return q.shell.nnode == 4 ? "CQUAD8" : "CTRIA6"; }

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

/// CBUSH: generalized spring between GA and GB (gb = 0: grounded) at the point S of the line GA-GB
/// (OCID = -1) or at GA + (S1, S2, S3) in system OCID. Element axes: system CID (cid >= 0) or x along
/// GA -> GB, y in the plane of x and the orientation vector (GO or X1-X3 in GA's CD system).
/// CBUSH1D (one_d): EID PID GA GB CID, the rod-type spring on a PBUSH1D: the CBUSH of stiffness K along
/// the element axis only (x of CID, or GA -> GB when CID is blank), as linear Nastran solutions
/// convert it (OptiStruct's reference says so in its CBUSH1D remarks); no orientation vector, S = 0.5.
struct Bush {
  int id = 0, pid = 0, ga = 0, gb = 0;
  bool one_d = false;                           ///< CBUSH1D
  bool has_g0 = false, has_v = false;
  int g0 = 0;
  Eigen::Vector3d v = Eigen::Vector3d::Zero();
  int cid = -1;                                 ///< -1 = blank
  double s = 0.5;
  int ocid = -1;
  Eigen::Vector3d s_ocid = Eigen::Vector3d::Zero();  ///< S1 S2 S3 (OCID >= 0)
  CardRef ref;
};

inline const char* bush_card(const Bush& b) { return b.one_d ? "CBUSH1D" : "CBUSH"; }

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

/// GENEL: a general element on the dofs UI (n) and UD (m), in the grids' CD systems (scalar points:
/// component 0). Stiffness form (K) or flexibility form (Z, K = Z^-1), the lower triangle given by
/// columns; S (n x m, by rows) the rigid-body matrix u_i = S u_d, computed from the geometry when UD
/// holds six dofs and S is blank (MSC QRG GENEL):
///   [f_i]   [  K       -K S   ] [u_i]
///   [f_d] = [ -S^T K  S^T K S ] [u_d]
struct Genel {
  struct Dof {
    int point = 0;                              ///< grid or scalar point id
    int c = 0;                                  ///< 1-6 for a grid, 0 for a scalar point
  };
  int id = 0;
  std::vector<Dof> ui, ud;
  bool flexibility = false;                     ///< Z given (else K)
  std::vector<double> kz;                       ///< n (n + 1) / 2 values: KZ11 KZ21 ... KZn1 KZ22 ...
  std::vector<double> s;                        ///< n m values S11 S12 ... S1m S21 ...; empty: from UD
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

}  // namespace seflex::fem
