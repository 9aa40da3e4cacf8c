#pragma once
// The datasets of the inertia invariants (format 1.2) and geometric-stiffness invariants (1.3) in a superelement file (
// docs/superelement-format.md): one table, used by the writer, the reader and `seflex info`, so
// names and shapes cannot drift apart. Internal to io/.
#include <Eigen/Core>
#include <string>
#include <type_traits>

#include "seflex/superelement/inertia_invariants.hpp"
#include "seflex/superelement/stiffening_invariants.hpp"

namespace seflex::io::detail {

/// Calls f(name, matrix, rows, cols) for every field of `inv` (const or not), with the shape the
/// field must have for a body of reduced size n with m fixed-interface modes. Dataset names are "inv." + the field name, and
/// "inv.FIELD.k" for the k-th member of an array field. Fixed-size fields pass their Eigen matrix.
template <class Inv, class F>
void for_each_invariant_dataset(Inv& inv, Eigen::Index n, Eigen::Index m, F&& f) {
  static_assert(std::is_same_v<std::remove_const_t<Inv>, se::InertiaInvariants>);
  auto each = [&](const char* field, auto& arr, Eigen::Index rows, Eigen::Index cols) {
    for (std::size_t k = 0; k < arr.size(); ++k)
      f(std::string("inv.") + field + "." + std::to_string(k), arr[k], rows, cols);
  };
  const std::string p = "inv.";
  f(p + "Mpp", inv.Mpp, n, n);
  f(p + "PmE0", inv.PmE0, n, 6);
  f(p + "E0mE0", inv.E0mE0, 6, 6);
  f(p + "HP", inv.HP, 3 * n, n);
  f(p + "HE0", inv.HE0, 18, n);
  f(p + "HE1", inv.HE1, 9 * n, n);
  f(p + "PmLX", inv.PmLX, n, 6);
  f(p + "E0mLX", inv.E0mLX, 6, 6);
  each("PmLP", inv.PmLP, n, n);
  each("E0mLP", inv.E0mLP, 6, n);
  f(p + "HLX", inv.HLX, 18, n);
  each("HLP", inv.HLP, 3 * n, n);
  each("PmGP", inv.PmGP, n, n);
  each("E0mGP", inv.E0mGP, 6, n);
  each("HGP", inv.HGP, 3 * n, n);
  f(p + "PgOO", inv.PgOO, n, 9);
  f(p + "EgOO", inv.EgOO, 3, 9);
  each("PgOV", inv.PgOV, n, n);
  each("EgOV", inv.EgOV, 3, n);
  f(p + "mode_max_translation", inv.mode_max_translation, m, 1);
}

/// Calls f(name, matrix, rows, cols) for every matrix of the geometric-stiffness invariants (format 1.3):
/// "stiff.inertia.c" (c = 0..11) and "stiff.interface.j" (j = 0..6N-1), each n x n. The interface vector
/// of a non-const `st` is sized to 6N first.
template <class St, class F>
void for_each_stiffening_dataset(St& st, Eigen::Index n, int N, F&& f) {
  static_assert(std::is_same_v<std::remove_const_t<St>, se::StiffeningInvariants>);
  if constexpr (!std::is_const_v<St>) st.interface.resize(static_cast<std::size_t>(6 * N));
  for (std::size_t c = 0; c < st.inertia.size(); ++c) f("stiff.inertia." + std::to_string(c), st.inertia[c], n, n);
  for (std::size_t j = 0; j < static_cast<std::size_t>(6 * N) && j < st.interface.size(); ++j)
    f("stiff.interface." + std::to_string(j), st.interface[j], n, n);
}

/// The stiffening invariants of the same body with its first n_new coordinates: each matrix's
/// top-left corner (exact: G = B^T K_sigma B, and the stress states do not depend on the modes kept).
inline se::StiffeningInvariants truncate_stiffening(const se::StiffeningInvariants& st, Eigen::Index n_new) {
  if (!st.present()) return st;
  se::StiffeningInvariants out = st;
  out.n = static_cast<int>(n_new);
  for (auto& G : out.inertia) G = G.topLeftCorner(n_new, n_new).eval();
  for (auto& G : out.interface) G = G.topLeftCorner(n_new, n_new).eval();
  return out;
}

/// Total bytes of the invariants' datasets for reduced size n (float64).
inline std::uint64_t invariant_bytes(Eigen::Index n, Eigen::Index m) {
  se::InertiaInvariants dummy;
  std::uint64_t total = 0;
  for_each_invariant_dataset(dummy, n, m, [&](const std::string&, auto&, Eigen::Index r, Eigen::Index c) {
    total += static_cast<std::uint64_t>(r * c) * 8;
  });
  return total;
}

/// The invariants of the same body with only its first n_new reduced coordinates (fewer
/// fixed-interface modes): every index of size n in the tensors is a column of the recovery
/// matrix, and T[r, c, k] is stored with r fastest, so the truncation is each field's top-left
/// corner of the shape the table gives for n_new. Exact (the invariants are sums over FE nodes of
/// products of recovery columns).
inline se::InertiaInvariants truncate_invariants(const se::InertiaInvariants& inv, Eigen::Index n_new) {
  if (!inv.present()) return inv;
  se::InertiaInvariants out = inv;
  out.n = static_cast<int>(n_new);
  const Eigen::Index m_new = n_new - (inv.n - inv.mode_max_translation.size());  // the 6N interface columns stay
  for_each_invariant_dataset(out, n_new, m_new, [](const std::string&, auto& A, Eigen::Index r, Eigen::Index c) {
    if (A.rows() != r || A.cols() != c) A = A.topLeftCorner(r, c).eval();
  });
  return out;
}

}  // namespace seflex::io::detail
