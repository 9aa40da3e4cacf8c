#pragma once
// The three-stage Radau IIA method (order 5, stage order 3, L-stable, stiffly accurate; Hairer and
// Wanner, Solving ODEs II, sections IV.5 and IV.8) and what its simplified Newton iteration, error
// estimate and dense output need (internal to radau5.cpp; tests/mbd/radau5_test.cpp checks it).
//
// Collocation at c = ((4 - sqrt 6)/10, (4 + sqrt 6)/10, 1): with stage increments Z_i = Y_i - y_0,
//   Z = h (A x I) F(Y),   y_1 = y_0 + Z_3,
// and the stage derivatives are recovered from the increments by A^-1 (the derivative at the nodes
// of the polynomial through (0, 0) and (c_j, Z_j)). A^-1 = T Lambda T^-1 with
//   Lambda = [gamma 0 0; 0 alpha -beta; 0 beta alpha]
// (one real eigenvalue gamma, one complex pair alpha +- i beta), which splits the 3n x 3n Newton
// system into one real and one complex n x n system. The embedded third-order estimate
//   y^_1 - y_1 = gamma0 h f(y_0) + sum_j e_j Z_j,   gamma0 = 1 / gamma,
// is the method with weights b^ on (x_0, x_0 + c_j h) and b^_0 = gamma0 that integrates polynomials
// of degree 2 exactly; with dd = gamma e, (I - h gamma0 J)^-1 (y^_1 - y_1) =
// (gamma/h - J)^-1 (f(y_0) + (1/h) sum_j dd_j Z_j). Everything is computed here from these
// definitions (A in closed form, the rest by 3 x 3 linear algebra), once.
#include <Eigen/Dense>
#include <Eigen/Eigenvalues>
#include <cmath>

namespace seflex::mbd::detail {

struct RadauIIA5 {
  Eigen::Vector3d c;
  Eigen::Matrix3d A, Ainv;
  Eigen::Matrix3d T, Tinv;  ///< Tinv Ainv T = Lambda
  double gamma = 0, alpha = 0, beta = 0;
  Eigen::Vector3d dd;       ///< error estimate: (1/h) sum_j dd_j Z_j

  RadauIIA5() {
    const double s6 = std::sqrt(6.0);
    c << (4 - s6) / 10, (4 + s6) / 10, 1.0;
    A << (88 - 7 * s6) / 360, (296 - 169 * s6) / 1800, (-2 + 3 * s6) / 225,  //
        (296 + 169 * s6) / 1800, (88 + 7 * s6) / 360, (-2 - 3 * s6) / 225,    //
        (16 - s6) / 36, (16 + s6) / 36, 1.0 / 9;
    Ainv = A.inverse();
    const Eigen::EigenSolver<Eigen::Matrix3d> es(Ainv);
    int real = 0;
    for (int k = 1; k < 3; ++k)
      if (std::abs(es.eigenvalues()[k].imag()) < std::abs(es.eigenvalues()[real].imag())) real = k;
    const int cplx = real == 0 ? 1 : 0;
    gamma = es.eigenvalues()[real].real();
    std::complex<double> lam = es.eigenvalues()[cplx];
    Eigen::Vector3cd v = es.eigenvectors().col(cplx);
    if (lam.imag() < 0) {  // take the eigenvalue alpha + i beta, beta > 0
      lam = std::conj(lam);
      v = v.conjugate();
    }
    alpha = lam.real();
    beta = lam.imag();
    // Ainv (x + i y) = (alpha + i beta)(x + i y): Ainv x = alpha x - beta y, Ainv y = beta x + alpha y,
    // so [x y] carries the block [alpha beta; -beta alpha]; [x -y] carries [alpha -beta; beta alpha].
    T.col(0) = es.eigenvectors().col(real).real();
    T.col(1) = v.real();
    T.col(2) = -v.imag();
    Tinv = T.inverse();
    // Embedded weights b^ (with b^_0 = 1/gamma at x_0): exact for 1, x, x^2.
    const double g0 = 1.0 / gamma;
    Eigen::Matrix3d V;
    V << 1, 1, 1, c.transpose(), c.cwiseProduct(c).transpose();
    const Eigen::Vector3d bh = V.inverse() * Eigen::Vector3d(1 - g0, 0.5, 1.0 / 3);
    const Eigen::Vector3d b = A.row(2).transpose();
    dd = gamma * (Ainv.transpose() * (bh - b));
  }

  /// Lagrange basis of the collocation polynomial through (0, 0) and (c_j, Z_j): p(s) = sum_j l_j(s) Z_j.
  Eigen::Vector3d basis(double s) const {
    Eigen::Vector3d l;
    for (int j = 0; j < 3; ++j) {
      double v = s / c[j];
      for (int k = 0; k < 3; ++k)
        if (k != j) v *= (s - c[k]) / (c[j] - c[k]);
      l[j] = v;
    }
    return l;
  }
};

/// The tableau, computed at the first call.
inline const RadauIIA5& radau_iia5() {
  static const RadauIIA5 tableau;
  return tableau;
}

}  // namespace seflex::mbd::detail
