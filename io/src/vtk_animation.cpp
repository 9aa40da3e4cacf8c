// ParaView time series of deformed FE meshes (VTK XML unstructured grids + a PVD collection). The
// grid is computed here and written by the VTK plugin (vtk_writer.hpp), loaded at the first step.
#include "seflex/io/vtk_animation.hpp"

#include <array>
#include <cstdint>
#include <cstdio>
#include <unordered_map>

#include "seflex/common/error.hpp"
#include "vtk_writer.hpp"

namespace seflex::io {

void deformed_mesh(const se::Superelement& se, const BodySnapshot& s, Eigen::Matrix3Xd& positions,
                   Eigen::Matrix3Xd& elastic) {
  const Eigen::Index nfe = se.p_BoI_B.cols();
  positions.resize(3, nfe);
  elastic.setZero(3, nfe);
  Eigen::VectorXd U;
  if (s.q.size() > 0 && nfe > 0) {  // a body without its mesh part (reduce --no-mesh) has no points
    SEFLEX_DEMAND(s.q.size() == se.size(), "snapshot q has the wrong size for body " + se.name);
    SEFLEX_DEMAND(se.recovery.rows() == 6 * nfe, "body " + se.name + " has no recovery matrix to animate");
    U = se.recovery * s.q;
  }
  for (Eigen::Index i = 0; i < nfe; ++i) {
    Eigen::Vector3d u_B = U.size() ? Eigen::Vector3d(U.segment<3>(6 * i)) : Eigen::Vector3d::Zero();
    elastic.col(i) = s.R_WB * u_B;
    positions.col(i) = s.p_WBo + s.R_WB * (se.p_BoI_B.col(i) + u_B);
  }
}

/// The grid as plain data (points and point data refreshed every step) and the plugin's writer.
struct PvdSeries::Vtk {
  std::vector<double> points, elastic, displacement;  // 3 x total each
  std::vector<std::int32_t> cell_types;
  std::vector<std::int64_t> offsets{0}, connectivity;
  std::vector<int> body, element_id;
  std::vector<double> element_result;         // per cell (when some body has stress modes)
  std::vector<std::int64_t> result_index;     // per cell: index into its body's element values, -1 none
  std::array<vtk_plugin::Array, 2> point_data;
  std::vector<vtk_plugin::Array> cell_data;
  vtk_plugin::Grid grid;
  std::unique_ptr<VtkGridWriter> writer;
};

PvdSeries::PvdSeries(std::filesystem::path folder, std::string stem, std::vector<const se::Superelement*> bodies,
                     bool overwrite)
    : folder_(std::move(folder)), stem_(std::move(stem)), bodies_(std::move(bodies)) {
  if (!overwrite && std::filesystem::exists(pvd_path()))
    throw InputError(SourceRef{pvd_path().string(), 0}, "exists already; refusing to overwrite it");
  std::error_code ec;
  std::filesystem::create_directories(folder_ / stem_, ec);
  if (ec) throw InputError(SourceRef{(folder_ / stem_).string(), 0}, "cannot create folder: " + ec.message());
}

PvdSeries::~PvdSeries() = default;

void PvdSeries::write_step(double time, const std::vector<BodySnapshot>& snapshots) {
  SEFLEX_DEMAND(snapshots.size() == bodies_.size(), "one snapshot per body expected");
  Eigen::Index total = 0;
  for (const auto* b : bodies_) total += b->p_BoI_B.cols();
  const bool first = !vtk_;
  if (first) {  // the grid's cells and arrays, once; the writer at the end of this step's data
    auto v = std::make_unique<Vtk>();
    v->points.resize(static_cast<std::size_t>(3 * total));
    v->elastic.resize(v->points.size());
    v->displacement.resize(v->points.size());
    Eigen::Index offset = 0;
    bool results = false;
    for (const auto& sn : snapshots) results = results || (sn.element_ids && sn.element_values);
    for (std::size_t b = 0; b < bodies_.size(); ++b) {
      std::unordered_map<int, std::int64_t> where;  // element id -> index in the body's element values
      if (const auto* ids = snapshots[b].element_ids)
        for (std::size_t e = 0; e < ids->size(); ++e) where.emplace((*ids)[e], static_cast<std::int64_t>(e));
      for (const auto& c : bodies_[b]->cells) {
        if (results) {
          const auto it = where.find(c.element_id);
          v->result_index.push_back(it == where.end() ? -1 : it->second);
        }
        const int nn = static_cast<int>(c.type);
        for (int k = 0; k < nn; ++k) v->connectivity.push_back(offset + c.nodes[k]);
        v->offsets.push_back(static_cast<std::int64_t>(v->connectivity.size()));
        v->cell_types.push_back(nn == 2 ? vtk_plugin::kLine : nn == 3 ? vtk_plugin::kTriangle : vtk_plugin::kQuad);
        v->body.push_back(static_cast<int>(b));
        v->element_id.push_back(c.element_id);
      }
      offset += bodies_[b]->p_BoI_B.cols();
    }
    const auto cells = static_cast<std::int64_t>(v->cell_types.size());
    v->point_data = {vtk_plugin::Array{"elastic_displacement", vtk_plugin::ValueType::kDouble, 3, total, v->elastic.data()},
                     vtk_plugin::Array{"displacement", vtk_plugin::ValueType::kDouble, 3, total, v->displacement.data()}};
    v->cell_data = {vtk_plugin::Array{"body", vtk_plugin::ValueType::kInt, 1, cells, v->body.data()},
                    vtk_plugin::Array{"element_id", vtk_plugin::ValueType::kInt, 1, cells, v->element_id.data()}};
    if (results) {
      v->element_result.assign(static_cast<std::size_t>(cells), 0.0);
      v->cell_data.push_back(vtk_plugin::Array{"element_result", vtk_plugin::ValueType::kDouble, 1, cells, v->element_result.data()});
    }
    vtk_plugin::Grid& g = v->grid;
    g.point_count = total;
    g.points = v->points.data();
    g.cell_count = cells;
    g.cell_types = v->cell_types.data();
    g.offsets = v->offsets.data();
    g.connectivity = v->connectivity.data();
    g.point_data = v->point_data.data();
    g.point_data_count = static_cast<std::int32_t>(v->point_data.size());
    g.active_vectors = "elastic_displacement";
    g.cell_data = v->cell_data.data();
    g.cell_data_count = static_cast<std::int32_t>(v->cell_data.size());
    first_positions_.resize(3, total);
    vtk_ = std::move(v);
  }
  Vtk& v = *vtk_;
  Eigen::Index offset = 0;
  for (std::size_t b = 0; b < bodies_.size(); ++b) {
    deformed_mesh(*bodies_[b], snapshots[b], positions_, elastic_);
    for (Eigen::Index i = 0; i < positions_.cols(); ++i) {
      const Eigen::Index k = offset + i;
      if (first) first_positions_.col(k) = positions_.col(i);
      const Eigen::Vector3d d = positions_.col(i) - first_positions_.col(k);
      for (int r = 0; r < 3; ++r) {
        const auto at = static_cast<std::size_t>(3 * k + r);
        v.points[at] = positions_(r, i);
        v.elastic[at] = elastic_(r, i);
        v.displacement[at] = d(r);
      }
    }
    offset += positions_.cols();
  }
  if (!v.element_result.empty()) {
    std::size_t c = 0;
    for (std::size_t b = 0; b < bodies_.size(); ++b)
      for (std::size_t k = 0; k < bodies_[b]->cells.size(); ++k, ++c) {
        const std::int64_t i = v.result_index[c];
        v.element_result[c] = i >= 0 && snapshots[b].element_values ? snapshots[b].element_values[i] : 0.0;
      }
  }
  if (!v.writer) v.writer = std::make_unique<VtkGridWriter>(v.grid, false);  // loads the plugin at the first step

  char name[64];
  std::snprintf(name, sizeof name, "%s_%06d.vtu", stem_.c_str(), steps_);
  const std::filesystem::path rel = std::filesystem::path(stem_) / name;
  v.writer->write(v.grid, folder_ / rel);
  ++steps_;
  append_to_collection(time, rel.generic_string());
}

void PvdSeries::append_to_collection(double time, const std::string& file) {
  static constexpr char tail[] = "  </Collection>\n</VTKFile>\n";
  if (!pvd_.is_open()) {
    pvd_.open(pvd_path(), std::ios::out | std::ios::trunc | std::ios::binary);
    pvd_ << "<?xml version=\"1.0\"?>\n<VTKFile type=\"Collection\" version=\"0.1\" byte_order=\"LittleEndian\">\n"
            "  <Collection>\n";
  }
  // The new entry goes where the closing tags were; the closing tags follow, so the file on disk is
  // a complete collection after every step.
  char line[512];
  const int len =
      std::snprintf(line, sizeof line, "    <DataSet timestep=\"%.9g\" group=\"\" part=\"0\" file=\"%s\"/>\n", time, file.c_str());
  SEFLEX_DEMAND(len > 0 && len < static_cast<int>(sizeof line), "animation file name too long");
  pvd_.write(line, len);
  pvd_.write(tail, sizeof tail - 1);
  pvd_.flush();
  if (!pvd_) throw InputError(SourceRef{pvd_path().string(), 0}, "cannot be written");
  pvd_.seekp(-static_cast<std::streamoff>(sizeof tail - 1), std::ios::cur);
}

}  // namespace seflex::io
