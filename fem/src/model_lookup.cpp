#include "model_lookup.hpp"

#include "seflex/fem/finalize.hpp"


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
