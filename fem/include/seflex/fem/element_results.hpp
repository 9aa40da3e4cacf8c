#pragma once
// Element results (Nastran's element force and stress output) from an element's displacement vector.
//
// One function per element type turns the element's grid displacements (6 per grid, basic) into a
// fixed list of LINEAR components (element_result_components); everything derived and nonlinear (von
// Mises, the largest of a few) comes afterwards from those components (element_result_peak), so that a
// result is a matrix row block times a displacement vector: the stress modes of a superelement are the
// components of each basis vector, and a run recovers them as stress modes x elastic coordinates.
//
// Conventions (MSC Nastran QRG element output; the signs checked against MYSTRAN 12's output of the
// validation deck tests/data/validation/mystran_static_loads/ALL-ELEM-TEST):
// - Shell (CQUAD4, CQUADR, CTRIA3, CTRIAR): at the centroid, in the element coordinate system (CTRIA3:
//   x along G1->G2; CQUAD4: x bisects the angle between the diagonals G1-G3 and G2-G4; z the normal):
//   membrane forces Nx Ny Nxy, moments Mx My Mxy, transverse shears Qx Qy (all per unit width), and
//   the fibre stresses sx sy txy at Z1 and Z2 (PSHELL Z1/Z2, default -T/2 and +T/2 from the material
//   mid-surface, which ZOFFS moves off the grids), sigma(z) = N / T - M z / I with I = (12I/T^3) T^3 / 12
//   and M about that mid-surface (Nastran's sign: a positive Mx is tension on the bottom, z < 0).
//   Transverse shears are zero without transverse shear flexibility (PSHELL MID3 blank, Kirchhoff
//   plate), as Nastran prints them. PCOMP/PCOMPG sections: the homogeneous-plate fibre formula of the
//   total thickness (no ply stresses).
// - Bar (CBAR, CBEAM): bending moments at end A plane 1, plane 2, end B plane 1, plane 2, shears in
//   plane 1 and 2, axial force (tension positive), torque, in element axes; plane 1 is x-y (moment
//   about z), plane 2 x-z; dM/dx = -V in both planes (the CBAR force output of the QRG).
// - Rod (CROD, CONROD, CTUBE): axial force (tension positive), torque, axial stress F / A.
// - Solid (CHEXA, CPENTA, CTETRA, CPYRAM): stresses sx sy sz txy tyz tzx at the centroid, basic axes
//   (PSOLID CORDM blank: the basic system).
// - Spring (CELAS1-4): force k (u1 - u2) on its two dofs.
// - Bush (CBUSH): forces Fx Fy Fz and moments Mx My Mz in element axes, K (u_B - u_A) at the spring
//   point (GB blank: u_B = 0).
// Elements with no results (CSHEAR, CTRIA6, CQUAD8, CBEND, GENEL, rigid elements, masses) are listed
// in ElementResultMap::missing (card and count) so that a caller can warn.
#include <Eigen/Core>
#include <array>
#include <string>
#include <vector>

#include "seflex/fem/model.hpp"

namespace seflex::fem {

struct Quad4Element;
struct Tria3Element;
struct BarElement;
struct RodElement;
struct SolidElement;
struct BushElement;

enum class ResultKind : unsigned char { Shell = 0, Bar = 1, Rod = 2, Solid = 3, Spring = 4, Bush = 5 };
constexpr int kResultKinds = 6;

/// Names of the linear components of a kind, in their order (CSV column names).
const std::vector<std::string>& element_result_components(ResultKind kind);
inline int element_result_count(ResultKind kind) { return static_cast<int>(element_result_components(kind).size()); }

/// The derived scalar that ranks an element (stress envelope): shells the larger of the von Mises
/// stresses at Z1 and Z2 (fibre 1 or 2), solids the von Mises stress, bars the largest bending moment
/// magnitude, rods the axial stress magnitude, springs and bushes the largest force magnitude.
struct ResultPeak {
  double value = 0;
  int fibre = 0;  ///< shells: 1 (Z1) or 2 (Z2); 0 otherwise
};
ResultPeak element_result_peak(ResultKind kind, const double* components);
/// What element_result_peak measures for a kind ("von_mises", "moment", "axial_stress", "force").
const char* element_result_peak_name(ResultKind kind);
/// Von Mises of a plane stress state.
double plane_von_mises(double sx, double sy, double txy);

/// Fibre distances of a shell for its stresses (PSHELL Z1/Z2 from the material mid-surface; default -T/2,
/// +T/2), its ZOFFS and the bending inertia per width of the fibre formula.
struct ShellFibres {
  double z1 = 0, z2 = 0, zoffs = 0, I = 0;  ///< I: bending inertia per width (12I/T^3) T^3 / 12
};

// Per element type: linear components from the element's grid displacements (basic, 6 per grid).
Eigen::Matrix<double, 14, 1> quad4_results(const Quad4Element& e, const ShellFibres& f, const Eigen::Matrix<double, 24, 1>& u);
Eigen::Matrix<double, 14, 1> tria3_results(const Tria3Element& e, const ShellFibres& f, const Eigen::Matrix<double, 18, 1>& u);
Eigen::Matrix<double, 8, 1> bar_results(const BarElement& e, const Eigen::Matrix<double, 12, 1>& u);
Eigen::Vector3d rod_results(const RodElement& e, const Eigen::Matrix<double, 12, 1>& u);
/// u: 3 translations per grid (basic).
Eigen::Matrix<double, 6, 1> solid_results(const SolidElement& e, const Eigen::Ref<const Eigen::VectorXd>& u);
Eigen::Matrix<double, 6, 1> bush_results(const BushElement& e, const Eigen::Matrix<double, 12, 1>& u);

/// The element results of a set of elements of a finalized model as one linear map from g-set
/// displacements (each grid's CD components): results = R u_g, element after element, each element's
/// components in the order of its kind. Built once; R is dense in the elements' own dofs only.
struct ElementResultMap {
  struct Entry {
    int id = 0;
    ResultKind kind = ResultKind::Shell;
    std::string card;          ///< CQUAD4, CBAR, ...
    Eigen::Index row = 0;      ///< first row of its components
  };
  std::vector<Entry> entries;
  Eigen::Index rows = 0;
  /// R as sparse rows: for each result row, the dofs it reads and their weights.
  std::vector<Eigen::Index> ptr{0};
  std::vector<Eigen::Index> dof;
  std::vector<double> weight;
  /// Cards of the selected elements that have no element results, with their counts.
  std::vector<std::pair<std::string, int>> missing;

  /// results = R u_g (results sized rows).
  void apply(const Eigen::Ref<const Eigen::VectorXd>& u_g, Eigen::Ref<Eigen::VectorXd> results) const;
  Eigen::VectorXd apply(const Eigen::Ref<const Eigen::VectorXd>& u_g) const;
  /// R U for the columns of U (g-set x n): rows x n.
  Eigen::MatrixXd apply_columns(const Eigen::Ref<const Eigen::MatrixXd>& U) const;
};

/// The result map of the elements whose ids are in `ids` (empty: every element with results). An
/// element id found in no element with results is listed in `missing` as ("unknown id N", 1).
ElementResultMap make_element_result_map(const Model& model, const std::vector<int>& ids = {});

}  // namespace seflex::fem
