#pragma once
// Linear buckling (Nastran SOL 105) of a finalized model: the statics of a preload subcase, then
//
//   (K + lambda K_sigma(u_preload)) phi = 0
//
// for the lowest positive load factors lambda of the subcase that selects METHOD (EIGRL: ND roots,
// V1/V2 bounds on lambda; EIGB is refused by check_card_usage because seflex does not read it).
// K_sigma is fem::assemble_geometric_stiffness of the preload displacements; both matrices are
// reduced to the f-set of the buckling subcase's SPC/MPC and rigid elements (T^T K_sigma T: rigid
// elements carry no differential stiffness, docs/buckling.md).
//
// Eigensolver (linalg/eigensolver.hpp, the seam `seflex modes` uses): K_sigma is indefinite, so it
// cannot be the seam's "mass". With alpha > 0 and B = K - alpha K_sigma (positive definite when
// alpha is below the magnitude of every negative load factor), the pencil
//   K phi = mu B phi,    mu = lambda / (lambda + alpha)
// has the same vectors; lambda in (0, inf) maps monotonically onto mu in (0, 1), the modes K_sigma
// does not load (lambda = inf) onto mu = 1 and negative factors onto mu > 1, so the lowest mu are the
// lowest positive load factors. The shift-invert operator about 0 is (K)^-1 B = I - alpha K^-1 K_sigma,
// whose Krylov spaces do not depend on alpha. alpha starts at half the smallest K_ii / K_sigma,ii
// over the dofs where K_sigma,ii > 0 (an upper bound of the smallest negative factor's magnitude
// is the Rayleigh quotient of that unit vector) and is divided by 10 until B factorises. lambda is
// finally the Rayleigh quotient -phi^T K phi / phi^T K_sigma phi.
//
// Preload subcase: STATSUB(BUCKLING) (or STATSUB) of the buckling subcase if given, else the first
// subcase before it that selects a LOAD. Errors (InputError): no subcase selects METHOD, no preload
// subcase, a preload that stresses nothing (K_sigma = 0), STATSUB naming no subcase.
#include <Eigen/Core>
#include <optional>

#include "seflex/fem/dof_map.hpp"
#include "seflex/fem/model.hpp"
#include "seflex/solutions/case_selection.hpp"
#include "seflex/linalg/eigensolver.hpp"

namespace seflex::solutions {

struct BucklingOptions {
  std::optional<int> count;  ///< overrides EIGRL ND
  linalg::EigenBackend backend = linalg::EigenOptions{}.backend;
  bool ignore_unknown_cards = false;  ///< solve without the cards seflex does not know (check_card_usage)
};

struct BucklingSolution {
  solutions::CaseSelection preload, buckling;
  fem::DofMap dofs;
  Eigen::Index n_free = 0;
  Eigen::VectorXd u_preload_g;            ///< preload displacements (g-set, CD)
  Eigen::VectorXd load_factors;           ///< ascending, positive
  Eigen::MatrixXd shapes_g;               ///< g-set x m, largest |component| = 1 (Nastran NORM = MAX)
  Eigen::VectorXd generalized_stiffness;  ///< phi^T K phi of the normalised shapes
  double alpha = 0;                       ///< the spectral parameter used
  linalg::EigenStats stats;
};

/// The preload and buckling subcases of a deck (the rules above); throws InputError.
std::pair<solutions::CaseSelection, solutions::CaseSelection> buckling_cases(const fem::Model& model);

/// The subcases a buckling solution runs, for check_card_usage(Buckling): the preload, then the
/// buckling subcase when it is another one.
std::vector<solutions::CaseSelection> buckling_case_list(const fem::Model& model);

BucklingSolution solve_buckling(const fem::Model& model, const BucklingOptions& options = {});

}  // namespace seflex::solutions
