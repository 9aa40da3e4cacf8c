#pragma once
// The VTK writer as io reaches it: a table of entry points exported by the plugin libseflex_vtk.so
// (io/vtk_plugin/, the only code that links VTK), which io loads with dlopen at the first VTK file it
// writes (io/src/vtk_writer.cpp; the search is common/plugin.hpp's: $SEFLEX_VTK_PLUGIN, beside the
// executable, where the build put it). Commands that write no VTK file never load VTK's libraries.
//
// Plain data only: io computes the points, cells and arrays (vtk_animation.cpp, vtk_modes.cpp) and
// the plugin copies them into a vtkUnstructuredGrid and writes it with vtkXMLUnstructuredGridWriter
// (appended raw data). No seflex type, no C++ library type and no exception crosses the table; errors
// come back as a return value and a message. kVtkPluginAbi (bumped when the table or a struct here
// changes) and vtk_plugin_fingerprint() (their sizes) let the loader refuse a plugin from another build.
#include <cstddef>
#include <cstdint>

#include "seflex/common/plugin.hpp"

namespace seflex::io::vtk_plugin {

inline constexpr int kVtkPluginAbi = 1;

/// Name of the plugin's entry point: extern "C" const Plugin* seflex_vtk_plugin().
inline constexpr const char* kVtkPluginEntry = "seflex_vtk_plugin";

/// VTK's cell type numbers (vtkCellType.h; the plugin checks them at compile time).
enum CellType : std::int32_t {
  kVertex = 1,
  kLine = 3,
  kTriangle = 5,
  kQuad = 9,
  kTetra = 10,
  kHexahedron = 12,
  kWedge = 13,
  kPyramid = 14,
  kQuadraticTetra = 24,
  kQuadraticHexahedron = 25,
  kQuadraticWedge = 26,
  kQuadraticPyramid = 27,
};

enum class ValueType : std::int32_t { kDouble = 1, kInt = 2 };

/// One named array: `tuples` x `components` values, tuple after tuple (double or int).
struct Array {
  const char* name = nullptr;
  ValueType type = ValueType::kDouble;
  std::int32_t components = 1;
  std::int64_t tuples = 0;
  const void* values = nullptr;
};

/// An unstructured grid. Cell c has the points connectivity[offsets[c] .. offsets[c+1]) (0-based point
/// indices; offsets has cell_count + 1 entries). Point data arrays have point_count tuples, cell data
/// arrays cell_count; field data any. active_vectors (may be null) names a point data array.
struct Grid {
  std::int64_t point_count = 0;
  const double* points = nullptr;  ///< 3 x point_count: x y z of each point
  std::int64_t cell_count = 0;
  const std::int32_t* cell_types = nullptr;  ///< CellType per cell
  const std::int64_t* offsets = nullptr;
  const std::int64_t* connectivity = nullptr;
  const Array* point_data = nullptr;
  std::int32_t point_data_count = 0;
  const char* active_vectors = nullptr;
  const Array* cell_data = nullptr;
  std::int32_t cell_data_count = 0;
  const Array* field_data = nullptr;
  std::int32_t field_data_count = 0;
};

struct Writer;  // the plugin's: the VTK grid, its arrays and the XML writer

/// Error messages are written into `error` (NUL-terminated, at most error_size bytes).
struct Plugin {
  std::int32_t abi = kVtkPluginAbi;
  std::uint64_t fingerprint = 0;
  /// A writer holding a copy of `grid` (appended raw data, compressed by VTK's default compressor
  /// (zlib) if `compress`, else not). Returns null on failure.
  Writer* (*create)(const Grid* grid, std::int32_t compress, char* error, std::size_t error_size) = nullptr;
  /// Copies the points and the point data values of `grid` (the same names, counts and sizes as at
  /// create; cells, cell and field data are not read) into the writer's grid and writes the .vtu file
  /// `path`. Returns 0 on success.
  std::int32_t (*write)(Writer* writer, const Grid* grid, const char* path, char* error, std::size_t error_size) = nullptr;
  void (*destroy)(Writer* writer) = nullptr;
};

/// The sizes of the structs that cross the table, combined: equal on both sides of one build.
inline std::uint64_t vtk_plugin_fingerprint() {
  return size_fingerprint({sizeof(Plugin), sizeof(Grid), sizeof(Array), sizeof(CellType), sizeof(ValueType)});
}

}  // namespace seflex::io::vtk_plugin
