// CBEND / PBEND curved beam (see element_bend.hpp).
#include "seflex/fem/element_bend.hpp"

#include <Eigen/Cholesky>
#include <Eigen/LU>
#include <cmath>
#include <string>

#include "model_lookup.hpp"
#include "seflex/common/so3.hpp"
#include "seflex/fem/assembly.hpp"

namespace seflex::fem {
namespace {

using Matrix6 = Eigen::Matrix<double, 6, 6>;
constexpr double kPi = 3.14159265358979323846;

// 16-point Gauss-Legendre on [-1, 1] (positive abscissae, weights).
constexpr double kGaussX[8] = {0.095012509837637454, 0.28160355077925892, 0.45801677765722737, 0.61787624440264377, 0.755404408355003, 0.86563120238783176, 0.9445750230732326, 0.98940093499164994};
constexpr double kGaussW[8] = {0.18945061045506859, 0.18260341504492361, 0.16915651939500262, 0.14959598881657676, 0.12462897125553403, 0.095158511682492591, 0.062253523938647706, 0.027152459411754037};

}  // namespace

NodeMatrix<2> bend_stiffness(const BendElement& e) {
  const IsotropicMaterial& m = e.material;
  Matrix6 F = Matrix6::Zero();  // section compliance: N, V_r, V_z, T, M_r, M_z
  F(0, 0) = 1.0 / (m.E * e.A);
  F(1, 1) = e.K1 > 0.0 ? 1.0 / (e.K1 * m.G * e.A) : 0.0;
  F(2, 2) = e.K2 > 0.0 ? 1.0 / (e.K2 * m.G * e.A) : 0.0;
  F(3, 3) = 1.0 / (m.G * e.J);
  F(4, 4) = 1.0 / (m.E * e.I2);
  F(5, 5) = 1.0 / (m.E * e.I1);
  const Eigen::Vector3d ea = (e.x_A - e.center) / e.radius, eb = e.normal.cross(ea);
  Matrix6 C = Matrix6::Zero();  // flexibility of GB, GA clamped, basic (force, moment) -> (u, theta)
  for (int k = 0; k < 16; ++k) {
    const double xi = k < 8 ? -kGaussX[7 - k] : kGaussX[k - 8], w = k < 8 ? kGaussW[7 - k] : kGaussW[k - 8];
    const double phi = 0.5 * e.angle * (1.0 + xi);
    const Eigen::Vector3d r = std::cos(phi) * ea + std::sin(phi) * eb, t = -std::sin(phi) * ea + std::cos(phi) * eb;
    const Eigen::Vector3d x = e.center + e.radius * r;
    Eigen::Matrix3d R;  // section axes t, r, z as rows
    R.row(0) = t;
    R.row(1) = r;
    R.row(2) = e.normal;
    Matrix6 D = Matrix6::Zero();  // section resultants (local) of a tip load (F_B, M_B) in basic
    D.topLeftCorner<3, 3>() = R;
    D.bottomRightCorner<3, 3>() = R;
    D.bottomLeftCorner<3, 3>() = R * so3::skew(e.x_B - x);  // m = M_B + (x_B - x) x F_B
    C += (0.5 * e.angle * e.radius * w) * D.transpose() * F * D;
  }
  const Matrix6 K_BB = C.ldlt().solve(Matrix6::Identity());
  const Matrix6 S = rigid_link(e.x_B - e.x_A);  // GB's motion of GA's rigid motion
  NodeMatrix<2> K;
  K.topLeftCorner<6, 6>() = S.transpose() * K_BB * S;
  K.topRightCorner<6, 6>() = -S.transpose() * K_BB;
  K.bottomLeftCorner<6, 6>() = -K_BB * S;
  K.bottomRightCorner<6, 6>() = K_BB;
  return 0.5 * (K + K.transpose());
}

NodeMatrix<2> bend_mass(const BendElement& e) {
  const double m = (e.material.rho * e.A + e.nsm) * e.radius * e.angle;
  NodeMatrix<2> M = NodeMatrix<2>::Zero();
  for (int n = 0; n < 2; ++n) M.block<3, 3>(6 * n, 6 * n).diagonal().setConstant(0.5 * m);
  return M;
}

BendElement make_bend_element(const Model& model, const Bend& bend) {
  BendElement e;
  const Grid& ga = model.grids[detail::grid_index(model, bend.ga, bend.ref, "CBEND", bend.id, "4 (GA)")];
  const Grid& gb = model.grids[detail::grid_index(model, bend.gb, bend.ref, "CBEND", bend.id, "5 (GB)")];
  e.x_A = ga.x_basic;
  e.x_B = gb.x_basic;
  const auto it = model.bend_prop_index.find(bend.pid);
  if (it == model.bend_prop_index.end())
    detail::fail(model, bend.ref, "CBEND", bend.id, "3 (PID)", "references PBEND " + std::to_string(bend.pid) + ", which is not defined");
  const BendProperty& p = model.bend_props[it->second];
  e.A = p.A, e.I1 = p.I1, e.I2 = p.I2, e.J = p.J, e.K1 = p.K1, e.K2 = p.K2, e.nsm = p.nsm;
  e.material = detail::material(model, p.mid, p.ref, "PBEND", p.id, "3 (MID)");
  if (!(e.material.E > 0.0 && e.material.G > 0.0))
    detail::fail(model, p.ref, "PBEND", p.id, "3 (MID)", "MAT1 " + std::to_string(p.mid) + " needs E > 0 and G > 0 for a curved beam");

  // The orientation: towards G0, or the vector X1-X3 in GA's displacement system.
  const char* ofield = bend.has_g0 ? "6 (G0)" : "6-8 (X1-X3)";
  Eigen::Vector3d d;
  if (bend.has_g0)
    d = model.grids[detail::grid_index(model, bend.g0, bend.ref, "CBEND", bend.id, "6 (G0)")].x_basic - e.x_A;
  else
    d = detail::axes_at(model, ga.cd, e.x_A, bend.ref, "CBEND", bend.id, "4 (GA)") * bend.v;
  const Eigen::Vector3d c = e.x_B - e.x_A;
  const double L = c.norm();
  if (!(L > 0.0)) detail::fail(model, bend.ref, "CBEND", bend.id, "5 (GB)", "GA and GB are at the same point; expected a bend of nonzero chord");
  auto bad = [&](const char* field, const std::string& what) { detail::fail(model, bend.ref, "CBEND", bend.id, field, what); };
  if (!(c.cross(d).norm() > 1e-9 * L * d.norm()))
    bad(ofield, "the orientation is zero or along the chord GA-GB; expected a direction that, with the chord, spans the plane of the arc");
  switch (bend.geom) {
    case 1: {  // centre on the line from GA along d: |C - A| = |C - B|
      const double lambda = c.squaredNorm() / (2.0 * d.dot(c));
      e.center = e.x_A + lambda * d;
      e.normal = (e.x_A - e.center).cross(e.x_B - e.center).normalized();  // the shorter arc
      break;
    }
    case 2: {  // tangent at GA along d: the centre on GA's normal to d, on B's side
      const Eigen::Vector3d dt = d.normalized();
      const Eigen::Vector3d n = (c - c.dot(dt) * dt).normalized();
      const double R = c.squaredNorm() / (2.0 * c.dot(n));
      e.center = e.x_A + R * n;
      e.normal = ((e.x_A - e.center) / R).cross(dt);  // the arc leaves GA along d
      break;
    }
    case 3:
    case 4: {  // radius RB or angle THETAB; the centre on the side of the chord away from d
      double R = p.rb;
      if (bend.geom == 3 && !(R > 0.0))
        bad("9 (GEOM)", "GEOM = 3 and PBEND " + std::to_string(p.id) + " gives no RB; expected the bend radius RB > 0 on the PBEND");
      if (bend.geom == 4) {
        if (!(p.thetab_deg > 0.0 && p.thetab_deg < 180.0))
          bad("9 (GEOM)", "GEOM = 4 and PBEND " + std::to_string(p.id) +
                              " gives no THETAB in (0, 180) degrees; expected the arc angle THETAB on the PBEND");
        R = 0.5 * L / std::sin(0.5 * p.thetab_deg * kPi / 180.0);
      }
      if (!(2.0 * R >= L))
        bad("9 (GEOM)", "the radius RB = " + std::to_string(R) + " of PBEND " + std::to_string(p.id) +
                            " is less than half the chord GA-GB (" + std::to_string(0.5 * L) + "); expected RB >= chord / 2");
      const Eigen::Vector3d w = (d - d.dot(c) / c.squaredNorm() * c).normalized();  // towards d, normal to the chord
      e.center = 0.5 * (e.x_A + e.x_B) - std::sqrt(std::max(0.0, R * R - 0.25 * L * L)) * w;
      e.normal = (e.x_A - e.center).cross(e.x_B - e.center).normalized();
      if (!(e.normal.norm() > 0.5)) e.normal = c.cross(w).normalized();  // a half circle
      break;
    }
    default: bad("9 (GEOM)", "GEOM = " + std::to_string(bend.geom) + "; expected 1, 2, 3 or 4");
  }
  e.radius = (e.x_A - e.center).norm();
  const Eigen::Vector3d ea = (e.x_A - e.center) / e.radius, eb = e.normal.cross(ea), rb = e.x_B - e.center;
  e.angle = std::atan2(rb.dot(eb), rb.dot(ea));
  if (e.angle <= 0.0) e.angle += 2.0 * kPi;
  // a radius up to 1e8 chords: a nearly straight bend (pyNastran's randvar2.bdf: 1e6) loses about
  // log10(R / L) digits to the arc positions about the far centre
  if (!(e.radius < 1e8 * L) || !(std::abs(rb.norm() - e.radius) <= 1e-9 * e.radius))
    bad(ofield, "the orientation gives no circular arc through GA and GB (GEOM = " + std::to_string(bend.geom) + ")");
  return e;
}

}  // namespace seflex::fem
