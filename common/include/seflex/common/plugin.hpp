#pragma once
// Plugins: shared modules that seflex loads with dlopen the first time they are needed, so that the
// command starts without their heavy libraries (the distributed backend, libseflex_parallel.so:
// parallel/include/seflex/parallel/backend.hpp; the VTK writer, libseflex_vtk.so:
// io/vtk_plugin/vtk_plugin_api.hpp). Each exports one extern "C" entry point returning a table of
// functions that starts with an ABI number and a fingerprint; the loader checks both.
//
// Where a plugin is looked for, in this order: the path in its environment variable (alone, if set),
// the file beside the running executable (/proc/self/exe), the path where the build put it (compiled
// in). A missing plugin, a file that cannot be loaded, one without the entry point or from another
// build is a PluginError naming the files tried and the environment variable.
#include <dlfcn.h>

#include <cstddef>
#include <cstdint>
#include <cstdlib>
#include <filesystem>
#include <initializer_list>
#include <string>
#include <system_error>
#include <vector>

#include "seflex/common/error.hpp"

namespace seflex {

/// A plugin that is missing or not the one this build expects.
class PluginError : public Error {
 public:
  using Error::Error;
};

struct PluginSpec {
  std::string what;        ///< for messages, e.g. "the distributed backend"
  std::string file_name;   ///< e.g. "libseflex_parallel.so"
  std::string env_var;     ///< e.g. "SEFLEX_PARALLEL_PLUGIN"
  std::string build_path;  ///< where the build put it (compiled in)
  std::string entry;       ///< the extern "C" entry point
  int dlopen_flags = RTLD_NOW | RTLD_LOCAL;
};

struct LoadedPlugin {
  std::string path;      ///< the file loaded
  void* entry = nullptr;  ///< the entry point's address (never null)
};

/// The candidate files of `spec`, in search order: $env_var alone if set, else beside the
/// executable, then build_path.
inline std::vector<std::string> plugin_candidates(const PluginSpec& spec) {
  std::vector<std::string> out;
  if (const char* env = std::getenv(spec.env_var.c_str()); env != nullptr && *env != '\0') {
    out.emplace_back(env);
    return out;  // the user's choice, alone
  }
  std::error_code ec;
  const std::filesystem::path self = std::filesystem::read_symlink("/proc/self/exe", ec);
  if (!ec) out.push_back((self.parent_path() / spec.file_name).string());
  if (out.empty() || out.back() != spec.build_path) out.push_back(spec.build_path);
  return out;
}

/// Loads the first candidate that exists and finds its entry point; the module stays loaded until
/// the process ends. Throws PluginError (no candidate exists; dlopen fails; no entry point).
inline LoadedPlugin load_plugin(const PluginSpec& spec) {
  std::string tried;
  for (const std::string& path : plugin_candidates(spec)) {
    if (!std::filesystem::exists(path)) {
      tried += (tried.empty() ? "" : ", ") + path;
      continue;
    }
    void* handle = dlopen(path.c_str(), spec.dlopen_flags);
    if (handle == nullptr) {
      const char* why = dlerror();
      throw PluginError(spec.what + " " + path + " could not be loaded: " + (why ? why : "?") + "; set " +
                        spec.env_var + " to the " + spec.file_name + " of this build");
    }
    void* entry = dlsym(handle, spec.entry.c_str());
    if (entry == nullptr)
      throw PluginError(spec.what + " " + path + " has no entry point " + spec.entry + ": not a seflex plugin");
    return {path, entry};
  }
  throw PluginError(spec.what + " (" + spec.file_name + ") is not installed: looked for " + tried + "; set " +
                    spec.env_var + " to its path");
}

/// The error for a plugin whose ABI number or fingerprint differs from the loader's.
inline PluginError plugin_mismatch(const PluginSpec& spec, const std::string& path) {
  return PluginError(spec.what + " " + path + " was built from other sources than this seflex command; rebuild both (cmake --build)");
}

/// Loads `spec`'s plugin and calls its entry point, `const Table* entry()`; the table must carry
/// `abi` and `fingerprint` (members of those names). Throws PluginError.
template <class Table>
const Table* load_plugin_table(const PluginSpec& spec, int abi, std::uint64_t fingerprint) {
  const LoadedPlugin plugin = load_plugin(spec);
  const Table* table = reinterpret_cast<const Table* (*)()>(plugin.entry)();
  if (table == nullptr || table->abi != abi || table->fingerprint != fingerprint) throw plugin_mismatch(spec, plugin.path);
  return table;
}

/// FNV-1a over the sizes of the types that cross a plugin's table: equal on both sides of one build.
inline std::uint64_t size_fingerprint(std::initializer_list<std::size_t> sizes) {
  std::uint64_t h = 1469598103934665603ull;
  for (std::size_t s : sizes) {
    h ^= s;
    h *= 1099511628211ull;
  }
  return h;
}

}  // namespace seflex
