// Loading the distributed backend's plugin (parallel/include/seflex/parallel/backend.hpp): the first
// run that asks for `--backend slepc` loads libseflex_parallel.so; no other command does. The search
// (SEFLEX_PARALLEL_PLUGIN, beside the command, the build's path) is common/plugin.hpp's.
#ifdef SEFLEX_HAVE_MPI
#include "seflex/common/plugin.hpp"

#include "distributed_run.hpp"

namespace seflex::app {
namespace {

const parallel::Backend* load_backend() {
  PluginSpec spec;
  spec.what = "the distributed backend";
  spec.file_name = "libseflex_parallel.so";
  spec.env_var = "SEFLEX_PARALLEL_PLUGIN";
  spec.build_path = SEFLEX_PARALLEL_PLUGIN;
  spec.entry = parallel::kBackendEntry;
  // RTLD_GLOBAL: Open MPI's components, which MPI_Init loads, resolve MPI's symbols from the global scope.
  spec.dlopen_flags = RTLD_NOW | RTLD_GLOBAL;
  const LoadedPlugin plugin = load_plugin(spec);
  using Entry = const parallel::Backend* (*)();
  const parallel::Backend* b = reinterpret_cast<Entry>(plugin.entry)();
  if (b == nullptr || b->abi != parallel::kBackendAbi || b->fingerprint != parallel::backend_fingerprint())
    throw plugin_mismatch(spec, plugin.path);
  return b;  // the plugin stays loaded until the process ends
}

}  // namespace

const parallel::Backend& parallel_backend() {
  static const parallel::Backend* backend = load_backend();
  return *backend;
}

}  // namespace seflex::app
#endif
