// libseflex_vtk.so: the VTK XML writer behind io's plain-data table (vtk_plugin_api.hpp). The only
// code of seflex that links VTK.
#include <vtkCellData.h>
#include <vtkCellType.h>
#include <vtkDataArray.h>
#include <vtkDoubleArray.h>
#include <vtkFieldData.h>
#include <vtkIntArray.h>
#include <vtkNew.h>
#include <vtkPointData.h>
#include <vtkPoints.h>
#include <vtkSmartPointer.h>
#include <vtkUnstructuredGrid.h>
#include <vtkXMLUnstructuredGridWriter.h>

#include <cstdio>
#include <cstring>
#include <exception>
#include <memory>
#include <vector>

#include "vtk_plugin_api.hpp"

namespace seflex::io::vtk_plugin {

constexpr bool same(CellType ours, VTKCellType vtk) { return static_cast<int>(ours) == static_cast<int>(vtk); }
static_assert(same(kVertex, VTK_VERTEX) && same(kLine, VTK_LINE) && same(kTriangle, VTK_TRIANGLE) && same(kQuad, VTK_QUAD) &&
              same(kTetra, VTK_TETRA) && same(kHexahedron, VTK_HEXAHEDRON) && same(kWedge, VTK_WEDGE) &&
              same(kQuadraticTetra, VTK_QUADRATIC_TETRA) && same(kQuadraticHexahedron, VTK_QUADRATIC_HEXAHEDRON) &&
              same(kQuadraticWedge, VTK_QUADRATIC_WEDGE) && same(kPyramid, VTK_PYRAMID) &&
              same(kQuadraticPyramid, VTK_QUADRATIC_PYRAMID));

struct Writer {
  vtkNew<vtkPoints> points;
  vtkNew<vtkUnstructuredGrid> grid;
  std::vector<vtkSmartPointer<vtkDataArray>> point_data;  ///< in the order of Grid::point_data
  std::vector<vtkSmartPointer<vtkDataArray>> cell_data;   ///< in the order of Grid::cell_data
  vtkNew<vtkXMLUnstructuredGridWriter> writer;
};

namespace {

void fail(char* error, std::size_t size, const char* message) {
  if (error != nullptr && size > 0) std::snprintf(error, size, "%s", message);
}

vtkSmartPointer<vtkDataArray> make_array(const Array& a) {
  vtkSmartPointer<vtkDataArray> out;
  if (a.type == ValueType::kInt) out = vtkSmartPointer<vtkIntArray>::New();
  else out = vtkSmartPointer<vtkDoubleArray>::New();
  out->SetName(a.name);
  out->SetNumberOfComponents(a.components);
  out->SetNumberOfTuples(a.tuples);
  return out;
}

/// Copies a's values into `out` (made by make_array from an array of the same type and size).
void copy_values(const Array& a, vtkDataArray* out) {
  const std::size_t n = static_cast<std::size_t>(a.tuples) * static_cast<std::size_t>(a.components);
  if (n == 0) return;
  if (a.type == ValueType::kInt) std::memcpy(vtkIntArray::SafeDownCast(out)->GetPointer(0), a.values, n * sizeof(int));
  else std::memcpy(vtkDoubleArray::SafeDownCast(out)->GetPointer(0), a.values, n * sizeof(double));
}

void set_points(const Grid& g, Writer& w) {
  for (std::int64_t i = 0; i < g.point_count; ++i)
    w.points->SetPoint(i, g.points[3 * i], g.points[3 * i + 1], g.points[3 * i + 2]);
  w.points->Modified();
}

Writer* create(const Grid* g, std::int32_t compress, char* error, std::size_t error_size) {
  try {
    auto w = std::make_unique<Writer>();
    w->points->SetDataTypeToDouble();
    w->points->SetNumberOfPoints(g->point_count);
    set_points(*g, *w);
    for (std::int64_t c = 0; c < g->cell_count; ++c) {
      std::vector<vtkIdType> ids(g->connectivity + g->offsets[c], g->connectivity + g->offsets[c + 1]);
      w->grid->InsertNextCell(g->cell_types[c], static_cast<vtkIdType>(ids.size()), ids.data());
    }
    w->grid->SetPoints(w->points);
    for (std::int32_t k = 0; k < g->point_data_count; ++k) {
      w->point_data.push_back(make_array(g->point_data[k]));
      copy_values(g->point_data[k], w->point_data.back());
      w->grid->GetPointData()->AddArray(w->point_data.back());
    }
    if (g->active_vectors != nullptr) w->grid->GetPointData()->SetActiveVectors(g->active_vectors);
    for (std::int32_t k = 0; k < g->cell_data_count; ++k) {
      w->cell_data.push_back(make_array(g->cell_data[k]));
      copy_values(g->cell_data[k], w->cell_data.back());
      w->grid->GetCellData()->AddArray(w->cell_data.back());
    }
    for (std::int32_t k = 0; k < g->field_data_count; ++k) {
      vtkSmartPointer<vtkDataArray> a = make_array(g->field_data[k]);
      copy_values(g->field_data[k], a);
      w->grid->GetFieldData()->AddArray(a);
    }
    w->writer->SetInputData(w->grid);
    w->writer->SetDataModeToAppended();
    w->writer->EncodeAppendedDataOff();
    if (compress == 0) w->writer->SetCompressorTypeToNone();
    return w.release();
  } catch (const std::exception& e) {
    fail(error, error_size, e.what());
  } catch (...) {
    fail(error, error_size, "unknown exception in the VTK writer");
  }
  return nullptr;
}

std::int32_t write(Writer* w, const Grid* g, const char* path, char* error, std::size_t error_size) {
  try {
    if (g->point_count != w->points->GetNumberOfPoints() ||
        g->point_data_count != static_cast<std::int32_t>(w->point_data.size())) {
      fail(error, error_size, "the grid's points or point data differ from the writer's");
      return 1;
    }
    set_points(*g, *w);
    for (std::size_t k = 0; k < w->point_data.size(); ++k) {
      const Array& a = g->point_data[k];
      vtkDataArray* out = w->point_data[k];
      if (a.tuples != out->GetNumberOfTuples() || a.components != out->GetNumberOfComponents()) {
        fail(error, error_size, "a point data array differs in size from the writer's");
        return 1;
      }
      copy_values(a, out);
      out->Modified();
    }
    // Cell data may change from step to step too (element results); same sizes as at creation.
    if (g->cell_data_count == static_cast<std::int32_t>(w->cell_data.size()))
      for (std::size_t k = 0; k < w->cell_data.size(); ++k) {
        const Array& a = g->cell_data[k];
        vtkDataArray* out = w->cell_data[k];
        if (a.tuples != out->GetNumberOfTuples() || a.components != out->GetNumberOfComponents()) continue;
        copy_values(a, out);
        out->Modified();
      }
    w->grid->Modified();
    w->writer->SetFileName(path);
    if (w->writer->Write() != 1) {
      fail(error, error_size, "VTK writer failed");
      return 1;
    }
    return 0;
  } catch (const std::exception& e) {
    fail(error, error_size, e.what());
  } catch (...) {
    fail(error, error_size, "unknown exception in the VTK writer");
  }
  return 1;
}

void destroy(Writer* w) { delete w; }

}  // namespace
}  // namespace seflex::io::vtk_plugin

extern "C" __attribute__((visibility("default"))) const seflex::io::vtk_plugin::Plugin* seflex_vtk_plugin() {
  using namespace seflex::io::vtk_plugin;
  static const Plugin plugin = [] {
    Plugin p;
    p.fingerprint = vtk_plugin_fingerprint();
    p.create = &create;
    p.write = &write;
    p.destroy = &destroy;
    return p;
  }();
  return &plugin;
}
