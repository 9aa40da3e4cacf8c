#pragma once
// io's side of the VTK plugin (io/vtk_plugin/vtk_plugin_api.hpp): the plugin is loaded at the first
// VtkGridWriter made in the process (never before), then kept. Throws PluginError if it cannot be
// found or is not this build's (the message names the files tried and SEFLEX_VTK_PLUGIN).
#include <filesystem>

#include "vtk_plugin_api.hpp"

namespace seflex::io {

/// The plugin's table; loads libseflex_vtk.so at the first call. Throws PluginError.
const vtk_plugin::Plugin& vtk_writer_plugin();

/// One .vtu writer of a grid whose cells and arrays are fixed; the points and point data values may
/// change between writes (the animation's steps).
class VtkGridWriter {
 public:
  /// Copies `grid` into the plugin's writer (compressed appended data if `compress`). Throws
  /// PluginError (no plugin) or InvariantError (the plugin's message).
  VtkGridWriter(const vtk_plugin::Grid& grid, bool compress);
  ~VtkGridWriter();
  VtkGridWriter(const VtkGridWriter&) = delete;
  VtkGridWriter& operator=(const VtkGridWriter&) = delete;

  /// Writes `grid`'s points and point data values (same layout as at construction) to `path`.
  /// Throws InputError naming `path` if the plugin reports a failure.
  void write(const vtk_plugin::Grid& grid, const std::filesystem::path& path);

 private:
  const vtk_plugin::Plugin& plugin_;
  vtk_plugin::Writer* writer_ = nullptr;
};

}  // namespace seflex::io
