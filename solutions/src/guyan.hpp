#pragma once
// Static (Guyan) condensation of the f-set to the a-set, as Nastran does for ASET/ASET1 and
// OMIT/OMIT1 (MSC Nastran Dynamic Analysis User's Guide, "Guyan reduction"):
//
//   f = a + o,   u_o = G_oa u_a,   G_oa = -K_oo^-1 K_oa,
//   K_aa_bar = K_aa + K_ao G_oa,   M_aa_bar = T^T M_ff T  with T = [I; G_oa]
//     = M_aa + M_ao G_oa + G_oa^T M_oa + G_oa^T M_oo G_oa.
//
// The a-set: the dofs of the ASET/ASET1 cards if there are any (every other f-set dof is omitted;
// OMIT entries are then redundant), otherwise every f-set dof not on an OMIT/OMIT1 card. An a-set or
// o-set dof that is also constrained (SPC, GRID PS) or dependent (rigid element, MPC) is an
// InputError naming both cards (Nastran's sets are mutually exclusive); a dof AUTOSPC removed is
// skipped. G_oa is dense (o x a): memory o * a * 8 bytes.
#include <Eigen/Core>
#include <optional>
#include <vector>

#include "seflex/fem/constraints.hpp"
#include "seflex/fem/model.hpp"
#include "seflex/linalg/sparse_factorization.hpp"

namespace seflex::solutions::detail {

struct GuyanReduction {
  std::vector<Eigen::Index> a, o;  ///< f-set indices of the a-set and the o-set, ascending
  linalg::SparseMatrixd K_aa, M_aa;        ///< condensed, a x a, both triangles
  Eigen::MatrixXd G_oa;            ///< o x a
  bool from_aset = true;           ///< the a-set came from ASET cards (else from OMIT cards)

  /// f-set vectors (n_f x k) of a-set vectors (a x k): u_a in place, u_o = G_oa u_a.
  Eigen::MatrixXd expand(const Eigen::MatrixXd& x_a, Eigen::Index n_f) const;
};

/// The condensation of `c` (a constrained system of `model`), or nullopt when the model has no
/// ASET/ASET1/OMIT/OMIT1 card or they omit nothing. Throws InputError for conflicting sets, an
/// empty a-set, and a singular K_oo (naming a grid and component of the o-set).
std::optional<GuyanReduction> guyan_reduction(const fem::Model& model, const fem::GlobalMatrices& g,
                                              const fem::ConstrainedSystem& c, linalg::FactorizationBackend backend);

}  // namespace seflex::solutions::detail
