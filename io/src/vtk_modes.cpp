// Mode shapes as VTK XML unstructured grid point data (vtk_modes.hpp).
#include "seflex/io/vtk_modes.hpp"

#include <vtkCellData.h>
#include <vtkCellType.h>
#include <vtkDoubleArray.h>
#include <vtkFieldData.h>
#include <vtkIntArray.h>
#include <vtkNew.h>
#include <vtkPointData.h>
#include <vtkPoints.h>
#include <vtkUnstructuredGrid.h>
#include <vtkXMLUnstructuredGridWriter.h>

#include <cstdio>
#include <string>

#include "seflex/common/error.hpp"
#include "seflex/io/results_csv.hpp"
#include "seflex/reduction/grid_results.hpp"

namespace seflex::io {
namespace {

enum ElementType : int { kBar = 1, kRod = 2, kSpring = 3, kRbe2 = 4, kTria = 5, kQuad = 6, kMass = 7, kRbar = 8, kRbe3 = 9,
                   kSolid = 10 };

/// Cells of the mesh (grid ids resolved through the finalized model's index).
class MeshCells {
 public:
  explicit MeshCells(const fem::Model& model) : model_(model) {
    ids_->SetName("element_id");
    types_->SetName("element_type");
  }
  void add(int vtk_type, std::initializer_list<int> grid_ids, int element_id, ElementType type) {
    add(vtk_type, grid_ids.begin(), static_cast<int>(grid_ids.size()), element_id, type);
  }
  void add(int vtk_type, const int* grid_ids, int count, int element_id, ElementType type) {
    vtkIdType pts[20];
    int n = 0;
    for (int k = 0; k < count && k < 20; ++k) {
      const int g = grid_ids[k];
      const auto it = model_.grid_index.find(g);
      if (it == model_.grid_index.end()) return;  // scalar point or grounded end: nothing to draw
      pts[n++] = static_cast<vtkIdType>(it->second);
    }
    grid_->InsertNextCell(vtk_type, n, pts);
    ids_->InsertNextValue(element_id);
    types_->InsertNextValue(type);
  }
  vtkUnstructuredGrid* grid() { return grid_; }
  void attach() {
    grid_->GetCellData()->AddArray(ids_);
    grid_->GetCellData()->AddArray(types_);
  }

 private:
  const fem::Model& model_;
  vtkNew<vtkUnstructuredGrid> grid_;
  vtkNew<vtkIntArray> ids_, types_;
};

vtkNew<vtkDoubleArray> vector_array(const std::string& name, const reduction::GridTable& table, int first_column) {
  vtkNew<vtkDoubleArray> a;
  a->SetName(name.c_str());
  a->SetNumberOfComponents(3);
  a->SetNumberOfTuples(table.rows());
  for (Eigen::Index i = 0; i < table.rows(); ++i)
    a->SetTuple3(i, table(i, first_column), table(i, first_column + 1), table(i, first_column + 2));
  return a;
}

}  // namespace

void write_mode_shapes_vtu(const std::filesystem::path& path, const fem::Model& model,
                           const reduction::NormalModes& modes, bool overwrite) {
  check_writable(path, overwrite);
  MeshCells cells(model);
  vtkNew<vtkPoints> points;
  points->SetDataTypeToDouble();
  points->SetNumberOfPoints(static_cast<vtkIdType>(model.grids.size()));
  vtkNew<vtkIntArray> grid_ids;
  grid_ids->SetName("grid_id");
  for (std::size_t i = 0; i < model.grids.size(); ++i) {
    const Eigen::Vector3d& x = model.grids[i].x_basic;
    points->SetPoint(static_cast<vtkIdType>(i), x.x(), x.y(), x.z());
    grid_ids->InsertNextValue(model.grids[i].id);
  }
  for (const auto& b : model.bars) cells.add(VTK_LINE, {b.ga, b.gb}, b.id, kBar);
  for (const auto& r : model.rods) cells.add(VTK_LINE, {r.ga, r.gb}, r.id, kRod);
  for (const auto& s : model.springs)
    if (s.g2 != 0 && !s.scalar_points) cells.add(VTK_LINE, {s.g1, s.g2}, s.id, kSpring);
  for (const auto& b : model.bushes)
    if (b.gb != 0) cells.add(VTK_LINE, {b.ga, b.gb}, b.id, kSpring);
  for (const auto& r : model.rbe2)
    for (int gm : r.gm) cells.add(VTK_LINE, {r.gn, gm}, r.id, kRbe2);
  for (const auto& r : model.rbars) cells.add(VTK_LINE, {r.ga, r.gb}, r.id, kRbar);
  for (const auto& r : model.rbe3)
    for (const auto& g : r.groups)
      for (int gi : g.grids) cells.add(VTK_LINE, {r.refgrid, gi}, r.id, kRbe3);
  for (const auto& s : model.shells) {
    if (s.nnode == 3) cells.add(VTK_TRIANGLE, {s.g[0], s.g[1], s.g[2]}, s.id, kTria);
    else cells.add(VTK_QUAD, {s.g[0], s.g[1], s.g[2], s.g[3]}, s.id, kQuad);
  }
  for (const auto& s : model.solids) {
    // VTK's quadratic cells list the top-face edges before the vertical ones; Nastran the reverse.
    static const int hexa20[20] = {0, 1, 2, 3, 4, 5, 6, 7, 8, 9, 10, 11, 16, 17, 18, 19, 12, 13, 14, 15};
    static const int penta15[15] = {0, 1, 2, 3, 4, 5, 6, 7, 8, 12, 13, 14, 9, 10, 11};
    // Some mid-edge grids blank: VTK has no such cell; drawn as the linear cell of its corners.
    const int n = s.quadratic() && s.missing_mid != 0 ? s.corners() : s.nnode;
    int g[20];
    const int* order = n == 20 ? hexa20 : n == 15 ? penta15 : nullptr;
    for (int k = 0; k < n; ++k) g[k] = s.g[static_cast<std::size_t>(order ? order[k] : k)];
    const int type = n == 8 ? VTK_HEXAHEDRON : n == 20 ? VTK_QUADRATIC_HEXAHEDRON : n == 6 ? VTK_WEDGE
                   : n == 15 ? VTK_QUADRATIC_WEDGE : n == 4 ? VTK_TETRA : VTK_QUADRATIC_TETRA;
    cells.add(type, g, n, s.id, kSolid);
  }
  for (const auto& c : model.conm2) cells.add(VTK_VERTEX, {c.grid}, c.id, kMass);
  cells.attach();
  vtkUnstructuredGrid* grid = cells.grid();
  grid->SetPoints(points);
  grid->GetPointData()->AddArray(grid_ids);

  const Eigen::Index m = modes.eigenvalues.size();
  const int width = static_cast<int>(std::to_string(std::max<Eigen::Index>(m, 1)).size());
  for (Eigen::Index k = 0; k < m; ++k) {
    char tag[32];
    std::snprintf(tag, sizeof tag, "mode_%0*d", std::max(width, 2), static_cast<int>(k + 1));
    const reduction::GridTable shape = reduction::grid_vectors_basic(model, modes.dofs, modes.shapes_g.col(k));
    grid->GetPointData()->AddArray(vector_array(std::string(tag) + "_displacement", shape, 0));
    grid->GetPointData()->AddArray(vector_array(std::string(tag) + "_rotation", shape, 3));
    if (k == 0) grid->GetPointData()->SetActiveVectors((std::string(tag) + "_displacement").c_str());
  }
  vtkNew<vtkDoubleArray> eigenvalue, frequency;
  eigenvalue->SetName("eigenvalue");
  frequency->SetName("frequency_hz");
  const Eigen::VectorXd hz = modes.cycles();
  for (Eigen::Index k = 0; k < m; ++k) {
    eigenvalue->InsertNextValue(modes.eigenvalues(k));
    frequency->InsertNextValue(hz(k));
  }
  grid->GetFieldData()->AddArray(eigenvalue);
  grid->GetFieldData()->AddArray(frequency);

  vtkNew<vtkXMLUnstructuredGridWriter> writer;
  writer->SetFileName(path.string().c_str());
  writer->SetInputData(grid);
  writer->SetDataModeToAppended();
  writer->EncodeAppendedDataOff();
  if (writer->Write() != 1) throw InputError(SourceRef{path.string(), 0}, "cannot be written (VTK writer failed)");
}

}  // namespace seflex::io
