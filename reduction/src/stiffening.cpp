// Geometric-stiffness invariants of a Craig-Bampton superelement (stiffening.hpp).
#include "seflex/reduction/stiffening.hpp"

#include "seflex/common/error.hpp"
#include "seflex/common/so3.hpp"
#include "seflex/fem/assembly.hpp"
#include "seflex/fem/geometric_stiffness.hpp"
#include "seflex/superelement/symmetric_basis.hpp"

namespace seflex::reduction {

Eigen::MatrixXd inertia_load_cases(const fem::Model& model, const fem::DofMap& dofs,
                                   const Eigen::SparseMatrix<double>& M_gg, const Eigen::Vector3d& p_frame) {
  const auto axes = fem::grid_cd_axes(model);
  Eigen::MatrixXd D = Eigen::MatrixXd::Zero(static_cast<Eigen::Index>(dofs.size()), 12);
  for (std::size_t i = 0; i < model.grids.size(); ++i) {
    const Eigen::Vector3d X = model.grids[i].x_basic - p_frame;
    Eigen::Matrix<double, 6, 12> B = Eigen::Matrix<double, 6, 12>::Zero();  // basic components
    B.block<3, 3>(0, 0).setIdentity();
    B.block<3, 3>(0, 3) = -so3::skew(X);
    B.block<3, 3>(3, 3).setIdentity();
    for (int s = 0; s < 6; ++s) B.block<3, 1>(0, 6 + s) = se::sym_basis(s) * X;
    if (const auto& A = axes[i]) {  // CD components = A^T basic
      B.topRows<3>() = A->transpose() * B.topRows<3>();
      B.bottomRows<3>() = A->transpose() * B.bottomRows<3>();
    }
    for (int k = 0; k < 6; ++k) D.row(dofs.grid_dof(static_cast<Eigen::Index>(i), k + 1)) = B.row(k);
  }
  return -(M_gg * D);
}

se::StiffeningInvariants compute_stiffening_invariants(const fem::Model& model, const fem::DofMap& dofs,
                                                       const Eigen::SparseMatrix<double>& T_gf,
                                                       const Eigen::MatrixXd& B_f, Eigen::Index n_b,
                                                       const Eigen::MatrixXd& inertia_responses_f, int part,
                                                       int parts) {
  SEFLEX_DEMAND(B_f.rows() == T_gf.cols() && inertia_responses_f.rows() == T_gf.cols(),
                "stiffening invariants: the basis and the responses need one row per f-dof");
  SEFLEX_DEMAND(inertia_responses_f.cols() == se::StiffeningInvariants::kInertiaCases,
                "stiffening invariants: 12 inertia responses expected");
  SEFLEX_DEMAND(n_b >= 0 && n_b <= B_f.cols() && n_b % 6 == 0, "stiffening invariants: bad interface size");
  SEFLEX_DEMAND(parts >= 1 && part >= 0 && part < parts, "stiffening invariants: bad share of the cases");
  const Eigen::MatrixXd B_g = T_gf * B_f;  // g x n
  se::StiffeningInvariants out;
  out.n = static_cast<int>(B_f.cols());
  auto project = [&](Eigen::Index k, const Eigen::VectorXd& u_f) {
    if (k % parts != part) return Eigen::MatrixXd(Eigen::MatrixXd::Zero(out.n, out.n));  // another part's case
    const Eigen::VectorXd u_g = T_gf * u_f;
    const Eigen::SparseMatrix<double> Ks = fem::assemble_geometric_stiffness(model, dofs, u_g);
    const Eigen::MatrixXd KB = Ks * B_g;
    Eigen::MatrixXd G = B_g.transpose() * KB;
    return Eigen::MatrixXd(0.5 * (G + G.transpose()));
  };
  for (int c = 0; c < se::StiffeningInvariants::kInertiaCases; ++c)
    out.inertia[static_cast<std::size_t>(c)] = project(c, inertia_responses_f.col(c));
  out.interface.reserve(static_cast<std::size_t>(n_b));
  for (Eigen::Index j = 0; j < n_b; ++j)
    out.interface.push_back(project(se::StiffeningInvariants::kInertiaCases + j, B_f.col(j)));
  return out;
}

}  // namespace seflex::reduction
