#pragma once
// Internal helpers of the fem library: look up the cards an element references, with InputError
// messages that name the file:line, card, id and field. Not a public header.
//
// The coordinate-system and PARAM helpers here stand in for the public ones declared in
// finalize.hpp until those are implemented; they read only what fem::finalize resolves
// (CoordSys::origin/axes/type, Grid::x_basic).
#include <Eigen/Core>
#include <string>

#include "seflex/common/error.hpp"
#include "seflex/fem/material.hpp"
#include "seflex/fem/model.hpp"

namespace seflex::fem::detail {

/// Source location of a card ("deck.bdf:57").
SourceRef source_of(const Model& model, const CardRef& ref);

/// Throw InputError "<file:line>: <card> <id>, field <field>: <what>".
[[noreturn]] void fail(const Model& model, const CardRef& ref, const std::string& card, int id,
                       const std::string& field, const std::string& what);

/// Index of GRID `grid_id`; throws InputError naming the referring card if it is not defined.
std::uint32_t grid_index(const Model& model, int grid_id, const CardRef& ref, const std::string& card, int id,
                         const std::string& field);

/// MAT1 `mid` as an isotropic material; throws InputError naming the referring card.
IsotropicMaterial material(const Model& model, int mid, const CardRef& ref, const std::string& card, int id,
                           const std::string& field);

/// Axes (columns, in basic) of coordinate system `cid` at basic point x; cid = 0 gives identity.
/// Throws InputError naming the referring card if cid is not defined.
Eigen::Matrix3d axes_at(const Model& model, int cid, const Eigen::Vector3d& x_basic, const CardRef& ref,
                        const std::string& card, int id, const std::string& field);

/// First value of PARAM `name` as a number, or `fallback` if absent; throws InputError if not a number.
double param_number(const Model& model, const std::string& name, double fallback);

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
