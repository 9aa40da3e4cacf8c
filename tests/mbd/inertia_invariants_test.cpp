// The full inertia from the inertia invariants (docs/inertia-invariants.md) against the nodal-sum
// evaluation of formulation 2.4 it replaces (mbd::inertia_force_nodal, kept as the reference), on
// random large motions (|Omega| ~ 3 rad/s, elastic amplitude ~1e-3 of the body size, random modal
// coordinates) of: the demo's yoke and panel (meshes/, as scripts/demo.sh reduces them), the spin-up
// beam (bench/study/spinup_beam.bdf), a body with CONM2 offsets and products of inertia and
// consistent (COUPMASS) beam mass, and the test-only L-frame with internal modes.
// Force, mass, gyroscopic and configuration tangents and kinetic energy agree to 1e-10 relative.
// The one term the invariants leave out (the gyroscopic moment quadratic in the elastic rotation
// rates) is measured here against the whole force.
#include <gtest/gtest.h>

#include <cstdio>
#include <random>

#include "beam_superelement.hpp"
#include "seflex/common/so3.hpp"
#include "seflex/io/model_reader.hpp"
#include "seflex/mbd/bodies/aic_element.hpp"
#include "seflex/mbd/model.hpp"
#include "seflex/reduction/craig_bampton_superelement.hpp"
#include "test_support.hpp"

using namespace seflex;
using namespace seflex::mbd;
using Eigen::Matrix3d;
using Eigen::MatrixXd;
using Eigen::Vector3d;
using Eigen::VectorXd;

namespace {

se::Superelement reduce(const std::filesystem::path& deck, const std::vector<int>& interfaces, int modes) {
  const fem::Model model = io::read_model(deck);
  reduction::SuperelementOptions o;
  o.interface_ids = interfaces;
  o.modes.modes = modes;
  o.name = deck.stem().string();
  return reduction::reduce_to_superelement(model, o);
}

double rel(const MatrixXd& a, const MatrixXd& b) { return (a - b).norm() / std::max(b.norm(), 1e-300); }

struct Sizes {
  double worst = 0;            // largest relative difference invariants vs nodal
  double dropped_term = 0;     // |f(elastic gyro) - f(without)| / |f|
};

// Random states of body `s`; `omega` the angular-velocity scale, `amp` the elastic amplitude (m/m).
Sizes compare(const se::Superelement& s, double omega, double amp, int states = 6) {
  const AicElement e = make_aic_element(s);
  EXPECT_TRUE(e.inv.present());
  EXPECT_TRUE(e.has_fe_data);
  std::mt19937 rng(11);
  std::normal_distribution<double> nd;
  auto rvec = [&](double sc) -> Vector3d { return Vector3d(nd(rng), nd(rng), nd(rng)) * sc; };
  Sizes out;
  for (int k = 0; k < states; ++k) {
    const Matrix3d R_B = so3::exp(rvec(1.0));
    const Vector3d p_B = rvec(1.0);
    std::vector<Matrix3d> R_WI;
    std::vector<Vector3d> p_WI;
    for (int j = 0; j < e.N; ++j) {
      p_WI.push_back(p_B + R_B * (e.x[static_cast<std::size_t>(j)] + rvec(amp * e.length)));
      R_WI.push_back(R_B * so3::exp(rvec(amp)) * e.C[static_cast<std::size_t>(j)]);
    }
    VectorXd eta(e.m);
    for (int i = 0; i < e.m; ++i) eta[i] = amp * e.length * nd(rng) / std::max(e.eta_amplitude[i], 1e-12);
    AicKinematics kin;
    recover_frame(e, R_WI, p_WI, eta, FrameRecovery::Newton6, frame_guess(e, R_WI[0] , p_WI[0]), kin);
    // Velocities: a rigid rotation at ~omega plus elastic rates; accelerations random.
    const Vector3d Om = rvec(omega), vB = rvec(1.0);
    VectorXd v(e.n), a(e.n);
    for (int j = 0; j < e.N; ++j) {
      const Vector3d r = kin.frame.R_WB * (e.x[static_cast<std::size_t>(j)] + kin.xi.segment<3>(6 * j));
      v.segment<3>(6 * j) = vB + Om.cross(r) + rvec(omega * amp * e.length);
      v.segment<3>(6 * j + 3) = Om + rvec(omega * amp);
      a.segment<3>(6 * j) = rvec(1.0);
      a.segment<3>(6 * j + 3) = rvec(1.0);
    }
    for (int i = 0; i < e.m; ++i) {
      v[6 * e.N + i] = omega * amp * e.length * nd(rng) / std::max(e.eta_amplitude[i], 1e-12);
      a[6 * e.N + i] = nd(rng) / std::max(e.eta_amplitude[i], 1e-12);
    }
    InertiaResult inv, ref, with_gyro;
    inertia_force(e, kin, InertiaModel::Full, v, a, true, inv);
    inertia_force_nodal(e, kin, v, a, true, false, ref);
    inertia_force_nodal(e, kin, v, a, false, true, with_gyro);
    for (double d : {rel(inv.f, ref.f), rel(inv.Mt, ref.Mt), rel(inv.Ct, ref.Ct), rel(inv.Kt, ref.Kt),
                     std::abs(inv.kinetic - ref.kinetic) / ref.kinetic})
      out.worst = std::max(out.worst, d);
    EXPECT_LT(rel(inv.f, ref.f), 1e-10) << s.name << " state " << k;
    EXPECT_LT(rel(inv.Mt, ref.Mt), 1e-10) << s.name << " state " << k;
    EXPECT_LT(rel(inv.Ct, ref.Ct), 1e-10) << s.name << " state " << k;
    EXPECT_LT(rel(inv.Kt, ref.Kt), 1e-10) << s.name << " state " << k;
    EXPECT_LT(std::abs(inv.kinetic - ref.kinetic), 1e-10 * ref.kinetic) << s.name << " state " << k;
    // Without the velocity tangent: the same force, mass and configuration tangent, no Ct.
    InertiaResult cheap;
    AicWorkspace ws;
    inertia_force(e, kin, InertiaModel::Full, v, a, InertiaMatrices::NoVelocityTangent, cheap, ws);
    EXPECT_TRUE(inv.has_Ct);
    EXPECT_FALSE(cheap.has_Ct);
    EXPECT_EQ(rel(cheap.f, inv.f), 0.0) << s.name << " state " << k;
    EXPECT_EQ(rel(cheap.Mt, inv.Mt), 0.0) << s.name << " state " << k;
    EXPECT_EQ(rel(cheap.Kt, inv.Kt), 0.0) << s.name << " state " << k;
    out.dropped_term = std::max(out.dropped_term, rel(with_gyro.f, ref.f));
  }
  std::printf("%-12s n = %3d: invariants vs nodal sums %.2e; dropped elastic-gyro term %.2e of the force\n",
              s.name.c_str(), s.size(), out.worst, out.dropped_term);
  return out;
}

}  // namespace

TEST(InertiaInvariants, DemoYokeAndPanelMatchNodalSums) {
  const auto dir = test::source_dir() / "meshes";
  compare(reduce(dir / "yoke.bdf", {1, 3, 4}, 10), 3.0, 1e-3);
  compare(reduce(dir / "panel.bdf", {1, 2, 3, 4}, 10), 3.0, 1e-3);
  compare(reduce(dir / "panel.bdf", {5, 6}, 0), 3.0, 1e-3);
}

TEST(InertiaInvariants, SpinupBeamMatchesNodalSums) {
  compare(reduce(test::source_dir() / "bench" / "study" / "spinup_beam.bdf", {1, 11}, 6), 6.0, 1e-2);
}

TEST(InertiaInvariants, ConmOffsetsAndCoupledMassMatchNodalSums) {
  test::TempDir dir;
  // A 2 m CBAR cantilever-like free body with consistent mass (COUPMASS) and two CONM2 with offsets,
  // products of inertia and a coordinate system: translation-rotation coupling in M_fe.
  const auto deck = dir.write("conm.bdf", R"(SOL 103
CEND
BEGIN BULK
PARAM,COUPMASS,1
GRID,1,,0.0,0.0,0.0
GRID,2,,0.5,0.0,0.0
GRID,3,,1.0,0.1,0.0
GRID,4,,1.5,0.1,0.05
GRID,5,,2.0,0.0,0.0
CBAR,1,10,1,2,0.0,0.0,1.0
CBAR,2,10,2,3,0.0,0.0,1.0
CBAR,3,10,3,4,0.0,0.0,1.0
CBAR,4,10,4,5,0.0,0.0,1.0
PBAR,10,1,1.0E-3,2.0E-7,3.0E-7,4.0E-7
MAT1,1,7.0E10,,0.3,2700.0
CORD2R,7,,0.0,0.0,0.0,0.0,0.3,1.0,+CR
+CR,1.0,0.2,0.0
CONM2,100,2,,1.5,0.05,-0.02,0.03,,+C1
+C1,0.02,0.001,0.015,-0.002,0.003,0.01
CONM2,101,4,7,0.8,0.1,0.0,-0.04,,+C2
+C2,0.004,0.0,0.006,0.001,0.0,0.005
ENDDATA
)");
  compare(reduce(deck, {1, 5}, 4), 3.0, 1e-3);
}

TEST(InertiaInvariants, LFrameWithInternalModesAndRotaryInertiaMatchesNodalSums) {
  auto fe = test::l_frame();
  fe.consistent_mass = true;
  for (int i = 0; i < fe.nodes(); ++i) fe.point_masses.push_back(0.2 + 0.1 * i);
  const se::Superelement s = test::craig_bampton(fe, {0, 8, 6}, 3, 3, "lframe");
  ASSERT_FALSE(s.invariants.present());  // the test builder predates them: make_aic_element computes them
  compare(s, 3.0, 1e-3);
}

TEST(InertiaInvariants, RefusedWithoutInvariantsOrMesh) {
  auto fe = test::l_frame();
  se::Superelement s = test::craig_bampton(fe, {0, 8, 6}, 3, 0, "lframe");
  s.recovery.resize(0, 0);
  s.M_fe.resize(0, 0);
  s.fe_node_ids.clear();
  s.p_BoI_B.resize(3, 0);
  s.cells.clear();
  const AicElement e = make_aic_element(s);
  EXPECT_FALSE(e.inv.present());
  const auto invariants_error = [](const se::Superelement& body) -> std::string {
    try {
      se::compute_inertia_invariants(body);
    } catch (const InputError& err) {
      return err.what();
    }
    ADD_FAILURE() << "no InputError";
    return "";
  };
  EXPECT_EQ(invariants_error(s), "superelement 'lframe': the inertia invariants need the recovery matrix (6 x 0 FE node "
                                 "rows by " + std::to_string(s.size()) + " columns)");
  se::Superelement no_mass = test::craig_bampton(fe, {0, 8, 6}, 3, 0, "lframe");
  no_mass.M_fe.resize(0, 0);
  EXPECT_EQ(invariants_error(no_mass), "superelement 'lframe': the inertia invariants need the FE mass matrix M_fe (" +
                                           std::to_string(6 * no_mass.p_BoI_B.cols()) + " square)");
  ModelBuilder mb;
  const auto sei = mb.add_superelement(s);
  std::vector<NodeIndex> nodes;
  for (int j = 0; j < 3; ++j) nodes.push_back(mb.add_node("n" + std::to_string(j), Pose{Matrix3d::Identity(), e.x[j]}));
  FlexibleBodyOptions fo;
  fo.inertia = InertiaModel::Full;
  try {
    mb.add_flexible_body("arm", sei, nodes, Pose{}, fo);
    ADD_FAILURE() << "a full-inertia body without invariants or mesh was accepted";
  } catch (const InputError& err) {
    EXPECT_NE(std::string(err.what()).find("flexible body 'arm': full inertia needs the inertia invariants of superelement 'lframe'"),
              std::string::npos) << err.what();
    EXPECT_NE(std::string(err.what()).find("reduce it again"), std::string::npos) << err.what();
  }
}
