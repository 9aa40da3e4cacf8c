// Grid point weight generator (see mass_properties.hpp).
#include "seflex/fem/mass_properties.hpp"

#include <Eigen/Eigenvalues>
#include <array>
#include <cstdint>
#include <vector>

#include "model_lookup.hpp"
#include "seflex/fem/finalize.hpp"
#include "seflex/fem/assembly.hpp"
#include "seflex/fem/element_bar.hpp"
#include "seflex/fem/element_bend.hpp"
#include "seflex/fem/element_bush.hpp"
#include "seflex/fem/element_conm1.hpp"
#include "seflex/fem/element_conm2.hpp"
#include "seflex/fem/element_rod.hpp"
#include "seflex/fem/element_shear_panel.hpp"
#include "seflex/fem/element_shell_quad4.hpp"
#include "seflex/fem/element_shell_quadratic.hpp"
#include "seflex/fem/element_solid.hpp"
#include "seflex/fem/element_shell_tria3.hpp"

namespace seflex::fem {
namespace {

using Matrix6 = Eigen::Matrix<double, 6, 6>;

// M0 += D^T M D for an element matrix on N nodes in basic.
template <int N>
void add_element(const std::array<Eigen::Vector3d, N>& x, const Eigen::Vector3d& ref, const NodeMatrix<N>& M,
                 Matrix6& M0) {
  const Eigen::Matrix<double, 6 * N, 6> D = rigid_body_modes<N>(x, ref);
  M0.noalias() += D.transpose() * M * D;
}

// M0 += rigid mass of a point mass m at r (relative to the reference point): [m I, -m S; m S, -m S^2].
void add_point_mass(double m, const Eigen::Vector3d& r, Matrix6& M0) {
  const Eigen::Matrix3d S = so3::skew(r);
  M0.topLeftCorner<3, 3>().diagonal().array() += m;
  M0.topRightCorner<3, 3>() -= m * S;
  M0.bottomLeftCorner<3, 3>() += m * S;
  M0.bottomRightCorner<3, 3>() -= m * S * S;
}

}  // namespace

MassProperties mass_properties(const Model& model, std::optional<int> reference_grid) {
  MassProperties mp;
  const AssemblyOptions opt = assembly_options(model);
  mp.wtmass = opt.wtmass;
  const int grdpnt = reference_grid ? *reference_grid : static_cast<int>(param_number(model, "GRDPNT"));
  if (grdpnt > 0) {
    if (const auto it = model.grid_index.find(grdpnt); it != model.grid_index.end()) {
      mp.reference_grid = grdpnt;
      mp.reference = model.grids[it->second].x_basic;
    }
  }
  const Eigen::Vector3d& ref = mp.reference;
  const MassKind kind = opt.mass;
  Matrix6 M0 = Matrix6::Zero();

  for (const Bar& b : model.bars) {
    const BarElement e = make_bar_element(model, b);
    add_element<2>({e.x_A, e.x_B}, ref, bar_mass(e, kind), M0);
  }
  for (const Rod& r : model.rods) {
    const RodElement e = make_rod_element(model, r);
    add_element<2>({e.x_A, e.x_B}, ref, rod_mass(e, kind), M0);
  }
  detail::ShellSectionCache sections;
  std::vector<double> grid_mass;  // lumped CQUAD4 masses by grid index
  for (const Shell& s : model.shells) {
    const ShellSection& sec = sections.get(model, s);
    if (s.nnode == 4) {
      if (kind == MassKind::Lumped) {
        // Fast path: four point masses (no element object needed beyond the corner positions).
        // Their masses are summed per grid first (grid_mass), and each grid's sum added to M0 once.
        Quad4Element e;
        e.section = sec;
        std::uint32_t gi[4];
        for (int k = 0; k < 4; ++k) {
          gi[k] = detail::grid_index(model, s.g[k], s.ref, shell_card(s), s.id, "G");
          e.x[k] = model.grids[gi[k]].x_basic;
        }
        const auto m = quad4_lumped_masses(e);
        if (grid_mass.empty()) grid_mass.assign(model.grids.size(), 0.0);
        for (int k = 0; k < 4; ++k) grid_mass[gi[k]] += m[k];
      } else {
        const Quad4Element e = make_quad4_element(model, s, &sec);
        add_element<4>(e.x, ref, quad4_mass(e, kind), M0);
      }
    } else {
      const Tria3Element e = make_tria3_element(model, s, &sec);
      add_element<3>(e.x, ref, tria3_mass(e, kind), M0);
    }
  }
  for (std::size_t i = 0; i < grid_mass.size(); ++i)
    if (grid_mass[i] != 0.0) add_point_mass(grid_mass[i], model.grids[i].x_basic - ref, M0);
  for (const Solid& so : model.solids) {  // translations only: D_e = [I, -skew(x_a - ref)] per grid
    const SolidElement e = make_solid_element(model, so, true);
    const Eigen::MatrixXd M = solid_mass(e, kind);
    Eigen::MatrixXd D = Eigen::MatrixXd::Zero(3 * e.nnode, 6);
    for (int a = 0; a < e.nnode; ++a) D.block<3, 6>(3 * a, 0) = rigid_link(e.x[static_cast<std::size_t>(a)] - ref).topRows<3>();
    M0 += D.transpose() * M * D;
  }
  for (const QuadraticShell& q : model.shells8) {
    const QuadraticShellElement e = make_quadratic_shell_element(model, q, &sections.get(model, q.shell));
    add_element<8>(e.x, ref, quadratic_shell_mass(e, kind), M0);
  }
  for (const Bend& b : model.bends) {
    const BendElement e = make_bend_element(model, b);
    add_element<2>({e.x_A, e.x_B}, ref, bend_mass(e), M0);
  }
  for (const ShearPanel& s : model.shear_panels) {
    const ShearPanelElement e = make_shear_panel_element(model, s);
    add_element<4>(e.x, ref, shear_panel_mass(e), M0);
  }
  for (const Bush& b : model.bushes) {
    const BushElement e = make_bush_element(model, b);
    if (e.mass != 0.0) add_element<2>({e.x_A, e.x_B}, ref, bush_mass(e), M0);
  }
  for (const Conm2& c : model.conm2) {
    const Conm2Element e = make_conm2_element(model, c);
    add_element<1>({e.x_grid}, ref, conm2_mass(e), M0);
  }
  for (const Conm1& c : model.conm1) {
    const Grid& g = model.grids[detail::grid_index(model, c.grid, c.ref, "CONM1", c.id, "3 (G)")];
    add_element<1>({g.x_basic}, ref, conm1_mass(model, c), M0);
  }
  M0 = 0.5 * (M0 + M0.transpose()).eval();
  mp.M0 = M0;

  // GPWG summary: M0 = [m I, -m skew(c); m skew(c), J_ref], c = CG - reference.
  mp.mass = M0.topLeftCorner<3, 3>().trace() / 3.0;
  Eigen::Vector3d c = Eigen::Vector3d::Zero();
  if (mp.mass > 0.0) c = Eigen::Vector3d(M0(1, 5), M0(2, 3), M0(0, 4)) / mp.mass;
  mp.cg = ref + c;
  mp.I_cg = M0.bottomRightCorner<3, 3>() - mp.mass * (c.squaredNorm() * Eigen::Matrix3d::Identity() - c * c.transpose());
  mp.I_cg = 0.5 * (mp.I_cg + mp.I_cg.transpose()).eval();
  const Eigen::SelfAdjointEigenSolver<Eigen::Matrix3d> es(mp.I_cg);
  mp.principal_moments = es.eigenvalues();
  mp.principal_axes = es.eigenvectors();
  if (mp.principal_axes.determinant() < 0.0) mp.principal_axes.col(2) *= -1.0;
  return mp;
}

}  // namespace seflex::fem
