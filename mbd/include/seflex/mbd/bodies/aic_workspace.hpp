#pragma once
// Scratch of the AIC kernel (frame recovery, elastic force, inertia) for one body: every
// intermediate matrix of an evaluation lives here, sized at the first evaluation and reused, so
// the time loop allocates nothing (issue 12; tests/alloc). Held per body in Data (FlexibleBodyData).
// Names follow the kernels (aic_element.cpp, aic_inertia.cpp); sizes with n = 6N + m.
#include <Eigen/Core>
#include <array>
#include <vector>

namespace seflex::mbd {

struct AicWorkspace {
  // Elastic force and tangent.
  Eigen::VectorXd g, fw;             ///< n      K xi, Tx^T K xi
  Eigen::MatrixXd n6;                ///< n x 6  products with Phi_rig; the tangent's L (right factor ZxL)
  Eigen::MatrixXd PK;                ///< 6 x n  the tangent's R (left factor Zx^T)
  Eigen::MatrixXd S3;                ///< n x 3  stacked skew matrices
  // Inertia in body axes and its world rotation.
  Eigen::VectorXd w, ab, fi, c, xid; ///< n
  Eigen::MatrixXd Mw, Cw, Ki;        ///< n x n
  // Full inertia from the invariants.
  Eigen::MatrixXd PmE, MR, Q;        ///< n x 6
  Eigen::MatrixXd sixn;              ///< 6 x n
  Eigen::VectorXd t, q, pm, v1, v2;  ///< n, 9n (q), scratch
  Eigen::VectorXd eta_f;             ///< n - 6: V_f^T xi or V_f^T xi_dot (AicElement::V_f)
  Eigen::MatrixXd CLp, GPp, GVp, DOp, n3;  ///< n x 6, n x 3 (GPp, GVp, DOp, n3)
  std::array<Eigen::MatrixXd, 3> HGPxi;    ///< 3 x n
  Eigen::MatrixXd Ap, Ae, Xp, Xe;    ///< n x n, 6 x n, n x n (the velocity tangent's B), 6 x n
  Eigen::MatrixXd nn;                ///< n x n scratch
  Eigen::MatrixXd AOm, AD, ADPhi;    ///< n x 3, n x n (nodal reference only), n x 6 (the velocity tangent's L)
  // Geometric stiffening (aic_stiffening.cpp).
  Eigen::VectorXd sw, sab, sc, sxid;  ///< n: body-axis velocities, accelerations, c, xi_dot
  Eigen::VectorXd Uxi;                ///< r n: U_i xi for every basis matrix i (AicElement::G_basis), stacked
  Eigen::VectorXd yx;                 ///< r: xi^T U_i xi
  Eigen::VectorXd Gxi;                ///< 12 n: G_c xi for the inertia cases c < 12 (formed for the tangents)
  bool Gxi_formed = false;            ///< Gxi belongs to the current Uxi
  Eigen::VectorXd Uxi_at;             ///< the xi of Uxi: reused while xi and the element are unchanged
  const double* Uxi_of = nullptr;     ///< (FFRF-LM's differences in the frame coordinates keep xi)
  Eigen::VectorXd mu;                 ///< k: [lambda; xi_b + s]
  Eigen::VectorXd Wmu;                ///< r: W mu, sum_c mu_c G_c in the basis U
  Eigen::VectorXd fb, fs;             ///< 6N: foreshortening loads b and their interface displacements s
  Eigen::MatrixXd Qr;                 ///< r x n: 1/2 P Y^T + W_b E^T (the Hessian's interface terms)
  Eigen::MatrixXd YQ;                 ///< n x n: Y Qr
  Eigen::MatrixXd Keff;               ///< n x n: K + Hessian of V_G
};

}  // namespace seflex::mbd
