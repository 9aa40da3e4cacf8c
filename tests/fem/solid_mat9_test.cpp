// MAT9 (anisotropic solid material) on PSOLID, against independent references:
// - a MAT1 written as a MAT9 (G = the isotropic elasticity matrix) gives the MAT1 element's stiffness,
//   mass and thermal load to 1e-12, in basic axes and in rotated material axes (CORDM), for every
//   solid type;
// - an orthotropic bar (engineering constants E1 E2 E3 nu12 nu13 nu23 G12 G13 G23, material axes
//   rotated by CORDM) under uniaxial stress: the strains are the compliance matrix times the stress,
//   rotated by hand with tensor algebra (eps_B = R eps_M R^T), and the apparent modulus and Poisson
//   ratio along x follow the closed-form in-plane rotation formulas (Jones, Mechanics of Composite
//   Materials, 2nd ed., 1999, eqs. 2.97-2.98).
#include <gtest/gtest.h>

#include <cmath>
#include <map>

#include "fem_test_util.hpp"
#include "seflex/common/error.hpp"
#include "seflex/fem/assembly.hpp"
#include "seflex/fem/element_solid.hpp"
#include "seflex/fem/loads.hpp"
#include "solid_mesh.hpp"

namespace seflex::fem::test {
namespace {

constexpr double kPi = 3.14159265358979323846;
constexpr SolidType kAll[] = {SolidType::Hexa8,  SolidType::Hexa20, SolidType::Penta6,
                              SolidType::Penta15, SolidType::Tetra4, SolidType::Tetra10};

/// MAT9 `id` with the 6 x 6 matrix G (upper triangle row by row, as on the card).
Mat9& add_mat9(Model& m, int id, const Eigen::Matrix<double, 6, 6>& G, double rho) {
  Mat9 mat;
  mat.id = id;
  for (int i = 0, k = 0; i < 6; ++i)
    for (int j = i; j < 6; ++j) mat.g[static_cast<std::size_t>(k++)] = G(i, j);
  mat.rho = rho;
  m.mat9.push_back(mat);
  return m.mat9.back();
}

Eigen::Matrix3d rotation(const Eigen::Vector3d& axis, double angle) {
  return Eigen::AngleAxisd(angle, axis.normalized()).toRotationMatrix();
}

/// Voigt (xx yy zz xy yz zx, engineering shear) <-> tensor, written out independently of fem.
Eigen::Matrix3d strain_tensor(const Eigen::Matrix<double, 6, 1>& e) {
  Eigen::Matrix3d E;
  E << e[0], e[3] / 2, e[5] / 2, e[3] / 2, e[1], e[4] / 2, e[5] / 2, e[4] / 2, e[2];
  return E;
}
Eigen::Matrix<double, 6, 1> stress_voigt(const Eigen::Matrix3d& S) {
  Eigen::Matrix<double, 6, 1> s;
  s << S(0, 0), S(1, 1), S(2, 2), S(0, 1), S(1, 2), S(2, 0);
  return s;
}

TEST(SolidMat9, IsotropicMat9EqualsMat1InAnyMaterialAxes) {
  const double E = 7.0e10, nu = 0.33, rho = 2700, alpha = 2.3e-5;
  for (const SolidType type : kAll)
    for (const int cordm : {0, 7}) {
      Model m1;
      BoxMesh box;
      box.Lx = 2.0;
      add_box_solids(m1, box, type, E, nu, rho, [](const Eigen::Vector3d& x) {
        return Eigen::Vector3d(x.x() + 0.1 * x.y() * x.z(), x.y() - 0.05 * x.x(), x.z() + 0.07 * x.x() * x.y());
      });
      m1.mat1[0].alpha = alpha;
      m1.mat1[0].tref = 20.0;
      m1.default_temperatures.push_back({5, 120.0, {}});
      Model m9 = m1;
      m9.mat1.clear();
      Mat9& mat = add_mat9(m9, 1, isotropic_elasticity(E, nu), rho);
      mat.a = {alpha, alpha, alpha, 0, 0, 0};
      mat.tref = 20.0;
      if (cordm != 0) {
        add_rect_coord(m9, cordm, Eigen::Vector3d(1, 2, 3), rotation(Eigen::Vector3d(1, -2, 0.5), 0.7));
        m9.solid_props[0].cordm = cordm;
      }
      finalize_for_test(m1);
      finalize_for_test(m9);
      const GlobalMatrices g1 = assemble(m1, assembly_options(m1)), g9 = assemble(m9, assembly_options(m9));
      const std::string what = std::string(name(type)) + " CORDM " + std::to_string(cordm);
      EXPECT_LT((g9.K - g1.K).norm(), 1e-12 * g1.K.norm()) << what;
      EXPECT_LT((g9.M - g1.M).norm(), 1e-12 * g1.M.norm()) << what;
      const Eigen::VectorXd p1 = thermal_load_vector(m1, g1.dofs, 5), p9 = thermal_load_vector(m9, g9.dofs, 5);
      EXPECT_GT(p1.norm(), 0.0);
      EXPECT_LT((p9 - p1).norm(), 1e-12 * p1.norm()) << what;
    }
}

// Orthotropic bar 4 x 1 x 1 (4 CHEXA 8, PSOLID defaults), material axes CORDM 7 rotated about z by
// theta (case 1) or about a skew axis (case 2); uniaxial stress sigma along basic x from consistent
// end forces (a uniform traction on a rectangle: a quarter of the face force per corner), supported
// statically determinately. The FE solution is the homogeneous one: u = H x + c at every grid.
TEST(SolidMat9, OrthotropicBarUnderUniaxialStressMatchesTheCompliance) {
  const double E1 = 150e9, E2 = 10e9, E3 = 12e9, nu12 = 0.3, nu13 = 0.25, nu23 = 0.4, G12 = 5e9, G13 = 6e9, G23 = 3.5e9;
  Eigen::Matrix<double, 6, 6> S = Eigen::Matrix<double, 6, 6>::Zero();  // compliance, material axes
  S(0, 0) = 1 / E1, S(1, 1) = 1 / E2, S(2, 2) = 1 / E3;
  S(0, 1) = S(1, 0) = -nu12 / E1;
  S(0, 2) = S(2, 0) = -nu13 / E1;
  S(1, 2) = S(2, 1) = -nu23 / E2;
  S(3, 3) = 1 / G12, S(4, 4) = 1 / G23, S(5, 5) = 1 / G13;
  const Eigen::Matrix<double, 6, 6> G = S.inverse();
  const double sigma = 1.0e6, theta = 30.0 * kPi / 180.0;
  const Eigen::Matrix3d rotations[2] = {rotation(Eigen::Vector3d::UnitZ(), theta), rotation(Eigen::Vector3d(0.3, -1, 2), 1.1)};
  for (int c = 0; c < 2; ++c) {
    const Eigen::Matrix3d& R_BM = rotations[c];  // material axes (columns) in basic
    Model m;
    BoxMesh box;
    box.nx = 4, box.Lx = 4.0;
    const auto lattice = add_box_solids(m, box, SolidType::Hexa8, 1.0, 0.0, 1.0);
    m.mat1.clear();
    add_mat9(m, 1, G, 1600.0);
    add_rect_coord(m, 7, Eigen::Vector3d(0.5, -1, 2), R_BM);
    m.solid_props[0].cordm = 7;
    finalize_for_test(m);
    const GlobalMatrices g = assemble(m, assembly_options(m));
    Eigen::VectorXd p = Eigen::VectorXd::Zero(g.dofs.size());
    std::map<Eigen::Index, double> fixed;
    for (const auto& [id, l] : lattice) {
      const Eigen::Index gi = m.grid_index.at(id);
      const double face_force = sigma * box.Ly * box.Lz / 4;  // one cell face = the whole end face
      if (l[0] == 2 * box.nx) p[g.dofs.grid_dof(gi, 1)] += face_force;
      if (l[0] == 0) p[g.dofs.grid_dof(gi, 1)] -= face_force;
      if (l[0] == 0 && l[1] == 0 && l[2] == 0)
        for (int cc = 1; cc <= 3; ++cc) fixed[g.dofs.grid_dof(gi, cc)] = 0.0;
      if (l[0] == 2 * box.nx && l[1] == 0 && l[2] == 0) fixed[g.dofs.grid_dof(gi, 2)] = fixed[g.dofs.grid_dof(gi, 3)] = 0.0;
      if (l[0] == 0 && l[1] == 2 && l[2] == 0) fixed[g.dofs.grid_dof(gi, 3)] = 0.0;
    }
    const Eigen::VectorXd u = solve_translations(m, g, p, fixed);
    // Fit u = H x + c over every grid (exact for the homogeneous solution).
    Eigen::MatrixXd A(static_cast<Eigen::Index>(m.grids.size()), 4), U(static_cast<Eigen::Index>(m.grids.size()), 3);
    for (std::size_t i = 0; i < m.grids.size(); ++i) {
      A.row(static_cast<Eigen::Index>(i)) << m.grids[i].x_basic.transpose(), 1.0;
      U.row(static_cast<Eigen::Index>(i)) = translation(m, g, u, m.grids[i].id).transpose();
    }
    const Eigen::MatrixXd X = A.colPivHouseholderQr().solve(U);  // 4 x 3: rows x y z 1
    const Eigen::Matrix3d H = X.topRows<3>().transpose();
    EXPECT_LT((A * X - U).norm(), 1e-9 * U.norm()) << "case " << c << ": not homogeneous";
    const Eigen::Matrix3d eps_fe = 0.5 * (H + H.transpose());
    // By hand: sigma_M = R^T sigma_B R; eps_M = S sigma_M (Voigt); eps_B = R eps_M R^T.
    Eigen::Matrix3d sigma_B = Eigen::Matrix3d::Zero();
    sigma_B(0, 0) = sigma;
    const Eigen::Matrix<double, 6, 1> eps_M = S * stress_voigt(R_BM.transpose() * sigma_B * R_BM);
    const Eigen::Matrix3d eps_B = R_BM * strain_tensor(eps_M) * R_BM.transpose();
    EXPECT_LT((eps_fe - eps_B).norm(), 1e-9 * eps_B.norm()) << "case " << c << "\nFE:\n" << eps_fe << "\nby hand:\n" << eps_B;
    if (c == 0) {  // Jones eqs. 2.97-2.98, rotation by theta in the 1-2 plane
      const double cs = std::cos(theta), sn = std::sin(theta);
      const double inv_Ex = std::pow(cs, 4) / E1 + (1 / G12 - 2 * nu12 / E1) * sn * sn * cs * cs + std::pow(sn, 4) / E2;
      const double nu_xy = (nu12 / E1 * (std::pow(sn, 4) + std::pow(cs, 4)) - (1 / E1 + 1 / E2 - 1 / G12) * sn * sn * cs * cs) / inv_Ex;
      EXPECT_NEAR(sigma / eps_fe(0, 0), 1 / inv_Ex, 1e-9 / inv_Ex);
      EXPECT_NEAR(-eps_fe(1, 1) / eps_fe(0, 0), nu_xy, 1e-9);
      EXPECT_GT(std::abs(eps_fe(0, 1)), 1e-3 * eps_fe(0, 0));  // shear coupling of the off-axis material
    }
  }
}

TEST(SolidMat9, UnusableMaterialAxesAndMatricesAreErrors) {
  auto model = [](int cordm, const Eigen::Matrix<double, 6, 6>& G, CoordType type = CoordType::Rectangular) {
    Model m;
    BoxMesh box;
    add_box_solids(m, box, SolidType::Hexa8, 1.0, 0.0, 1.0);
    m.mat1.clear();
    add_mat9(m, 1, G, 1.0);
    if (cordm > 0) add_rect_coord(m, cordm, Eigen::Vector3d::Zero(), Eigen::Matrix3d::Identity()).type = type;
    m.solid_props[0].cordm = cordm;
    finalize_for_test(m);
    return m;
  };
  auto error = [](const Model& m) {
    try {
      make_solid_element(m, m.solids[0]);
    } catch (const InputError& e) {
      return std::string(e.what());
    }
    return std::string("no error");
  };
  const Eigen::Matrix<double, 6, 6> iso = isotropic_elasticity(1e9, 0.3);
  EXPECT_NE(error(model(-1, iso)).find("PSOLID 1, field 4 (CORDM): is -1 (the element coordinate system) with MAT9 1"), std::string::npos)
      << error(model(-1, iso));
  {  // the mass needs neither the axes nor G (seflex info's mass properties)
    const Model m = model(-1, iso);
    EXPECT_EQ(make_solid_element(m, m.solids[0], true).rho, 1.0);
  }
  EXPECT_NE(error(model(3, iso, CoordType::Cylindrical)).find("PSOLID 1, field 4 (CORDM): coordinate system 3 is cylindrical"), std::string::npos)
      << error(model(3, iso, CoordType::Cylindrical));
  Eigen::Matrix<double, 6, 6> bad = iso;
  bad(0, 1) = bad(1, 0) = 2 * bad(0, 0);  // |G12| > G11: indefinite
  EXPECT_NE(error(model(0, bad)).find("MAT9 1, field G11-G66: the 6 x 6 matrix G is not positive definite"), std::string::npos)
      << error(model(0, bad));
}

}  // namespace
}  // namespace seflex::fem::test
