// gmsh's C API through dlopen (gmsh_api.hpp says why).
#include "gmsh_api.hpp"

#include <dlfcn.h>
#include <gmshc.h>

#include <mutex>

#include "seflex/common/error.hpp"

namespace seflex::io::gmsh::api {
namespace {

#define SEFLEX_STR2(x) #x
#define SEFLEX_STR(x) SEFLEX_STR2(x)
// The soname of the gmsh whose gmshc.h we compiled against (Debian: libgmsh.so.4.8).
constexpr const char* kLibrary = "libgmsh.so." SEFLEX_STR(GMSH_API_VERSION_MAJOR) "." SEFLEX_STR(GMSH_API_VERSION_MINOR);

struct Functions {
  decltype(&::gmshInitialize) initialize = nullptr;
  decltype(&::gmshFinalize) finalize = nullptr;
  decltype(&::gmshClear) clear = nullptr;
  decltype(&::gmshFree) free = nullptr;
  decltype(&::gmshOptionSetNumber) option_set_number = nullptr;
  decltype(&::gmshOnelabClear) onelab_clear = nullptr;
  decltype(&::gmshOnelabGetNames) onelab_get_names = nullptr;
  decltype(&::gmshOnelabSetNumber) onelab_set_number = nullptr;
  decltype(&::gmshOnelabGetNumber) onelab_get_number = nullptr;
  decltype(&::gmshLoggerStart) logger_start = nullptr;
  decltype(&::gmshLoggerStop) logger_stop = nullptr;
  decltype(&::gmshLoggerGet) logger_get = nullptr;
  decltype(&::gmshOpen) open = nullptr;
  decltype(&::gmshWrite) write = nullptr;
  decltype(&::gmshModelGetDimension) model_get_dimension = nullptr;
  decltype(&::gmshModelMeshGenerate) mesh_generate = nullptr;
  decltype(&::gmshModelMeshGetElementTypes) mesh_get_element_types = nullptr;
  decltype(&::gmshModelMeshGetElementProperties) mesh_get_element_properties = nullptr;
  decltype(&::gmshModelMeshGetNodes) mesh_get_nodes = nullptr;
  decltype(&::gmshModelMeshGetElements) mesh_get_elements = nullptr;
  decltype(&::gmshModelGetPhysicalGroups) model_get_physical_groups = nullptr;
  decltype(&::gmshModelGetPhysicalName) model_get_physical_name = nullptr;
  decltype(&::gmshModelGetEntitiesForPhysicalGroup) model_get_entities_for_physical_group = nullptr;
};

Functions g_fn;

template <class F>
void bind(void* lib, F& f, const char* symbol) {
  f = reinterpret_cast<F>(dlsym(lib, symbol));
  if (!f)
    throw Error(std::string("gmsh: ") + kLibrary + " has no function " + symbol +
                "; expected the gmsh " GMSH_API_VERSION " library seflex was built with");
}

void load_once() {
  void* lib = dlopen(kLibrary, RTLD_NOW | RTLD_LOCAL);
  if (!lib) {
    const char* why = dlerror();
    throw Error(std::string("reading a gmsh file needs ") + kLibrary + " (Debian package libgmsh4.8, installed by " +
                "scripts/install-deps.sh), which cannot be loaded: " + (why ? why : "unknown reason"));
  }
  Functions f;
  bind(lib, f.initialize, "gmshInitialize");
  bind(lib, f.finalize, "gmshFinalize");
  bind(lib, f.clear, "gmshClear");
  bind(lib, f.free, "gmshFree");
  bind(lib, f.option_set_number, "gmshOptionSetNumber");
  bind(lib, f.onelab_clear, "gmshOnelabClear");
  bind(lib, f.onelab_get_names, "gmshOnelabGetNames");
  bind(lib, f.onelab_set_number, "gmshOnelabSetNumber");
  bind(lib, f.onelab_get_number, "gmshOnelabGetNumber");
  bind(lib, f.logger_start, "gmshLoggerStart");
  bind(lib, f.logger_stop, "gmshLoggerStop");
  bind(lib, f.logger_get, "gmshLoggerGet");
  bind(lib, f.open, "gmshOpen");
  bind(lib, f.write, "gmshWrite");
  bind(lib, f.model_get_dimension, "gmshModelGetDimension");
  bind(lib, f.mesh_generate, "gmshModelMeshGenerate");
  bind(lib, f.mesh_get_element_types, "gmshModelMeshGetElementTypes");
  bind(lib, f.mesh_get_element_properties, "gmshModelMeshGetElementProperties");
  bind(lib, f.mesh_get_nodes, "gmshModelMeshGetNodes");
  bind(lib, f.mesh_get_elements, "gmshModelMeshGetElements");
  bind(lib, f.model_get_physical_groups, "gmshModelGetPhysicalGroups");
  bind(lib, f.model_get_physical_name, "gmshModelGetPhysicalName");
  bind(lib, f.model_get_entities_for_physical_group, "gmshModelGetEntitiesForPhysicalGroup");
  g_fn = f;  // the library stays loaded for the life of the process
}

// Copy a gmsh-allocated array into a vector and free it.
template <class T>
std::vector<T> take(T* p, std::size_t n) {
  std::vector<T> v(p, p + (p ? n : 0));
  if (p) g_fn.free(p);
  return v;
}
std::string take_string(char* p) {
  std::string s = p ? p : "";
  if (p) g_fn.free(p);
  return s;
}
std::vector<std::string> take_strings(char** p, std::size_t n) {
  std::vector<std::string> v;
  v.reserve(n);
  for (std::size_t i = 0; i < n && p; ++i) v.push_back(take_string(p[i]));
  if (p) g_fn.free(p);
  return v;
}
std::vector<std::vector<std::size_t>> take_nested(std::size_t** p, std::size_t* sizes, std::size_t nn) {
  std::vector<std::vector<std::size_t>> v(p ? nn : 0);
  for (std::size_t i = 0; i < v.size(); ++i) v[i] = take(p[i], sizes[i]);
  if (p) g_fn.free(p);
  if (sizes) g_fn.free(sizes);
  return v;
}

}  // namespace

void load() {
  static std::once_flag once;
  std::call_once(once, load_once);  // an exception leaves the flag unset: the next read tries again
}

int initialize() {
  load();
  int ierr = 0;
  g_fn.initialize(0, nullptr, /*readConfigFiles=*/0, &ierr);
  return ierr;
}
int finalize() {
  int ierr = 0;
  g_fn.finalize(&ierr);
  return ierr;
}
int clear() {
  int ierr = 0;
  g_fn.clear(&ierr);
  return ierr;
}
int option_set_number(const std::string& name, double value) {
  int ierr = 0;
  g_fn.option_set_number(name.c_str(), value, &ierr);
  return ierr;
}
int onelab_clear() {
  int ierr = 0;
  g_fn.onelab_clear("", &ierr);
  return ierr;
}
int onelab_get_names(std::vector<std::string>& names) {
  int ierr = 0;
  char** p = nullptr;
  std::size_t n = 0;
  g_fn.onelab_get_names(&p, &n, "", &ierr);
  names = take_strings(p, n);
  return ierr;
}
int onelab_set_number(const std::string& name, double value) {
  int ierr = 0;
  g_fn.onelab_set_number(name.c_str(), &value, 1, &ierr);
  return ierr;
}
int onelab_get_number(const std::string& name, std::vector<double>& values) {
  int ierr = 0;
  double* p = nullptr;
  std::size_t n = 0;
  g_fn.onelab_get_number(name.c_str(), &p, &n, &ierr);
  values = take(p, n);
  return ierr;
}
int logger_start() {
  int ierr = 0;
  g_fn.logger_start(&ierr);
  return ierr;
}
int logger_stop() {
  int ierr = 0;
  g_fn.logger_stop(&ierr);
  return ierr;
}
int logger_get(std::vector<std::string>& log) {
  int ierr = 0;
  char** p = nullptr;
  std::size_t n = 0;
  g_fn.logger_get(&p, &n, &ierr);
  log = take_strings(p, n);
  return ierr;
}
int open(const std::string& file) {
  int ierr = 0;
  g_fn.open(file.c_str(), &ierr);
  return ierr;
}
int write(const std::string& file) {
  int ierr = 0;
  g_fn.write(file.c_str(), &ierr);
  return ierr;
}
int model_get_dimension(int& dim) {
  int ierr = 0;
  dim = g_fn.model_get_dimension(&ierr);
  return ierr;
}
int mesh_generate(int dim) {
  int ierr = 0;
  g_fn.mesh_generate(dim, &ierr);
  return ierr;
}
int mesh_get_element_types(std::vector<int>& types) {
  int ierr = 0;
  int* p = nullptr;
  std::size_t n = 0;
  g_fn.mesh_get_element_types(&p, &n, -1, -1, &ierr);
  types = take(p, n);
  return ierr;
}
int mesh_get_element_properties(int type, std::string& name, int& dim, int& order, int& num_nodes) {
  int ierr = 0;
  char* s = nullptr;
  double* local = nullptr;
  std::size_t local_n = 0;
  int primary = 0;
  g_fn.mesh_get_element_properties(type, &s, &dim, &order, &num_nodes, &local, &local_n, &primary, &ierr);
  name = take_string(s);
  take(local, local_n);
  return ierr;
}
int mesh_get_nodes(std::vector<std::size_t>& tags, std::vector<double>& coords) {
  int ierr = 0;
  std::size_t* t = nullptr;
  double* c = nullptr;
  double* par = nullptr;
  std::size_t tn = 0, cn = 0, pn = 0;
  g_fn.mesh_get_nodes(&t, &tn, &c, &cn, &par, &pn, -1, -1, /*includeBoundary=*/0, /*returnParametricCoord=*/0, &ierr);
  tags = take(t, tn);
  coords = take(c, cn);
  take(par, pn);
  return ierr;
}
int mesh_get_elements(std::vector<int>& types, std::vector<std::vector<std::size_t>>& element_tags,
                      std::vector<std::vector<std::size_t>>& node_tags, int dim, int tag) {
  int ierr = 0;
  int* ty = nullptr;
  std::size_t ty_n = 0;
  std::size_t** et = nullptr;
  std::size_t* et_n = nullptr;
  std::size_t et_nn = 0;
  std::size_t** nt = nullptr;
  std::size_t* nt_n = nullptr;
  std::size_t nt_nn = 0;
  g_fn.mesh_get_elements(&ty, &ty_n, &et, &et_n, &et_nn, &nt, &nt_n, &nt_nn, dim, tag, &ierr);
  types = take(ty, ty_n);
  element_tags = take_nested(et, et_n, et_nn);
  node_tags = take_nested(nt, nt_n, nt_nn);
  return ierr;
}
int model_get_physical_groups(std::vector<std::pair<int, int>>& dim_tags) {
  int ierr = 0;
  int* p = nullptr;
  std::size_t n = 0;
  g_fn.model_get_physical_groups(&p, &n, -1, &ierr);
  const std::vector<int> flat = take(p, n);
  dim_tags.clear();
  for (std::size_t i = 0; i + 1 < flat.size(); i += 2) dim_tags.emplace_back(flat[i], flat[i + 1]);
  return ierr;
}
int model_get_physical_name(int dim, int tag, std::string& name) {
  int ierr = 0;
  char* s = nullptr;
  g_fn.model_get_physical_name(dim, tag, &s, &ierr);
  name = take_string(s);
  return ierr;
}
int model_get_entities_for_physical_group(int dim, int tag, std::vector<int>& tags) {
  int ierr = 0;
  int* p = nullptr;
  std::size_t n = 0;
  g_fn.model_get_entities_for_physical_group(dim, tag, &p, &n, &ierr);
  tags = take(p, n);
  return ierr;
}

}  // namespace seflex::io::gmsh::api
