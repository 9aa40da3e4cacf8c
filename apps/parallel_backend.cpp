// Loading the distributed backend's plugin (parallel/include/seflex/parallel/backend.hpp): the first
// run that asks for `--backend slepc` loads libseflex_parallel.so; no other command does.
#ifdef SEFLEX_HAVE_MPI
#include <dlfcn.h>

#include <cstdlib>
#include <filesystem>
#include <stdexcept>
#include <string>
#include <vector>

#include "distributed_run.hpp"

namespace seflex::app {
namespace {

/// Where the plugin may be: $SEFLEX_PARALLEL_PLUGIN, beside the command, where the build put it.
std::vector<std::string> plugin_candidates() {
  std::vector<std::string> out;
  if (const char* env = std::getenv("SEFLEX_PARALLEL_PLUGIN"); env != nullptr && *env != '\0') {
    out.emplace_back(env);
    return out;  // the user's choice, alone
  }
  std::error_code ec;
  const std::filesystem::path self = std::filesystem::read_symlink("/proc/self/exe", ec);
  if (!ec) out.push_back((self.parent_path() / "libseflex_parallel.so").string());
  out.emplace_back(SEFLEX_PARALLEL_PLUGIN);
  return out;
}

const parallel::Backend* load_backend() {
  const std::vector<std::string> candidates = plugin_candidates();
  std::string tried;
  for (const std::string& path : candidates) {
    if (!std::filesystem::exists(path)) {
      tried += (tried.empty() ? "" : ", ") + path;
      continue;
    }
    // RTLD_GLOBAL: Open MPI's components, which MPI_Init loads, resolve MPI's symbols from the global scope.
    void* handle = dlopen(path.c_str(), RTLD_NOW | RTLD_GLOBAL);
    if (handle == nullptr) {
      const char* why = dlerror();
      throw std::runtime_error("the distributed backend " + path + " could not be loaded: " + (why ? why : "?"));
    }
    using Entry = const parallel::Backend* (*)();
    auto entry = reinterpret_cast<Entry>(dlsym(handle, parallel::kBackendEntry));
    if (entry == nullptr)
      throw std::runtime_error("the distributed backend " + path + " has no entry point " + parallel::kBackendEntry +
                               ": not a seflex plugin");
    const parallel::Backend* b = entry();
    if (b == nullptr || b->abi != parallel::kBackendAbi || b->fingerprint != parallel::backend_fingerprint())
      throw std::runtime_error("the distributed backend " + path +
                               " was built from other sources than this seflex command; rebuild both (cmake --build)");
    return b;  // the plugin stays loaded until the process ends
  }
  throw std::runtime_error("the distributed backend (libseflex_parallel.so) is not installed: looked for " + tried +
                           "; set SEFLEX_PARALLEL_PLUGIN to its path");
}

}  // namespace

const parallel::Backend& parallel_backend() {
  static const parallel::Backend* backend = load_backend();
  return *backend;
}

}  // namespace seflex::app
#endif
