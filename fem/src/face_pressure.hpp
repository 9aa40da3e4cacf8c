#pragma once
// Internal: work-equivalent grid forces of a PLOAD4 on a shell or on a face of a solid (loads.hpp).
#include <Eigen/Core>
#include <cstdint>
#include <vector>

#include "seflex/fem/model.hpp"

namespace seflex::fem::detail {

struct GridForce {
  std::uint32_t grid = 0;   ///< index in Model::grids
  Eigen::Vector3d f_basic = Eigen::Vector3d::Zero();
};

/// f_a = int N_a p(s, t) d(s, t) dA over a CQUAD4 (bilinear, P1..P4 at G1..G4) or CTRIA3 (linear,
/// P1..P3), d = the element normal (right-hand rule on G1 G2 G3) or N / |N| in system CID.
void shell_face_forces(const Model& model, const Shell& shell, const FaceLoad& load, std::vector<GridForce>& out);

/// The same over the face of a solid chosen by G1 and G3/G4 (QRG PLOAD4), with the element's own
/// shape functions (mid-edge grids included); the pressure, linear or bilinear between P1 (at G1),
/// P2, P3 (P4) going around the face from G1 in the direction of the face's outward normal, acts
/// along the inward normal (positive pressure pushes on the face), or along N / |N|.
void solid_face_forces(const Model& model, const Solid& solid, const FaceLoad& load, std::vector<GridForce>& out);

}  // namespace seflex::fem::detail
