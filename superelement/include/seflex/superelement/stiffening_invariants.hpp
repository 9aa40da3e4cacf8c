#pragma once
// Geometric-stiffness (stress-stiffening) invariants of a superelement (docs/geometric-stiffening.md):
// the differential stiffness K_sigma of the FE model for the stress states a body in motion carries,
// projected on the Craig-Bampton basis once by `seflex reduce`, so that the run adds the stiffening
// of its current inertia and interface loads at a cost set by the reduced size n alone.
//
// With B = [Psi Phi] the basis (q = [u_1; theta_1; ...; u_N; theta_N; eta], interface amplitudes in
// body axes), each matrix is G = B^T K_sigma(s) B for one stress state s:
//   inertia[c]   the body held at its interface nodes under the d'Alembert load of a unit rigid-body
//                acceleration of the frame: c = 0..2 unit acceleration of the frame origin along x, y, z
//                (load -M E0 e_c), c = 3..5 unit angular acceleration about x, y, z (-M E0 e_c),
//                c = 6..11 the centrifugal field of W = Om~ Om~ = sum_s w_s S_s (load -M L_s(X), with
//                S_s and L_s as in inertia_invariants.hpp, s = xx, yy, zz, xy, xz, yz);
//   interface[j] the j-th constraint mode (unit displacement or rotation j of the interface, the other
//                interface dofs held), j = 0..6N-1.
// In the run (load factors lambda = [a_o - g; alpha; w_s] of the frame, all in body axes) the body's
// stress stiffness is
//   K_G(lambda, q) = sum_c lambda_c inertia[c] + sum_j q_j interface[j]
// with the stress held at the current loads (docs/geometric-stiffening.md says why not the cubic
// energy); the fixed-interface modes' own dynamic stresses are left out (the inertia load cases carry
// the quasi-static part of them).
#include <Eigen/Core>
#include <array>
#include <vector>

namespace seflex::se {

struct StiffeningInvariants {
  int n = 0;  ///< reduced size the matrices belong to; 0 = absent
  static constexpr int kInertiaCases = 12;
  std::array<Eigen::MatrixXd, kInertiaCases> inertia;  ///< n x n each, symmetric
  std::vector<Eigen::MatrixXd> interface;              ///< 6N of them, n x n each, symmetric

  bool present() const { return n > 0; }
};

}  // namespace seflex::se
