#pragma once
// Internal helpers of the fem library: look up the cards an element references, with InputError
// messages that name the file:line, card, id and field. Not a public header.
#include <Eigen/Core>
#include <string>

#include "seflex/common/error.hpp"
#include "seflex/fem/material.hpp"
#include "seflex/fem/model.hpp"

namespace seflex::fem::detail {

/// Throw InputError "<file:line>: <card> <id>, field <field>: <what>".
[[noreturn]] void fail(const Model& model, const CardRef& ref, const std::string& card, int id,
                       const std::string& field, const std::string& what);

/// Index of GRID `grid_id`; throws InputError naming the referring card if it is not defined.
std::uint32_t grid_index(const Model& model, int grid_id, const CardRef& ref, const std::string& card, int id,
                         const std::string& field);

/// MAT1 `mid` as an isotropic material; throws InputError naming the referring card.
IsotropicMaterial material(const Model& model, int mid, const CardRef& ref, const std::string& card, int id,
                           const std::string& field);

/// fem::displacement_axes of system `cid` at basic point x, throwing InputError naming the referring
/// card if cid is not defined (finalize checks this for read decks; models built in code may not).
Eigen::Matrix3d axes_at(const Model& model, int cid, const Eigen::Vector3d& x_basic, const CardRef& ref,
                        const std::string& card, int id, const std::string& field);

}  // namespace seflex::fem::detail

#include <unordered_map>

#include "seflex/fem/section.hpp"

namespace seflex::fem::detail {

/// Shell sections resolved once per PSHELL (elements with their own corner thicknesses are
/// resolved each time).
class ShellSectionCache {
 public:
  const ShellSection& get(const Model& model, const Shell& shell) {
    if (shell.t[0] != 0.0 || shell.t[1] != 0.0 || shell.t[2] != 0.0 || shell.t[3] != 0.0) {
      own_ = make_shell_section(model, shell);
      return own_;
    }
    auto it = by_pid_.find(shell.pid);
    if (it == by_pid_.end()) it = by_pid_.emplace(shell.pid, make_shell_section(model, shell)).first;
    return it->second;
  }

 private:
  std::unordered_map<int, ShellSection> by_pid_;
  ShellSection own_;
};

}  // namespace seflex::fem::detail

namespace seflex::fem::detail {

/// MAT1, MAT2 or MAT8 `mid` as a shell layer; throws InputError naming the referring card if it is
/// none of them.
ShellMaterial shell_material(const Model& model, int mid, const CardRef& ref, const std::string& card, int id,
                             const std::string& field);

}  // namespace seflex::fem::detail

namespace seflex::fem::detail {

/// Material angle of a CQUAD4/CTRIA3 (radians, about the element normal, from the element x axis
/// e1 toward e2; e1 along the projected G1-G2 edge): THETA, or with MCID the angle of the projection
/// of the x axis of rectangular system MCID (0 = basic) on the element plane (QRG CQUAD4, THETA/MCID).
/// Throws InputError for an undefined, cylindrical or spherical MCID, or an x axis normal to the element.
double material_angle(const Model& model, const Shell& shell, const Eigen::Vector3d& e1, const Eigen::Vector3d& e2,
                      const Eigen::Vector3d& centroid);

}  // namespace seflex::fem::detail
