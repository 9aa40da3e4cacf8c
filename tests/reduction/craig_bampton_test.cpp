// Craig-Bampton reduction and the absolute-interface-coordinate superelement on a model built in
// code (craig_bampton_models.hpp), against independent references: dense eigensolutions of the
// full model and of the fixed-interface problem, fem::mass_properties (element by element), the
// identities of formulation.md test T1, and Rayleigh-Ritz bounds.
#include "seflex/reduction/craig_bampton.hpp"

#include <gtest/gtest.h>

#include "craig_bampton_checks.hpp"
#include "craig_bampton_models.hpp"
#include "seflex/fem/mass_properties.hpp"
#include "seflex/reduction/craig_bampton_superelement.hpp"

namespace seflex {
namespace {

using cbtest::box_frame;
using cbtest::max_abs;
using cbtest::skew;
using reduction::reduce_to_superelement;
using reduction::SuperelementOptions;

/// `block`: the fixed-interface modes from the block Lanczos on the factor of K_ii (used by default
/// for interiors of 2000 dofs and more) instead of solve_eigenproblem.
SuperelementOptions options(std::vector<int> ids, int modes, bool block = false) {
  SuperelementOptions o;
  o.interface_ids = std::move(ids);
  o.modes.modes = modes;
  if (block) o.modes.block_lanczos_min_size = 0;
  return o;
}

/// Free-free eigenvalues of the full model, dense (K + s M is positive definite for s > 0).
std::vector<double> full_free_free(const fem::Model& m) {
  const auto d = cbtest::dense_system(m);
  return fem::test::dense_eigenvalues(d.K, d.M, 100.0);
}

// With every fixed-interface mode kept the Craig-Bampton basis spans the whole f-set (up to the
// massless dofs, which static condensation handles exactly), so the reduced model has the full
// model's eigenvalues (Craig & Bampton 1968).
TEST(CraigBampton, AllModesKeptReproduceFullEigenvalues) {
  for (const bool block : {false, true}) {
    const fem::Model m = box_frame();
    const se::Superelement s = reduce_to_superelement(m, options({1, 7}, 100000, block));
    const std::vector<double> full = full_free_free(m);
    const Eigen::VectorXd red = reduction::reduced_eigenvalues(s, s.size());
    // The massless rotations of the interface grids make the reduced mass matrix singular too
    // (rank M_red <= rank M): the same number of finite eigenvalues.
    ASSERT_EQ(red.size(), static_cast<Eigen::Index>(full.size()));
    const double top = full.back();
    for (std::size_t k = 0; k < full.size(); ++k) {
      if (k < 6) {
        EXPECT_LT(std::abs(red(static_cast<Eigen::Index>(k))), 1e-8 * full[6]) << "rigid mode " << k;
        EXPECT_LT(std::abs(full[k]), 1e-8 * full[6]);
      } else {
        EXPECT_NEAR(red(static_cast<Eigen::Index>(k)) / full[k], 1.0, 1e-8 * top / full[k]) << "mode " << k + 1;
      }
    }
  }
}

// formulation.md section 6.2, test T1 (identities of sections 1.2-1.3) to 1e-10, with an interface
// grid in a rotated displacement system and an RBE2-dependent grid carried by the recovery.
TEST(CraigBampton, FormulationT1Identities) {
  const fem::Model m = box_frame();
  const se::Superelement s = reduce_to_superelement(m, options({1, 3, 7}, 5));
  ASSERT_TRUE(se::check_consistency(s).empty());
  cbtest::expect_t1_identities(s, "box frame {1, 3, 7}");
}

// Mass properties: the superelement's, and those of the reduced mass matrix, equal the grid point
// weight generator's (fem::mass_properties, element by element, times WTMASS) to 1e-10.
TEST(CraigBampton, MassPropertiesEqualFullModel) {
  for (const bool coupled : {false, true}) {
    const fem::Model m = box_frame(coupled);
    const se::Superelement s = reduce_to_superelement(m, options({1, 3, 7}, 4));
    const fem::MassProperties mp = fem::mass_properties(m, s.frame_node_id);
    const double w = 0.5;  // PARAM WTMASS of the model
    EXPECT_NEAR(s.mass / (w * mp.mass), 1.0, 1e-10);
    const Eigen::Vector3d X_f = m.grids[m.grid_index.at(s.frame_node_id)].x_basic;
    EXPECT_LT((s.p_BoCm_B - (mp.cg - X_f)).norm(), 1e-10);
    EXPECT_LT(max_abs(s.I_Cm_B - w * mp.I_cg), 1e-10 * max_abs(mp.I_cg));
    // Rigid-body mass of the reduced model about the frame node.
    const Eigen::MatrixXd R0 = reduction::interface_rigid_modes(s);
    const Eigen::MatrixXd M0 = R0.transpose() * s.M.topLeftCorner(R0.rows(), R0.rows()) * R0;
    EXPECT_LT(max_abs(M0 - w * mp.M0), 1e-10 * max_abs(mp.M0)) << (coupled ? "coupled" : "lumped");
    // The FE mass matrix in basic reproduces the reduced mass matrix through the recovery.
    const Eigen::MatrixXd Mr = s.recovery.transpose() * (s.M_fe * s.recovery);
    EXPECT_LT(max_abs(Mr - s.M), 1e-10 * max_abs(s.M));
  }
}

// Free-free: exactly six rigid-body modes; elastic frequencies are Rayleigh-Ritz upper bounds of
// the full model's and decrease as modes are added (the bases are nested).
TEST(CraigBampton, SixRigidModesAndConvergenceFromAbove) {
  const fem::Model m = box_frame();
  const std::vector<double> full = full_free_free(m);
  Eigen::VectorXd previous;
  for (const int modes : {0, 5, 10, 20}) {
    const se::Superelement s = reduce_to_superelement(m, options({1, 7}, modes));
    const Eigen::VectorXd red = reduction::reduced_eigenvalues(s, 16);
    ASSERT_EQ(red.size(), std::min(16, s.size()));
    int rigid = 0;
    for (Eigen::Index k = 0; k < red.size(); ++k) rigid += std::abs(red(k)) < 1e-8 * full[6];
    EXPECT_EQ(rigid, 6) << modes << " modes";
    for (int k = 6; k < red.size(); ++k) {
      EXPECT_GE(red(k), full[static_cast<std::size_t>(k)] * (1 - 1e-10))
          << "mode " << k + 1 << ", " << modes << " modes";
      if (k < previous.size()) {
        EXPECT_LE(red(k), previous(k) * (1 + 1e-10)) << "mode " << k + 1 << ", " << modes << " modes";
      }
    }
    if (modes == 20) {
      EXPECT_NEAR(red(6) / full[6], 1.0, 1e-3);  // the first elastic mode has converged
    }
    previous = red;
  }
}

/// Dense fixed-interface modes of the box with interfaces {1, 7} and the effective-mass reference.
struct FixedInterfaceReference {
  cbtest::DenseModes modes;
  Eigen::MatrixXd L;  // all modes x 6 participation factors
};
FixedInterfaceReference fixed_interface_reference(const fem::Model& m, const std::vector<int>& ids,
                                                  const Eigen::Vector3d& X_f) {
  const auto d = cbtest::dense_system(m);
  std::vector<char> boundary(static_cast<std::size_t>(d.c.n_free()), 0);
  for (int id : ids)
    for (int k = 0; k < 6; ++k) boundary[static_cast<std::size_t>(d.c.g_to_f[6 * m.grid_index.at(id) + k])] = 1;
  std::vector<Eigen::Index> interior;
  for (Eigen::Index f = 0; f < d.c.n_free(); ++f)
    if (!boundary[static_cast<std::size_t>(f)]) interior.push_back(f);
  const auto ni = static_cast<Eigen::Index>(interior.size());
  Eigen::MatrixXd Kii(ni, ni), Mii(ni, ni), MiR(ni, 6);
  // Rigid motion of the f-set about the frame node, from the geometry (each grid's CD components).
  const auto axes = fem::grid_cd_axes(m);
  Eigen::MatrixXd R(d.c.n_free(), 6);
  for (Eigen::Index f = 0; f < d.c.n_free(); ++f) {
    const Eigen::Index g = d.c.f_to_g[static_cast<std::size_t>(f)];
    const std::size_t gi = static_cast<std::size_t>(g / 6);
    const int comp = static_cast<int>(g % 6);
    Eigen::Matrix<double, 6, 6> B = Eigen::Matrix<double, 6, 6>::Identity();
    B.block<3, 3>(0, 3) = -skew(m.grids[gi].x_basic - X_f);
    const Eigen::Matrix3d A = axes[gi] ? *axes[gi] : Eigen::Matrix3d::Identity();
    R.row(f) = (A.transpose() * B.middleRows<3>(comp < 3 ? 0 : 3)).row(comp % 3);
  }
  const Eigen::MatrixXd MR = d.M * R;
  for (Eigen::Index r = 0; r < ni; ++r) {
    MiR.row(r) = MR.row(interior[static_cast<std::size_t>(r)]);
    for (Eigen::Index c = 0; c < ni; ++c) {
      Kii(r, c) = d.K(interior[static_cast<std::size_t>(r)], interior[static_cast<std::size_t>(c)]);
      Mii(r, c) = d.M(interior[static_cast<std::size_t>(r)], interior[static_cast<std::size_t>(c)]);
    }
  }
  FixedInterfaceReference ref;
  ref.modes = cbtest::dense_modes(Kii, Mii);
  ref.L = ref.modes.X.transpose() * MiR;
  return ref;
}

// Truncation report against a dense fixed-interface eigensolution: effective mass fractions per
// direction (sum over kept modes of L^2 over the sum over all modes), the highest kept and the
// first neglected frequency; lumped (M_ib = 0) and coupled mass (M_ib != 0).
TEST(CraigBampton, TruncationReportMatchesDenseReference) {
  for (const bool coupled : {false, true})
    for (const bool block : {false, true}) {
      const fem::Model m = box_frame(coupled);
      const se::Superelement s = reduce_to_superelement(m, options({1, 7}, 4, block));
      const auto ref = fixed_interface_reference(m, {1, 7}, s.p_OBo);
      for (int k = 0; k < 4; ++k)
        EXPECT_NEAR(s.mode_frequencies_hz(k) / reduction::eigenvalue_to_hz(ref.modes.lambda(k)), 1.0, 1e-9);
      EXPECT_NEAR(s.truncation.max_kept_hz, reduction::eigenvalue_to_hz(ref.modes.lambda(3)),
                  1e-9 * s.truncation.max_kept_hz);
      EXPECT_NEAR(s.truncation.first_neglected_hz, reduction::eigenvalue_to_hz(ref.modes.lambda(4)),
                  1e-9 * s.truncation.first_neglected_hz);
      for (int d = 0; d < 6; ++d) {
        const double kept = ref.L.col(d).head(4).squaredNorm(), total = ref.L.col(d).squaredNorm();
        EXPECT_NEAR(s.truncation.effective_mass_fraction[static_cast<std::size_t>(d)], kept / total, 1e-9)
            << "direction " << d << (coupled ? " (coupled mass)" : "") << (block ? " (block Lanczos)" : "");
      }
      const se::Superelement all = reduce_to_superelement(m, options({1, 7}, 100000, block));
      for (double f : all.truncation.effective_mass_fraction) EXPECT_NEAR(f, 1.0, 1e-9);
      EXPECT_EQ(all.truncation.first_neglected_hz, 0.0);
      EXPECT_EQ(all.num_modes, ref.modes.lambda.size());
    }
}

// --fmax: all fixed-interface modes up to the limit, the next one reported as the first neglected.
TEST(CraigBampton, FrequencyLimitKeepsModesUpToIt) {
  for (const bool block : {false, true}) {
    const fem::Model m = box_frame();
    SuperelementOptions o = options({1, 7}, 0, block);
    const se::Superelement four = reduce_to_superelement(m, options({1, 7}, 5));
    o.modes.modes.reset();
    o.modes.fmax_hz = 0.5 * (four.mode_frequencies_hz(3) + four.mode_frequencies_hz(4));
    const se::Superelement s = reduce_to_superelement(m, o);
    ASSERT_EQ(s.num_modes, 4);
    EXPECT_NEAR(s.truncation.first_neglected_hz / four.mode_frequencies_hz(4), 1.0, 1e-9);
    EXPECT_LE(s.truncation.max_kept_hz, *o.modes.fmax_hz);
    EXPECT_LT(max_abs(s.K - four.K.topLeftCorner(6 * 2 + 4, 6 * 2 + 4)), 1e-9 * max_abs(s.K));
  }
}

// The generic reduction on the f-set, boundary given dof by dof: constraint modes are the static
// response to unit boundary displacements (identity on b, interior in equilibrium), raw; the
// fixed-interface modes are M-orthonormal and K-orthogonal to the constraint modes.
TEST(CraigBampton, ConstraintModesAreStaticAndRaw) {
  const fem::Model m = box_frame();
  const auto d = cbtest::dense_system(m);
  // Grid 1 x y z, grid 2 y z, grid 4 z (a statically determinate support) and grid 5's rotation about x,
  // in an order that is not the f-set order (f-dof of grid index i, component c: 6 i + c - 1).
  const std::vector<Eigen::Index> boundary = {7, 0, 1, 2, 27, 8, 20};
  for (const Eigen::Index block_min : {Eigen::Index{2000}, Eigen::Index{0}}) {
    reduction::CraigBamptonOptions o;
    o.modes = 6;
    o.block_lanczos_min_size = block_min;
    const reduction::CraigBamptonBasis cb = reduction::craig_bampton(d.c.K_ff, d.c.M_ff, boundary, o);
    EXPECT_EQ(cb.stats.block_solves > 0, block_min == 0);
    const auto nb = static_cast<Eigen::Index>(boundary.size());
    for (Eigen::Index k = 0; k < nb; ++k)
      for (Eigen::Index j = 0; j < nb; ++j)
        EXPECT_EQ(cb.Psi(boundary[static_cast<std::size_t>(j)], k), j == k ? 1.0 : 0.0);
    const Eigen::MatrixXd KPsi = d.K * cb.Psi;
    for (Eigen::Index f : cb.interior) EXPECT_LT(KPsi.row(f).cwiseAbs().maxCoeff(), 1e-9 * max_abs(d.K));
    EXPECT_LT(max_abs(cb.Psi.transpose() * KPsi - cb.K.topLeftCorner(nb, nb)), 1e-9 * max_abs(cb.K));
    EXPECT_LT(max_abs(cb.Phi.transpose() * d.M * cb.Phi - Eigen::MatrixXd::Identity(6, 6)), 1e-10);
    EXPECT_LT(max_abs(cb.Phi.transpose() * d.K * cb.Phi - Eigen::MatrixXd(cb.eigenvalues.asDiagonal())),
              1e-9 * cb.eigenvalues.maxCoeff());
    EXPECT_LT(max_abs(cb.Psi.transpose() * d.K * cb.Phi), 1e-9 * max_abs(d.K));
    EXPECT_LT(max_abs(cb.Phi.transpose() * d.M * cb.Psi - cb.M.bottomLeftCorner(6, nb)),
              1e-12 * max_abs(d.M) * d.M.rows());
    for (Eigen::Index f : boundary) EXPECT_EQ(cb.Phi.row(f).cwiseAbs().maxCoeff(), 0.0);
  }
}

// Default frame node: the free, non-interface grid nearest the centre of mass.
TEST(CraigBampton, DefaultFrameNodeIsNearestTheCentreOfMass) {
  const fem::Model m = box_frame();
  const se::Superelement s = reduce_to_superelement(m, options({1, 7}, 0));
  const Eigen::Vector3d cg = s.p_OBo + s.p_BoCm_B;
  double best = 1e300;
  int id = 0;
  for (const auto& g : m.grids)
    if (g.id != 1 && g.id != 7 && g.id != 30 && (g.x_basic - cg).norm() < best) {
      best = (g.x_basic - cg).norm();
      id = g.id;
    }
  EXPECT_EQ(s.frame_node_id, id);
  SuperelementOptions o = options({1, 7}, 0);
  o.frame_node = 13;
  EXPECT_EQ(reduce_to_superelement(m, o).frame_node_id, 13);
}

void expect_input_error(const fem::Model& m, const SuperelementOptions& o, const std::vector<std::string>& parts) {
  try {
    reduce_to_superelement(m, o);
    ADD_FAILURE() << "no error";
  } catch (const InputError& e) {
    for (const auto& p : parts)
      EXPECT_NE(std::string(e.what()).find(p), std::string::npos) << e.what() << "\nlacks: " << p;
  }
}

TEST(CraigBampton, BadInterfaceAndFrameNodesAreInputErrors) {
  fem::Model m = box_frame();
  expect_input_error(m, options({1, 99}, 0), {"interface node 99", "no GRID 99"});
  expect_input_error(m, options({1, 30}, 0), {"interface node 30", "123456 depend on RBE2 401"});
  expect_input_error(m, options({1, 7, 1}, 0), {"interface node 1", "listed twice"});
  SuperelementOptions o = options({1, 7}, 0);
  o.frame_node = 7;
  expect_input_error(m, o, {"frame node 7", "is an interface node"});
  o.frame_node = 30;
  expect_input_error(m, o, {"frame node 30", "RBE2 401"});
  fem::test::add_spc1(m, 5, fem::test::mask("456"), 2);
  m.case_control.global.spc = 5;
  expect_input_error(m, options({2, 7}, 0), {"interface node 2", "components 456", "SPC set 5"});
}

TEST(CraigBampton, InteriorNotHeldByTheInterfaceIsAnInputError) {
  fem::Model m = box_frame();
  fem::test::add_grid(m, 40, 2.0, 0, 0);
  fem::test::add_grid(m, 41, 2.5, 0, 0);
  fem::test::add_cbar(m, 500, 1, 40, 41, Eigen::Vector3d(0, 0, 1));
  fem::test::finalize_for_test(m);
  expect_input_error(m, options({1, 7}, 0), {"has no stiffness", "connected to no interface node"});
}

}  // namespace
}  // namespace seflex
