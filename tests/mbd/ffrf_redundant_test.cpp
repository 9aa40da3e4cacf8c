// Redundant constraints of the multiplier baselines (docs/ffrf.md, "Redundant constraints"): a
// parallelogram four-bar hanging under gravity, its crank on a pair of coaxial hinges. Modelled in 3D
// with revolute joints it has 3 redundant equations from the planar loop and 5 from the hinge pair;
// rigid-LM must find and name them and move as the one-degree-of-freedom closed form.
#include <gtest/gtest.h>

#include <cmath>

#include "mbd_models.hpp"
#include "seflex/common/error.hpp"
#include "seflex/mbd/ffrf/ffrf.hpp"
#include "seflex/mbd/solvers/integrator.hpp"

using namespace seflex;
using namespace seflex::mbd;
using Eigen::Matrix3d;
using Eigen::Vector3d;

namespace {

constexpr double kA = 0.4;      // crank and rocker length [m]
constexpr double kD = 0.6;      // ground and coupler length [m]
constexpr double kH = 0.05;     // half the distance between the crank's two coaxial hinges [m]
constexpr double kTheta0 = 1.0; // initial crank angle from the downward vertical [rad]
constexpr int kNe = 4;          // beam elements per link

test::BeamSection section() {
  test::BeamSection s;
  s.A = 4e-4;
  s.Iy = s.Iz = 2e-8;
  s.J = 4e-8;
  return s;
}

/// Crank: a cross beam along z through the pivot A (its ends A1, A2 carry the hinge pair) and the arm
/// from A to B along u. FE coordinates relative to A (the frame node), world axes.
test::FrameFE crank_fe(const Vector3d& u) {
  test::FrameFE fe;
  fe.section = section();
  fe.consistent_mass = true;
  fe.pts = {Vector3d(0, 0, -kH), Vector3d::Zero(), Vector3d(0, 0, kH)};
  fe.elements = {{0, 1}, {1, 2}};
  for (int i = 1; i <= kNe; ++i) {
    fe.pts.push_back(u * (kA * i / kNe));
    fe.elements.emplace_back(i == 1 ? 1 : 2 + i - 1, 2 + i);
  }
  return fe;
}

struct FourBar {
  Model model;
  double J = 0.0;  ///< moment of inertia of the mechanism about the crank angle [kg m^2]
  double S = 0.0;  ///< g S sin(theta): the gravity moment [kg m]
};

/// Mass and first moment about `origin` of a FE model (its rigid-body mass matrix), and the
/// second moment about the z axis through it.
struct RigidProps {
  double m = 0.0, Jz = 0.0;
  Vector3d first = Vector3d::Zero();
};
RigidProps rigid_props(test::FrameFE& fe, const Vector3d& origin) {
  test::assemble(fe);
  const Eigen::MatrixXd P = test::fe_rigid_modes(fe, origin);
  const Eigen::MatrixXd Mr = P.transpose() * fe.M * P;
  RigidProps r;
  r.m = Mr(0, 0);
  r.Jz = Mr(5, 5);
  // Translation x rotation block: M_tr = m [r_cm]x^T, so m r_cm = (M(2,4) ... ): read it off.
  r.first = Vector3d(Mr(1, 5), -Mr(0, 5), 0.0);  // m (x_cm, y_cm) in the plane: M(1,5) = m x, M(0,5) = -m y
  return r;
}

FourBar four_bar() {
  const Vector3d u(std::sin(kTheta0), -std::cos(kTheta0), 0.0);
  const Vector3d A = Vector3d::Zero(), B = A + kA * u, C = B + Vector3d(kD, 0, 0), D = A + Vector3d(kD, 0, 0);
  test::FrameFE crank = crank_fe(u);
  test::FrameFE coupler = test::straight_beam(kD, kNe, section());
  test::FrameFE rocker = test::straight_beam(kA, kNe, section(), -u);
  const Matrix3d I = Matrix3d::Identity();
  ModelBuilder mb;
  const auto se_crank = mb.add_superelement(test::craig_bampton(crank, {0, 2, 2 + kNe}, 1, 2, "crank"));
  const auto se_coupler = mb.add_superelement(test::craig_bampton(coupler, {0, kNe}, kNe / 2, 2, "coupler"));
  const auto se_rocker = mb.add_superelement(test::craig_bampton(rocker, {0, kNe}, kNe / 2, 2, "rocker"));
  const auto hA1 = mb.add_hinge("A1", mb.add_ground("ground A1", Pose{I, A - Vector3d(0, 0, kH)}), Vector3d::UnitZ());
  const auto hA2 = mb.add_hinge("A2", mb.add_ground("ground A2", Pose{I, A + Vector3d(0, 0, kH)}), Vector3d::UnitZ());
  const auto nB = mb.add_node("B", Pose{I, B});
  mb.add_flexible_body("crank", se_crank, {mb.hinge_child(hA1), mb.hinge_child(hA2), nB}, Pose{I, A});
  const auto hB = mb.add_hinge("B", nB, Vector3d::UnitZ());
  const auto nC = mb.add_node("C", Pose{I, C});
  mb.add_flexible_body("coupler", se_coupler, {mb.hinge_child(hB), nC}, Pose{I, B + coupler.pts[kNe / 2]});
  const auto hC = mb.add_hinge("C", nC, Vector3d::UnitZ());
  const auto hD = mb.add_hinge("D", mb.add_ground("ground D", Pose{I, D}), Vector3d::UnitZ());
  mb.add_flexible_body("rocker", se_rocker, {mb.hinge_child(hC), mb.hinge_child(hD)}, Pose{I, C + rocker.pts[kNe / 2]});
  mb.set_gravity(Vector3d(0, -9.81, 0));
  FourBar out{mb.build()};
  // The closed form: crank and rocker turn by the same angle about A and D, the coupler translates on
  // a circle of radius kA. J theta'' = -g (S_y sin + ...): with theta from the downward vertical, the
  // potential is g sum m y_cm(theta), each link's first moment turning with theta.
  const RigidProps pc = rigid_props(crank, Vector3d::Zero()), pr = rigid_props(rocker, -kA * u);  // about A and D
  test::assemble(coupler);
  const double m_coupler = (test::fe_rigid_modes(coupler, Vector3d::Zero()).transpose() * coupler.M *
                            test::fe_rigid_modes(coupler, Vector3d::Zero()))(0, 0);
  out.J = pc.Jz + pr.Jz + m_coupler * kA * kA;
  // First moments at theta0 about the pivots, along u (the arms are straight beams along u).
  const Vector3d first = pc.first + pr.first + m_coupler * kA * u;
  out.S = first.dot(u);  // the arms' centres of mass lie on u: |first| along u
  EXPECT_LT((first - out.S * u).norm(), 1e-12 * out.S);
  return out;
}

/// theta(t) of J theta'' = -g S sin(theta), theta(0) = kTheta0, at rest: RK4 with a step of 1e-5 s
/// (the error of 1e-4 s steps differs from it by 1e-12 rad: converged).
std::vector<double> closed_form(const FourBar& fb, const std::vector<double>& times) {
  const double k = 9.81 * fb.S / fb.J;
  auto f = [k](const Eigen::Vector2d& y) { return Eigen::Vector2d(y[1], -k * std::sin(y[0])); };
  Eigen::Vector2d y(kTheta0, 0.0);
  double t = 0.0;
  const double h = 1e-5;
  std::vector<double> out;
  for (double tt : times) {
    while (t < tt - 1e-12) {
      const double hh = std::min(h, tt - t);
      const Eigen::Vector2d k1 = f(y), k2 = f(y + 0.5 * hh * k1), k3 = f(y + 0.5 * hh * k2), k4 = f(y + hh * k3);
      y += hh / 6 * (k1 + 2 * k2 + 2 * k3 + k4);
      t += hh;
    }
    out.push_back(y[0]);
  }
  return out;
}

int hinge_index(const Model& m, const std::string& name) {
  for (std::size_t h = 0; h < m.hinges.size(); ++h)
    if (m.hinges[h].name == name) return static_cast<int>(h);
  return -1;
}

}  // namespace

// The 8 dependent equations, named: the second hinge of the pair loses its 3 translations and the 2
// rotations across its axis; the last joint of the planar loop (D) its translation along z and its
// rotations about x and y.
TEST(FfrfRedundant, FourBarRedundantEquationsFoundAndNamed) {
  const FourBar fb = four_bar();
  FfrfOptions o;
  o.rigid = true;
  const FfrfSystem sys = make_ffrf_system(fb.model, o);
  ASSERT_EQ(sys.num_multipliers(), 30);  // five joints, six equations each
  ASSERT_EQ(sys.num_coords, 3 * 6 + 5);  // three frames, five hinge angles: 23 - 22 = 1 dof
  ASSERT_EQ(sys.redundant.size(), 8u);
  const std::string text = describe_redundant(sys.redundant);
  std::printf("%s\n", text.c_str());
  EXPECT_EQ(text,
            "hinge 'A2': translation along x, y, z; rotation about (1, 0, 0), (0, 1, 0) | "
            "hinge 'D': translation along z; rotation about (1, 0, 0), (0, 1, 0)");
  // Without the removal the system is singular (the failure this replaces).
  o.remove_redundant = false;
  const FfrfSystem all = make_ffrf_system(fb.model, o);
  EXPECT_TRUE(all.redundant.empty());
  IntegratorSettings st;
  st.t_end = 0.01;
  EXPECT_THROW(simulate_ffrf(fb.model, st, o), ConvergenceError);
}

// The motion: crank, rocker and the redundant hinge against the closed form over one and a half
// swings. Measured at local error tolerance 1e-8: max |theta - theta_ref| = 2.1e-5 rad for the crank,
// the rocker and the coupler's two hinges (the integration error), 0 between the hinge pair (its
// angle follows from the kept rotation equation exactly); limits 5e-5 and 1e-12.
TEST(FfrfRedundant, FourBarRigidLmMovesAsTheClosedForm) {
  const FourBar fb = four_bar();
  IntegratorSettings st;
  st.t_end = 2.0;
  st.output_interval = 0.02;
  st.h_initial = 1e-4;
  st.tol_angle = st.tol_position = 1e-8;
  st.rho_inf = 0.9;
  FfrfOptions o;
  o.rigid = true;
  test::Recorder rec;
  const FfrfStats stats = simulate_ffrf(fb.model, st, o, &rec);
  EXPECT_EQ(stats.constraints, 22);
  std::vector<double> times;
  for (const auto& s : rec.samples) times.push_back(s.t);
  const std::vector<double> ref = closed_form(fb, times);
  const int a1 = hinge_index(fb.model, "A1"), a2 = hinge_index(fb.model, "A2"), b = hinge_index(fb.model, "B"),
            c = hinge_index(fb.model, "C"), d = hinge_index(fb.model, "D");
  double e_crank = 0.0, e_pair = 0.0, e_rocker = 0.0, e_coupler = 0.0, swing = 0.0;
  for (std::size_t k = 0; k < rec.samples.size(); ++k) {
    const auto& h = rec.samples[k].hinges;
    const double dtheta = ref[k] - kTheta0;
    swing = std::max(swing, std::abs(dtheta));
    e_crank = std::max(e_crank, std::abs(h[static_cast<std::size_t>(a1)].phi - dtheta));
    e_pair = std::max(e_pair, std::abs(h[static_cast<std::size_t>(a2)].phi - h[static_cast<std::size_t>(a1)].phi));
    e_rocker = std::max(e_rocker, std::abs(h[static_cast<std::size_t>(d)].phi - dtheta));
    // The coupler translates: it turns by -theta relative to the crank and by +theta into the rocker.
    e_coupler = std::max({e_coupler, std::abs(h[static_cast<std::size_t>(b)].phi + dtheta), std::abs(h[static_cast<std::size_t>(c)].phi - dtheta)});
  }
  std::printf("four-bar rigid-LM: swing %.3f rad; max error crank %.2e, hinge pair %.2e, rocker %.2e, coupler %.2e rad; "
              "%ld steps; drift %.1e m %.1e rad\n",
              swing, e_crank, e_pair, e_rocker, e_coupler, stats.run.steps, stats.drift_position, stats.drift_rotation);
  EXPECT_GT(swing, 1.9);  // swings through to about -theta0
  EXPECT_LT(e_crank, 5e-5);
  EXPECT_LT(e_rocker, 5e-5);
  EXPECT_LT(e_coupler, 5e-5);
  EXPECT_LT(e_pair, 1e-12);
}

// A flexible body is not a rigid one: with the links' modes (FFRF-LM) no equation of the hinge pair
// or the loop depends on the others (the cross beam bends, the links twist out of the plane), and
// none is removed.
TEST(FfrfRedundant, FlexibleFourBarKeepsEveryEquation) {
  const FourBar fb = four_bar();
  const FfrfSystem sys = make_ffrf_system(fb.model, FfrfOptions{});
  EXPECT_EQ(sys.num_multipliers(), 30);
  EXPECT_TRUE(sys.redundant.empty()) << describe_redundant(sys.redundant);
}
