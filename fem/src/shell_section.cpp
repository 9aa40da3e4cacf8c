// PSHELL resolution for CQUAD4 / CTRIA3 (see section.hpp).
#include "model_lookup.hpp"
#include "seflex/fem/section.hpp"

namespace seflex::fem {

ShellSection make_shell_section(const Model& model, const Shell& shell) {
  const std::string card = shell.nnode == 4 ? "CQUAD4" : "CTRIA3";
  const auto it = model.shell_prop_index.find(shell.pid);
  if (it == model.shell_prop_index.end())
    detail::fail(model, shell.ref, card, shell.id, "3 (PID)",
                 "references PSHELL " + std::to_string(shell.pid) + ", which is not defined");
  const ShellProperty& p = model.shell_props[it->second];
  ShellSection s;
  if (p.mid1 > 0) {
    s.has_membrane = true;
    s.membrane = detail::material(model, p.mid1, p.ref, "PSHELL", p.id, "3 (MID1)");
  }
  if (p.mid2 > 0) {
    s.has_bending = true;
    s.bending = detail::material(model, p.mid2, p.ref, "PSHELL", p.id, "5 (MID2)");
  }
  if (p.mid3 > 0) {
    s.has_shear = true;
    s.shear = detail::material(model, p.mid3, p.ref, "PSHELL", p.id, "7 (MID3)");
  }
  if (!s.has_membrane && !s.has_bending)
    detail::fail(model, p.ref, "PSHELL", p.id, "3, 5 (MID1, MID2)", "expected a membrane or bending material");
  s.bend_ratio = p.bend_ratio;
  s.ts_t = p.ts_t;
  s.nsm = p.nsm;
  s.rho = s.has_membrane ? s.membrane.rho : s.bending.rho;
  double sum = 0.0;
  for (int k = 0; k < shell.nnode; ++k) {
    const double tk = shell.t[k];
    sum += tk == 0.0 ? p.t : (shell.tflag == 1 ? tk * p.t : tk);
  }
  s.t = sum / shell.nnode;
  if (!(s.t > 0.0))
    detail::fail(model, shell.ref, card, shell.id, "T1-T4",
                 "has no positive thickness (PSHELL " + std::to_string(p.id) + " field 4 T, or the corner thicknesses)");
  return s;
}

}  // namespace seflex::fem
