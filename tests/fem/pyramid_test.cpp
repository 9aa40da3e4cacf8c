// CPYRAM 5 and 13 (Bedrosian's rational pyramids, fem/src/solid_shape_pyram.cpp) against independent
// references:
// - interpolation: Kronecker delta at the grids, partition of unity, the complete linear (5 grids)
//   and quadratic (13 grids) polynomials reproduced (Bedrosian, IJNME 35 (1992) 95-108), derivatives
//   against central finite differences;
// - the collapsed-cube rule against the closed-form moments of the reference pyramid (base 2 x 2,
//   height 1): V = 4/3, int zeta dV = 1/3, int xi^2 dV = 4/15;
// - six rigid-body modes and no other zero eigenvalue of a distorted element (5, 13 and 9 grids);
// - the constant-strain patch test (Irons & Razzaque 1972; MacNeal & Harder, Finite Elements in
//   Analysis and Design 1 (1985) 3-20, test 1) on distorted meshes of pyramids, and of pyramids with
//   hexahedra and tetrahedra sharing conforming faces;
// - a cube of pyramids in uniaxial tension (PLOAD4 on the pyramids' bases): u = sigma x / E,
//   lateral contraction nu sigma / E, centroid stress sigma (exact: a linear field); mass rho V and
//   the box's inertia m (b^2 + c^2) / 12 (a rigid rotation is a linear field, reproduced exactly);
// - a cantilever under a tip load converging to Timoshenko beam theory (Timoshenko & Goodier, Theory
//   of Elasticity, 3rd ed., sec. 21: d = P L^3 / (3 E I) + P L / (k G A), k = 5/6 with nu = 0);
// - PLOAD4 on a triangular face: the resultant p A along the inward normal;
// - a distorted (non-convex) or collapsed element is refused, naming the element.
#include <gtest/gtest.h>

#include <cmath>
#include <map>
#include <set>

#include "fem_test_util.hpp"
#include "pyramid_mesh.hpp"
#include "seflex/common/error.hpp"
#include "seflex/fem/assembly.hpp"
#include "seflex/fem/element_results.hpp"
#include "seflex/fem/element_solid.hpp"
#include "seflex/fem/loads.hpp"
#include "seflex/fem/mass_properties.hpp"
#include "solid_mesh.hpp"
#include "solid_shapes.hpp"

namespace seflex::fem::test {
namespace {

using Shape = Solid::Shape;

/// Natural coordinates of the 13 grids (QRG CPYRAM order).
std::array<Eigen::Vector3d, 13> pyramid_nodes() {
  std::array<Eigen::Vector3d, 13> x;
  x[0] = {-1, -1, 0}, x[1] = {1, -1, 0}, x[2] = {1, 1, 0}, x[3] = {-1, 1, 0}, x[4] = {0, 0, 1};
  for (int e = 0; e < 8; ++e) {
    const auto ends = detail::solid_edge_ends(Shape::Pyram, e);
    x[static_cast<std::size_t>(5 + e)] = 0.5 * (x[static_cast<std::size_t>(ends[0])] + x[static_cast<std::size_t>(ends[1])]);
  }
  return x;
}

/// Points inside the pyramid, away from the apex.
std::vector<Eigen::Vector3d> inside_points() {
  std::vector<Eigen::Vector3d> p;
  for (int k = 0; k < 12; ++k) {
    const double z = 0.05 + 0.9 * (0.5 + 0.5 * std::sin(1.3 * k + 0.2));
    p.emplace_back((1 - z) * std::sin(2.1 * k), (1 - z) * std::cos(0.7 * k + 1), z);
  }
  return p;
}

TEST(PyramidShape, InterpolatesAndReproducesPolynomials) {
  const auto X = pyramid_nodes();
  // Monomials of degree <= 1 (5 grids) or <= 2 (13 grids), and the 9-grid element (edges to the apex
  // blank: straight) only the linear ones.
  auto monomial = [](int k, const Eigen::Vector3d& x) {
    static const int pw[10][3] = {{0, 0, 0}, {1, 0, 0}, {0, 1, 0}, {0, 0, 1}, {2, 0, 0},
                                  {0, 2, 0}, {0, 0, 2}, {1, 1, 0}, {0, 1, 1}, {1, 0, 1}};
    return std::pow(x[0], pw[k][0]) * std::pow(x[1], pw[k][1]) * std::pow(x[2], pw[k][2]);
  };
  struct Case {
    int nnode;
    std::uint16_t missing;
    int monomials;
  };
  for (const Case cs : {Case{5, 0, 4}, Case{13, 0, 10}, Case{9, 0xF0, 4}, Case{12, 0x01, 4}}) {
    // The grids present: corners, then the mid-edge grids not in `missing`.
    std::vector<Eigen::Vector3d> nodes(X.begin(), X.begin() + 5);
    if (cs.nnode > 5)
      for (int e = 0; e < 8; ++e)
        if (!(cs.missing >> e & 1u)) nodes.push_back(X[static_cast<std::size_t>(5 + e)]);
    ASSERT_EQ(static_cast<int>(nodes.size()), cs.nnode);
    detail::ShapeValues s;
    // Tolerances: 10 times the largest error measured (2026-12-07): Kronecker delta 2e-14, monomials
    // 2e-16, gradients against central differences 1.5e-10.
    for (int b = 0; b < cs.nnode; ++b) {  // Kronecker delta (the apex included: N there is bounded)
      detail::solid_shape(Shape::Pyram, cs.nnode, cs.missing, nodes[static_cast<std::size_t>(b)], s);
      for (int a = 0; a < cs.nnode; ++a) EXPECT_NEAR(s.N[a], a == b ? 1.0 : 0.0, 2e-13) << cs.nnode << " grids, N" << a + 1 << " at grid " << b + 1;
    }
    for (const Eigen::Vector3d& x : inside_points()) {
      detail::solid_shape(Shape::Pyram, cs.nnode, cs.missing, x, s);
      for (int k = 0; k < cs.monomials; ++k) {
        double f = 0;
        Eigen::Vector3d g = Eigen::Vector3d::Zero();
        for (int a = 0; a < cs.nnode; ++a) {
          const double fa = monomial(k, nodes[static_cast<std::size_t>(a)]);
          f += s.N[a] * fa;
          g += fa * Eigen::Vector3d(s.dN[a][0], s.dN[a][1], s.dN[a][2]);
        }
        Eigen::Vector3d g_exact;
        for (int j = 0; j < 3; ++j) {  // exact gradient by central differences of the monomial
          Eigen::Vector3d h = Eigen::Vector3d::Zero();
          h[j] = 1e-6;
          g_exact[j] = (monomial(k, x + h) - monomial(k, x - h)) / 2e-6;
        }
        EXPECT_NEAR(f, monomial(k, x), 2e-15) << cs.nnode << " grids, monomial " << k;
        EXPECT_LT((g - g_exact).norm(), 1.5e-9) << cs.nnode << " grids, gradient of monomial " << k;
      }
      // Every derivative against central differences of the functions.
      for (int j = 0; j < 3; ++j) {
        Eigen::Vector3d h = Eigen::Vector3d::Zero();
        h[j] = 1e-6;
        detail::ShapeValues sp, sm;
        detail::solid_shape(Shape::Pyram, cs.nnode, cs.missing, x + h, sp);
        detail::solid_shape(Shape::Pyram, cs.nnode, cs.missing, x - h, sm);
        for (int a = 0; a < cs.nnode; ++a) EXPECT_NEAR(s.dN[a][j], (sp.N[a] - sm.N[a]) / 2e-6, 1.5e-9) << cs.nnode << " grids, dN" << a + 1;
      }
    }
  }
}

TEST(PyramidShape, CollapsedCubeRuleGivesThePyramidsMoments) {
  for (const int n : {2, 3, 4}) {
    double V = 0, Z = 0, XX = 0;
    for (const auto& q : detail::solid_rule(Shape::Pyram, n)) {
      V += q.w;
      Z += q.w * q.xi[2];
      XX += q.w * q.xi[0] * q.xi[0];
      EXPECT_LE(std::abs(q.xi[0]), 1 - q.xi[2]);
    }
    // Measured (2026-12-07): 9e-16 at most.
    EXPECT_NEAR(V, 4.0 / 3.0, 4e-15) << n;
    EXPECT_NEAR(Z, 1.0 / 3.0, 4e-15) << n;
    if (n >= 3) EXPECT_NEAR(XX, 4.0 / 15.0, 4e-15) << n;  // degree 4 in zeta: needs 3 points
  }
}

/// One pyramid (5, 9 or 13 grids) on a rectangular base 2 x 1.5, apex 1.2 above a point off the
/// centre, every grid moved by up to `distortion`.
Model one_pyramid(int nnode, double distortion, std::uint16_t missing = 0) {
  Model m;
  add_mat1(m, 1, 2.0e11, 0.3, 7800);
  SolidProperty p;
  p.id = 1, p.mid = 1;
  m.solid_props.push_back(p);
  const auto X = pyramid_nodes();
  Solid s;
  s.id = 7, s.pid = 1, s.shape = Shape::Pyram;
  s.missing_mid = missing;
  int n = 0;
  for (int a = 0; a < 13; ++a) {
    if (a >= 5 && (nnode == 5 || (missing >> (a - 5) & 1u))) continue;
    const Eigen::Vector3d& xi = X[static_cast<std::size_t>(a)];
    Eigen::Vector3d x(1.0 * xi[0] + 0.3 * xi[2], 0.75 * xi[1] - 0.2 * xi[2], 1.2 * xi[2]);
    x += distortion * Eigen::Vector3d(std::sin(1.3 * a + 1), std::cos(2.1 * a), std::sin(0.7 * a + 2));
    add_grid(m, 100 + a, x.x(), x.y(), x.z());
    s.g[static_cast<std::size_t>(n++)] = 100 + a;
  }
  s.nnode = static_cast<std::uint8_t>(n);
  m.solids.push_back(s);
  return m;
}

TEST(PyramidElement, SixRigidBodyModesAndSymmetryOnADistortedElement) {
  struct Case {
    int nnode;
    std::uint16_t missing;
  };
  for (const Case cs : {Case{5, 0}, Case{13, 0}, Case{9, 0xF0}}) {
    Model m = one_pyramid(cs.nnode, 0.08, cs.missing);
    finalize_for_test(m);
    const SolidElement e = make_solid_element(m, m.solids[0]);
    const Eigen::MatrixXd K = solid_stiffness(e);
    EXPECT_LT((K - K.transpose()).norm(), 1e-15 * K.norm()) << cs.nnode;  // symmetrised: 0 measured
    // 3N - 6 positive eigenvalues: no spurious zero-energy mode.
    EXPECT_EQ(null_space_dimension(K, 1e-10), 6) << cs.nnode << " grids";
    const Eigen::MatrixXd Mc = solid_mass(e, MassKind::Coupled), Ml = solid_mass(e, MassKind::Lumped);
    const double mass = 7800 * solid_volume(e);  // measured (2026-12-07): 6e-16 relative
    EXPECT_NEAR(Mc.sum() / 3, mass, 1e-14 * mass);
    EXPECT_NEAR(Ml.diagonal().sum() / 3, mass, 1e-14 * mass);
    EXPECT_GT(Ml.diagonal().minCoeff(), 0.0);
  }
}

// A uniform temperature rise: the equivalent loads equal K times the free expansion alpha dT x (a
// linear field, which the element reproduces: B u = alpha dT (1 1 1 0 0 0) at every point).
TEST(PyramidElement, ThermalLoadIsTheStiffnessTimesTheFreeExpansion) {
  for (const int nnode : {5, 13}) {
    Model m = one_pyramid(nnode, 0.08);
    finalize_for_test(m);
    const SolidElement e = make_solid_element(m, m.solids[0]);
    const double alpha = 2.3e-5, dT = 40;
    const Eigen::VectorXd f = solid_thermal_load(e, alpha, Eigen::VectorXd::Constant(nnode, dT));
    Eigen::VectorXd u(3 * nnode);
    for (int a = 0; a < nnode; ++a) u.segment<3>(3 * a) = alpha * dT * e.x[static_cast<std::size_t>(a)];
    const Eigen::VectorXd Ku = solid_stiffness(e) * u;
    EXPECT_LT((f - Ku).norm(), 1e-14 * Ku.norm()) << nnode << " grids";  // measured 1.5e-15 relative
  }
}

TEST(PyramidElement, LumpedMassOfTheLinearPyramidIsRhoIntNdV) {
  // Straight pyramid (base 2 x 1.5, height 1.2, apex off centre): the apex carries int zeta dV = V / 4
  // (its centroid height is h / 4), each base corner 3 V / 16 (symmetry of the base functions).
  Model m = one_pyramid(5, 0.0);
  finalize_for_test(m);
  const SolidElement e = make_solid_element(m, m.solids[0]);
  const double V = 2.0 * 1.5 * 1.2 / 3;
  EXPECT_NEAR(solid_volume(e), V, 2e-15);  // measured (2026-12-07): 2e-16, and 5e-13 of 2340 below
  const Eigen::MatrixXd Ml = solid_mass(e, MassKind::Lumped);
  EXPECT_NEAR(Ml(12, 12), 7800 * V / 4, 5e-12);
  for (int a = 0; a < 4; ++a) EXPECT_NEAR(Ml(3 * a, 3 * a), 7800 * 3 * V / 16, 5e-12);
}

/// The unit cube in 2 x 2 x 2 cells of pyramids (mixed: with CHEXA and CTETRA).
PyramidBox unit_cube(bool quadratic, bool mixed) {
  PyramidBox box;
  box.nx = box.ny = box.nz = 2;
  box.quadratic = quadratic, box.mixed = mixed;
  return box;
}

TEST(PyramidElement, PatchTestOnDistortedPyramidAndMixedMeshes) {
  Eigen::Matrix3d A;  // u = A x + c: a general constant strain (and rotation)
  A << 1.0e-3, 2.0e-4, -3.0e-4, 5.0e-4, -2.0e-3, 1.0e-4, -4.0e-4, 3.0e-4, 1.5e-3;
  const Eigen::Vector3d c(1e-3, -2e-3, 5e-4);
  for (const bool quadratic : {false, true})
    for (const bool mixed : {false, true}) {
      Model m;
      const auto lattice = add_pyramid_box(m, unit_cube(quadratic, mixed), 1.0e5, 0.3, 1.0);
      std::map<Shape, int> count;
      for (const Solid& s : m.solids) ++count[s.shape];
      // Mixed: 4 CHEXA cells, 4 cells of 6 faces, 12 of them on the boundary, every other one 2 CTETRA.
      EXPECT_EQ(count[Shape::Pyram], mixed ? 18 : 48);
      EXPECT_EQ(count[Shape::Tetra], mixed ? 12 : 0);
      EXPECT_EQ(count[Shape::Hexa], mixed ? 4 : 0);
      // Interior grids (strictly inside the box) moved by up to 3 % (quadratic) or 7 % of a cell.
      const std::set<int> interior = distort_interior(m, lattice, 8, quadratic ? 0.015 : 0.035);
      const double worst = patch_test_error(m, interior, A, c);  // measured (2026-12-07): 1.5e-17
      EXPECT_LT(worst, 2e-16) << (quadratic ? "13" : "5") << " grids" << (mixed ? ", mixed" : "")
                              << ": interior grids off the linear field by " << worst;
    }
}

/// PLOAD4 on every element face in the lattice plane axis = value (pyramid bases, CHEXA faces, CTETRA
/// triangles), pressure p along n.
void pload4_on_plane(Model& m, const std::map<int, std::array<int, 3>>& lattice, int axis, int value, int sid, double p,
                     const Eigen::Vector3d& n) {
  for (const Solid& s : m.solids) {
    std::vector<int> on, off;
    for (int k = 0; k < s.corners(); ++k)
      (lattice.at(s.g[static_cast<std::size_t>(k)])[static_cast<std::size_t>(axis)] == value ? on : off).push_back(k);
    if (on.size() < 3 || (on.size() == 3 && s.shape != Shape::Tetra)) continue;
    FaceLoad l;
    l.sid = sid, l.eid = s.id, l.p = {p, p, p, p}, l.n = n;
    l.g1 = s.g[static_cast<std::size_t>(on[0])];
    if (s.shape == Shape::Tetra) {  // G4: the corner off the face
      l.g34 = s.g[static_cast<std::size_t>(off[0])];
      m.face_loads.push_back(l);
      continue;
    }
    for (const int k : on) {  // the corner diagonally opposite on[0]: differs in both in-plane coordinates
      const auto& a = lattice.at(l.g1);
      const auto& b = lattice.at(s.g[static_cast<std::size_t>(k)]);
      int differ = 0;
      for (int j = 0; j < 3; ++j) differ += a[static_cast<std::size_t>(j)] != b[static_cast<std::size_t>(j)];
      if (differ == 2) l.g34 = s.g[static_cast<std::size_t>(k)];
    }
    m.face_loads.push_back(l);
  }
}

TEST(PyramidElement, CubeOfPyramidsInUniaxialTension) {
  const double E = 7.0e10, nu = 0.33, sigma = 2.0e6;
  for (const bool quadratic : {false, true})
    for (const bool mixed : {false, true}) {
      Model m;
      const auto lattice = add_pyramid_box(m, unit_cube(quadratic, mixed), E, nu, 2700);
      pload4_on_plane(m, lattice, 0, 8, 1, sigma, Eigen::Vector3d(1, 0, 0));
      finalize_for_test(m);
      const GlobalMatrices g = assemble(m, assembly_options(m));
      const Eigen::VectorXd p = load_vector(m, g.dofs, 1);
      double Fx = 0;
      for (Eigen::Index gi = 0; gi < static_cast<Eigen::Index>(m.grids.size()); ++gi) Fx += p[g.dofs.grid_dof(gi, 1)];
      // Measured (2026-12-07): Fx 6e-16, displacements 1e-14 and stresses 1.4e-14 relative.
      EXPECT_NEAR(Fx, sigma * 1.0, 1e-14 * sigma);
      std::map<Eigen::Index, double> fixed;  // symmetry planes x = 0, y = 0, z = 0
      for (const auto& [id, l] : lattice)
        for (int c = 0; c < 3; ++c)
          if (l[static_cast<std::size_t>(c)] == 0) fixed[g.dofs.grid_dof(m.grid_index.at(id), c + 1)] = 0.0;
      const Eigen::VectorXd u = solve_translations(m, g, p, fixed);
      double worst = 0;
      for (const Grid& gr : m.grids) {
        const Eigen::Vector3d exact(sigma / E * gr.x.x(), -nu * sigma / E * gr.x.y(), -nu * sigma / E * gr.x.z());
        worst = std::max(worst, (translation(m, g, u, gr.id) - exact).norm());
      }
      EXPECT_LT(worst, 1e-13 * sigma / E) << (quadratic ? "13" : "5") << " grids" << (mixed ? ", mixed" : "");
      // Centroid stresses of every element: (sigma, 0, 0, 0, 0, 0).
      double worst_stress = 0;
      for (const Solid& s : m.solids) {
        const SolidElement e = make_solid_element(m, s);
        Eigen::VectorXd ue(3 * s.nnode);
        for (int a = 0; a < s.nnode; ++a) ue.segment<3>(3 * a) = translation(m, g, u, s.g[static_cast<std::size_t>(a)]);
        Eigen::Matrix<double, 6, 1> expected = Eigen::Matrix<double, 6, 1>::Zero();
        expected[0] = sigma;
        worst_stress = std::max(worst_stress, (solid_results(e, ue) - expected).norm());
      }
      EXPECT_LT(worst_stress, 1.5e-13 * sigma) << (quadratic ? "13" : "5") << " grids" << (mixed ? ", mixed" : "");
    }
}

TEST(PyramidElement, MassAndInertiaOfABoxOfPyramids) {
  for (const bool quadratic : {false, true})
    for (const bool coupled : {false, true}) {
      Model m;
      PyramidBox box;
      box.nx = 3, box.ny = 2, box.nz = 2, box.Lx = 0.3, box.Ly = 0.2, box.Lz = 0.1, box.quadratic = quadratic;
      add_pyramid_box(m, box, 7.0e10, 0.33, 2700);
      if (coupled) add_param(m, "COUPMASS", "1");
      finalize_for_test(m);
      const MassProperties mp = mass_properties(m);
      const double mass = 2700 * 0.3 * 0.2 * 0.1;  // measured (2026-12-07): 6e-16, 2e-16 m, 4e-15 relative
      EXPECT_NEAR(mp.mass, mass, 1e-14 * mass);
      EXPECT_LT((mp.cg - Eigen::Vector3d(0.15, 0.1, 0.05)).norm(), 2e-15);
      if (!coupled) continue;  // lumped masses give the grids' point inertia, not the continuum's
      const Eigen::Vector3d I(mass * (0.04 + 0.01) / 12, mass * (0.09 + 0.01) / 12, mass * (0.09 + 0.04) / 12);
      EXPECT_LT((mp.I_cg.diagonal() - I).norm(), 4e-14 * I.norm()) << (quadratic ? "13" : "5") << " grids";
    }
}

// Cantilever 10 x 1 x 1 clamped at x = 0, uniform shear traction on the end (PLOAD4 with a
// direction on the pyramids' bases), total P = 1 along -z, nu = 0.
double cantilever_tip_ratio(bool quadratic, int nx, int nyz) {
  const double E = 1.0e4, L = 10, P = 1;
  const double reference = P * L * L * L / (3 * E / 12) + P * L / (5.0 / 6.0 * E / 2);
  Model m;
  PyramidBox box;
  box.nx = nx, box.ny = box.nz = nyz, box.Lx = L, box.quadratic = quadratic;
  const auto lattice = add_pyramid_box(m, box, E, 0.0, 1.0);
  pload4_on_plane(m, lattice, 0, 4 * nx, 1, P, Eigen::Vector3d(0, 0, -1));
  finalize_for_test(m);
  const GlobalMatrices g = assemble(m, assembly_options(m));
  return mean_tip_deflection(m, g, load_vector(m, g.dofs, 1), lattice, 4 * nx) / reference;
}

TEST(PyramidElement, CantileverConvergesToBeamTheory) {
  // Each refinement brings the tip closer to beam theory; the finest mesh within about 1.5 times its
  // error measured (2026-12-07): tip / theory 0.520, 0.811, 0.945 (CPYRAM 5: stiff, as the
  // constant-strain tetrahedra it resembles) and 0.99590, 0.99890, 0.99994 (CPYRAM 13).
  struct Mesh {
    int nx, nyz;
  };
  for (const bool quadratic : {false, true}) {
    const std::vector<Mesh> meshes = quadratic ? std::vector<Mesh>{{5, 1}, {10, 1}, {20, 2}} : std::vector<Mesh>{{10, 1}, {20, 2}, {40, 4}};
    double previous = 1e300, r = 0;
    for (const Mesh& mesh : meshes) {
      r = cantilever_tip_ratio(quadratic, mesh.nx, mesh.nyz);
      EXPECT_LT(std::abs(r - 1), previous) << (quadratic ? 13 : 5) << " grids, " << mesh.nx << " cells";
      previous = std::abs(r - 1);
    }
    EXPECT_NEAR(r, 1.0, quadratic ? 1e-4 : 0.08);
  }
}

TEST(PyramidElement, Pload4OnATriangularFaceGivesPressureTimesAreaInward) {
  for (const int nnode : {5, 13}) {
    Model m = one_pyramid(nnode, 0.0);
    FaceLoad l;
    l.sid = 4, l.eid = 7, l.p = {3.0, 3.0, 3.0, 3.0};
    l.g1 = 102, l.g34 = 101;  // base corners G3 and G2: the face G2 G3 G5
    m.face_loads.push_back(l);
    finalize_for_test(m);
    const Eigen::Vector3d F = load_resultant(m, 4);
    const Eigen::Vector3d x1 = m.grids[m.grid_index.at(101)].x, x2 = m.grids[m.grid_index.at(102)].x,
                          x5 = m.grids[m.grid_index.at(104)].x;
    Eigen::Vector3d nA = 0.5 * (x2 - x1).cross(x5 - x1);  // G2 G3 G5 counter-clockwise seen from outside
    const Eigen::Vector3d centre(0.075, -0.05, 0.3);     // inside the pyramid
    if (nA.dot(x1 - centre) < 0) nA = -nA;
    // Measured (2026-12-07): 4.5e-16.
    EXPECT_LT((F + 3.0 * nA).norm(), 4e-15 * nA.norm()) << nnode << " grids: " << F.transpose();
  }
}

TEST(PyramidElement, DistortedOrCollapsedElementsAreRefused) {
  auto error = [](Model m) {
    finalize_for_test(m);
    try {
      make_solid_element(m, m.solids[0]);
    } catch (const InputError& e) {
      return std::string(e.what());
    }
    return std::string();
  };
  {  // apex in the plane of the base: collapsed
    Model m = one_pyramid(5, 0.0);
    m.grids[4].x.z() = 0;
    EXPECT_NE(error(m).find("CPYRAM 7"), std::string::npos) << error(m);
    EXPECT_NE(error(m).find("degenerate or distorted"), std::string::npos);
  }
  {  // base corners G3 and G4 swapped: a bow-tie base, the Jacobian changes sign
    Model m = one_pyramid(13, 0.0);
    std::swap(m.grids[2].x, m.grids[3].x);
    EXPECT_NE(error(m).find("CPYRAM 7"), std::string::npos) << error(m);
  }
  {  // the base collapsed to a line (G3 on G2, G4 on G1): no volume
    Model m = one_pyramid(5, 0.0);
    m.grids[2].x = m.grids[1].x;
    m.grids[3].x = m.grids[0].x;
    EXPECT_NE(error(m).find("degenerate or distorted"), std::string::npos) << error(m);
  }
  {  // the apex below the base: the element turned inside out but not distorted, accepted
    Model m = one_pyramid(5, 0.0);
    m.grids[4].x.z() = -1.2;
    EXPECT_EQ(error(m), "");
  }
}

}  // namespace
}  // namespace seflex::fem::test
