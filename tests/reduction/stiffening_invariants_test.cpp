// Geometric-stiffness invariants of a superelement (reduction/stiffening.hpp, docs/geometric-stiffening.md)
// against the classic rotating cantilever: a uniform Euler-Bernoulli beam clamped to a hub of radius 0
// turning at Omega. Its flapwise (out of the plane of rotation) bending frequencies, linearised about the
// steady spin, are those of M eta'' + (K + K_G(Omega)) eta = 0, K_G the stiffness of the centrifugal tension
// rho A Omega^2 (L^2 - x^2) / 2 (no softening term: the centrifugal field has no component along the axis of
// rotation). Reference: the dimensionless frequencies omega sqrt(rho A L^4 / EI) against the dimensionless
// speed gamma = Omega sqrt(rho A L^4 / EI) in tests/data/mbd/rotating_cantilever_frequencies.csv, computed
// independently of seflex by bench/references/rotating_cantilever.py with the Frobenius power series of
// Wright, Smith, Thresher and Wang, "Vibration modes of centrifugally stiffened beams", J. Appl. Mech. 49
// (1982) 197-202 (roots to 1e-13; a converged Hermite FE agrees to 1.3e-7); at gamma = 0 they equal the
// published clamped-free values (Thomson, Theory of Vibration with Applications, app. D.3). The issue's
// check: within 1 % up to gamma = 10 with one superelement. Also the invariants' own identities: symmetry,
// the interface cases of a body held at one node vanish, and the signs of the axial load cases.
#include <gtest/gtest.h>

#include <Eigen/Eigenvalues>
#include <array>
#include <cmath>
#include <fstream>
#include <sstream>
#include <string>
#include <vector>

#include "fem_models.hpp"
#include "seflex/common/so3.hpp"
#include "seflex/fem/assembly.hpp"
#include "seflex/fem/constraints.hpp"
#include "seflex/reduction/craig_bampton_superelement.hpp"

namespace seflex::reduction {
namespace {

// The spin-up beam of Simo and Vu-Quoc: L = 10 m, EI = 1.4e4 N m^2 (flapwise, plane 2), EA = 2.8e7 N,
// rho A = 1.2 kg/m; in-plane bending 4 times stiffer so that the two families of modes stay apart.
constexpr double kL = 10.0, kA = 1e-2, kE = 2.8e9, kRho = 120.0, kIflap = 5e-6, kIlag = 2e-5;

fem::Model cantilever(int elements) {
  fem::Model m;
  for (int i = 0; i <= elements; ++i) test::add_grid(m, i + 1, kL * i / elements, 0, 0);
  test::add_mat1(m, 1, kE, 0.3, kRho);
  test::add_pbar(m, 1, 1, kA, kIlag, kIflap, 1e-5);
  for (int i = 0; i < elements; ++i) test::add_cbar(m, i + 1, 1, i + 1, i + 2, {0, 1, 0});
  test::finalize_for_test(m);
  return m;
}

/// Rows gamma, flap1, flap2, flap3 of the reference table (comment lines start with '#').
std::vector<std::array<double, 4>> reference_table() {
  std::ifstream in(std::string(SEFLEX_TEST_DATA) + "/mbd/rotating_cantilever_frequencies.csv");
  EXPECT_TRUE(in.good());
  std::vector<std::array<double, 4>> rows;
  std::string line;
  bool header = true;
  while (std::getline(in, line)) {
    if (line.empty() || line[0] == '#') continue;
    if (header) { header = false; continue; }
    std::istringstream fields(line);
    std::array<double, 4> r{};
    std::string f;
    for (double& v : r) {
      std::getline(fields, f, ',');
      v = std::stod(f);
    }
    rows.push_back(r);
  }
  return rows;
}

struct Reduced {
  se::Superelement s;
  double scale = 0;  // sqrt(rho A L^4 / EI)
};

Reduced reduce_cantilever(int elements, int modes) {
  const fem::Model m = cantilever(elements);
  SuperelementOptions o;
  o.interface_ids = {1};
  o.modes.modes = modes;
  o.name = "cantilever";
  Reduced r;
  r.s = reduce_to_superelement(m, o);
  r.scale = std::sqrt(kRho * kA * std::pow(kL, 4) / (kE * kIflap));
  return r;
}

/// Flapwise dimensionless frequencies at gamma with the hub node held: the modal block of
/// K + sum_c lambda_c G_c, lambda = [a_o; 0; w_s], W = Om~ Om~ for Om = Omega e_z and a_o = W p_Bo
/// (the frame origin's centripetal acceleration about the hub at the basic origin).
std::vector<double> flapwise(const Reduced& r, double gamma) {
  const se::Superelement& s = r.s;
  const Eigen::Index m = s.num_modes;
  const double Omega = gamma / r.scale;
  const Eigen::Vector3d Om(0, 0, Omega);
  const Eigen::Matrix3d W = so3::skew(Om) * so3::skew(Om);
  const Eigen::Vector3d a_o = W * s.p_OBo;
  double lambda[12] = {a_o.x(), a_o.y(), a_o.z(), 0, 0, 0, W(0, 0), W(1, 1), W(2, 2), W(0, 1), W(0, 2), W(1, 2)};
  Eigen::MatrixXd K = s.K;
  for (int c = 0; c < 12; ++c) K += lambda[c] * s.stiffening.inertia[static_cast<std::size_t>(c)];
  const Eigen::MatrixXd Kmm = K.bottomRightCorner(m, m), Mmm = s.M.bottomRightCorner(m, m);
  Eigen::GeneralizedSelfAdjointEigenSolver<Eigen::MatrixXd> es(Kmm, Mmm);
  EXPECT_EQ(es.info(), Eigen::Success);
  // Keep the modes whose FE translations are out of plane (z) for the most part.
  const Eigen::MatrixXd U = s.recovery.rightCols(m) * es.eigenvectors();
  std::vector<double> out;
  for (Eigen::Index k = 0; k < m; ++k) {
    double z = 0, all = 0;
    for (Eigen::Index i = 0; i < U.rows() / 6; ++i) {
      z += U(6 * i + 2, k) * U(6 * i + 2, k);
      all += U.middleRows<3>(6 * i).col(k).squaredNorm();
    }
    if (z > 0.99 * all) out.push_back(std::sqrt(es.eigenvalues()(k)) * r.scale);
  }
  return out;
}

TEST(StiffeningInvariants, RotatingCantileverMatchesTheFrobeniusSeries) {
  const Reduced r = reduce_cantilever(40, 12);
  ASSERT_TRUE(r.s.stiffening.present());
  const auto table = reference_table();
  ASSERT_GE(table.size(), 11u);
  double worst = 0;
  for (const auto& row : table) {
    const double gamma = row[0];
    if (gamma > 10) continue;
    const std::vector<double> f = flapwise(r, gamma);
    ASSERT_GE(f.size(), 3u) << "gamma " << gamma;
    for (int k = 0; k < 3; ++k) {
      const double ref = row[static_cast<std::size_t>(k + 1)];
      const double err = std::abs(f[static_cast<std::size_t>(k)] / ref - 1.0);
      worst = std::max(worst, err);
      EXPECT_LT(err, 0.01) << "gamma " << gamma << " mode " << k + 1 << ": " << f[static_cast<std::size_t>(k)]
                           << " against " << ref;
    }
  }
  std::printf("rotating cantilever, 40 CBAR, 12 fixed-interface modes: largest error %.2e (gamma <= 10)\n", worst);
}

TEST(StiffeningInvariants, InvariantsAreSymmetricAndAHeldBodyHasNoInterfaceStress) {
  const Reduced r = reduce_cantilever(10, 4);
  const se::StiffeningInvariants& st = r.s.stiffening;
  ASSERT_EQ(st.n, r.s.size());
  ASSERT_EQ(st.interface.size(), 6u);
  const double scale = r.s.K.cwiseAbs().maxCoeff();
  for (const auto& G : st.inertia) EXPECT_LE((G - G.transpose()).cwiseAbs().maxCoeff(), 1e-12 * G.cwiseAbs().maxCoeff());
  // One interface node: its constraint modes move the body rigidly, which stresses nothing.
  for (const auto& G : st.interface) EXPECT_LE(G.cwiseAbs().maxCoeff(), 1e-9 * scale);
  // Signs on the first flapwise mode (the first fixed-interface mode): a unit acceleration of the body
  // along +x is pushed by the hub, so the beam is in compression and softens (G_0 < 0); the centrifugal
  // case xx (W_xx = -Omega^2 when spinning about z) pulls it outwards: -Omega^2 G_6 > 0 stiffens.
  const Eigen::Index eta1 = 6;
  EXPECT_LT(st.inertia[0](eta1, eta1), 0.0);
  EXPECT_LT(st.inertia[6](eta1, eta1), 0.0);
  // A unit acceleration across the beam (y or z) loads it in bending, not axially: no first-order stiffening.
  EXPECT_LE(std::abs(st.inertia[2](eta1, eta1)), 1e-6 * std::abs(st.inertia[0](eta1, eta1)));
}

// The distributed reduce shares the 12 + 6N projections out over the ranks (case k on rank k mod P)
// and sums them (SuperelementOptions::sum_stiffening, MPI_Allreduce there; here the parts are added
// up by the test): each part computes its own cases only, and the parts add up to the whole.
TEST(StiffeningInvariants, SharedOutCasesAddUpToTheWhole) {
  const fem::Model m = cantilever(10);
  SuperelementOptions o;
  o.interface_ids = {1, 11};  // both ends held: the constraint modes stress the beam
  o.modes.modes = 3;
  o.name = "cantilever";
  const se::Superelement whole = reduce_to_superelement(m, o);
  const se::StiffeningInvariants& w = whole.stiffening;
  const Eigen::Index n = whole.size();
  ASSERT_EQ(w.interface.size(), 12u);
  constexpr int kParts = 3;
  const std::size_t cases = se::StiffeningInvariants::kInertiaCases + w.interface.size();
  std::vector<Eigen::MatrixXd> sum(cases, Eigen::MatrixXd::Zero(n, n));
  for (int part = 0; part < kParts; ++part) {
    o.stiffening_rank = part;
    o.stiffening_ranks = kParts;
    int calls = 0;
    o.sum_stiffening = [&](const std::vector<double*>& matrices, std::size_t count, bool failed_here) {
      ++calls;
      EXPECT_FALSE(failed_here);
      ASSERT_EQ(matrices.size(), cases);
      ASSERT_EQ(count, static_cast<std::size_t>(n * n));
      for (std::size_t k = 0; k < cases; ++k) {
        const Eigen::Map<const Eigen::MatrixXd> G(matrices[k], n, n);
        if (static_cast<int>(k) % kParts != part) {
          EXPECT_EQ(G.cwiseAbs().maxCoeff(), 0.0) << "case " << k;
        }
        sum[k] += G;
      }
    };
    (void)reduce_to_superelement(m, o);
    EXPECT_EQ(calls, 1);
  }
  for (std::size_t k = 0; k < cases; ++k) {
    const Eigen::MatrixXd& G = k < 12 ? w.inertia[k] : w.interface[k - 12];
    EXPECT_LE((sum[k] - G).cwiseAbs().maxCoeff(), 1e-12 * G.cwiseAbs().maxCoeff()) << "case " << k;
  }
  EXPECT_GT(w.interface[0].cwiseAbs().maxCoeff(), 0.0);  // axial constraint mode: tension, not nothing
}

}  // namespace
}  // namespace seflex::reduction
