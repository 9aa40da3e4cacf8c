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

PvdSeries::PvdSeries(std::filesystem::path folder, std::string stem, std::vector<const se::Superelement*> bodies,
                     bool overwrite)
    : folder_(std::move(folder)), stem_(std::move(stem)), bodies_(std::move(bodies)) {
  if (!overwrite && std::filesystem::exists(pvd_path()))
    throw InputError(SourceRef{pvd_path().string(), 0}, "exists already; refusing to overwrite it");
  std::error_code ec;
  std::filesystem::create_directories(folder_ / stem_, ec);
  if (ec) throw InputError(SourceRef{(folder_ / stem_).string(), 0}, "cannot create folder: " + ec.message());
}

void PvdSeries::write_step(double time, const std::vector<BodySnapshot>& snapshots) {
  SEFLEX_DEMAND(snapshots.size() == bodies_.size(), "one snapshot per body expected");
  vtkNew<vtkPoints> points;
  points->SetDataTypeToDouble();
  vtkNew<vtkDoubleArray> elastic_arr, disp_arr;
  elastic_arr->SetName("elastic_displacement");
  elastic_arr->SetNumberOfComponents(3);
  disp_arr->SetName("displacement");
  disp_arr->SetNumberOfComponents(3);
  vtkNew<vtkIntArray> body_arr, eid_arr;
  body_arr->SetName("body");
  eid_arr->SetName("element_id");
  vtkNew<vtkUnstructuredGrid> grid;

  Eigen::Index total = 0;
  for (const auto* b : bodies_) total += b->p_BoI_B.cols();
  const bool first = entries_.empty();
  if (first) first_positions_.resize(3, total);
  points->SetNumberOfPoints(total);
  elastic_arr->SetNumberOfTuples(total);
  disp_arr->SetNumberOfTuples(total);

  Eigen::Index offset = 0;
  Eigen::Matrix3Xd pos, el;
  for (std::size_t b = 0; b < bodies_.size(); ++b) {
    const auto& se = *bodies_[b];
    deformed_mesh(se, snapshots[b], pos, el);
    for (Eigen::Index i = 0; i < pos.cols(); ++i) {
      const Eigen::Index k = offset + i;
      if (first) first_positions_.col(k) = pos.col(i);
      points->SetPoint(k, pos(0, i), pos(1, i), pos(2, i));
      elastic_arr->SetTuple3(k, el(0, i), el(1, i), el(2, i));
      const Eigen::Vector3d d = pos.col(i) - first_positions_.col(k);
      disp_arr->SetTuple3(k, d.x(), d.y(), d.z());
    }
    for (const auto& c : se.cells) {
      const int nn = static_cast<int>(c.type);
      vtkIdType ids[4];
      for (int k = 0; k < nn; ++k) ids[k] = offset + c.nodes[k];
      const int type = nn == 2 ? VTK_LINE : nn == 3 ? VTK_TRIANGLE : VTK_QUAD;
      grid->InsertNextCell(type, nn, ids);
      body_arr->InsertNextValue(static_cast<int>(b));
      eid_arr->InsertNextValue(c.element_id);
    }
    offset += pos.cols();
  }
  grid->SetPoints(points);
  grid->GetPointData()->AddArray(elastic_arr);
  grid->GetPointData()->AddArray(disp_arr);
  grid->GetPointData()->SetActiveVectors("elastic_displacement");
  grid->GetCellData()->AddArray(body_arr);
  grid->GetCellData()->AddArray(eid_arr);

  char name[64];
  std::snprintf(name, sizeof name, "%s_%06d.vtu", stem_.c_str(), static_cast<int>(entries_.size()));
  const std::filesystem::path rel = std::filesystem::path(stem_) / name;
  vtkNew<vtkXMLUnstructuredGridWriter> writer;
  writer->SetFileName((folder_ / rel).string().c_str());
  writer->SetInputData(grid);
  writer->SetDataModeToAppended();
  writer->EncodeAppendedDataOff();
  writer->SetCompressorTypeToNone();
  if (writer->Write() != 1) throw InputError(SourceRef{(folder_ / rel).string(), 0}, "VTK writer failed");
  entries_.emplace_back(time, rel.generic_string());

  // Rewrite the collection so it is always complete up to the last step.
  const auto tmp = folder_ / (stem_ + ".pvd.tmp");
  {
    std::ofstream out(tmp, std::ios::trunc);
    out << "<?xml version=\"1.0\"?>\n<VTKFile type=\"Collection\" version=\"0.1\" byte_order=\"LittleEndian\">\n"
           "  <Collection>\n";
    char line[512];
    for (const auto& [t, file] : entries_) {
      std::snprintf(line, sizeof line, "    <DataSet timestep=\"%.9g\" group=\"\" part=\"0\" file=\"%s\"/>\n", t, file.c_str());
      out << line;
    }
    out << "  </Collection>\n</VTKFile>\n";
    if (!out) throw InputError(SourceRef{tmp.string(), 0}, "cannot be written");
  }
  std::filesystem::rename(tmp, pvd_path());
}

}  // namespace seflex::io
