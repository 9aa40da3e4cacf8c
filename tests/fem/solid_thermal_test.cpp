// Thermal loads of CHEXA/CPENTA/CTETRA (TEMP/TEMPD, MAT1 ALPHA/TREF) and the CHEXA 8 reduced shear
// integration (PSOLID IN = TWO), against independent references:
// - a free body heated uniformly expands by alpha dT x with no stress; a body whose temperature is
//   linear in space is also stress free (Timoshenko & Goodier, Theory of Elasticity, 3rd ed.,
//   sec. 150), which the linear solids reproduce exactly when the field is linear in each element;
// - a bar held axially at both ends carries sigma = -E alpha dT (uniaxial stress, lateral faces
//   free: the lateral strain is (1 + nu) alpha dT);
// - pure bending of a rectangular cantilever with nu = 0: tip deflection M L^2 / (2 E I) (Euler-
//   Bernoulli is exact there), which the reduced shear CHEXA 8 reproduces exactly and plain 2 x 2 x 2
//   Gauss does not (shear locking); the element keeps the six rigid-body modes only.
#include <gtest/gtest.h>

#include <cmath>
#include <map>

#include "fem_test_util.hpp"
#include "seflex/fem/assembly.hpp"
#include "seflex/fem/element_solid.hpp"
#include "seflex/fem/loads.hpp"
#include "solid_mesh.hpp"

namespace seflex::fem::test {
namespace {

constexpr double kPi = 3.14159265358979323846;
constexpr double E = 2.0e11, nu = 0.3, alpha = 1.2e-5, tref = 20.0;

enum class Hexa8Scheme { Bubble, Full, ReducedShear };

void set_scheme(Model& m, Hexa8Scheme s) {
  if (s == Hexa8Scheme::Bubble) return;
  m.solid_props[0].in = SolidProperty::Integration::Two;
  m.solid_props[0].isop = s == Hexa8Scheme::Full ? SolidProperty::Isop::Full : SolidProperty::Isop::Reduced;
}

void set_expansion(Model& m) {
  m.mat1[0].alpha = alpha;
  m.mat1[0].tref = tref;
}

/// Hold the rigid-body motion of a box [0, Lx] x [0, Ly] x [0, Lz] at three corners (origin: xyz;
/// (Lx, 0, 0): y, z; (0, Ly, 0): z), which leaves any free thermal deformation about the origin alone.
std::map<Eigen::Index, double> statically_determinate(const Model& m, const GlobalMatrices& g,
                                                      const std::map<int, std::array<int, 3>>& lattice, const BoxMesh& box) {
  std::map<Eigen::Index, double> fixed;
  for (const auto& [id, l] : lattice) {
    const Eigen::Index gi = m.grid_index.at(id);
    if (l[0] == 0 && l[1] == 0 && l[2] == 0)
      for (int c = 1; c <= 3; ++c) fixed[g.dofs.grid_dof(gi, c)] = 0.0;
    if (l[0] == 2 * box.nx && l[1] == 0 && l[2] == 0) fixed[g.dofs.grid_dof(gi, 2)] = fixed[g.dofs.grid_dof(gi, 3)] = 0.0;
    if (l[0] == 0 && l[1] == 2 * box.ny && l[2] == 0) fixed[g.dofs.grid_dof(gi, 3)] = 0.0;
  }
  return fixed;
}

// Every solid type (and the three CHEXA 8 integrations) on a distorted 2 x 2 x 2 box (the corners stay
// in place), TEMPD 100: u = alpha dT x at every grid.
TEST(SolidThermalLoad, FreeBoxExpandsFreely) {
  struct Case {
    SolidType type;
    Hexa8Scheme scheme;
  };
  const Case cases[] = {{SolidType::Hexa8, Hexa8Scheme::Bubble}, {SolidType::Hexa8, Hexa8Scheme::Full},
                        {SolidType::Hexa8, Hexa8Scheme::ReducedShear}, {SolidType::Hexa20, Hexa8Scheme::Bubble},
                        {SolidType::Penta6, Hexa8Scheme::Bubble}, {SolidType::Penta15, Hexa8Scheme::Bubble},
                        {SolidType::Tetra4, Hexa8Scheme::Bubble}, {SolidType::Tetra10, Hexa8Scheme::Bubble}};
  auto distort = [](const Eigen::Vector3d& x) {
    const double s = 0.08 * std::sin(kPi * x.x()) * std::sin(kPi * x.y() / 2) * std::sin(kPi * x.z() / 3);
    return Eigen::Vector3d(x.x() + s, x.y() - 0.5 * s, x.z() + 0.7 * s);
  };
  for (const Case& cs : cases) {
    Model m;
    BoxMesh box;
    box.nx = box.ny = box.nz = 2;
    box.Lx = 1, box.Ly = 2, box.Lz = 3;
    const auto lattice = add_box_solids(m, box, cs.type, E, nu, 7800.0, distort);
    set_expansion(m);
    if (cs.type == SolidType::Hexa8) set_scheme(m, cs.scheme);
    m.default_temperatures.push_back({5, 100.0, {}});
    finalize_for_test(m);
    const GlobalMatrices g = assemble(m, assembly_options(m));
    const Eigen::VectorXd p = thermal_load_vector(m, g.dofs, 5);
    const Eigen::VectorXd u = solve_translations(m, g, p, statically_determinate(m, g, lattice, box));
    const double e = alpha * 80.0;
    double worst = 0;
    for (const Grid& gr : m.grids) worst = std::max(worst, (translation(m, g, u, gr.id) - e * gr.x_basic).norm());
    EXPECT_LT(worst, 1e-12 * e * 3) << name(cs.type) << " scheme " << static_cast<int>(cs.scheme);
    EXPECT_LT((g.K * u - p).norm(), 1e-9 * p.norm()) << name(cs.type);  // no reaction: stress free
  }
}

// Temperature linear in z (TEMP at every grid: T - TREF from 50 to 90), one CHEXA 8 / CTETRA 4 per
// cell: thermal loads are self-equilibrated (zero resultant force and moment), and their virtual work
// on the homogeneous deformation u = x, which every element represents exactly, is
//   sum_a p_a . x_a = int sigma_T : I dV = 3 E alpha / (1 - 2 nu) int (T - TREF) dV
// (D (1 1 1 0 0 0) = E / (1 - 2 nu) (1 1 1 0 0 0); int (T - TREF) dV = 70 on the unit cube).
TEST(SolidThermalLoad, LinearTemperatureGivesSelfEquilibratedLoads) {
  for (const SolidType type : {SolidType::Hexa8, SolidType::Tetra4}) {
    Model m;
    BoxMesh box;
    box.nx = box.ny = box.nz = 2;
    const auto lattice = add_box_solids(m, box, type, E, nu, 7800.0);
    set_expansion(m);
    for (const auto& [id, l] : lattice) m.grid_temperatures.push_back({5, id, tref + 50.0 + 40.0 * l[2] / (2.0 * box.nz), {}});
    finalize_for_test(m);
    const GlobalMatrices g = assemble(m, assembly_options(m));
    const Eigen::VectorXd p = thermal_load_vector(m, g.dofs, 5);
    Eigen::Vector3d F = Eigen::Vector3d::Zero(), M = Eigen::Vector3d::Zero();
    double work = 0;
    for (const auto& [id, l] : lattice) {
      const Eigen::Vector3d f = translation(m, g, p, id), x = m.grids[m.grid_index.at(id)].x_basic;
      F += f;
      M += x.cross(f);
      work += f.dot(x);
    }
    const double scale = E * alpha * 90.0;
    EXPECT_LT(F.norm(), 1e-12 * scale) << name(type);
    EXPECT_LT(M.norm(), 1e-12 * scale) << name(type);
    EXPECT_NEAR(work / (3 * E * alpha * 70.0 / (1 - 2 * nu)), 1.0, 1e-12) << name(type);
  }
}

// A bar 4 x 1 x 1 (2 CHEXA 8 across, 8 along) held in x at both ends, free laterally (only the
// rigid-body motion held): uniform dT = 60 gives sigma_xx = -E alpha dT, so the reactions of each
// end sum to E alpha dT A, and the lateral faces move out by (1 + nu) alpha dT.
TEST(SolidThermalLoad, AxiallyHeldBarCarriesMinusEAlphaDeltaT) {
  for (const Hexa8Scheme scheme : {Hexa8Scheme::Bubble, Hexa8Scheme::Full, Hexa8Scheme::ReducedShear}) {
    Model m;
    BoxMesh box;
    box.nx = 8, box.ny = box.nz = 2, box.Lx = 4;
    const auto lattice = add_box_solids(m, box, SolidType::Hexa8, E, nu, 7800.0);
    set_expansion(m);
    set_scheme(m, scheme);
    m.default_temperatures.push_back({5, tref + 60.0, {}});
    finalize_for_test(m);
    const GlobalMatrices g = assemble(m, assembly_options(m));
    const Eigen::VectorXd p = thermal_load_vector(m, g.dofs, 5);
    std::map<Eigen::Index, double> fixed;
    for (const auto& [id, l] : lattice) {
      const Eigen::Index gi = m.grid_index.at(id);
      if (l[0] == 0 || l[0] == 2 * box.nx) fixed[g.dofs.grid_dof(gi, 1)] = 0.0;
      if (l[0] == 0 && l[1] == 0 && l[2] == 0) fixed[g.dofs.grid_dof(gi, 2)] = fixed[g.dofs.grid_dof(gi, 3)] = 0.0;
      if (l[0] == 0 && l[1] == 2 * box.ny && l[2] == 0) fixed[g.dofs.grid_dof(gi, 3)] = 0.0;
      if (l[0] == 0 && l[1] == 0 && l[2] == 2 * box.nz) fixed[g.dofs.grid_dof(gi, 2)] = 0.0;
    }
    const Eigen::VectorXd u = solve_translations(m, g, p, fixed);
    const Eigen::VectorXd r = g.K * u - p;  // reactions on the held dofs
    double right = 0, left = 0;
    for (const auto& [id, l] : lattice) {
      const Eigen::Index gi = m.grid_index.at(id);
      if (l[0] == 0) left += r[g.dofs.grid_dof(gi, 1)];
      if (l[0] == 2 * box.nx) right += r[g.dofs.grid_dof(gi, 1)];
      if (l[1] == 2 * box.ny && l[0] == box.nx) {
        EXPECT_NEAR(translation(m, g, u, id).y() / ((1 + nu) * alpha * 60.0), 1.0, 1e-9) << static_cast<int>(scheme);
      }
    }
    const double N = E * alpha * 60.0 * 1.0;
    EXPECT_NEAR(left / N, 1.0, 1e-9) << static_cast<int>(scheme);    // the bar pushes the supports apart:
    EXPECT_NEAR(right / -N, 1.0, 1e-9) << static_cast<int>(scheme);  // reactions inward
  }
}

// Cantilever 10 x 1 x 1, one CHEXA 8 through the depth, nu = 0, end couple of linearly varying axial
// tractions (consistent nodal loads +-s/12 at the four end grids: M = s/6): tip deflection
// M L^2 / (2 E I). Reduced shear (IN = TWO, ISOP = REDUCED) and the bubble modes are exact; plain
// 2 x 2 x 2 Gauss (ISOP = FULL) locks.
TEST(SolidElement, Hexa8ReducedShearIsExactInPureBending) {
  const double Ey = 1.0e4, L = 10, s = 6.0, M = s / 6, I = 1.0 / 12;
  const double reference = M * L * L / (2 * Ey * I);
  for (const Hexa8Scheme scheme : {Hexa8Scheme::ReducedShear, Hexa8Scheme::Bubble, Hexa8Scheme::Full}) {
    Model m;
    BoxMesh box;
    box.nx = 10, box.Lx = L;
    const auto lattice = add_box_solids(m, box, SolidType::Hexa8, Ey, 0.0, 1.0);
    set_scheme(m, scheme);
    finalize_for_test(m);
    const GlobalMatrices g = assemble(m, assembly_options(m));
    Eigen::VectorXd p = Eigen::VectorXd::Zero(g.dofs.size());
    std::map<Eigen::Index, double> fixed;
    for (const auto& [id, l] : lattice) {
      const Eigen::Index gi = m.grid_index.at(id);
      if (l[0] == 0)
        for (int c = 1; c <= 3; ++c) fixed[g.dofs.grid_dof(gi, c)] = 0.0;
      if (l[0] == 2 * box.nx) p[g.dofs.grid_dof(gi, 1)] = (l[2] == 0 ? 1.0 : -1.0) * s / 12;  // bends toward +z
    }
    const Eigen::VectorXd u = solve_translations(m, g, p, fixed);
    double w = 0;
    for (const auto& [id, l] : lattice)
      if (l[0] == 2 * box.nx) w += translation(m, g, u, id).z() / 4;
    if (scheme == Hexa8Scheme::Full)
      EXPECT_LT(w / reference, 0.75);
    else
      EXPECT_NEAR(w / reference, 1.0, 1e-9) << static_cast<int>(scheme);
  }
  // one distorted element: symmetric, exactly six zero-energy (rigid-body) modes
  Model m;
  BoxMesh box;
  const auto lattice = add_box_solids(m, box, SolidType::Hexa8, Ey, 0.3, 1.0, [](const Eigen::Vector3d& x) {
    return Eigen::Vector3d(x.x() + 0.2 * x.y() * x.z(), x.y() + 0.1 * x.x(), x.z() - 0.15 * x.x() * x.y());
  });
  set_scheme(m, Hexa8Scheme::ReducedShear);
  finalize_for_test(m);
  const Eigen::MatrixXd K = solid_stiffness(make_solid_element(m, m.solids[0]));
  EXPECT_LT((K - K.transpose()).norm(), 1e-12 * K.norm());
  EXPECT_EQ(null_space_dimension(K), 6);
}

}  // namespace
}  // namespace seflex::fem::test
