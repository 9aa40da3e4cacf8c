// The gmsh library (gmsh_mesh.hpp: library::read, library::write_msh) and load_gmsh_mesh, which
// gives it .geo files and every other file to seflex's own reader (read_msh): the only file of seflex
// that calls gmsh (through its C API, loaded at the first use: gmsh_api.hpp). gmsh is a process-wide singleton (one current model, global options): a Session initialises it
// quietly (General.Terminal = 0, messages to the logger), is held by one read at a time, and always
// finalises it, also when the read throws.
// General.AbortOnError = 0: gmsh then reports errors only to its logger, where they are read after
// every call. With gmsh's API default (throw from inside the call) a syntax error thrown out of the
// .geo parser leaves the parser in a broken state, and the next read in the process fails with a
// bogus "line 0: syntax error" (gmsh 4.8; tests/io/gmsh_bad_input_test.cpp).
#include <algorithm>
#include <cstdio>
#include <mutex>
#include <string>
#include <vector>

#include "gmsh_api.hpp"
#include "seflex/common/error.hpp"
#include "seflex/io/gmsh_mesh.hpp"
#include "seflex/io/nastran_lines.hpp"

namespace seflex::io::gmsh {
namespace {

std::mutex& session_mutex() {
  static std::mutex m;
  return m;
}
thread_local bool t_in_session = false;

/// Marks this thread as inside a gmsh session for its lifetime.
class ThreadFlag {
 public:
  ThreadFlag() {
    if (t_in_session)
      throw InvariantError("a gmsh read was started from inside another gmsh read on the same thread; gmsh is a "
                           "process-wide singleton and cannot nest");
    t_in_session = true;
  }
  ~ThreadFlag() { t_in_session = false; }
  ThreadFlag(const ThreadFlag&) = delete;
  ThreadFlag& operator=(const ThreadFlag&) = delete;
};

/// Exclusive, quiet use of gmsh; finalised on destruction whatever happened.
class Session {
 public:
  Session() : lock_(session_mutex()) {
    if (api::initialize() != 0) {
      api::finalize();
      throw Error("gmsh: the library could not be initialised");
    }
    api::option_set_number("General.Terminal", 0);
    api::option_set_number("General.AbortOnError", 0);
    api::onelab_clear();  // parameter values of an earlier read
    api::logger_start();
    std::vector<std::string> log;
    api::logger_get(log);
    log_start_ = log.size();
  }
  ~Session() {
    api::logger_stop();
    api::onelab_clear();
    api::clear();
    api::finalize();
  }
  Session(const Session&) = delete;
  Session& operator=(const Session&) = delete;

  /// gmsh's error messages of this session so far, without repeats.
  std::string errors() const {
    std::vector<std::string> log, lines;
    api::logger_get(log);
    for (std::size_t i = log_start_; i < log.size(); ++i)
      if (const std::string& l = log[i]; l.rfind("Error", 0) == 0) {
        const std::size_t colon = l.find(':');
        std::string text = colon == std::string::npos ? l : std::string(nastran::trim(l.substr(colon + 1)));
        if (std::find(lines.begin(), lines.end(), text) == lines.end()) lines.push_back(std::move(text));
      }
    std::string out;
    constexpr std::size_t kMaxLines = 8;
    for (std::size_t i = 0; i < lines.size() && i < kMaxLines; ++i) out += (i ? "; " : "") + lines[i];
    if (lines.size() > kMaxLines) out += "; ... (" + std::to_string(lines.size() - kMaxLines) + " more)";
    return out;
  }

 private:
  ThreadFlag flag_;
  std::unique_lock<std::mutex> lock_;
  std::size_t log_start_ = 0;
};

/// Run a gmsh call (returning gmsh's error flag); turn its failure (the flag, or an error in gmsh's
/// log) into an InputError "file: what: gmsh's messages".
template <class F>
void checked(const Session& session, const std::string& file, const std::string& what, F&& call) {
  const int ierr = call();
  const std::string errors = session.errors();
  if (ierr != 0 || !errors.empty())
    throw InputError(file + ": " + what + ": " + (errors.empty() ? std::string("gmsh reported a failure") : errors));
}

std::string lower_extension(const std::filesystem::path& p) {
  std::string e = p.extension().string();
  for (char& c : e) c = static_cast<char>(c >= 'A' && c <= 'Z' ? c - 'A' + 'a' : c);
  return e;
}

/// The ONELAB parameters a .geo file defined (DefineConstant[x = {value, Name "Path/x"}]).
std::vector<std::string> geo_parameters() {
  std::vector<std::string> names, out;
  api::onelab_get_names(names);
  for (auto& n : names)
    if (n.rfind("Gmsh/", 0) != 0 && n.rfind("ONELAB/", 0) != 0) out.push_back(std::move(n));
  return out;
}

/// `name` as the full ONELAB name or its last part (after the last '/', ordering digits ignored).
bool parameter_matches(const std::string& full, const std::string& name) {
  if (full == name) return true;
  std::size_t p = full.rfind('/');
  p = p == std::string::npos ? 0 : p + 1;
  while (p < full.size() && full[p] >= '0' && full[p] <= '9') ++p;
  return full.compare(p, std::string::npos, name) == 0;
}

/// Preset the parameters and parse the .geo file again with them.
void apply_parameters(const Session& session, const std::filesystem::path& path, const std::string& file,
                      const std::vector<GmshParameter>& parameters) {
  const std::vector<std::string> defined = geo_parameters();
  std::string list;
  for (const auto& d : defined) list += (list.empty() ? "" : ", ") + d;
  std::vector<std::string> full;
  for (const auto& p : parameters) {
    std::string match;
    for (const auto& d : defined)
      if (parameter_matches(d, p.name)) match = d;
    if (match.empty())
      throw InputError(file + ": no parameter '" + p.name + "'; expected one the .geo file defines with DefineConstant[" +
                       p.name + " = {value, Name \"Parameters/" + p.name + "\"}] (its parameters: " +
                       (list.empty() ? std::string("none") : list) + ")");
    api::onelab_set_number(match, p.value);
    full.push_back(match);
  }
  checked(session, file, "gmsh cannot read it", [&] { return api::open(path.string()); });
  for (std::size_t k = 0; k < parameters.size(); ++k) {
    std::vector<double> v;
    api::onelab_get_number(full[k], v);
    if (v.size() != 1 || v[0] != parameters[k].value)
      throw InputError(file + ": parameter '" + parameters[k].name + "' kept " + (v.empty() ? std::string("no value") : std::to_string(v[0])) +
                       " instead of the value given; expected a parameter that is not ReadOnly and accepts the value");
  }
}

/// Open `path` (parameters applied), and mesh a .geo file that holds no mesh up to its dimension.
void open_model(const Session& session, const std::filesystem::path& path, const std::string& file,
                const std::vector<GmshParameter>& parameters) {
  checked(session, file, "gmsh cannot read it", [&] { return api::open(path.string()); });
  if (!parameters.empty()) apply_parameters(session, path, file, parameters);
  std::vector<int> types;
  checked(session, file, "gmsh cannot list its elements", [&] { return api::mesh_get_element_types(types); });
  if (types.empty() && lower_extension(path) == ".geo") {
    int dim = 0;
    checked(session, file, "gmsh cannot read its dimension", [&] { return api::model_get_dimension(dim); });
    if (dim > 0) checked(session, file, "gmsh cannot mesh it", [&] { return api::mesh_generate(dim); });
  }
}

ElementBlock element_block(const Session& session, const std::string& file, int type, int entity,
                           std::vector<std::size_t>&& nodes) {
  ElementBlock b;
  b.type = type;
  b.entity_tag = entity;
  checked(session, file, "gmsh cannot describe element type " + std::to_string(type),
          [&] { return api::mesh_get_element_properties(type, b.type_name, b.dim, b.order, b.nodes_per_element); });
  b.nodes = std::move(nodes);
  return b;
}

}  // namespace

MeshData load_gmsh_mesh(const std::filesystem::path& path, const std::vector<GmshParameter>& parameters) {
  const std::string file = path.string();
  std::error_code ec;
  if (!std::filesystem::exists(path, ec)) throw InputError(file + ": no such file; expected a gmsh .msh or .geo file");
  if (!std::filesystem::is_regular_file(path, ec)) throw InputError(file + ": not a regular file; expected a gmsh .msh or .geo file");
  if (lower_extension(path) == ".geo") return library::read(path, parameters);
  if (!parameters.empty())
    throw InputError(file + ": parameter '" + parameters.front().name +
                     "' given for a mesh file; expected parameters only for a .geo file, which gmsh meshes");
  return read_msh(path);
}

namespace library {

MeshData read(const std::filesystem::path& path, const std::vector<GmshParameter>& parameters) {
  MeshData mesh;
  mesh.file = path.string();
  const std::string& file = mesh.file;
  Session session;
  open_model(session, path, file, parameters);
  checked(session, file, "gmsh cannot list its nodes", [&] { return api::mesh_get_nodes(mesh.node_tags, mesh.coords); });
  {
    std::vector<int> all_types;
    std::vector<std::vector<std::size_t>> tags, nodes;
    checked(session, file, "gmsh cannot list its elements", [&] { return api::mesh_get_elements(all_types, tags, nodes); });
    for (const auto& t : tags) mesh.total_elements += t.size();
  }

  std::vector<std::pair<int, int>> groups;
  checked(session, file, "gmsh cannot list its physical groups", [&] { return api::model_get_physical_groups(groups); });
  std::sort(groups.begin(), groups.end());
  for (const auto& group : groups) {
    const int dim = group.first, tag = group.second;  // no structured binding: clang 14 cannot capture one
    PhysicalGroup g;
    g.dim = dim;
    g.tag = tag;
    const std::string which = "physical group (" + std::to_string(dim) + ", " + std::to_string(tag) + ")";
    checked(session, file, "gmsh cannot name " + which, [&] { return api::model_get_physical_name(dim, tag, g.name); });
    checked(session, file, "gmsh cannot list the entities of " + which,
            [&] { return api::model_get_entities_for_physical_group(dim, tag, g.entities); });
    for (const int entity : g.entities) {
      std::vector<int> block_types;
      std::vector<std::vector<std::size_t>> element_tags, node_tags;
      checked(session, file, "gmsh cannot list the elements of " + which,
              [&] { return api::mesh_get_elements(block_types, element_tags, node_tags, dim, entity); });
      for (std::size_t k = 0; k < block_types.size(); ++k)
        if (!element_tags[k].empty())
          g.blocks.push_back(element_block(session, file, block_types[k], entity, std::move(node_tags[k])));
    }
    mesh.groups.push_back(std::move(g));
  }
  return mesh;
}

void write_msh(const std::filesystem::path& model, const std::vector<GmshParameter>& parameters, const std::filesystem::path& out,
               double version, bool binary) {
  const std::string file = model.string();
  Session session;
  open_model(session, model, file, parameters);
  api::option_set_number("Mesh.MshFileVersion", version);
  api::option_set_number("Mesh.Binary", binary ? 1 : 0);
  checked(session, file, "gmsh cannot write " + out.string(), [&] { return api::write(out.string()); });
}

std::vector<LibraryElementType> element_types(int last) {
  Session session;
  std::vector<LibraryElementType> types;
  for (int type = 1; type <= last; ++type) {
    LibraryElementType t;
    t.type = type;
    if (api::mesh_get_element_properties(type, t.name, t.dim, t.order, t.nodes) == 0 && !t.name.empty()) types.push_back(std::move(t));
  }
  return types;
}

}  // namespace library

}  // namespace seflex::io::gmsh
