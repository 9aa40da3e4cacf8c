// CELAS1 / CELAS2 element (see element_spring.hpp).
#include "seflex/fem/element_spring.hpp"

#include <tuple>

#include "model_lookup.hpp"

namespace seflex::fem {

SpringElement make_spring_element(const Model& model, const DofMap& dofs, const Spring& s) {
  const std::string card = s.scalar_points ? (s.inline_property ? "CELAS4" : "CELAS3") : (s.inline_property ? "CELAS2" : "CELAS1");
  SpringElement e;
  if (s.inline_property) {
    e.k = s.k;
  } else {
    const auto it = model.spring_prop_index.find(s.pid);
    if (it == model.spring_prop_index.end())
      detail::fail(model, s.ref, card, s.id, "3 (PID)",
                   "references PELAS " + std::to_string(s.pid) + ", which is not defined");
    e.k = model.spring_props[it->second].k;
  }
  std::tie(e.dof1, e.dof2) = scalar_element_dofs(model, dofs, s.ref, card, s.id, s.scalar_points, s.g1, s.c1, s.g2, s.c2);
  return e;
}

std::pair<Eigen::Index, Eigen::Index> scalar_element_dofs(const Model& model, const DofMap& dofs, const CardRef& ref,
                                                          const std::string& card, int id, bool scalar_points, int g1,
                                                          int c1, int g2, int c2) {
  const auto end = [&](int g, int c, const char* gfield) -> Eigen::Index {
    if (g == 0) return -1;
    const auto d = find_dof(model, dofs, g, c);
    if (!d) {
      const bool known = model.grid_index.count(g) || model.spoint_index.count(g);
      detail::fail(model, ref, card, id, gfield,
                   known ? "component " + std::to_string(c) + " of point " + std::to_string(g) +
                               " does not exist (expected 1-6 for a GRID, 0 or blank for an SPOINT)"
                         : "references point " + std::to_string(g) + ", which is neither a GRID nor an SPOINT");
    }
    return *d;
  };
  const char* f1 = scalar_points ? "4 (S1)" : "4-5 (G1, C1)";
  const char* f2 = scalar_points ? "5 (S2)" : "6-7 (G2, C2)";
  Eigen::Index d1 = end(g1, c1, f1), d2 = end(g2, c2, f2);
  if (d1 < 0) std::swap(d1, d2);
  if (d1 < 0) detail::fail(model, ref, card, id, f1, "both ends are blank (grounded); expected at least one point");
  if (d1 == d2) detail::fail(model, ref, card, id, f2, "both ends are the same degree of freedom");
  return {d1, d2};
}

}  // namespace seflex::fem
