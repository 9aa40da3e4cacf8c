// Loading the VTK plugin (vtk_writer.hpp) and the writer that calls it.
#include "vtk_writer.hpp"

#include <string>

#include "seflex/common/error.hpp"
#include "seflex/common/plugin.hpp"

namespace seflex::io {
namespace {

const vtk_plugin::Plugin* load_vtk_plugin() {
  const PluginSpec spec{"the VTK writer", "libseflex_vtk.so", "SEFLEX_VTK_PLUGIN", SEFLEX_VTK_PLUGIN,
                        vtk_plugin::kVtkPluginEntry, RTLD_NOW | RTLD_LOCAL};
  return load_plugin_table<vtk_plugin::Plugin>(spec, vtk_plugin::kVtkPluginAbi, vtk_plugin::vtk_plugin_fingerprint());
}

}  // namespace

const vtk_plugin::Plugin& vtk_writer_plugin() {
  static const vtk_plugin::Plugin* plugin = load_vtk_plugin();
  return *plugin;
}

VtkGridWriter::VtkGridWriter(const vtk_plugin::Grid& grid, bool compress) : plugin_(vtk_writer_plugin()) {
  char error[512] = "";
  writer_ = plugin_.create(&grid, compress ? 1 : 0, error, sizeof error);
  if (writer_ == nullptr) throw InvariantError(std::string("the VTK writer could not build the grid: ") + error);
}

VtkGridWriter::~VtkGridWriter() { plugin_.destroy(writer_); }

void VtkGridWriter::write(const vtk_plugin::Grid& grid, const std::filesystem::path& path) {
  char error[512] = "";
  if (plugin_.write(writer_, &grid, path.string().c_str(), error, sizeof error) != 0)
    throw InputError(SourceRef{path.string(), 0}, std::string("cannot be written (") + error + ")");
}

}  // namespace seflex::io
