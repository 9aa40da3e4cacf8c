// Isoparametric solids: stiffness, mass, resolution from the model (element_solid.hpp).
#include "seflex/fem/element_solid.hpp"

#include <Eigen/Dense>
#include <cmath>

#include "model_lookup.hpp"
#include "seflex/common/error.hpp"
#include "solid_shapes.hpp"

namespace seflex::fem {
namespace {

using detail::ShapeValues;

/// Shape values, x-gradients (rows a: dN_a/dx) and det J at natural point xi.
struct PointData {
  ShapeValues s;
  Eigen::Matrix<double, detail::kMaxSolidNodes, 3> dNdx;
  double detJ = 0;
  Eigen::Matrix3d J;  ///< J(i, j) = dx_i / dxi_j
};

void evaluate(const SolidElement& e, const Eigen::Vector3d& xi, PointData& p) {
  detail::solid_shape(e.shape, e.nnode, xi, p.s);
  p.J.setZero();
  for (int a = 0; a < e.nnode; ++a)
    for (int j = 0; j < 3; ++j) p.J.col(j) += p.s.dN[a][j] * e.x[static_cast<std::size_t>(a)];
  p.detJ = p.J.determinant();
  const Eigen::Matrix3d Jit = p.J.inverse().transpose();
  for (int a = 0; a < e.nnode; ++a)
    p.dNdx.row(a) = (Jit * Eigen::Vector3d(p.s.dN[a][0], p.s.dN[a][1], p.s.dN[a][2])).transpose();
}

/// Strain-displacement columns of one displacement gradient g (3 columns: u, v, w).
void strain_columns(const Eigen::Vector3d& g, Eigen::Ref<Eigen::Matrix<double, 6, 3>> B) {
  B.setZero();
  B(0, 0) = g[0];
  B(1, 1) = g[1];
  B(2, 2) = g[2];
  B(3, 0) = g[1], B(3, 1) = g[0];
  B(4, 1) = g[2], B(4, 2) = g[1];
  B(5, 0) = g[2], B(5, 2) = g[0];
}

Eigen::MatrixXd strain_matrix(const SolidElement& e, const PointData& p) {
  Eigen::MatrixXd B(6, 3 * e.nnode);
  for (int a = 0; a < e.nnode; ++a) {
    Eigen::Matrix<double, 6, 3> b;
    strain_columns(p.dNdx.row(a).transpose(), b);
    B.middleCols<3>(3 * a) = b;
  }
  return B;
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
  Eigen::Matrix3d J0it = Eigen::Matrix3d::Identity();
  double detJ0 = 0;
  if (bubbles) {
    Kci = Eigen::MatrixXd::Zero(n, 9);
    Kii = Eigen::MatrixXd::Zero(9, 9);
    PointData c;
    evaluate(e, Eigen::Vector3d::Zero(), c);
    J0it = c.J.inverse().transpose();
    detJ0 = c.detJ;
  }
  PointData p;
  for (const auto& q : detail::solid_rule(e.shape, e.points)) {
    evaluate(e, q.xi, p);
    const Eigen::MatrixXd B = strain_matrix(e, p);
    const double dV = std::abs(p.detJ) * q.w;
    const Eigen::MatrixXd DB = e.D * B;
    K.noalias() += B.transpose() * DB * dV;
    if (bubbles) {
      // Modes P_k = 1 - xi_k^2 (k = 0..2) for each component; gradient with the centre Jacobian,
      // scaled by det J0 / det J (constant strain patch test on any shape).
      Eigen::Matrix<double, 6, 9> Bi;
      for (int k = 0; k < 3; ++k) {
        Eigen::Vector3d dP = Eigen::Vector3d::Zero();
        dP[k] = -2 * q.xi[k];
        const Eigen::Vector3d g = (detJ0 / p.detJ) * (J0it * dP);
        strain_columns(g, Bi.middleCols<3>(3 * k));
      }
      Kci.noalias() += DB.transpose() * Bi * dV;
      Kii.noalias() += Bi.transpose() * e.D * Bi * dV;
    }
  }
  if (bubbles) K -= Kci * Kii.ldlt().solve(Kci.transpose());
  return 0.5 * (K + K.transpose());
}

double solid_volume(const SolidElement& e) {
  double V = 0;
  PointData p;
  for (const auto& q : detail::solid_rule(e.shape, e.nnode == 20 || e.nnode == 15 || e.nnode == 10 ? 4 : 3)) {
    evaluate(e, q.xi, p);
    V += std::abs(p.detJ) * q.w;
  }
  return V;
}

Eigen::MatrixXd solid_mass(const SolidElement& e, MassKind kind) {
  const int N = e.nnode;
  const bool quadratic = N == 20 || N == 15 || N == 10;
  Eigen::MatrixXd m = Eigen::MatrixXd::Zero(N, N);  // scalar mass rho int N_a N_b dV
  Eigen::VectorXd row = Eigen::VectorXd::Zero(N);   // rho int N_a dV
  PointData p;
  for (const auto& q : detail::solid_rule(e.shape, quadratic ? 4 : 3)) {
    evaluate(e, q.xi, p);
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
  if (quadratic) {  // HRZ: diagonal of the coupled mass scaled to the total
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
  for (int k = 0; k < s.nnode; ++k) {
    const std::uint32_t gi = detail::grid_index(model, s.g[static_cast<std::size_t>(k)], s.ref, card, s.id,
                                                "G" + std::to_string(k + 1));
    e.x[static_cast<std::size_t>(k)] = model.grids[gi].x_basic;
  }
  const auto pit = model.solid_prop_index.find(s.pid);
  if (pit == model.solid_prop_index.end())
    detail::fail(model, s.ref, card, s.id, "3 (PID)",
                 "references property " + std::to_string(s.pid) + ", which is not defined; expected the id of a PSOLID card");
  const SolidProperty& prop = model.solid_props[pit->second];
  if (!model.mat1_index.count(prop.mid)) {
    const char* other = model.mat2_index.count(prop.mid) ? "MAT2" : model.mat8_index.count(prop.mid) ? "MAT8" : nullptr;
    detail::fail(model, prop.ref, "PSOLID", prop.id, "3 (MID)",
                 "references material " + std::to_string(prop.mid) +
                     (other ? std::string(", a ") + other + " (a shell material)" : std::string(", which is not defined")) +
                     "; expected the id of a MAT1 card (solids support isotropic MAT1 only)");
  }
  const IsotropicMaterial mat = detail::material(model, prop.mid, prop.ref, "PSOLID", prop.id, "3 (MID)");
  if (!(mat.E > 0.0) || !(mat.nu > -1.0 && mat.nu < 0.5))
    detail::fail(model, prop.ref, "PSOLID", prop.id, "3 (MID)",
                 "MAT1 " + std::to_string(mat.id) + " has E = " + std::to_string(mat.E) + ", nu = " + std::to_string(mat.nu) +
                     "; a solid needs E > 0 and -1 < nu < 0.5");
  e.D = isotropic_elasticity(mat.E, mat.nu);
  e.rho = mat.rho;
  const bool linear = s.nnode == 8 || s.nnode == 6 || s.nnode == 4;
  using In = SolidProperty::Integration;
  using Isop = SolidProperty::Isop;
  if (!linear) {
    if (!mass_only && (prop.in == In::Two || prop.in == In::Bubble || prop.isop == Isop::Reduced))
      detail::fail(model, prop.ref, "PSOLID", prop.id, "5 (IN) / 7 (ISOP)",
                   std::string("is used by the ") + std::to_string(s.nnode) + "-grid " + card + " " + std::to_string(s.id) +
                       " with reduced integration (IN = TWO or BUBBLE, or ISOP = REDUCED), which seflex does not model; "
                       "expected IN blank or THREE and ISOP blank or FULL (full Gauss integration)");
    e.points = 3;
  } else if (s.shape == Solid::Shape::Hexa) {
    if (!mass_only && prop.in == In::Two && prop.isop != Isop::Full)
      detail::fail(model, prop.ref, "PSOLID", prop.id, "5 (IN) / 7 (ISOP)",
                   "IN = TWO with ISOP blank or REDUCED (reduced shear integration) is not modelled; expected IN blank or "
                   "BUBBLE (bubble functions, the default) or ISOP = FULL (2 x 2 x 2 Gauss)");
    if (prop.in == In::Three) {
      e.points = 3;
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
  PointData p;
  double sign = 0;
  auto check = [&](const Eigen::Vector3d& xi) {
    evaluate(e, xi, p);
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
