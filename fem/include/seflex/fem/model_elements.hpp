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
