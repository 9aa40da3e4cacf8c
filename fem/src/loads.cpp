// FORCE / MOMENT / LOAD (see loads.hpp).
#include "seflex/fem/loads.hpp"

#include "model_lookup.hpp"
#include "seflex/fem/finalize.hpp"
#include "seflex/common/error.hpp"

namespace seflex::fem {
namespace {

// Add the FORCE/MOMENT cards of set `sid` times `scale`; returns whether any card has this SID.
bool add_point_loads(const Model& model, const DofMap& dofs, int sid, double scale, Eigen::VectorXd& p) {
  bool found = false;
  for (const PointLoad& l : model.point_loads) {
    if (l.sid != sid) continue;
    found = true;
    const char* card = l.kind == PointLoad::Kind::Force ? "FORCE" : "MOMENT";
    const Eigen::Index gi = detail::grid_index(model, l.grid, l.ref, card, l.sid, "3 (G)");
    const Grid& g = model.grids[gi];
    const Eigen::Matrix3d A_cid = detail::axes_at(model, l.cid, g.x_basic, l.ref, card, l.sid, "4 (CID)");
    const Eigen::Matrix3d A_cd = detail::axes_at(model, g.cd, g.x_basic, g.ref, "GRID", g.id, "7 (CD)");
    const Eigen::Vector3d f_cd = A_cd.transpose() * (A_cid * (l.scale * l.n));
    const int c0 = l.kind == PointLoad::Kind::Force ? 1 : 4;
    for (int k = 0; k < 3; ++k) p[dofs.grid_dof(gi, c0 + k)] += scale * f_cd[k];
  }
  return found;
}

}  // namespace

Eigen::VectorXd load_vector(const Model& model, const DofMap& dofs, int sid) {
  Eigen::VectorXd p = Eigen::VectorXd::Zero(dofs.size());
  for (const LoadCombination& lc : model.load_combinations) {
    if (lc.sid != sid) continue;
    for (const auto& [si, li] : lc.terms)
      if (!add_point_loads(model, dofs, li, lc.s * si, p))
        throw InputError(where(model, lc.ref), "LOAD " + std::to_string(lc.sid) + ": references load set " +
                                                               std::to_string(li) +
                                                               ", but no FORCE or MOMENT card has that SID");
    return p;
  }
  if (!add_point_loads(model, dofs, sid, 1.0, p))
    throw InputError(SourceRef{model.files.empty() ? std::string() : model.files.front(), 0},
                     "case control LOAD = " + std::to_string(sid) +
                         ": no LOAD, FORCE or MOMENT bulk data card has SID " + std::to_string(sid));
  return p;
}

}  // namespace seflex::fem
