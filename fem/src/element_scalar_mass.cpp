// CMASS1-4 element (see element_scalar_mass.hpp).
#include "seflex/fem/element_scalar_mass.hpp"

#include <tuple>

#include "model_lookup.hpp"
#include "seflex/fem/element_spring.hpp"

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
  std::tie(e.dof1, e.dof2) = scalar_element_dofs(model, dofs, s.ref, card, s.id, s.scalar_points, s.g1, s.c1, s.g2, s.c2);
  return e;
}

}  // namespace seflex::fem
