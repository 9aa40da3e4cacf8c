// The spin-up beam of Simo and Vu-Quoc (1986) as ONE superelement (hub and tip interfaces, reduced by
// reduction::reduce_to_superelement from 20 CBARs) with and without geometric stiffening
// (docs/geometric-stiffening.md), against the converged nonlinear reference of
// bench/references/spinup_beam.py (a corotational beam of 80 elements, generalised-alpha, dt 1 ms; its
// mesh and step convergence is 0.02 % of the peak: tests/data/mbd/spinup_beam_reference.csv and
// spinup_beam_12rads_reference.csv). The check: the tip deflection history within 3 % of its peak,
// no runaway at 12 rad/s; and the axial tip displacement (foreshortening) within 3 % of its peak. Also
// the rank of the beam's invariants, which the element keeps as a basis of three matrices.
#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <fstream>
#include <sstream>

#include "fem_models.hpp"
#include "mbd_models.hpp"
#include "seflex/mbd/bodies/aic_element.hpp"
#include "seflex/mbd/ffrf/ffrf.hpp"
#include "seflex/mbd/forces/drive_profile.hpp"
#include "seflex/mbd/solvers/integrator.hpp"
#include "seflex/reduction/craig_bampton_superelement.hpp"

using namespace seflex;
using namespace seflex::mbd;
using Eigen::Matrix3d;
using Eigen::Vector3d;

namespace {

constexpr double kL = 10.0;

/// The beam of the benchmark: EI = 1.4e4 N m^2 in both planes, EA = 2.8e7 N, rho A = 1.2 kg/m, no
/// rotary inertia in bending (as the reference).
se::Superelement beam_superelement(int elements, int modes) {
  fem::Model m;
  for (int i = 0; i <= elements; ++i) test::add_grid(m, i + 1, kL * i / elements, 0, 0);
  test::add_mat1(m, 1, 2.8e9, 0.3, 120.0);
  test::add_pbar(m, 1, 1, 1e-2, 5e-6, 5e-6, 1e-5);
  for (int i = 0; i < elements; ++i) test::add_cbar(m, i + 1, 1, i + 1, i + 2, {0, 0, 1});
  // CBAR mass has no torsional inertia; the twist of the tip needs some (rho J per length, lumped).
  for (int i = 0; i <= elements; ++i)
    fem::test::add_conm2(m, 1000 + i, i + 1, 0.0).I11 = 120.0 * 1e-5 * kL / elements * (i == 0 || i == elements ? 0.5 : 1.0);
  test::finalize_for_test(m);
  reduction::SuperelementOptions o;
  o.interface_ids = {1, elements + 1};
  o.modes.modes = modes;
  o.name = "beam";
  return reduction::reduce_to_superelement(m, o);
}

using History = test::HubFrameTip;

History spin_up(const se::Superelement& s, bool stiffening, double rate, double t_end, bool ffrf = false) {
  ModelBuilder mb;
  const auto sei = mb.add_superelement(s);
  const auto g = mb.add_ground("hub axis", Pose{});
  HingeOptions ho;
  ho.drive = [rate](double t) { return spin_up_drive(rate, 15.0, t); };
  const auto h = mb.add_hinge("hub", g, Vector3d::UnitZ(), ho);
  const auto tip = mb.add_node("tip", Pose{Matrix3d::Identity(), Vector3d(kL, 0, 0)});
  FlexibleBodyOptions fo;
  fo.inertia = InertiaModel::Full;
  fo.geometric_stiffening = stiffening;
  mb.add_flexible_body("beam", sei, {mb.hinge_child(h), tip}, Pose{Matrix3d::Identity(), s.p_OBo}, fo);
  const Model model = mb.build();
  State st = initial_state(model);
  Data data(model);
  IntegratorSettings is;
  is.t_end = t_end;
  is.h_initial = 1e-3;
  is.rho_inf = 0.9;
  is.tol_position = is.tol_angle = 1e-6;
  is.output_interval = 0.05;
  test::Recorder rec;
  if (ffrf)
    simulate_ffrf(model, is, FfrfOptions{}, &rec);
  else
    simulate(model, st, data, is, &rec);
  return test::tip_in_hub_frame(rec, kL);
}

/// t -> v of a reference file (lines "t, v, u, torque"; '#' comments).
History reference(const std::string& name) {
  std::ifstream in(std::string(SEFLEX_TEST_DATA) + "/mbd/" + name);
  EXPECT_TRUE(in.good()) << name;
  History r;
  for (std::string line; std::getline(in, line);) {
    if (line.empty() || line[0] == '#') continue;
    std::istringstream f(line);
    std::string a, b, c;
    std::getline(f, a, ',');
    std::getline(f, b, ',');
    std::getline(f, c, ',');
    r.t.push_back(std::stod(a));
    r.v.push_back(std::stod(b));
    r.u.push_back(std::stod(c));
  }
  EXPECT_GT(r.t.size(), 100u) << name;  // 0 to 30 s every 0.05 s
  return r;
}

/// Largest |v - v_ref| (axial: |u - u_ref|) over the common output times, and the reference's peak |v| (|u|).
/// Every output time of the run must be a time of the reference (both every 0.05 s, the run's within the
/// reference's 0..30 s): otherwise nothing would be compared and the error would read 0.
std::pair<double, double> deviation(const History& h, const History& ref, bool axial = false) {
  const auto& x = axial ? h.u : h.v;
  const auto& xr = axial ? ref.u : ref.v;
  double err = 0, peak = 0;
  std::size_t k = 0, compared = 0;
  for (std::size_t i = 0; i < h.t.size(); ++i) {
    while (k < ref.t.size() && ref.t[k] < h.t[i] - 1e-9) ++k;
    if (k == ref.t.size()) break;
    if (std::abs(ref.t[k] - h.t[i]) > 1e-9) continue;
    err = std::max(err, std::abs(x[i] - xr[k]));
    ++compared;
  }
  EXPECT_GT(h.t.size(), 100u);  // at least 5 s of output
  EXPECT_EQ(compared, h.t.size()) << "output times of the run not found in the reference";
  for (double v : xr) peak = std::max(peak, std::abs(v));
  return {err, peak};
}

// The rank of a straight beam's invariants (docs/geometric-stiffening.md, "The rank of the
// invariants"). A bar's differential stiffness is that of its axial force alone
// (fem/src/element_bar_kg.cpp), and the beam's axial force has one of three shapes along x: constant
// (the interface cases' stretch), linear (the axial acceleration) and quadratic (the centrifugal
// component W_xx). The other 21 cases bend or twist the beam or move it rigidly. The element keeps
// 3 basis matrices and reproduces each of the 24 stored cases to 1e-12 of the largest of its group.
TEST(SpinupStiffening, StraightBeamInvariantsHaveRankThree) {
  const se::Superelement s = beam_superelement(20, 6);
  const AicElement e = make_aic_element(s);
  ASSERT_TRUE(e.has_stiffening());
  EXPECT_EQ(e.G_coef.rows(), 3);
  const Eigen::Index n = e.n;
  for (int group = 0; group < 2; ++group) {
    const auto& cases = group == 0 ? std::vector<Eigen::MatrixXd>(s.stiffening.inertia.begin(), s.stiffening.inertia.end())
                                   : s.stiffening.interface;
    double largest = 0;
    for (const auto& G : cases) largest = std::max(largest, G.norm());
    ASSERT_GT(largest, 0.0);
    for (std::size_t c = 0; c < cases.size(); ++c) {
      const int col = group == 0 ? static_cast<int>(c) : 12 + static_cast<int>(c);
      Eigen::MatrixXd back = Eigen::MatrixXd::Zero(n, n);
      for (Eigen::Index i = 0; i < e.G_coef.rows(); ++i) back += e.G_coef(i, col) * e.G_basis.middleCols(i * n, n);
      EXPECT_LE((back - cases[c]).norm(), 1e-12 * largest) << (group == 0 ? "inertia case " : "interface case ") << c;
    }
  }
}

TEST(SpinupStiffening, OneSuperelementFollowsTheNonlinearBeam) {
  const se::Superelement s = beam_superelement(20, 6);
  ASSERT_TRUE(s.stiffening.present());
  const History ref = reference("spinup_beam_reference.csv");
  const History on = spin_up(s, true, 6.0, 20.0);
  const History off = spin_up(s, false, 6.0, 20.0);
  const auto [e_on, peak] = deviation(on, ref);
  const auto [e_off, peak_off] = deviation(off, ref);
  std::printf("spin-up, one superelement: tip lag off the nonlinear beam by %.4f m with stiffening, %.4f m without "
              "(peak %.4f m)\n", e_on, e_off, peak);
  const auto [u_on, u_peak] = deviation(on, ref, true);
  const auto [u_off, u_peak_off] = deviation(off, ref, true);
  std::printf("  axial tip displacement (the bending's foreshortening): off by %.5f m with stiffening, %.5f m without "
              "(peak %.5f m)\n", u_on, u_off, u_peak);
  EXPECT_LT(e_on, 0.03 * peak);
  EXPECT_GT(e_off, 0.10 * peak);  // the defect the stiffening removes (issue 15: -0.75 m against -0.57 m)
  // The tip pulls in as the beam bends (0.019 m at the peak): the condensed quartic term's interface
  // shortening s = Kbb^+ b (docs/geometric-stiffening.md); a linear body has none.
  EXPECT_LT(u_on, 0.03 * u_peak);
  EXPECT_GT(u_off, 0.5 * u_peak);
}

// The FFRF-LM baseline with the same invariants (its frame accelerations and spin are coordinates, so
// the load factors come straight from them): the same check.
TEST(SpinupStiffening, FfrfLmOneSuperelementFollowsTheNonlinearBeam) {
  const se::Superelement s = beam_superelement(20, 6);
  const History ref = reference("spinup_beam_reference.csv");
  const History on = spin_up(s, true, 6.0, 20.0, true);
  const History off = spin_up(s, false, 6.0, 10.0, true);  // past the peak: enough to see the defect
  const auto [e_on, peak] = deviation(on, ref);
  const auto [e_off, peak_off] = deviation(off, ref);
  std::printf("spin-up, one superelement, FFRF-LM: tip lag off the nonlinear beam by %.4f m with stiffening, %.4f m "
              "without (peak %.4f m)\n", e_on, e_off, peak);
  EXPECT_LT(e_on, 0.03 * peak);
  EXPECT_GT(e_off, 0.10 * peak);
}

TEST(SpinupStiffening, NoRunawayAtTwelveRadiansPerSecond) {
  const se::Superelement s = beam_superelement(20, 6);
  const History ref = reference("spinup_beam_12rads_reference.csv");
  const History on = spin_up(s, true, 12.0, 20.0);
  const auto [err, peak] = deviation(on, ref);
  ASSERT_FALSE(on.t.empty());
  ASSERT_NEAR(on.t.back(), 20.0, 1e-9);  // 5 s at the constant rate checked below
  double after = 0;
  for (std::size_t i = 0; i < on.t.size(); ++i)
    if (on.t[i] >= 15.0) after = std::max(after, std::abs(on.v[i]));
  std::printf("spin-up to 12 rad/s, one superelement with stiffening: off the nonlinear beam by %.4f m (peak %.4f m), "
              "largest |v| after the ramp %.4f m\n", err, peak, after);
  EXPECT_LT(err, 0.03 * peak);
  EXPECT_LT(after, 0.02);
}

}  // namespace
