#pragma once
// Normal modes (Nastran SOL 103): K_ff phi = lambda M_ff phi on the free set, with the SPCs and
// the EIGRL/EIGR the case control selects (METHOD), recovered to the g-set and normalised.
//
// EIGRL/EIGR fields honoured: ND (number of roots; `count` overrides it), F1/F2 (frequency range
// in Hz, lambda = (2 pi f)^2), NORM = MASS (phi^T M phi = 1, the default), MAX (largest f-set
// component = +1) or POINT (component C of grid G = +1; MAX if that component is ~0). Mass-normalised
// modes are signed so that their largest f-set component is positive.
//
// Generalised mass and stiffness are phi^T M phi and phi^T K phi of the normalised modes, as
// Nastran's REAL EIGENVALUES table prints them.
//
// Constraints: the case control's SPC and MPC sets, rigid elements (fem/constraints.hpp). With
// ASET/ASET1 or OMIT/OMIT1 cards the f-set is condensed statically to the a-set first (Guyan
// reduction, as Nastran and MYSTRAN do; guyan.hpp) and the eigenproblem is solved on the a-set;
// the omitted dofs of the modes are recovered as u_o = G_oa u_a. The result says so (guyan).
// Before anything is assembled, check_card_usage(NormalModes) must find nothing Refused.
#include <Eigen/Core>
#include <optional>
#include <string>
#include <vector>

#include "seflex/fem/dof_map.hpp"
#include "seflex/fem/model.hpp"
#include "seflex/solutions/case_selection.hpp"
#include "seflex/linalg/eigensolver.hpp"

namespace seflex::solutions {

struct ModesOptions {
  std::optional<int> subcase;                 ///< default: the first subcase, else the global selections
  std::optional<int> count;                   ///< overrides ND (and lifts the need for a METHOD)
  linalg::EigenBackend backend = linalg::EigenOptions{}.backend;
  int block_size = linalg::EigenOptions{}.block_size;  ///< block of the block-Lanczos backend (like EIGRL MAXSET)
  linalg::FactorizationBackend factorization = linalg::kDefaultFactorization;
  std::vector<Eigen::Index> fixed_dofs;       ///< extra g-set dofs held at zero (fixed-interface modes)
  bool check_completeness = true;
  bool guyan = true;                          ///< honour ASET/OMIT (false: eigenproblem on the full f-set)
  bool ignore_unknown_cards = false;          ///< solve without the cards seflex does not know (check_card_usage)
  /// The distributed eigensolver (parallel/, --backend slepc): EigenOptions::external.
  linalg::ExternalEigensolver external;
};

enum class ModeNormalization : unsigned char { Mass, Max, Point };

/// The static condensation a solution applied (ASET/OMIT).
struct GuyanInfo {
  Eigen::Index a_dofs = 0, o_dofs = 0;  ///< sizes of the a-set and the omitted set
  bool from_aset = true;                ///< a-set from ASET/ASET1 (else the complement of OMIT/OMIT1)
};

struct NormalModes {
  CaseSelection selection;
  fem::DofMap dofs;
  Eigen::Index n_free = 0;
  std::optional<GuyanInfo> guyan;        ///< set when the eigenproblem was solved on a Guyan-reduced a-set
  ModeNormalization normalization = ModeNormalization::Mass;
  Eigen::VectorXd eigenvalues;           ///< m, ascending, (rad/s)^2 (in the deck's units)
  Eigen::MatrixXd shapes_g;              ///< g-set x m, each grid's CD system, normalised as above
  Eigen::VectorXd generalized_mass;      ///< phi^T M phi
  Eigen::VectorXd generalized_stiffness; ///< phi^T K phi
  linalg::EigenStats stats;

  Eigen::VectorXd radians() const;       ///< sqrt(|lambda|)
  Eigen::VectorXd cycles() const;        ///< sqrt(|lambda|) / (2 pi), Hz
};

/// Normal modes of a finalized model. Throws InputError for a missing or undefined METHOD (unless
/// `count` is given), an EIGRL that bounds nothing (no ND, no F2), undefined sets, and for a dof
/// with neither stiffness nor mass (named by grid and component); ConvergenceError if the
/// eigensolver does not converge.
NormalModes solve_normal_modes(const fem::Model& model, const ModesOptions& options = {});

}  // namespace seflex::solutions
