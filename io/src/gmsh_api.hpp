#pragma once
// gmsh's C API (gmshc.h), loaded with dlopen at the first gmsh read instead of linked: libgmsh
// brings about 90 shared libraries (OpenCASCADE, FLTK, ...) whose dynamic linking cost every seflex
// command about 0.4 s at start-up, also the commands that never read a .msh or .geo file
// (docs/benchmarks.md, "Start-up"). Only gmsh_session.cpp uses this; the signatures are checked
// against gmshc.h at compile time. Vectors are copied out of gmsh's buffers, which are freed.
#include <cstddef>
#include <string>
#include <utility>
#include <vector>

namespace seflex::io::gmsh::api {

/// Load libgmsh (once per process). Throws seflex::Error naming the library and dlerror() when it
/// cannot be loaded or lacks a function.
void load();

// Each call returns gmsh's error flag (0: success); gmsh's messages go to its logger.
int initialize();
int finalize();
int clear();
int option_set_number(const std::string& name, double value);
int onelab_clear();
int onelab_get_names(std::vector<std::string>& names);
int onelab_set_number(const std::string& name, double value);
int onelab_get_number(const std::string& name, std::vector<double>& values);
int logger_start();
int logger_stop();
int logger_get(std::vector<std::string>& log);
int open(const std::string& file);
int write(const std::string& file);
int model_get_dimension(int& dim);
int mesh_generate(int dim);
int mesh_get_element_types(std::vector<int>& types);
int mesh_get_element_properties(int type, std::string& name, int& dim, int& order, int& num_nodes);
int mesh_get_nodes(std::vector<std::size_t>& tags, std::vector<double>& coords);
/// Elements of one entity (dim, tag), or of the whole model with dim = tag = -1.
int mesh_get_elements(std::vector<int>& types, std::vector<std::vector<std::size_t>>& element_tags,
                      std::vector<std::vector<std::size_t>>& node_tags, int dim = -1, int tag = -1);
int model_get_physical_groups(std::vector<std::pair<int, int>>& dim_tags);
int model_get_physical_name(int dim, int tag, std::string& name);
int model_get_entities_for_physical_group(int dim, int tag, std::vector<int>& tags);

}  // namespace seflex::io::gmsh::api
