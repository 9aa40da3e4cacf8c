// Loading the distributed backend's plugin (parallel/include/seflex/parallel/backend.hpp): the first
// run that asks for `--backend slepc` loads libseflex_parallel.so; no other command does. The search
// (SEFLEX_PARALLEL_PLUGIN, beside the command, the build's path) is common/plugin.hpp's.
#ifdef SEFLEX_HAVE_MPI
#include "seflex/common/plugin.hpp"

#include "distributed_run.hpp"

namespace seflex::app {
namespace {

const parallel::Backend* load_backend() {
  // RTLD_GLOBAL: Open MPI's components, which MPI_Init loads, resolve MPI's symbols from the global scope.
  const PluginSpec spec{"the distributed backend", "libseflex_parallel.so", "SEFLEX_PARALLEL_PLUGIN",
                        SEFLEX_PARALLEL_PLUGIN, parallel::kBackendEntry, RTLD_NOW | RTLD_GLOBAL};
  return load_plugin_table<parallel::Backend>(spec, parallel::kBackendAbi, parallel::backend_fingerprint());
}

}  // namespace

const parallel::Backend& parallel_backend() {
  static const parallel::Backend* backend = load_backend();
  return *backend;
}

}  // namespace seflex::app
#endif
