// Isoparametric solids: stiffness, mass, resolution from the model (element_solid.hpp).
#include "seflex/fem/element_solid.hpp"

#include <Eigen/Dense>
#include <cmath>

#include "model_lookup.hpp"
#include "seflex/common/error.hpp"
#include "solid_kinematics.hpp"
#include "solid_shapes.hpp"

namespace seflex::fem {
using detail::SolidPointData;

namespace {

bool quadratic(const SolidElement& e) { return e.nnode > Solid::corners(e.shape); }

/// T (6 x 6) with eps_M = T eps_B for Voigt strains with engineering shears (xx yy zz xy yz zx),
/// frame M's axes the columns of R_BM: the strain tensor E_M = R_BM^T E_B R_BM, column by column.
Eigen::Matrix<double, 6, 6> strain_rotation(const Eigen::Matrix3d& R_BM) {
  static const int ij[6][2] = {{0, 0}, {1, 1}, {2, 2}, {0, 1}, {1, 2}, {2, 0}};
  Eigen::Matrix<double, 6, 6> T;
  for (int c = 0; c < 6; ++c) {
    Eigen::Matrix3d E = Eigen::Matrix3d::Zero();
    const int i = ij[c][0], j = ij[c][1];
    if (c < 3) E(i, i) = 1;
    else E(i, j) = E(j, i) = 0.5;  // engineering shear strain 1
    const Eigen::Matrix3d E_M = R_BM.transpose() * E * R_BM;
    for (int r = 0; r < 6; ++r) T(r, c) = r < 3 ? E_M(ij[r][0], ij[r][1]) : 2 * E_M(ij[r][0], ij[r][1]);
  }
  return T;
}

/// Elasticity and thermal expansion of a PSOLID's MAT9 in basic axes (element_solid.hpp); with
/// mass_only the density alone (the mass does not depend on the axes or on G).
void mat9_elasticity(const Model& model, const SolidProperty& prop, const Mat9& m, bool mass_only, SolidElement& e) {
  e.rho = m.rho;
  if (mass_only) return;
  Eigen::Matrix<double, 6, 6> G;
  for (int i = 0, k = 0; i < 6; ++i)
    for (int j = i; j < 6; ++j, ++k) G(i, j) = G(j, i) = m.g[static_cast<std::size_t>(k)];
  Eigen::Matrix3d R_BM = Eigen::Matrix3d::Identity();
  if (prop.cordm == -1)
    detail::fail(model, prop.ref, "PSOLID", prop.id, "4 (CORDM)",
                 "is -1 (the element coordinate system) with MAT9 " + std::to_string(m.id) +
                     ", which seflex does not model; expected 0 (basic) or a rectangular system for the anisotropic material's axes");
  if (prop.cordm > 0) {
    const auto it = model.coord_index.find(prop.cordm);
    if (it == model.coord_index.end())
      detail::fail(model, prop.ref, "PSOLID", prop.id, "4 (CORDM)",
                   "references coordinate system " + std::to_string(prop.cordm) + ", which is not defined");
    const CoordSys& c = model.coords[it->second];
    if (c.type != CoordType::Rectangular)
      detail::fail(model, prop.ref, "PSOLID", prop.id, "4 (CORDM)",
                   "coordinate system " + std::to_string(prop.cordm) + " is cylindrical or spherical; expected 0 or a "
                   "rectangular system for the axes of MAT9 " + std::to_string(m.id));
    R_BM = c.axes;
  }
  const Eigen::SelfAdjointEigenSolver<Eigen::Matrix<double, 6, 6>> eig(G, Eigen::EigenvaluesOnly);
  const double lo = eig.eigenvalues().minCoeff(), hi = eig.eigenvalues().maxCoeff();
  if (!(lo > 1e-12 * hi))
    detail::fail(model, m.ref, "MAT9", m.id, "G11-G66",
                 "the 6 x 6 matrix G is not positive definite (eigenvalues " + std::to_string(lo) + " to " + std::to_string(hi) +
                     "); expected a positive definite elasticity matrix");
  const Eigen::Matrix<double, 6, 6> T = strain_rotation(R_BM);
  e.D = T.transpose() * G * T;
  e.tref = m.tref;
  const Eigen::Map<const Eigen::Matrix<double, 6, 1>> a_M(m.a.data());
  e.alpha = a_M.isZero(0.0) ? 0.0 : 1.0;
  e.thermal_strain = strain_rotation(R_BM.transpose()) * a_M;  // eps_B = T(R_BM^T) eps_M
}

}  // namespace

Eigen::Matrix<double, 6, 6> isotropic_elasticity(double E, double nu) {
  const double lambda = E * nu / ((1 + nu) * (1 - 2 * nu)), mu = E / (2 * (1 + nu));
  Eigen::Matrix<double, 6, 6> D = Eigen::Matrix<double, 6, 6>::Zero();
  D.topLeftCorner<3, 3>().setConstant(lambda);
  for (int i = 0; i < 3; ++i) D(i, i) += 2 * mu;
  for (int i = 3; i < 6; ++i) D(i, i) = mu;
  return D;
}

Eigen::MatrixXd solid_stiffness(const SolidElement& e) {
  const int n = 3 * e.nnode;
  Eigen::MatrixXd K = Eigen::MatrixXd::Zero(n, n);
  const bool bubbles = e.scheme == SolidElement::Scheme::IncompatibleModes;
  Eigen::MatrixXd Kci, Kii;
  detail::BubbleCentre centre;
  if (bubbles) {
    Kci = Eigen::MatrixXd::Zero(n, 9);
    Kii = Eigen::MatrixXd::Zero(9, 9);
    centre = detail::bubble_centre(e);
  }
  const std::vector<detail::QuadraturePoint> rule = detail::solid_rule(e.shape, e.points);
  std::vector<Eigen::MatrixXd> B(rule.size());
  std::vector<double> detJ(rule.size());
  SolidPointData p;
  for (std::size_t i = 0; i < rule.size(); ++i) {
    detail::evaluate(e, rule[i].xi, p);
    B[i] = detail::strain_matrix(e, p);
    detJ[i] = std::abs(p.detJ);
  }
  if (e.scheme == SolidElement::Scheme::ReducedShear) detail::reduce_shear_rows(rule, detJ, B);
  for (std::size_t i = 0; i < rule.size(); ++i) {
    const double dV = detJ[i] * rule[i].w;
    const Eigen::MatrixXd DB = e.D * B[i];
    K.noalias() += B[i].transpose() * DB * dV;
    if (bubbles) {
      detail::evaluate(e, rule[i].xi, p);
      const Eigen::Matrix<double, 6, 9> Bi = detail::bubble_strain_matrix(centre, rule[i].xi, p.detJ);
      Kci.noalias() += DB.transpose() * Bi * dV;
      Kii.noalias() += Bi.transpose() * e.D * Bi * dV;
    }
  }
  if (bubbles) K -= Kci * Kii.ldlt().solve(Kci.transpose());
  return 0.5 * (K + K.transpose());
}

double solid_volume(const SolidElement& e) {
  double V = 0;
  SolidPointData p;
  for (const auto& q : detail::solid_rule(e.shape, quadratic(e) ? 4 : 3)) {
    detail::evaluate(e, q.xi, p);
    V += std::abs(p.detJ) * q.w;
  }
  return V;
}

Eigen::MatrixXd solid_mass(const SolidElement& e, MassKind kind) {
  const int N = e.nnode;
  const bool is_quadratic = quadratic(e);
  Eigen::MatrixXd m = Eigen::MatrixXd::Zero(N, N);  // scalar mass rho int N_a N_b dV
  Eigen::VectorXd row = Eigen::VectorXd::Zero(N);   // rho int N_a dV
  SolidPointData p;
  for (const auto& q : detail::solid_rule(e.shape, is_quadratic ? 4 : 3)) {
    detail::evaluate(e, q.xi, p);
    const double dm = e.rho * std::abs(p.detJ) * q.w;
    const Eigen::Map<const Eigen::VectorXd> Nv(p.s.N, N);
    m.noalias() += Nv * Nv.transpose() * dm;
    row += Nv * dm;
  }
  Eigen::MatrixXd M = Eigen::MatrixXd::Zero(3 * N, 3 * N);
  if (kind == MassKind::Coupled) {
    for (int a = 0; a < N; ++a)
      for (int b = 0; b < N; ++b)
        for (int c = 0; c < 3; ++c) M(3 * a + c, 3 * b + c) = m(a, b);
    return M;
  }
  Eigen::VectorXd lumped = row;
  if (is_quadratic) {  // HRZ: diagonal of the coupled mass scaled to the total
    const double total = row.sum(), diag = m.diagonal().sum();
    lumped = diag > 0 ? Eigen::VectorXd(m.diagonal() * (total / diag)) : Eigen::VectorXd::Zero(N);
  }
  for (int a = 0; a < N; ++a)
    for (int c = 0; c < 3; ++c) M(3 * a + c, 3 * a + c) = lumped[a];
  return M;
}

std::vector<std::vector<int>> solid_face_corners(Solid::Shape shape) {
  std::vector<std::vector<int>> out;
  for (const auto& f : detail::solid_faces(shape)) out.emplace_back(f.corners.begin(), f.corners.begin() + f.ncorner);
  return out;
}

SolidElement make_solid_element(const Model& model, const Solid& s, bool mass_only) {
  const char* card = s.card();
  SolidElement e;
  e.shape = s.shape;
  e.nnode = s.nnode;
  e.missing_mid = s.quadratic() ? s.missing_mid : 0;
  for (int k = 0; k < s.nnode; ++k) {
    const std::uint32_t gi = detail::grid_index(model, s.g[static_cast<std::size_t>(k)], s.ref, card, s.id,
                                                "G" + std::to_string(s.grid_number(k)));
    e.x[static_cast<std::size_t>(k)] = model.grids[gi].x_basic;
  }
  const auto pit = model.solid_prop_index.find(s.pid);
  if (pit == model.solid_prop_index.end())
    detail::fail(model, s.ref, card, s.id, "3 (PID)",
                 "references property " + std::to_string(s.pid) + ", which is not defined; expected the id of a PSOLID card");
  const SolidProperty& prop = model.solid_props[pit->second];
  if (const auto m9 = model.mat9_index.find(prop.mid); m9 != model.mat9_index.end()) {
    mat9_elasticity(model, prop, model.mat9[m9->second], mass_only, e);
  } else {
    if (!model.mat1_index.count(prop.mid)) {
      const char* other = model.mat2_index.count(prop.mid) ? "MAT2" : model.mat8_index.count(prop.mid) ? "MAT8" : nullptr;
      detail::fail(model, prop.ref, "PSOLID", prop.id, "3 (MID)",
                   "references material " + std::to_string(prop.mid) +
                       (other ? std::string(", a ") + other + " (a shell material)" : std::string(", which is not defined")) +
                       "; expected the id of a MAT1 or MAT9 card");
    }
    const IsotropicMaterial mat = detail::material(model, prop.mid, prop.ref, "PSOLID", prop.id, "3 (MID)");
    if (!(mat.E > 0.0) || !(mat.nu > -1.0 && mat.nu < 0.5))
      detail::fail(model, prop.ref, "PSOLID", prop.id, "3 (MID)",
                   "MAT1 " + std::to_string(mat.id) + " has E = " + std::to_string(mat.E) + ", nu = " + std::to_string(mat.nu) +
                       "; a solid needs E > 0 and -1 < nu < 0.5");
    e.D = isotropic_elasticity(mat.E, mat.nu);
    e.rho = mat.rho;
    const Mat1& m1 = model.mat1[model.mat1_index.at(prop.mid)];
    e.alpha = m1.alpha;
    e.tref = m1.tref;
  }
  const bool linear = !s.quadratic();
  using In = SolidProperty::Integration;
  using Isop = SolidProperty::Isop;
  if (!linear) {
    if (!mass_only && (prop.in == In::Two || prop.in == In::Bubble || prop.isop == Isop::Reduced))
      detail::fail(model, prop.ref, "PSOLID", prop.id, "5 (IN) / 7 (ISOP)",
                   std::string("is used by the ") + std::to_string(s.nnode) + "-grid " + card + " " + std::to_string(s.id) +
                       " with reduced integration (IN = TWO or BUBBLE, or ISOP = REDUCED), which seflex does not model; "
                       "expected IN blank or THREE and ISOP blank or FULL (full Gauss integration)");
    e.points = 3;
  } else if (s.shape == Solid::Shape::Pyram) {
    e.points = 2;  // exact for a parallelogram base (solid_shapes.hpp); IN and ISOP change nothing
  } else if (s.shape == Solid::Shape::Hexa) {
    if (prop.in == In::Three) {
      e.points = 3;
    } else if (prop.in == In::Two && prop.isop != Isop::Full) {  // reduced shear integration
      e.points = 2;
      e.scheme = SolidElement::Scheme::ReducedShear;
    } else if (prop.in == In::Two || (prop.in == In::Default && prop.isop == Isop::Full)) {
      e.points = 2;
    } else {
      e.points = 2;
      e.scheme = SolidElement::Scheme::IncompatibleModes;
    }
  } else {
    e.points = prop.in == In::Three ? 3 : 2;
  }
  // Geometry: det J must keep one sign over the element (either grid orientation is accepted).
  SolidPointData p;
  double sign = 0;
  auto check = [&](const Eigen::Vector3d& xi) {
    detail::evaluate(e, xi, p);
    const double sg = p.detJ > 0 ? 1.0 : p.detJ < 0 ? -1.0 : 0.0;
    if (sign == 0) sign = sg;
    if (sg == 0 || sg != sign || !std::isfinite(p.detJ))
      detail::fail(model, s.ref, card, s.id, "G1",
                   "the element is degenerate or distorted (the Jacobian determinant is zero or changes sign inside "
                   "it); expected the grid order of the QRG figure with a convex shape");
  };
  for (const auto& q : detail::solid_rule(e.shape, 3)) check(q.xi);
  return e;
}

}  // namespace seflex::fem
