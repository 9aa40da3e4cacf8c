#pragma once
// Redundant constraint equations of FFRF-LM and rigid-LM (ffrf_redundancy.cpp, docs/ffrf.md).
#include <Eigen/Core>
#include <string>
#include <vector>

#include "ffrf/ffrf_detail.hpp"

namespace seflex::mbd::detail {

/// Scratch of the rank tests, sized at the first use (no allocation after it while the rank holds).
struct RankScratch {
  Eigen::MatrixXd G, Q;  ///< scaled Jacobian; orthonormal basis of the kept rows (columns)
  Eigen::VectorXd v, c, phi, phidot;
  ConstraintEval ce;
};

/// Mark the equations of sys that depend on those before them at the initial configuration
/// (sys.removed, sys.redundant), when sys.options.remove_redundant.
void find_redundant(FfrfSystem& sys);

/// Empty when the equations kept at t = 0 are still independent at s and the removed ones still
/// depend on them; otherwise why not, naming the joints.
std::string rank_change(const FfrfSystem& sys, const FfrfState& s, RankScratch& w);

/// "hinge 'HL2b'", or "body 'panel' on node 'panel.3'": the joint of constraint c.
std::string constraint_joint_name(const FfrfSystem& sys, int c);

}  // namespace seflex::mbd::detail
