#pragma once
// Internal to fem: the dependent dofs of rigid elements, interpolation elements and MPCs, each
// expressed through other g-set dofs (in the grids' CD systems) before chains are resolved:
//
//   u_m = sum_k a_k u_k      (one DependentDof per m-set dof; the u_k may be dependent themselves)
//
// One function per card family, each in its own file: constraint_rigid.cpp (RBE2, RBAR, RBE1,
// CRIGD1-3, RROD, CRIGDR),
// constraint_rbe3.cpp (RBE3), constraint_mpc.cpp (MPC/MPCADD). constraints.cpp eliminates them.
// Every function throws InputError naming the card (file:line, id, field) for undefined grids,
// components that do not exist, and element definitions that do not determine their dependents.
#include <Eigen/Core>
#include <cstdint>
#include <optional>
#include <utility>
#include <vector>

#include "seflex/fem/constraints.hpp"
#include "seflex/fem/dof_map.hpp"
#include "seflex/fem/model.hpp"

namespace seflex::fem::detail {

using SparseRow = std::vector<std::pair<Eigen::Index, double>>;  ///< (g dof, coefficient)
using CdAxes = std::vector<std::optional<Eigen::Matrix3d>>;       ///< fem::grid_cd_axes

struct DependentDof {
  Eigen::Index dof = 0;       ///< the m-set dof
  SparseRow terms;            ///< u_dof = sum a u_k
  std::uint32_t card = 0;     ///< index into ConstraintEquations::cards
};

struct ConstraintEquations {
  std::vector<ConstraintCard> cards;
  std::vector<DependentDof> dependents;
  std::uint32_t add_card(const char* name, int id, const CardRef& ref) {
    cards.push_back({name, id, ref});
    return static_cast<std::uint32_t>(cards.size() - 1);
  }
};

/// 6 x 6 map from a rigid motion q = (u_p, theta) about basic point p (basic components) to the six
/// dofs of grid `gi` in its CD system: [A^T, -A^T skew(x_g - p); 0, A^T].
Eigen::Matrix<double, 6, 6> rigid_map(const Model& model, const CdAxes& axes, Eigen::Index gi, const Eigen::Vector3d& p);

/// RBE2, RBAR, RBE1, CRIGD1-3, RROD, CRIGDR (constraint_rigid.cpp).
void add_rigid_elements(const Model& model, const DofMap& dofs, const CdAxes& axes, ConstraintEquations& eq);

/// RBE3 (constraint_rbe3.cpp).
void add_rbe3_elements(const Model& model, const DofMap& dofs, const CdAxes& axes, ConstraintEquations& eq);

/// The MPC equations of set `sid` (MPCADD expanded; constraint_mpc.cpp). Throws InputError if no
/// MPC or MPCADD card has this SID.
void add_mpc_set(const Model& model, const DofMap& dofs, int sid, ConstraintEquations& eq);

/// Solve k constraint equations R u = 0 (R: k x c dense over the dofs `columns`) for the k dofs
/// `dependent` (each one of `columns`): u_m = -R_m^{-1} R_n u_n. Returns one row per dependent dof
/// over the other columns, or nullopt if R_m is singular (rank test relative to R's largest entry).
std::optional<std::vector<SparseRow>> solve_for_dependents(const Eigen::MatrixXd& R, const std::vector<Eigen::Index>& columns,
                                                           const std::vector<Eigen::Index>& dependent);

/// "grid 12 component 3" / "scalar point 7" for messages.
std::string dof_name(const Model& model, const DofMap& dofs, Eigen::Index dof);

}  // namespace seflex::fem::detail
