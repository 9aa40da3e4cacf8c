// Mode shapes as VTK XML unstructured grid point data (vtk_modes.hpp): the grid as plain data,
// written by the VTK plugin (vtk_writer.hpp).
#include "seflex/io/vtk_modes.hpp"

#include <algorithm>
#include <cstdint>
#include <cstdio>
#include <deque>
#include <string>
#include <vector>

#include "seflex/common/error.hpp"
#include "seflex/io/results_csv.hpp"
#include "seflex/solutions/grid_results.hpp"
#include "vtk_writer.hpp"

namespace seflex::io {
namespace {

using vtk_plugin::CellType;

enum ElementType : int { kBar = 1, kRod = 2, kSpring = 3, kRbe2 = 4, kTria = 5, kQuad = 6, kMass = 7, kRbar = 8, kRbe3 = 9,
                   kSolid = 10, kRigid = 11, kShear = 12, kBend = 13, kTria6 = 14, kQuad8 = 15 };

/// Cells of the mesh (grid ids resolved through the finalized model's index).
class MeshCells {
 public:
  explicit MeshCells(const fem::Model& model) : model_(model) {}
  void add(CellType vtk_type, std::initializer_list<int> grid_ids, int element_id, ElementType type) {
    add(vtk_type, grid_ids.begin(), static_cast<int>(grid_ids.size()), element_id, type);
  }
  void add(CellType vtk_type, const int* grid_ids, int count, int element_id, ElementType type) {
    const std::size_t start = connectivity.size();
    for (int k = 0; k < count && k < 20; ++k) {
      const auto it = model_.grid_index.find(grid_ids[k]);
      if (it == model_.grid_index.end()) {  // scalar point or grounded end: nothing to draw
        connectivity.resize(start);
        return;
      }
      connectivity.push_back(static_cast<std::int64_t>(it->second));
    }
    offsets.push_back(static_cast<std::int64_t>(connectivity.size()));
    types.push_back(vtk_type);
    ids.push_back(element_id);
    element_types.push_back(type);
  }

  std::vector<std::int32_t> types;
  std::vector<std::int64_t> offsets{0}, connectivity;
  std::vector<int> ids, element_types;

 private:
  const fem::Model& model_;
};

/// Three columns of `table` from first_column on, point after point.
std::vector<double> vector_values(const solutions::GridTable& table, int first_column) {
  std::vector<double> out;
  out.reserve(static_cast<std::size_t>(3 * table.rows()));
  for (Eigen::Index i = 0; i < table.rows(); ++i)
    for (int c = 0; c < 3; ++c) out.push_back(table(i, first_column + c));
  return out;
}

}  // namespace

void write_mode_shapes_vtu(const std::filesystem::path& path, const fem::Model& model,
                           const solutions::NormalModes& modes, bool overwrite) {
  check_writable(path, overwrite);
  MeshCells cells(model);
  const auto n_points = static_cast<std::int64_t>(model.grids.size());
  std::vector<double> points;
  std::vector<int> grid_ids;
  points.reserve(static_cast<std::size_t>(3 * n_points));
  for (const fem::Grid& g : model.grids) {
    points.insert(points.end(), {g.x_basic.x(), g.x_basic.y(), g.x_basic.z()});
    grid_ids.push_back(g.id);
  }
  for (const auto& b : model.bars) cells.add(vtk_plugin::kLine, {b.ga, b.gb}, b.id, kBar);
  for (const auto& r : model.rods) cells.add(vtk_plugin::kLine, {r.ga, r.gb}, r.id, kRod);
  for (const auto& s : model.springs)
    if (s.g2 != 0 && !s.scalar_points) cells.add(vtk_plugin::kLine, {s.g1, s.g2}, s.id, kSpring);
  for (const auto& b : model.bushes)
    if (b.gb != 0) cells.add(vtk_plugin::kLine, {b.ga, b.gb}, b.id, kSpring);
  for (const auto& r : model.rbe2)
    for (int gm : r.gm) cells.add(vtk_plugin::kLine, {r.gn, gm}, r.id, kRbe2);
  for (const auto& r : model.rbars) cells.add(vtk_plugin::kLine, {r.ga, r.gb}, r.id, kRbar);
  for (const auto& q : model.shells8) {  // drawn as the linear cell of the corners (mid-side grids may be blank)
    const fem::Shell& s = q.shell;
    if (s.nnode == 3) cells.add(vtk_plugin::kTriangle, {s.g[0], s.g[1], s.g[2]}, s.id, kTria6);
    else cells.add(vtk_plugin::kQuad, {s.g[0], s.g[1], s.g[2], s.g[3]}, s.id, kQuad8);
  }
  for (const auto& s : model.shear_panels) cells.add(vtk_plugin::kQuad, {s.g[0], s.g[1], s.g[2], s.g[3]}, s.id, kShear);
  for (const auto& b : model.bends) cells.add(vtk_plugin::kLine, {b.ga, b.gb}, b.id, kBend);
  for (const auto& r : model.rigid_bodies)  // RBE1, CRIGD1-3: lines from the first independent grid
    for (const auto& g : r.dependent) cells.add(vtk_plugin::kLine, {r.independent.front().grid, g.grid}, r.id, kRigid);
  for (const auto& r : model.rigid_rods) cells.add(vtk_plugin::kLine, {r.ga, r.gb}, r.id, kRigid);
  for (const auto& r : model.rbe3)
    for (const auto& g : r.groups)
      for (int gi : g.grids) cells.add(vtk_plugin::kLine, {r.refgrid, gi}, r.id, kRbe3);
  for (const auto& s : model.shells) {
    if (s.nnode == 3) cells.add(vtk_plugin::kTriangle, {s.g[0], s.g[1], s.g[2]}, s.id, kTria);
    else cells.add(vtk_plugin::kQuad, {s.g[0], s.g[1], s.g[2], s.g[3]}, s.id, kQuad);
  }
  for (const auto& s : model.solids) {
    // VTK's quadratic cells list the top-face edges before the vertical ones; Nastran the reverse.
    // The pyramids' orders agree (base edges, then the edges to the apex).
    static const int hexa20[20] = {0, 1, 2, 3, 4, 5, 6, 7, 8, 9, 10, 11, 16, 17, 18, 19, 12, 13, 14, 15};
    static const int penta15[15] = {0, 1, 2, 3, 4, 5, 6, 7, 8, 12, 13, 14, 9, 10, 11};
    // Some mid-edge grids blank: VTK has no such cell; drawn as the linear cell of its corners.
    const int n = s.quadratic() && s.missing_mid != 0 ? s.corners() : s.nnode;
    int g[20];
    const int* order = n == 20 ? hexa20 : n == 15 ? penta15 : nullptr;
    for (int k = 0; k < n; ++k) g[k] = s.g[static_cast<std::size_t>(order ? order[k] : k)];
    const CellType type = n == 8 ? vtk_plugin::kHexahedron : n == 20 ? vtk_plugin::kQuadraticHexahedron
                        : n == 6 ? vtk_plugin::kWedge : n == 15 ? vtk_plugin::kQuadraticWedge
                        : n == 5 ? vtk_plugin::kPyramid : n == 13 ? vtk_plugin::kQuadraticPyramid
                        : n == 4 ? vtk_plugin::kTetra : vtk_plugin::kQuadraticTetra;
    cells.add(type, g, n, s.id, kSolid);
  }
  for (const auto& c : model.conm2) cells.add(vtk_plugin::kVertex, {c.grid}, c.id, kMass);

  // Point data: grid_id, then per mode its displacement and rotation; field data: eigenvalue, frequency_hz.
  const Eigen::Index m = modes.eigenvalues.size();
  const int width = static_cast<int>(std::to_string(std::max<Eigen::Index>(m, 1)).size());
  std::deque<std::string> names;            // stable addresses for the arrays' names
  std::deque<std::vector<double>> values;  // and values
  std::vector<vtk_plugin::Array> point_data{{"grid_id", vtk_plugin::ValueType::kInt, 1, n_points, grid_ids.data()}};
  for (Eigen::Index k = 0; k < m; ++k) {
    char tag[32];
    std::snprintf(tag, sizeof tag, "mode_%0*d", std::max(width, 2), static_cast<int>(k + 1));
    const solutions::GridTable shape = solutions::grid_vectors_basic(model, modes.dofs, modes.shapes_g.col(k));
    for (int part = 0; part < 2; ++part) {
      names.push_back(std::string(tag) + (part == 0 ? "_displacement" : "_rotation"));
      values.push_back(vector_values(shape, 3 * part));
      point_data.push_back({names.back().c_str(), vtk_plugin::ValueType::kDouble, 3, shape.rows(), values.back().data()});
    }
  }
  const Eigen::VectorXd hz = modes.cycles();
  const std::vector<vtk_plugin::Array> field_data{
      {"eigenvalue", vtk_plugin::ValueType::kDouble, 1, m, modes.eigenvalues.data()},
      {"frequency_hz", vtk_plugin::ValueType::kDouble, 1, m, hz.data()}};
  const std::vector<vtk_plugin::Array> cell_data{
      {"element_id", vtk_plugin::ValueType::kInt, 1, static_cast<std::int64_t>(cells.ids.size()), cells.ids.data()},
      {"element_type", vtk_plugin::ValueType::kInt, 1, static_cast<std::int64_t>(cells.ids.size()), cells.element_types.data()}};

  vtk_plugin::Grid grid;
  grid.point_count = n_points;
  grid.points = points.data();
  grid.cell_count = static_cast<std::int64_t>(cells.types.size());
  grid.cell_types = cells.types.data();
  grid.offsets = cells.offsets.data();
  grid.connectivity = cells.connectivity.data();
  grid.point_data = point_data.data();
  grid.point_data_count = static_cast<std::int32_t>(point_data.size());
  grid.active_vectors = m > 0 ? point_data[1].name : nullptr;
  grid.cell_data = cell_data.data();
  grid.cell_data_count = static_cast<std::int32_t>(cell_data.size());
  grid.field_data = field_data.data();
  grid.field_data_count = static_cast<std::int32_t>(field_data.size());
  VtkGridWriter(grid, true).write(grid, path);
}

}  // namespace seflex::io
