// CTRIA6 / CQUAD8: MITC7 / MITC9 plates with quadratic membranes (see element_shell_quadratic.hpp).
#include "seflex/fem/element_shell_quadratic.hpp"

#include <Eigen/Dense>
#include <cmath>
#include <string>
#include <vector>

#include "model_lookup.hpp"
#include "seflex/common/error.hpp"

namespace seflex::fem {
namespace {

using Eigen::MatrixXd;
using Eigen::VectorXd;
using Row = Eigen::Matrix<double, 1, Eigen::Dynamic>;
constexpr int kU = 0, kV = 1, kW = 2, kRx = 3, kRy = 4, kRz = 5;

/// Shape functions of the element's fields at one point: `f` for u, v, w, theta_z (quadrilateral:
/// nine-node Lagrange; triangle: six-node, the bubble entry 0), `r` for theta_x, theta_y (the
/// triangle adds the cubic bubble as node 6), `g` for the geometry (quadrilateral nine-node with
/// the serendipity centre, triangle six-node). Natural derivatives d/dr, d/ds.
struct Shapes {
  int n = 9;  ///< nodes incl. the interior one: 9 or 7
  VectorXd f, fr, fs, r, rr, rs;
};

double lag(int i, double t) {  // quadratic Lagrange at -1, 0, 1 (i = -1, 0, 1)
  return i == 0 ? 1 - t * t : 0.5 * t * (t + i);
}
double dlag(int i, double t) { return i == 0 ? -2 * t : t + 0.5 * i; }

constexpr int kQuadR[9] = {-1, 1, 1, -1, 0, 1, 0, -1, 0};
constexpr int kQuadS[9] = {-1, -1, 1, 1, -1, 0, 1, 0, 0};

Shapes quad_shapes(double r, double s) {
  Shapes h;
  h.n = 9;
  h.f.resize(9), h.fr.resize(9), h.fs.resize(9);
  for (int k = 0; k < 9; ++k) {
    h.f[k] = lag(kQuadR[k], r) * lag(kQuadS[k], s);
    h.fr[k] = dlag(kQuadR[k], r) * lag(kQuadS[k], s);
    h.fs[k] = lag(kQuadR[k], r) * dlag(kQuadS[k], s);
  }
  h.r = h.f, h.rr = h.fr, h.rs = h.fs;
  return h;
}

Shapes tri_shapes(double r, double s) {
  Shapes h;
  h.n = 7;
  const double L[3] = {1 - r - s, r, s};
  const double dLr[3] = {-1, 1, 0}, dLs[3] = {-1, 0, 1};
  h.f = VectorXd::Zero(7), h.fr = VectorXd::Zero(7), h.fs = VectorXd::Zero(7);
  for (int i = 0; i < 3; ++i) {
    h.f[i] = L[i] * (2 * L[i] - 1);
    h.fr[i] = (4 * L[i] - 1) * dLr[i];
    h.fs[i] = (4 * L[i] - 1) * dLs[i];
    const int j = (i + 1) % 3;
    h.f[3 + i] = 4 * L[i] * L[j];
    h.fr[3 + i] = 4 * (dLr[i] * L[j] + L[i] * dLr[j]);
    h.fs[3 + i] = 4 * (dLs[i] * L[j] + L[i] * dLs[j]);
  }
  h.r = h.f, h.rr = h.fr, h.rs = h.fs;
  h.r[6] = 27 * L[0] * L[1] * L[2];
  h.rr[6] = 27 * (dLr[0] * L[1] * L[2] + L[0] * dLr[1] * L[2] + L[0] * L[1] * dLr[2]);
  h.rs[6] = 27 * (dLs[0] * L[1] * L[2] + L[0] * dLs[1] * L[2] + L[0] * L[1] * dLs[2]);
  return h;
}

struct Point {
  double r, s, w;  ///< natural coordinates and weight (natural area)
};

std::vector<Point> quad_rule() {
  const double a = std::sqrt(0.6), x[3] = {-a, 0, a}, w[3] = {5.0 / 9, 8.0 / 9, 5.0 / 9};
  std::vector<Point> p;
  for (int i = 0; i < 3; ++i)
    for (int j = 0; j < 3; ++j) p.push_back({x[i], x[j], w[i] * w[j]});
  return p;
}

std::vector<Point> tri_rule() {  // 7 points, degree 5 (natural area 1/2)
  const double q = std::sqrt(15.0);
  std::vector<Point> p{{1.0 / 3, 1.0 / 3, 9.0 / 80}};
  for (const double sign : {-1.0, 1.0}) {
    const double a = (6 + sign * q) / 21, w = (155 + sign * q) / 2400;
    p.push_back({a, a, w});
    p.push_back({1 - 2 * a, a, w});
    p.push_back({a, 1 - 2 * a, w});
  }
  return p;
}

/// The element in its plane: frame, node positions (all nodes incl. the interior one), the rules.
class Facet {
 public:
  explicit Facet(const QuadraticShellElement& e) : e_(e), quad_(e.corners == 4), n_(quad_ ? 9 : 7) {
    const auto& x = e.x;
    const Eigen::Vector3d nrm = quad_ ? (x[2] - x[0]).cross(x[3] - x[1]) : (x[1] - x[0]).cross(x[2] - x[0]);
    SEFLEX_DEMAND(nrm.norm() > 0.0, "quadratic shell of zero area");
    const Eigen::Vector3d e3 = nrm.normalized();
    const Eigen::Vector3d a = (x[1] - x[0]) - (x[1] - x[0]).dot(e3) * e3;
    R_BL_.col(0) = a.normalized();
    R_BL_.col(1) = e3.cross(R_BL_.col(0));
    R_BL_.col(2) = e3;
    c_ = Eigen::Vector3d::Zero();
    for (int k = 0; k < e.corners; ++k) c_ += x[static_cast<std::size_t>(k)] / e.corners;
    p_.assign(static_cast<std::size_t>(n_), Eigen::Vector2d::Zero());
    for (int k = 0; k < 2 * e.corners; ++k) {
      const Eigen::Vector3d r = R_BL_.transpose() * (x[static_cast<std::size_t>(k)] - c_);
      p_[static_cast<std::size_t>(node(k))] = r.head<2>();
    }
    if (quad_) {  // the serendipity centre: the nine-node map equals the eight-node one
      Eigen::Vector2d pc = Eigen::Vector2d::Zero();
      for (int k = 0; k < 4; ++k) pc += -0.25 * p_[static_cast<std::size_t>(k)] + 0.5 * p_[static_cast<std::size_t>(4 + k)];
      p_[8] = pc;
    }
    rule_ = quad_ ? quad_rule() : tri_rule();
  }

  bool quad() const { return quad_; }
  int nodes() const { return n_; }
  int dofs() const { return 6 * n_; }
  const Eigen::Matrix3d& R_BL() const { return R_BL_; }
  const std::vector<Point>& rule() const { return rule_; }
  /// Internal node index of element grid k (0..2 corners-1: corners; then the mid-sides).
  int node(int k) const { return k; }
  Shapes shapes(double r, double s) const { return quad_ ? quad_shapes(r, s) : tri_shapes(r, s); }

  /// J = [x_r y_r; x_s y_s] of the geometry map.
  Eigen::Matrix2d jacobian(const Shapes& h) const {
    Eigen::Matrix2d J = Eigen::Matrix2d::Zero();
    const int ng = quad_ ? 9 : 6;
    for (int k = 0; k < ng; ++k) {
      J.row(0) += h.fr[k] * p_[static_cast<std::size_t>(k)].transpose();
      J.row(1) += h.fs[k] * p_[static_cast<std::size_t>(k)].transpose();
    }
    return J;
  }

  /// Rows (over all dofs) of the covariant transverse shear e_r, e_s = w,_ + theta_y x,_ - theta_x y,_.
  void covariant_shear(double r, double s, Row& er, Row& es) const {
    const Shapes h = shapes(r, s);
    const Eigen::Matrix2d J = jacobian(h);
    er = Row::Zero(dofs()), es = Row::Zero(dofs());
    for (int k = 0; k < n_; ++k) {
      er[6 * k + kW] = h.fr[k], es[6 * k + kW] = h.fs[k];
      er[6 * k + kRy] = h.r[k] * J(0, 0), er[6 * k + kRx] = -h.r[k] * J(0, 1);
      es[6 * k + kRy] = h.r[k] * J(1, 0), es[6 * k + kRx] = -h.r[k] * J(1, 1);
    }
  }

  /// The assumed (MITC) covariant shear at (r, s): 2 x dofs.
  MatrixXd assumed_shear(double r, double s) const {
    MatrixXd out(2, dofs());
    if (quad_) {
      const double a = 1 / std::sqrt(3.0), b = std::sqrt(0.6);
      const double ta[2] = {-a, a}, tb[3] = {-b, 0, b};
      auto P = [&](int i, double t) { return i == 0 ? (a - t) / (2 * a) : (t + a) / (2 * a); };
      auto Q = [&](int j, double t) {
        return j == 1 ? 1 - t * t / (b * b) : t * (t + (j == 0 ? -b : b)) / (2 * b * b);
      };
      out.setZero();
      Row er, es;
      for (int i = 0; i < 2; ++i)
        for (int j = 0; j < 3; ++j) {
          covariant_shear(ta[i], tb[j], er, es);  // e_r tied at (+-a, s_j)
          out.row(0) += P(i, r) * Q(j, s) * er;
          covariant_shear(tb[j], ta[i], er, es);  // e_s tied at (r_j, +-a)
          out.row(1) += Q(j, r) * P(i, s) * es;
        }
      return out;
    }
    const Eigen::Matrix<double, 2, 8> Phi = rt_basis(r, s);
    out = Phi * tri_coefficients();
    return out;
  }

  /// Positions (basic) of the projected nodes: centroid + R_BL (p, 0).
  Eigen::Vector3d projected(int k) const {
    return c_ + R_BL_.leftCols<2>() * p_[static_cast<std::size_t>(node(k))];
  }

 private:
  /// The rotated Raviart-Thomas basis of degree 2 (eight vector fields (phi_r, phi_s)).
  static Eigen::Matrix<double, 2, 8> rt_basis(double r, double s) {
    Eigen::Matrix<double, 2, 8> P = Eigen::Matrix<double, 2, 8>::Zero();
    P(0, 0) = 1, P(0, 1) = r, P(0, 2) = s;
    P(1, 3) = 1, P(1, 4) = r, P(1, 5) = s;
    P(0, 6) = -s * r, P(1, 6) = r * r;
    P(0, 7) = -s * s, P(1, 7) = r * s;
    return P;
  }

  /// MITC7: the coefficients (8 x dofs) of the assumed shear in rt_basis from the tying conditions:
  /// the tangential shear at the two Gauss points of each edge, the means of e_r and e_s.
  MatrixXd tri_coefficients() const {
    if (tri_c_.size() > 0) return tri_c_;
    Eigen::Matrix<double, 8, 8> M;
    MatrixXd L(8, dofs());
    const double g = 1 / std::sqrt(3.0);
    int k = 0;
    Row er, es;
    for (int edge = 0; edge < 3; ++edge)
      for (const double t : {0.5 * (1 - g), 0.5 * (1 + g)}) {
        double r, s;
        Eigen::Vector2d tau;
        if (edge == 0) r = t, s = 0, tau = {1, 0};
        else if (edge == 1) r = 1 - t, s = t, tau = {-1, 1};
        else r = 0, s = 1 - t, tau = {0, -1};
        M.row(k) = tau.transpose() * rt_basis(r, s);
        covariant_shear(r, s, er, es);
        L.row(k) = tau[0] * er + tau[1] * es;
        ++k;
      }
    M.row(6).setZero(), M.row(7).setZero();
    L.row(6).setZero(), L.row(7).setZero();
    for (const Point& q : tri_rule()) {
      const Eigen::Matrix<double, 2, 8> P = rt_basis(q.r, q.s);
      M.row(6) += q.w * P.row(0);
      M.row(7) += q.w * P.row(1);
      covariant_shear(q.r, q.s, er, es);
      L.row(6) += q.w * er;
      L.row(7) += q.w * es;
    }
    tri_c_ = M.fullPivLu().solve(L);
    return tri_c_;
  }

  const QuadraticShellElement& e_;
  bool quad_;
  int n_;
  Eigen::Matrix3d R_BL_;
  Eigen::Vector3d c_;
  std::vector<Eigen::Vector2d> p_;
  std::vector<Point> rule_;
  mutable MatrixXd tri_c_;
};

/// Element matrices and vectors on all nodes (incl. the interior one), element axes.
struct Full {
  MatrixXd K;
  VectorXd f_pressure, f_thermal;
};

Full full_element(const Facet& f, const QuadraticShellElement& e, double k6rot) {
  const int nd = f.dofs(), n = f.nodes();
  Full out;
  out.K = MatrixXd::Zero(nd, nd);
  out.f_pressure = VectorXd::Zero(nd);
  out.f_thermal = VectorXd::Zero(nd);
  const ShellSection& sec = e.section;
  Eigen::Matrix<double, 6, 6> C;
  C << sec.A, sec.B, sec.B, sec.D;
  Eigen::Matrix<double, 6, 1> NM_T;
  NM_T << sec.NT, sec.MT;
  const double c_drill = k6rot * 1e-6 * sec.drill_Gt;
  for (const Point& q : f.rule()) {
    const Shapes h = f.shapes(q.r, q.s);
    const Eigen::Matrix2d J = f.jacobian(h);
    const double dA = J.determinant() * q.w;
    const Eigen::Matrix2d Ji = J.inverse();
    MatrixXd BmBk = MatrixXd::Zero(6, nd);
    Row Bd = Row::Zero(nd);
    for (int k = 0; k < n; ++k) {
      const Eigen::Vector2d df = Ji * Eigen::Vector2d(h.fr[k], h.fs[k]);  // d/dx, d/dy
      const Eigen::Vector2d dr = Ji * Eigen::Vector2d(h.rr[k], h.rs[k]);
      BmBk(0, 6 * k + kU) = df.x();
      BmBk(1, 6 * k + kV) = df.y();
      BmBk(2, 6 * k + kU) = df.y(), BmBk(2, 6 * k + kV) = df.x();
      BmBk(3, 6 * k + kRy) = dr.x();
      BmBk(4, 6 * k + kRx) = -dr.y();
      BmBk(5, 6 * k + kRy) = dr.y(), BmBk(5, 6 * k + kRx) = -dr.x();
      Bd[6 * k + kRz] = h.f[k];
      Bd[6 * k + kV] = -0.5 * df.x();
      Bd[6 * k + kU] = 0.5 * df.y();
      out.f_pressure[6 * k + kW] += h.f[k] * dA;
    }
    const MatrixXd Bg = Ji * f.assumed_shear(q.r, q.s);  // Cartesian gamma_xz, gamma_yz
    out.K.noalias() += dA * (BmBk.transpose() * C * BmBk + Bg.transpose() * sec.S * Bg);
    if (c_drill > 0.0) out.K.noalias() += (c_drill * dA) * Bd.transpose() * Bd;
    out.f_thermal.noalias() += dA * BmBk.transpose() * NM_T;
  }
  return out;
}

/// Kept dofs after the absent mid-side nodes are tied to their edges' corners, and the map from
/// them to all dofs (all = T kept); the interior dofs to condense (indices into kept).
struct Reduction {
  MatrixXd T;
  std::vector<int> boundary_node;  ///< kept boundary node -> element grid index 0..7
  int n_boundary_dofs = 0;
  std::vector<int> interior;       ///< kept dof indices of the interior node's active dofs
};

Reduction reduction(const Facet& f, const QuadraticShellElement& e) {
  Reduction red;
  const int nc = e.corners;
  std::vector<int> kept_nodes;  // internal node ids
  for (int k = 0; k < nc; ++k) kept_nodes.push_back(k), red.boundary_node.push_back(k);
  for (int k = 0; k < nc; ++k)
    if (e.has_mid[static_cast<std::size_t>(k)]) kept_nodes.push_back(nc + k), red.boundary_node.push_back(nc + k);
  red.n_boundary_dofs = 6 * static_cast<int>(kept_nodes.size());
  const int interior_node = f.nodes() - 1;
  kept_nodes.push_back(interior_node);
  const int nk = 6 * static_cast<int>(kept_nodes.size());
  red.T = MatrixXd::Zero(f.dofs(), nk);
  for (std::size_t j = 0; j < kept_nodes.size(); ++j)
    for (int d = 0; d < 6; ++d) red.T(6 * kept_nodes[j] + d, 6 * static_cast<int>(j) + d) = 1.0;
  for (int k = 0; k < nc; ++k) {
    if (e.has_mid[static_cast<std::size_t>(k)]) continue;
    const int m = nc + k, a = k, b = (k + 1) % nc;  // corners a, b are kept nodes a, b
    for (int d = 0; d < 6; ++d) {
      red.T(6 * m + d, 6 * a + d) = 0.5;
      red.T(6 * m + d, 6 * b + d) = 0.5;
    }
  }
  const int i0 = nk - 6;
  for (int d = 0; d < 6; ++d)
    if (f.quad() || d == kRx || d == kRy) red.interior.push_back(i0 + d);
  return red;
}

/// K, f on the boundary dofs: tie the absent mid-sides, condense the interior dofs (those with
/// stiffness; the drilling of the centre has none when K6ROT = 0).
void condense(const Reduction& red, const MatrixXd& K_all, const std::vector<const VectorXd*>& f_all, MatrixXd& Kb,
              std::vector<VectorXd>& fb) {
  const MatrixXd K = red.T.transpose() * K_all * red.T;
  const int nb = red.n_boundary_dofs;
  std::vector<int> in;
  for (const int i : red.interior)
    if (K(i, i) > 1e-14 * K.diagonal().cwiseAbs().maxCoeff()) in.push_back(i);
  const auto ni = static_cast<Eigen::Index>(in.size());
  MatrixXd Kbi(nb, ni), Kii(ni, ni);
  for (Eigen::Index j = 0; j < ni; ++j) {
    Kbi.col(j) = K.col(in[static_cast<std::size_t>(j)]).head(nb);
    for (Eigen::Index i = 0; i < ni; ++i) Kii(i, j) = K(in[static_cast<std::size_t>(i)], in[static_cast<std::size_t>(j)]);
  }
  const Eigen::LDLT<MatrixXd> ldlt(Kii);
  const MatrixXd X = ldlt.solve(Kbi.transpose());  // K_ii^-1 K_ib
  Kb = K.topLeftCorner(nb, nb) - Kbi * X;
  Kb = (0.5 * (Kb + Kb.transpose())).eval();
  fb.clear();
  for (const VectorXd* f : f_all) {
    const VectorXd fr = red.T.transpose() * *f;
    VectorXd fi(ni);
    for (Eigen::Index i = 0; i < ni; ++i) fi[i] = fr[in[static_cast<std::size_t>(i)]];
    fb.push_back(fr.head(nb) - X.transpose() * fi);
  }
}

/// The boundary matrix (element axes, kept grids) as the 48 x 48 basic matrix on grids 0..7 with
/// the rigid links from the grids to their projections.
NodeMatrix<8> to_grids(const Facet& f, const QuadraticShellElement& e, const Reduction& red, const MatrixXd& Kb) {
  NodeMatrix<8> K = NodeMatrix<8>::Zero();
  const std::size_t nk = red.boundary_node.size();
  for (std::size_t a = 0; a < nk; ++a)
    for (std::size_t b = 0; b < nk; ++b)
      K.block<6, 6>(6 * red.boundary_node[a], 6 * red.boundary_node[b]) =
          Kb.block<6, 6>(6 * static_cast<Eigen::Index>(a), 6 * static_cast<Eigen::Index>(b));
  rotate_local_to_basic<8>(f.R_BL(), K);
  std::array<Eigen::Vector3d, 8> d;
  for (int k = 0; k < 8; ++k)
    d[static_cast<std::size_t>(k)] = k < 2 * e.corners ? Eigen::Vector3d(f.projected(k) - e.x[static_cast<std::size_t>(k)])
                                                       : Eigen::Vector3d::Zero();
  apply_node_offsets<8>(d, K);
  return K;
}

Eigen::Matrix<double, 48, 1> load_to_grids(const Facet& f, const QuadraticShellElement& e, const Reduction& red,
                                           const VectorXd& fb) {
  Eigen::Matrix<double, 48, 1> out = Eigen::Matrix<double, 48, 1>::Zero();
  for (std::size_t a = 0; a < red.boundary_node.size(); ++a) {
    const int k = red.boundary_node[a];
    Eigen::Matrix<double, 6, 1> v;
    v << f.R_BL() * fb.segment<3>(6 * static_cast<Eigen::Index>(a)), f.R_BL() * fb.segment<3>(6 * static_cast<Eigen::Index>(a) + 3);
    const Eigen::Vector3d d = f.projected(k) - e.x[static_cast<std::size_t>(k)];
    out.segment<6>(6 * k) = rigid_link(d).transpose() * v;
  }
  return out;
}

Eigen::Matrix<double, 48, 1> load(const QuadraticShellElement& e, double k6rot, bool thermal, double value) {
  const Facet f(e);
  const Full full = full_element(f, e, k6rot);
  const Reduction red = reduction(f, e);
  MatrixXd Kb;
  std::vector<VectorXd> fb;
  condense(red, full.K, {thermal ? &full.f_thermal : &full.f_pressure}, Kb, fb);
  return value * load_to_grids(f, e, red, fb[0]);
}

}  // namespace

NodeMatrix<8> quadratic_shell_stiffness(const QuadraticShellElement& e, double k6rot) {
  const Facet f(e);
  const Full full = full_element(f, e, k6rot);
  const Reduction red = reduction(f, e);
  MatrixXd Kb;
  std::vector<VectorXd> fb;
  condense(red, full.K, {}, Kb, fb);
  return to_grids(f, e, red, Kb);
}

Eigen::Matrix<double, 48, 1> quadratic_shell_pressure_load(const QuadraticShellElement& e, double p, double k6rot) {
  return load(e, k6rot, false, p);
}

Eigen::Matrix<double, 48, 1> quadratic_shell_thermal_load(const QuadraticShellElement& e, double dT, double k6rot) {
  return load(e, k6rot, true, dT);
}

Eigen::Vector3d quadratic_shell_normal(const QuadraticShellElement& e) { return Facet(e).R_BL().col(2); }

NodeMatrix<8> quadratic_shell_mass(const QuadraticShellElement& e, MassKind kind) {
  const Facet f(e);
  const int nc = e.corners, ng = 2 * nc;
  // the serendipity eight-node (quadrilateral) or six-node (triangle) translational field
  MatrixXd Mn = MatrixXd::Zero(ng, ng);
  const double mpa = e.section.mass_per_area();
  for (const Point& q : f.rule()) {
    const Shapes h = f.shapes(q.r, q.s);
    const double dA = f.jacobian(h).determinant() * q.w;
    VectorXd N(ng);
    if (f.quad()) {
      for (int k = 0; k < 4; ++k) {  // serendipity: the Lagrange functions with the centre's shared out
        N[k] = h.f[k] - 0.25 * h.f[8];
        N[4 + k] = h.f[4 + k] + 0.5 * h.f[8];
      }
    } else {
      N = h.f.head(6);
    }
    Mn.noalias() += (mpa * dA) * N * N.transpose();
  }
  // absent mid-side grids: their value the mean of the edge's corners
  MatrixXd T = MatrixXd::Identity(ng, ng);
  for (int k = 0; k < nc; ++k)
    if (!e.has_mid[static_cast<std::size_t>(k)]) {
      T.row(nc + k).setZero();
      T(nc + k, k) = T(nc + k, (k + 1) % nc) = 0.5;
      T.col(nc + k).setZero();
    }
  Mn = (T.transpose() * Mn * T).eval();
  if (kind == MassKind::Lumped) {  // HRZ: the diagonal scaled to the element's mass
    const double total = Mn.sum(), diag = Mn.diagonal().sum();
    const VectorXd m = Mn.diagonal() * (diag > 0.0 ? total / diag : 0.0);
    Mn = m.asDiagonal();
  }
  NodeMatrix<8> M = NodeMatrix<8>::Zero();
  for (int i = 0; i < ng; ++i)
    for (int j = 0; j < ng; ++j)
      if (Mn(i, j) != 0.0) M.block<3, 3>(6 * i, 6 * j) = Mn(i, j) * Eigen::Matrix3d::Identity();
  // the mass sits at the grids: no rigid links (as the CQUAD4's)
  return M;
}

QuadraticShellElement make_quadratic_shell_element(const Model& model, const QuadraticShell& q, const ShellSection* section) {
  const Shell& s = q.shell;
  const char* card = quadratic_shell_card(q);
  QuadraticShellElement e;
  e.corners = s.nnode;
  const int nc = e.corners;
  for (int k = 0; k < nc; ++k)
    e.x[static_cast<std::size_t>(k)] =
        model.grids[detail::grid_index(model, s.g[static_cast<std::size_t>(k)], s.ref, card, s.id, "G" + std::to_string(k + 1))].x_basic;
  for (int k = 0; k < nc; ++k) {
    const auto mk = static_cast<std::size_t>(k);
    e.has_mid[mk] = q.mid[mk] != 0;
    e.x[static_cast<std::size_t>(nc + k)] =
        e.has_mid[mk] ? model.grids[detail::grid_index(model, q.mid[mk], s.ref, card, s.id, "G" + std::to_string(nc + k + 1))].x_basic
                      : Eigen::Vector3d(0.5 * (e.x[mk] + e.x[static_cast<std::size_t>((k + 1) % nc)]));
  }
  const auto& x = e.x;
  const Eigen::Vector3d n = nc == 4 ? (x[2] - x[0]).cross(x[3] - x[1]) : (x[1] - x[0]).cross(x[2] - x[0]);
  if (!(n.norm() > 0.0))
    detail::fail(model, s.ref, card, s.id, "", "its corners lie on one line (zero area); expected a triangle or quadrilateral");
  // convex corners, and a mid-side layout whose map stays one to one (positive Jacobian everywhere)
  for (int k = 0; k < nc; ++k) {
    const Eigen::Vector3d a = x[static_cast<std::size_t>((k + 1) % nc)] - x[static_cast<std::size_t>(k)];
    const Eigen::Vector3d b = x[static_cast<std::size_t>((k + nc - 1) % nc)] - x[static_cast<std::size_t>(k)];
    if (!(a.cross(b).dot(n) > 1e-12 * a.norm() * b.norm() * n.norm()))
      detail::fail(model, s.ref, card, s.id, "G" + std::to_string(k + 1),
                   "the interior angle at G" + std::to_string(k + 1) + " is 180 degrees or more; expected a convex element with its corners in order around it");
  }
  const Eigen::Vector3d e3 = n.normalized();
  const Eigen::Vector3d a = (x[1] - x[0]) - (x[1] - x[0]).dot(e3) * e3, e1 = a.normalized();
  Eigen::Vector3d centroid = Eigen::Vector3d::Zero();
  for (int k = 0; k < nc; ++k) centroid += x[static_cast<std::size_t>(k)] / nc;
  const double theta = detail::material_angle(model, s, e1, e3.cross(e1), centroid);
  e.section = (section ? *section : make_shell_section(model, s)).in_element_axes(theta).offset(s.zoffs);
  const Facet f(e);
  for (const Point& p : f.rule()) {
    const double det = f.jacobian(f.shapes(p.r, p.s)).determinant();
    if (!(det > 0.0))
      detail::fail(model, s.ref, card, s.id, "",
                   "its mid-side grids distort it so much that its map folds over (Jacobian <= 0); expected each mid-side grid "
                   "near the middle of its edge");
  }
  return e;
}

}  // namespace seflex::fem
