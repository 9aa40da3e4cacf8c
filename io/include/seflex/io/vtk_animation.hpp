#pragma once
// ParaView time series of deformed FE meshes: one .vtu file per output step holding every body's
// full FE mesh (from its superelement's recovery matrix), listed in a .pvd collection that is
// complete after every step (the new entry and the closing tags are written over the previous
// closing tags and flushed: O(1) per step), so a run that stops early still leaves a readable
// animation. The cells and the VTK objects are built at the first step and reused.
//
// Point coordinates are the deformed positions p_WI = p_WBo + R_WB (p_BoI_B + U_I), U = recovery q.
// Point data: "elastic_displacement" (R_WB U_I, world axes) - apply ParaView's "Warp By Vector" with
// scale factor s - 1 to exaggerate the elastic deformation s times; "displacement" (from the position
// in the first step written). Cell data: "body" (index of the body), "element_id" (FE element id) and,
// when a snapshot of the first step carries element results, "element_result" (BodySnapshot::element_values
// at the cell's element: von Mises stress, moment, force; 0 where a body has none).
#include <Eigen/Core>
#include <cstdint>
#include <filesystem>
#include <fstream>
#include <memory>
#include <string>
#include <vector>

#include "seflex/superelement/superelement.hpp"

namespace seflex::io {

/// Pose and elastic state of one body at one instant.
struct BodySnapshot {
  Eigen::Matrix3d R_WB = Eigen::Matrix3d::Identity();  ///< floating-frame orientation in world
  Eigen::Vector3d p_WBo = Eigen::Vector3d::Zero();     ///< floating-frame origin in world
  Eigen::VectorXd q;                                   ///< local elastic coordinates (size se.size(); empty = rigid)
  /// Element results to colour the cells by (docs/stresses.md): element_values[k] the value (von Mises
  /// stress, moment, force) of element (*element_ids)[k]; null: none. Given at the first step or never.
  const std::vector<std::int32_t>* element_ids = nullptr;
  const double* element_values = nullptr;
};

class PvdSeries {
 public:
  /// Bodies are fixed for the whole series (pointers must outlive the writer). Files go to
  /// `folder/stem.pvd` and `folder/stem/stem_NNNNNN.vtu`. Throws InputError if the .pvd exists
  /// and !overwrite, or the folder cannot be written.
  PvdSeries(std::filesystem::path folder, std::string stem, std::vector<const se::Superelement*> bodies,
            bool overwrite = false);
  ~PvdSeries();
  PvdSeries(const PvdSeries&) = delete;
  PvdSeries& operator=(const PvdSeries&) = delete;

  /// Write one step (snapshots in the order of the bodies) and update the .pvd.
  void write_step(double time, const std::vector<BodySnapshot>& snapshots);

  int steps_written() const { return steps_; }
  std::filesystem::path pvd_path() const { return folder_ / (stem_ + ".pvd"); }

 private:
  struct Vtk;  // the grid, its arrays and the writer (VTK types stay out of this header)
  void append_to_collection(double time, const std::string& file);

  std::filesystem::path folder_;
  std::string stem_;
  std::vector<const se::Superelement*> bodies_;
  int steps_ = 0;
  std::ofstream pvd_;
  Eigen::Matrix3Xd first_positions_, positions_, elastic_;
  std::unique_ptr<Vtk> vtk_;
};

/// Deformed positions (3 x n_fe, world) and elastic displacements (world axes) of one body.
void deformed_mesh(const se::Superelement& se, const BodySnapshot& s, Eigen::Matrix3Xd& positions,
                   Eigen::Matrix3Xd& elastic_displacement);

}  // namespace seflex::io
