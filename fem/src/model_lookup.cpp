#include "model_lookup.hpp"

#include <cmath>
#include <cstdlib>

namespace seflex::fem::detail {

SourceRef source_of(const Model& model, const CardRef& ref) {
  SourceRef s;
  if (ref.file < model.files.size()) s.file = model.files[ref.file];
  s.line = static_cast<int>(ref.line);
  return s;
}

void fail(const Model& model, const CardRef& ref, const std::string& card, int id, const std::string& field,
          const std::string& what) {
  std::string msg = card + " " + std::to_string(id);
  if (!field.empty()) msg += ", field " + field;
  throw InputError(source_of(model, ref), msg + ": " + what);
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
  if (cid == 0) return Eigen::Matrix3d::Identity();
  const auto it = model.coord_index.find(cid);
  if (it == model.coord_index.end())
    fail(model, ref, card, id, field, "references coordinate system " + std::to_string(cid) + ", which is not defined");
  const CoordSys& c = model.coords[it->second];
  const Eigen::Matrix3d& A = c.axes;
  if (c.type == CoordType::Rectangular) return A;
  const Eigen::Vector3d r = A.transpose() * (x_basic - c.origin);
  const double phi = std::atan2(r.y(), r.x());  // azimuth (0 on the axis)
  const double cp = std::cos(phi), sp = std::sin(phi);
  Eigen::Matrix3d L;  // local axes expressed in the system's own axes
  if (c.type == CoordType::Cylindrical) {
    L.col(0) << cp, sp, 0.0;
    L.col(1) << -sp, cp, 0.0;
    L.col(2) << 0.0, 0.0, 1.0;
  } else {  // spherical: r, theta (from e3), phi
    const double th = std::atan2(std::hypot(r.x(), r.y()), r.z());
    const double ct = std::cos(th), st = std::sin(th);
    L.col(0) << st * cp, st * sp, ct;
    L.col(1) << ct * cp, ct * sp, -st;
    L.col(2) << -sp, cp, 0.0;
  }
  return A * L;
}

double param_number(const Model& model, const std::string& name, double fallback) {
  for (const Param& p : model.params) {
    if (p.name != name) continue;
    if (p.values.empty() || p.values.front().empty()) return fallback;
    const std::string& s = p.values.front();
    char* end = nullptr;
    const double v = std::strtod(s.c_str(), &end);
    if (end == s.c_str() || *end != '\0') {
      if (s == "YES" || s == "ON") return 1.0;
      if (s == "NO" || s == "OFF") return -1.0;
      throw InputError(source_of(model, p.ref), "PARAM " + name + ": value '" + s + "' is not a number");
    }
    return v;
  }
  return fallback;
}

}  // namespace seflex::fem::detail
