// CBUSH element (see element_bush.hpp).
#include "seflex/fem/element_bush.hpp"

#include <cmath>
#include <string>

#include "model_lookup.hpp"

namespace seflex::fem {

BushElement make_bush_element(const Model& model, const Bush& b) {
  const char* card = bush_card(b);
  const char* prop_card = b.one_d ? "PBUSH1D" : "PBUSH";
  const char* cid_field = b.one_d ? "6 (CID)" : "9 (CID)";
  BushElement e;
  const auto it = model.bush_prop_index.find(b.pid);
  if (it == model.bush_prop_index.end())
    detail::fail(model, b.ref, card, b.id, "3 (PID)", "references " + std::string(prop_card) + " " + std::to_string(b.pid) + ", which is not defined");
  const BushProperty& p = model.bush_props[it->second];
  if (p.one_d != b.one_d)
    detail::fail(model, b.ref, card, b.id, "3 (PID)", "references " + std::string(p.one_d ? "PBUSH1D" : "PBUSH") + " " + std::to_string(b.pid) +
                                                          "; expected a " + prop_card + " card");
  e.k = p.k;
  e.mass = p.one_d ? p.mass : 0.0;
  const Grid& ga = model.grids[detail::grid_index(model, b.ga, b.ref, card, b.id, "4 (GA)")];
  e.x_A = ga.x_basic;
  e.grounded = b.gb == 0;
  e.x_B = e.grounded ? e.x_A : model.grids[detail::grid_index(model, b.gb, b.ref, card, b.id, "5 (GB)")].x_basic;
  const Eigen::Vector3d d = e.x_B - e.x_A;
  const double L = d.norm();
  // QRG CBUSH remark: with GA and GB closer than 1e-4 (or GB blank) the axes come from CID.
  const bool coincident = e.grounded || L < 1e-4;
  if (b.cid >= 0) {
    e.R_BE = detail::axes_at(model, b.cid, e.x_A, b.ref, card, b.id, cid_field);
  } else if (coincident) {
    detail::fail(model, b.ref, card, b.id, cid_field,
                 e.grounded ? "blank, and GB is blank (grounded); expected a coordinate system for the element axes"
                            : "blank, and GA and GB coincide; expected a coordinate system for the element axes");
  } else if (b.one_d) {  // only x matters (K along it): y, z any pair completing a right-handed frame
    const Eigen::Vector3d ex = d / L;
    Eigen::Vector3d t = Eigen::Vector3d::Unit(0);
    if (std::abs(ex.x()) > 0.9) t = Eigen::Vector3d::Unit(1);
    const Eigen::Vector3d ez = ex.cross(t).normalized();
    e.R_BE.col(0) = ex;
    e.R_BE.col(1) = ez.cross(ex);
    e.R_BE.col(2) = ez;
  } else {
    Eigen::Vector3d v;
    if (b.has_g0) {
      v = model.grids[detail::grid_index(model, b.g0, b.ref, card, b.id, "6 (GO)")].x_basic - e.x_A;
    } else if (b.has_v) {
      v = ga.cd == 0 ? b.v : Eigen::Vector3d(detail::axes_at(model, ga.cd, e.x_A, b.ref, card, b.id, "6-8 (X1-X3)") * b.v);
    } else {
      detail::fail(model, b.ref, card, b.id, "6-8 (GO/X1-X3)", "blank and CID blank; expected an orientation vector, a grid GO or CID");
    }
    const Eigen::Vector3d ex = d / L;
    const Eigen::Vector3d zz = ex.cross(v);
    if (!(zz.norm() > 1e-9 * v.norm()))
      detail::fail(model, b.ref, card, b.id, b.has_g0 ? "6 (GO)" : "6-8 (X1-X3)",
                   "orientation vector is zero or parallel to GA-GB; expected a vector off the element axis");
    const Eigen::Vector3d ez = zz.normalized();
    e.R_BE.col(0) = ex;
    e.R_BE.col(1) = ez.cross(ex);
    e.R_BE.col(2) = ez;
  }
  if (b.ocid >= 0) {
    const Eigen::Matrix3d A = detail::axes_at(model, b.ocid, e.x_A, b.ref, card, b.id, "3 of continuation 1 (OCID)");
    e.p_P = e.x_A + A * b.s_ocid;
  } else {
    if (!(b.s >= 0.0 && b.s <= 1.0))
      detail::fail(model, b.ref, card, b.id, "2 of continuation 1 (S)", "S = " + std::to_string(b.s) + "; expected 0 <= S <= 1");
    e.p_P = e.x_A + b.s * d;
  }
  return e;
}

NodeMatrix<2> bush_stiffness(const BushElement& e) {
  Matrix6 Ke = Matrix6::Zero();
  for (int i = 0; i < 6; ++i) Ke(i, i) = e.k[i];
  NodeMatrix<1> K1 = Ke;
  rotate_local_to_basic<1>(e.R_BE, K1);
  NodeMatrix<2> K = NodeMatrix<2>::Zero();
  if (e.grounded) {
    K.topLeftCorner<6, 6>() = K1;
    apply_node_offsets<2>({e.p_P - e.x_A, Eigen::Vector3d::Zero()}, K);
    return K;
  }
  K.topLeftCorner<6, 6>() = K1;
  K.bottomRightCorner<6, 6>() = K1;
  K.topRightCorner<6, 6>() = -K1;
  K.bottomLeftCorner<6, 6>() = -K1;
  apply_node_offsets<2>({e.p_P - e.x_A, e.p_P - e.x_B}, K);
  return K;
}

NodeMatrix<2> bush_mass(const BushElement& e) {
  NodeMatrix<2> M = NodeMatrix<2>::Zero();
  for (int i = 0; i < 3; ++i) {
    M(i, i) = 0.5 * e.mass;
    if (!e.grounded) M(6 + i, 6 + i) = 0.5 * e.mass;
  }
  return M;
}

}  // namespace seflex::fem
