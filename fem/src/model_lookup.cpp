#include "model_lookup.hpp"

#include "seflex/fem/finalize.hpp"
#include "seflex/fem/section.hpp"

#include <cmath>


namespace seflex::fem::detail {

void fail(const Model& model, const CardRef& ref, const std::string& card, int id, const std::string& field,
          const std::string& what) {
  std::string msg = card + " " + std::to_string(id);
  if (!field.empty()) msg += ", field " + field;
  throw InputError(where(model, ref), msg + ": " + what);
}

std::uint32_t grid_index(const Model& model, int grid_id, const CardRef& ref, const std::string& card, int id,
                         const std::string& field) {
  const auto it = model.grid_index.find(grid_id);
  if (it == model.grid_index.end())
    fail(model, ref, card, id, field, "references GRID " + std::to_string(grid_id) + ", which is not defined");
  return it->second;
}

IsotropicMaterial material(const Model& model, int mid, const CardRef& ref, const std::string& card, int id,
                           const std::string& field) {
  const auto it = model.mat1_index.find(mid);
  if (it == model.mat1_index.end())
    fail(model, ref, card, id, field, "references MAT1 " + std::to_string(mid) + ", which is not defined");
  const Mat1& m = model.mat1[it->second];
  IsotropicMaterial out;
  out.id = m.id;
  out.E = m.E;
  out.G = m.G;
  out.nu = m.nu;
  out.rho = m.rho;
  return out;
}

Eigen::Matrix3d axes_at(const Model& model, int cid, const Eigen::Vector3d& x_basic, const CardRef& ref,
                        const std::string& card, int id, const std::string& field) {
  if (cid != 0 && !model.coord_index.count(cid))
    fail(model, ref, card, id, field, "references coordinate system " + std::to_string(cid) + ", which is not defined");
  return displacement_axes(model, cid, x_basic);
}

}  // namespace seflex::fem::detail

namespace seflex::fem::detail {

ShellMaterial shell_material(const Model& model, int mid, const CardRef& ref, const std::string& card, int id,
                             const std::string& field) {
  if (const auto it = model.mat1_index.find(mid); it != model.mat1_index.end()) return fem::shell_material(model.mat1[it->second]);
  if (const auto it = model.mat2_index.find(mid); it != model.mat2_index.end()) return fem::shell_material(model.mat2[it->second]);
  if (const auto it = model.mat8_index.find(mid); it != model.mat8_index.end()) return fem::shell_material(model.mat8[it->second]);
  fail(model, ref, card, id, field,
       "references material " + std::to_string(mid) + ", which is not defined; expected the id of a MAT1, MAT2 or MAT8 card");
}

}  // namespace seflex::fem::detail

namespace seflex::fem::detail {

double material_angle(const Model& model, const Shell& shell, const Eigen::Vector3d& e1, const Eigen::Vector3d& e2,
                      const Eigen::Vector3d& centroid) {
  constexpr double kPi = 3.14159265358979323846;
  if (!shell.theta_is_mcid) return shell.theta_deg * kPi / 180.0;
  const std::string card = shell_card(shell);
  const std::string field = shell.nnode == 4 ? "8 (MCID)" : "7 (MCID)";
  if (shell.mcid != 0) {
    const auto it = model.coord_index.find(shell.mcid);
    if (it == model.coord_index.end())
      fail(model, shell.ref, card, shell.id, field,
           "references coordinate system " + std::to_string(shell.mcid) + ", which is not defined");
    if (model.coords[it->second].type != CoordType::Rectangular)
      fail(model, shell.ref, card, shell.id, field,
           "coordinate system " + std::to_string(shell.mcid) +
               " is cylindrical or spherical; expected a rectangular system (CORD1R, CORD2R) or 0 for the material axis");
  }
  const Eigen::Vector3d x = axes_at(model, shell.mcid, centroid, shell.ref, card, shell.id, field).col(0);
  const double c = x.dot(e1), s = x.dot(e2);
  if (!(std::hypot(c, s) > 1e-6 * x.norm()))
    fail(model, shell.ref, card, shell.id, field,
         "the x axis of coordinate system " + std::to_string(shell.mcid) +
             " is normal to the element; expected an axis with a projection on its plane");
  return std::atan2(s, c);
}

}  // namespace seflex::fem::detail
