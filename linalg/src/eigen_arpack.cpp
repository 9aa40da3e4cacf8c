// ARPACK backend: dsaupd/dseupd in shift-invert mode 3 (bmat = 'G', which = 'LM'), reverse
// communication with OP = (K - sigma M)^-1 M and B = M. For bmat = 'G' ARPACK forces the start vector
// into the range of OP, and dseupd purifies the Ritz vectors, so a singular M is fine.
#include <random>
#include <string>
#include <vector>

#include "shift_invert.hpp"

extern "C" {
// arpack-ng ISO_C_BINDING interface (libarpack2, a_int = int); declared here rather than through
// arpack.h, whose complex prototypes are C99-only.
void dsaupd_c(int* ido, char const* bmat, int n, char const* which, int nev, double tol, double* resid, int ncv,
              double* v, int ldv, int* iparam, int* ipntr, double* workd, double* workl, int lworkl, int* info);
void dseupd_c(int rvec, char const* howmny, int const* select, double* d, double* z, int ldz, double sigma,
              char const* bmat, int n, char const* which, int nev, double tol, double* resid, int ncv, double* v,
              int ldv, int* iparam, int* ipntr, double* workd, double* workl, int lworkl, int* info);
}

namespace seflex::linalg {

KrylovResult run_arpack(ShiftInvertOperator& op, int nev, int ncv, double tol, int max_restarts, unsigned seed) {
  const Eigen::Index n64 = op.rows();
  SEFLEX_DEMAND(n64 < (Eigen::Index{1} << 31) / (ncv + 1), "ARPACK: problem too large for 32-bit indices");
  const int n = static_cast<int>(n64);
  std::vector<double> resid(static_cast<std::size_t>(n)), v(static_cast<std::size_t>(n) * static_cast<std::size_t>(ncv)),
      workd(3 * static_cast<std::size_t>(n));
  const int lworkl = ncv * (ncv + 8);
  std::vector<double> workl(static_cast<std::size_t>(lworkl));
  std::mt19937_64 rng(seed);
  std::uniform_real_distribution<double> uniform(-1.0, 1.0);
  for (double& r : resid) r = uniform(rng);
  int iparam[11] = {0}, ipntr[11] = {0};
  iparam[0] = 1;             // exact shifts
  iparam[2] = max_restarts;  // maximum Arnoldi update iterations
  iparam[6] = 3;             // mode 3: shift-invert, generalised
  int ido = 0, info = 1;     // info = 1: resid holds the start vector
  const char bmat[] = "G", which[] = "LM";
  for (;;) {
    dsaupd_c(&ido, bmat, n, which, nev, tol, resid.data(), ncv, v.data(), n, iparam, ipntr, workd.data(), workl.data(),
             lworkl, &info);
    double* x = workd.data() + ipntr[0] - 1;
    double* y = workd.data() + ipntr[1] - 1;
    if (ido == -1) {
      op.apply(x, y);  // y = OP x
    } else if (ido == 1) {
      op.apply_inverse(workd.data() + ipntr[2] - 1, y);  // M x is at ipntr[2]
    } else if (ido == 2) {
      op.apply_M(x, y);
    } else {
      break;
    }
  }
  KrylovResult result;
  result.restarts = iparam[2];
  if (info < 0) SEFLEX_DEMAND(false, "ARPACK dsaupd failed (info " + std::to_string(info) + ")");
  result.converged = info == 0;
  const int nconv = iparam[4];
  if (nconv <= 0) return result;
  std::vector<int> select(static_cast<std::size_t>(ncv), 1);
  Eigen::VectorXd d(nev);
  Eigen::MatrixXd z(n, nev);
  int ierr = 0;
  // sigma = 0: dseupd then returns 1/theta, and theta is what the caller wants.
  dseupd_c(1, "A", select.data(), d.data(), z.data(), n, 0.0, bmat, n, which, nev, tol, resid.data(), ncv, v.data(), n,
           iparam, ipntr, workd.data(), workl.data(), lworkl, &ierr);
  SEFLEX_DEMAND(ierr == 0, "ARPACK dseupd failed (info " + std::to_string(ierr) + ")");
  // dseupd orders 1/theta ascending: theta descending, as promised.
  result.theta = d.head(nconv).cwiseInverse();
  result.vectors = z.leftCols(nconv);
  return result;
}

}  // namespace seflex::linalg
