// CMASS1-4 element (see element_scalar_mass.hpp).
#include "seflex/fem/element_scalar_mass.hpp"

#include "model_lookup.hpp"

namespace seflex::fem {

ScalarMassElement make_scalar_mass_element(const Model& model, const DofMap& dofs, const ScalarMass& s) {
  const std::string card = s.scalar_points ? (s.inline_property ? "CMASS4" : "CMASS3") : (s.inline_property ? "CMASS2" : "CMASS1");
  ScalarMassElement e;
  if (s.inline_property) {
    e.m = s.m;
  } else {
    const auto it = model.mass_prop_index.find(s.pid);
    if (it == model.mass_prop_index.end())
      detail::fail(model, s.ref, card, s.id, "3 (PID)", "references PMASS " + std::to_string(s.pid) + ", which is not defined");
    e.m = model.mass_props[it->second].m;
  }
  const auto end = [&](int g, int c, const char* gfield) -> Eigen::Index {
    if (g == 0) return -1;
    const auto d = find_dof(model, dofs, g, c);
    if (!d) {
      const bool known = model.grid_index.count(g) || model.spoint_index.count(g);
      detail::fail(model, s.ref, card, s.id, gfield,
                   known ? "component " + std::to_string(c) + " of point " + std::to_string(g) +
                               " does not exist (expected 1-6 for a GRID, 0 or blank for an SPOINT)"
                         : "references point " + std::to_string(g) + ", which is neither a GRID nor an SPOINT");
    }
    return *d;
  };
  const char* f1 = s.scalar_points ? "4 (S1)" : "4-5 (G1, C1)";
  const char* f2 = s.scalar_points ? "5 (S2)" : "6-7 (G2, C2)";
  e.dof1 = end(s.g1, s.c1, f1);
  e.dof2 = end(s.g2, s.c2, f2);
  if (e.dof1 < 0) std::swap(e.dof1, e.dof2);
  if (e.dof1 < 0) detail::fail(model, s.ref, card, s.id, f1, "both ends are blank (grounded); expected at least one point");
  if (e.dof1 == e.dof2) detail::fail(model, s.ref, card, s.id, f2, "both ends are the same degree of freedom");
  return e;
}

}  // namespace seflex::fem
