// ParaView time series of deformed FE meshes (VTK XML unstructured grids + a PVD collection).
#include "seflex/io/vtk_animation.hpp"

#include <vtkCellArray.h>
#include <vtkCellData.h>
#include <vtkCellType.h>
#include <vtkDoubleArray.h>
#include <vtkIntArray.h>
#include <vtkNew.h>
#include <vtkPointData.h>
#include <vtkPoints.h>
#include <vtkUnstructuredGrid.h>
#include <vtkXMLUnstructuredGridWriter.h>

#include <cstdio>

#include "seflex/common/error.hpp"

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

struct PvdSeries::Vtk {
  vtkNew<vtkPoints> points;
  vtkNew<vtkDoubleArray> elastic, displacement;
  vtkNew<vtkIntArray> body, element_id;
  vtkNew<vtkUnstructuredGrid> grid;
  vtkNew<vtkXMLUnstructuredGridWriter> writer;
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
  if (first) {  // the grid's cells, arrays and the writer, once
    vtk_ = std::make_unique<Vtk>();
    Vtk& v = *vtk_;
    v.points->SetDataTypeToDouble();
    v.points->SetNumberOfPoints(total);
    v.elastic->SetName("elastic_displacement");
    v.elastic->SetNumberOfComponents(3);
    v.elastic->SetNumberOfTuples(total);
    v.displacement->SetName("displacement");
    v.displacement->SetNumberOfComponents(3);
    v.displacement->SetNumberOfTuples(total);
    v.body->SetName("body");
    v.element_id->SetName("element_id");
    Eigen::Index offset = 0;
    for (std::size_t b = 0; b < bodies_.size(); ++b) {
      for (const auto& c : bodies_[b]->cells) {
        const int nn = static_cast<int>(c.type);
        vtkIdType ids[4];
        for (int k = 0; k < nn; ++k) ids[k] = offset + c.nodes[k];
        const int type = nn == 2 ? VTK_LINE : nn == 3 ? VTK_TRIANGLE : VTK_QUAD;
        v.grid->InsertNextCell(type, nn, ids);
        v.body->InsertNextValue(static_cast<int>(b));
        v.element_id->InsertNextValue(c.element_id);
      }
      offset += bodies_[b]->p_BoI_B.cols();
    }
    v.grid->SetPoints(v.points);
    v.grid->GetPointData()->AddArray(v.elastic);
    v.grid->GetPointData()->AddArray(v.displacement);
    v.grid->GetPointData()->SetActiveVectors("elastic_displacement");
    v.grid->GetCellData()->AddArray(v.body);
    v.grid->GetCellData()->AddArray(v.element_id);
    v.writer->SetInputData(v.grid);
    v.writer->SetDataModeToAppended();
    v.writer->EncodeAppendedDataOff();
    v.writer->SetCompressorTypeToNone();
    first_positions_.resize(3, total);
  }
  Vtk& v = *vtk_;
  Eigen::Index offset = 0;
  for (std::size_t b = 0; b < bodies_.size(); ++b) {
    deformed_mesh(*bodies_[b], snapshots[b], positions_, elastic_);
    for (Eigen::Index i = 0; i < positions_.cols(); ++i) {
      const Eigen::Index k = offset + i;
      if (first) first_positions_.col(k) = positions_.col(i);
      v.points->SetPoint(k, positions_(0, i), positions_(1, i), positions_(2, i));
      v.elastic->SetTuple3(k, elastic_(0, i), elastic_(1, i), elastic_(2, i));
      const Eigen::Vector3d d = positions_.col(i) - first_positions_.col(k);
      v.displacement->SetTuple3(k, d.x(), d.y(), d.z());
    }
    offset += positions_.cols();
  }
  v.points->Modified();
  v.elastic->Modified();
  v.displacement->Modified();
  v.grid->Modified();

  char name[64];
  std::snprintf(name, sizeof name, "%s_%06d.vtu", stem_.c_str(), steps_);
  const std::filesystem::path rel = std::filesystem::path(stem_) / name;
  v.writer->SetFileName((folder_ / rel).string().c_str());
  if (v.writer->Write() != 1) throw InputError(SourceRef{(folder_ / rel).string(), 0}, "VTK writer failed");
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
