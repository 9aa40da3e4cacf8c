// CHEXA 9-19, CPENTA 7-14 and CTETRA 5-9 grids: quadratic solids with some mid-edge grids blank (a
// straight edge, QRG CHEXA/CPENTA/CTETRA), built as Bathe's variable-number-of-nodes elements (Finite
// Element Procedures, 1996, sec. 5.3.1). Independent references:
// - the patch test (Irons & Razzaque 1972; MacNeal & Harder 1985, test 1): a linear displacement
//   field on the boundary of a distorted conforming mesh is reproduced exactly inside;
// - the full quadratic element with the missing grids at the midpoints of their straight edges and
//   their displacements tied to the mean of the edge's corners, T^T K_full T and T^T M_full T, must
//   equal the element without those grids (the same displacement field, integrated by the same rule);
// - mass: lumped (HRZ, as the full quadratic element) and coupled both sum to rho V.
#include <gtest/gtest.h>

#include <cmath>
#include <map>
#include <set>

#include "fem_test_util.hpp"
#include "seflex/fem/assembly.hpp"
#include "seflex/fem/element_solid.hpp"
#include "solid_mesh.hpp"

namespace seflex::fem::test {
namespace {

constexpr SolidType kQuadratic[] = {SolidType::Hexa20, SolidType::Penta15, SolidType::Tetra10};

/// Mid-edge grid k's corners (0-based), QRG order (as tests/fem/solid_mesh.hpp builds them).
std::array<int, 2> edge_ends(Solid::Shape shape, int k) {
  static const int hexa[12][2] = {{0, 1}, {1, 2}, {2, 3}, {3, 0}, {0, 4}, {1, 5}, {2, 6}, {3, 7}, {4, 5}, {5, 6}, {6, 7}, {7, 4}};
  static const int penta[9][2] = {{0, 1}, {1, 2}, {2, 0}, {0, 3}, {1, 4}, {2, 5}, {3, 4}, {4, 5}, {5, 3}};
  static const int tetra[6][2] = {{0, 1}, {1, 2}, {2, 0}, {0, 3}, {1, 3}, {2, 3}};
  const int(*e)[2] = shape == Solid::Shape::Hexa ? hexa : shape == Solid::Shape::Penta ? penta : tetra;
  return {e[k][0], e[k][1]};
}

/// A full quadratic solid without the mid-edge grids for which drop(k, grid id) is true.
Solid without_mids(const Solid& full, const std::function<bool(int, int)>& drop) {
  Solid s = full;
  const int corners = full.corners();
  int n = corners;
  s.missing_mid = 0;
  for (int k = 0; k < full.edges(); ++k) {
    const int grid = full.g[static_cast<std::size_t>(corners + k)];
    if (drop(k, grid)) {
      s.missing_mid = static_cast<std::uint16_t>(s.missing_mid | 1u << k);
      continue;
    }
    s.g[static_cast<std::size_t>(n++)] = grid;
  }
  for (int k = n; k < 20; ++k) s.g[static_cast<std::size_t>(k)] = 0;
  s.nnode = static_cast<std::uint8_t>(n);
  return s;
}

TEST(SolidPartial, PatchTestWithSomeMidEdgeGridsMissing) {
  Eigen::Matrix3d A;  // u = A x + c: a general constant strain (and rotation)
  A << 1.0e-3, 2.0e-4, -3.0e-4, 5.0e-4, -2.0e-3, 1.0e-4, -4.0e-4, 3.0e-4, 1.5e-3;
  const Eigen::Vector3d c(1e-3, -2e-3, 5e-4);
  for (const SolidType type : kQuadratic) {
    Model m;
    BoxMesh box;
    box.nx = box.ny = box.nz = 2;
    const auto lattice = add_box_solids(m, box, type, 1.0e5, 0.3, 1.0);
    // Drop about a third of the mid-edge grids, by grid (so neighbours agree: the mesh conforms).
    std::set<int> dropped;
    for (const auto& [id, l] : lattice)
      if ((l[0] % 2 || l[1] % 2 || l[2] % 2) && id % 3 == 0) dropped.insert(id);
    int partial = 0, full = 0;
    for (Solid& s : m.solids) {
      s = without_mids(s, [&](int, int grid) { return dropped.count(grid) > 0; });
      (s.missing_mid ? partial : full) += 1;
    }
    ASSERT_GT(partial, 0) << name(type);
    std::erase_if(m.grids, [&](const Grid& g) { return dropped.count(g.id) > 0; });
    // Move the interior grids by up to 3 % of a cell.
    const std::set<int> interior = distort_interior(m, lattice, 4, 0.03);
    const double worst = patch_test_error(m, interior, A, c);
    EXPECT_LT(worst, 1e-12) << name(type) << " (" << partial << " partial, " << full << " full elements): interior grids off "
                            << "the linear field by " << worst;
  }
}

/// One distorted element of each quadratic family; drop(k) selects the missing mid-edge grids.
void expect_equal_to_tied_full_element(SolidType type, const std::function<bool(int)>& drop, const char* what) {
  Model m;
  BoxMesh box;
  add_box_solids(m, box, type, 2.0e11, 0.3, 7800);
  int k = 0;
  for (Grid& g : m.grids) {  // 8 % distortion of every grid
    ++k;
    g.x += 0.08 * Eigen::Vector3d(std::sin(1.3 * k), std::cos(2.1 * k), std::sin(0.7 * k + 1));
  }
  const Solid full_in = m.solids[0];
  const Solid part = without_mids(full_in, [&](int e, int) { return drop(e); });
  // The full element's missing grids at the midpoints of their edges (straight).
  std::map<int, Eigen::Vector3d> x;
  for (const Grid& g : m.grids) x[g.id] = g.x;
  for (int e = 0; e < full_in.edges(); ++e) {
    if (!drop(e)) continue;
    const auto ends = edge_ends(full_in.shape, e);
    const int mid = full_in.g[static_cast<std::size_t>(full_in.corners() + e)];
    for (Grid& g : m.grids)
      if (g.id == mid)
        g.x = 0.5 * (x[full_in.g[static_cast<std::size_t>(ends[0])]] + x[full_in.g[static_cast<std::size_t>(ends[1])]]);
  }
  finalize_for_test(m);
  const SolidElement ef = make_solid_element(m, full_in), ep = make_solid_element(m, part);
  ASSERT_EQ(ep.nnode, part.nnode);
  // T: partial translations -> full translations (missing grid = mean of its edge's corners).
  const int nf = full_in.nnode, np = part.nnode;
  Eigen::MatrixXd T = Eigen::MatrixXd::Zero(3 * nf, 3 * np);
  std::map<int, int> column;  // grid id -> partial position
  for (int a = 0; a < np; ++a) column[part.g[static_cast<std::size_t>(a)]] = a;
  for (int a = 0; a < nf; ++a) {
    const int grid = full_in.g[static_cast<std::size_t>(a)];
    if (const auto it = column.find(grid); it != column.end()) {
      T.block<3, 3>(3 * a, 3 * it->second).setIdentity();
    } else {
      for (const int end : edge_ends(full_in.shape, a - full_in.corners())) T.block<3, 3>(3 * a, 3 * end) += 0.5 * Eigen::Matrix3d::Identity();
    }
  }
  const Eigen::MatrixXd Kf = solid_stiffness(ef), Kp = solid_stiffness(ep);
  const Eigen::MatrixXd Mf = solid_mass(ef, MassKind::Coupled), Mp = solid_mass(ep, MassKind::Coupled);
  EXPECT_LT((T.transpose() * Kf * T - Kp).norm(), 1e-12 * Kp.norm()) << name(type) << ", " << what;
  EXPECT_LT((T.transpose() * Mf * T - Mp).norm(), 1e-12 * Mp.norm()) << name(type) << ", " << what;
  EXPECT_EQ(null_space_dimension(Kp, 1e-10), 6) << name(type) << ", " << what;
  // Mass: rho V, lumped (HRZ, all positive) and coupled; V is the full element's (same geometry).
  const double mass = 7800 * solid_volume(ef);
  const Eigen::MatrixXd Ml = solid_mass(ep, MassKind::Lumped);
  EXPECT_NEAR(Ml.diagonal().sum() / 3, mass, 1e-12 * mass) << name(type) << ", " << what;
  EXPECT_NEAR(Mp.sum() / 3, mass, 1e-12 * mass) << name(type) << ", " << what;
  EXPECT_GT(Ml.diagonal().minCoeff(), 0.0) << name(type) << ", " << what;
  EXPECT_NEAR(solid_volume(ep), solid_volume(ef), 1e-13) << name(type) << ", " << what;
}

TEST(SolidPartial, EqualsTheFullElementWithStraightTiedEdges) {
  for (const SolidType type : kQuadratic) {
    expect_equal_to_tied_full_element(type, [](int k) { return k == 0; }, "first mid-edge grid missing");
    expect_equal_to_tied_full_element(type, [](int k) { return k % 2 == 1; }, "every other mid-edge grid missing");
    expect_equal_to_tied_full_element(type, [](int k) { return k != 2; }, "one mid-edge grid present");
  }
}

}  // namespace
}  // namespace seflex::fem::test
