// gmsh mesh + companion bulk data + $seflex directives -> fem::Model (docs/gmsh-input.md).
#include <algorithm>
#include <climits>
#include <map>
#include <unordered_map>
#include <unordered_set>

#include "seflex/common/error.hpp"
#include "seflex/fem/finalize.hpp"
#include "seflex/io/gmsh.hpp"
#include "seflex/io/gmsh_directives.hpp"
#include "seflex/io/gmsh_mesh.hpp"
#include "seflex/io/nastran.hpp"
#include "seflex/io/nastran_lines.hpp"

namespace seflex::io {
namespace gmsh {
namespace {

using Kind = GroupDirective::Kind;

bool makes_elements(Kind k) { return k == Kind::Shell || k == Kind::Bar || k == Kind::Beam || k == Kind::Rod; }

/// "physical surface 'plate'" (or "physical surface 3" when unnamed).
std::string group_label(const PhysicalGroup& g) {
  return std::string("physical ") + dimension_name(g.dim) + " " + (g.name.empty() ? std::to_string(g.tag) : "'" + g.name + "'");
}

/// What the directives say about one physical group.
struct GroupPlan {
  const GroupDirective* element = nullptr;  ///< Shell/Bar/Beam/Rod
  const GroupDirective* mass = nullptr;
  const GroupDirective* grid = nullptr;
  bool set = false;
  bool used() const { return element || mass || grid || set; }
};

/// gmsh node tag -> position in MeshData::node_tags (dense when the tags are, else hashed).
class NodeIndex {
 public:
  explicit NodeIndex(const std::vector<std::size_t>& tags) {
    std::size_t max_tag = 0;
    for (const std::size_t t : tags) max_tag = std::max(max_tag, t);
    dense_ = max_tag <= 4 * tags.size() + 1024;
    if (dense_) {
      positions_.assign(max_tag + 1, kNone);
      for (std::size_t i = 0; i < tags.size(); ++i) positions_[tags[i]] = i;
    } else {
      for (std::size_t i = 0; i < tags.size(); ++i) map_.emplace(tags[i], i);
    }
  }
  static constexpr std::size_t kNone = static_cast<std::size_t>(-1);
  std::size_t find(std::size_t tag) const {
    if (dense_) return tag < positions_.size() ? positions_[tag] : kNone;
    const auto it = map_.find(tag);
    return it == map_.end() ? kNone : it->second;
  }

 private:
  bool dense_ = true;
  std::vector<std::size_t> positions_;
  std::unordered_map<std::size_t, std::size_t> map_;
};

class ModelBuilder {
 public:
  /// `mesh_file`: index of the mesh in model.files (the CardRef of every card made from it).
  ModelBuilder(fem::Model& model, const MeshData& mesh, const Directives& directives, std::string props,
               std::uint32_t mesh_file)
      : m_(model), mesh_(mesh), dir_(directives), props_(std::move(props)), nodes_(mesh.node_tags),
        plans_(mesh.groups.size()), mesh_ref_{mesh_file, 0} {}

  void run() {
    check_mesh();
    plan_groups();
    check_unmapped();
    check_element_types();
    number_nodes();
    make_elements();
    make_masses();
    make_node_sets();
  }

 private:
  [[noreturn]] void fail_mesh(const std::string& problem) const { throw InputError(mesh_.file + ": " + problem); }
  [[noreturn]] void fail_directive(const GroupDirective& d, const std::string& problem) const {
    throw InputError(SourceRef{props_, d.line}, "$seflex group " + d.group + " " + d.keyword + ": " + problem);
  }

  std::string group_list() const {
    std::string s;
    for (const auto& g : mesh_.groups) s += (s.empty() ? "" : ", ") + (g.name.empty() ? std::to_string(g.tag) : g.name) +
                                            " (" + dimension_name(g.dim) + ")";
    return s.empty() ? "none" : s;
  }

  void check_mesh() const {
    if (mesh_.total_elements == 0)
      fail_mesh("the mesh has no elements; expected a meshed model (a .msh file with elements, or a .geo file gmsh can mesh)");
    if (mesh_.groups.empty())
      fail_mesh("the mesh has no physical groups; expected physical groups naming the parts (Physical Surface(\"plate\") = "
                "{...}; in a .geo file), mapped to properties in " + props_);
  }

  /// Match every directive with its groups; one element mapping per group.
  void plan_groups() {
    for (const auto& d : dir_.groups) {
      const int want_dim = d.kind == Kind::Shell ? 2 : makes_elements(d.kind) ? 1 : -1;
      bool found = false, other_dim = false;
      for (std::size_t i = 0; i < mesh_.groups.size(); ++i) {
        const PhysicalGroup& g = mesh_.groups[i];
        if (g.name != d.group) continue;
        if (want_dim >= 0 && g.dim != want_dim) {
          other_dim = true;
          continue;
        }
        found = true;
        GroupPlan& p = plans_[i];
        const GroupDirective** slot = makes_elements(d.kind) ? &p.element : d.kind == Kind::Mass ? &p.mass
                                                                        : d.kind == Kind::Grid   ? &p.grid
                                                                                                 : nullptr;
        if (slot) {
          if (*slot)
            fail_directive(d, "the group is already mapped on line " + std::to_string((*slot)->line) +
                                  " (" + std::string(kind_name((*slot)->kind)) + "); expected one such line per group");
          *slot = &d;
        } else {
          p.set = true;
        }
      }
      if (!found && other_dim)
        fail_directive(d, "no " + std::string(dimension_name(want_dim)) + " group of this name in " + mesh_.file + "; " +
                              std::string(kind_name(d.kind)) + " maps the elements of a physical " + dimension_name(want_dim) +
                              " (its physical groups: " + group_list() + ")");
      if (!found)
        fail_directive(d, "no physical group named '" + d.group + "' in " + mesh_.file + "; expected one of its physical groups: " +
                              group_list());
      if (makes_elements(d.kind)) check_property(d);
    }
  }

  void check_property(const GroupDirective& d) {
    using Source = fem::BarProperty::Source;
    bool ok = false;
    std::string have;
    switch (d.kind) {
      case Kind::Shell:
        for (const auto& p : m_.shell_props) ok |= p.id == d.pid;
        break;
      case Kind::Rod:
        for (const auto& p : m_.rod_props) ok |= p.id == d.pid;
        break;
      default:
        for (const auto& p : m_.bar_props)
          if (p.id == d.pid) {
            const bool bar = p.source == Source::PBAR || p.source == Source::PBARL;
            ok = bar == (d.kind == Kind::Bar);
            have = bar ? "a PBAR/PBARL" : "a PBEAM/PBEAML";
          }
    }
    if (!ok)
      fail_directive(d, std::string(kind_name(d.kind)) + " " + std::to_string(d.pid) + " is " +
                            (have.empty() ? "not defined in " + props_ : have + " card") + "; expected a " +
                            std::string(kind_name(d.kind)) + (d.kind == Kind::Bar ? "/PBARL" : d.kind == Kind::Beam ? "/PBEAML" : "") +
                            " card with PID " + std::to_string(d.pid));
    if ((d.kind == Kind::Bar || d.kind == Kind::Beam) && !d.v) {
      const fem::BarDefaults& def = d.kind == Kind::Bar ? m_.baror : m_.beamor;
      if (!def.present || (!def.has_g0 && def.v.squaredNorm() == 0.0))
        fail_directive(d, "no orientation vector; expected X1 X2 X3 after the PID (a vector in the bar's x-y plane, basic "
                          "system), or a " + std::string(d.kind == Kind::Bar ? "BAROR" : "BEAMOR") + " card in " + props_);
    }
  }

  void check_unmapped() const {
    for (std::size_t i = 0; i < mesh_.groups.size(); ++i) {
      const PhysicalGroup& g = mesh_.groups[i];
      if (g.dim == 3)
        fail_mesh(group_label(g) + ": volume elements are not supported; expected shells (surfaces) and bars (curves)");
      if (g.dim == 0 || plans_[i].used()) continue;
      if (g.name.empty())
        fail_mesh(group_label(g) + " has no name; expected a name (Physical " +
                  std::string(g.dim == 2 ? "Surface" : "Curve") + "(\"name\") = {...}) mapped in " + props_);
      std::size_t n = 0;
      for (const auto& b : g.blocks) n += b.count();
      fail_mesh(group_label(g) + " (" + std::to_string(n) + " elements) has no mapping in " + props_ + "; expected a line '$seflex group " +
                g.name + (g.dim == 2 ? " PSHELL <pid>'" : " PBAR <pid> <x1> <x2> <x3>'") +
                " (or SET / CONM2 if the group only names nodes)");
    }
  }

  /// First-order lines, triangles and quadrangles only; the same order everywhere.
  void check_element_types() const {
    const ElementBlock* first = nullptr;
    const PhysicalGroup* first_group = nullptr;
    for (std::size_t i = 0; i < mesh_.groups.size(); ++i) {
      const PhysicalGroup& g = mesh_.groups[i];
      if (g.dim == 0) continue;
      for (const auto& b : g.blocks) {
        if (!first) {
          first = &b;
          first_group = &g;
        } else if (b.order != first->order) {
          fail_mesh("mixed element orders: " + group_label(*first_group) + " has order-" + std::to_string(first->order) + " '" +
                    first->type_name + "' elements, " + group_label(g) + " order-" + std::to_string(b.order) + " '" +
                    b.type_name + "'; expected first-order elements throughout (Mesh.ElementOrder = 1)");
        }
      }
    }
    for (std::size_t i = 0; i < mesh_.groups.size(); ++i) {
      const PhysicalGroup& g = mesh_.groups[i];
      if (g.dim == 0) continue;
      std::size_t n = 0;
      for (const auto& b : g.blocks) {
        n += b.count();
        if (b.order != 1)
          fail_mesh(group_label(g) + ": '" + b.type_name + "' elements are of order " + std::to_string(b.order) +
                    ", which seflex does not support; expected first-order elements (2-node lines, 3-node triangles, "
                    "4-node quadrangles; Mesh.ElementOrder = 1)");
        const bool ok = (g.dim == 1 && b.type == 1) || (g.dim == 2 && (b.type == 2 || b.type == 3));
        if (!ok && plans_[i].element)
          fail_mesh(group_label(g) + ": '" + b.type_name + "' elements are not supported; expected " +
                    (g.dim == 1 ? "2-node lines" : "3-node triangles and 4-node quadrangles"));
      }
      if (n == 0 && plans_[i].element)
        fail_mesh(group_label(g) + " has no elements; expected a meshed group (is the mesh generated?)");
    }
  }

  /// Unique node positions of a group's elements, ascending by tag.
  std::vector<std::size_t> group_nodes(const PhysicalGroup& g) const {
    std::vector<std::size_t> tags;
    for (const auto& b : g.blocks) tags.insert(tags.end(), b.nodes.begin(), b.nodes.end());
    std::sort(tags.begin(), tags.end());
    tags.erase(std::unique(tags.begin(), tags.end()), tags.end());
    std::vector<std::size_t> out;
    out.reserve(tags.size());
    for (const std::size_t t : tags) {
      const std::size_t p = nodes_.find(t);
      if (p == NodeIndex::kNone) fail_mesh(group_label(g) + ": an element references node " + std::to_string(t) + ", which the mesh does not have");
      out.push_back(p);
    }
    return out;
  }

  void number_nodes() {
    const std::size_t n = mesh_.node_tags.size();
    id_of_.assign(n, 0);
    std::vector<char> needed(n, 0);
    std::unordered_set<int> taken;
    for (const auto& g : m_.grids) taken.insert(g.id);
    for (const auto& s : m_.spoints) taken.insert(s.id);
    std::unordered_map<int, const GroupDirective*> pinned_by;
    for (std::size_t i = 0; i < mesh_.groups.size(); ++i) {
      const PhysicalGroup& g = mesh_.groups[i];
      const GroupPlan& p = plans_[i];
      if (!p.used() && g.dim != 0) continue;
      const std::vector<std::size_t> nodes = group_nodes(g);
      for (const std::size_t k : nodes) needed[k] = 1;
      if (!p.grid) continue;
      const GroupDirective& d = *p.grid;
      if (nodes.size() != 1)
        fail_directive(d, group_label(g) + " has " + std::to_string(nodes.size()) + " nodes; expected a group of exactly one node");
      if (taken.count(d.grid) && !pinned_by.count(d.grid))
        fail_directive(d, "grid id " + std::to_string(d.grid) + " is already a GRID or SPOINT of " + props_ + "; expected an unused id");
      if (const auto it = pinned_by.find(d.grid); it != pinned_by.end() && id_of_[nodes[0]] != d.grid)
        fail_directive(d, "grid id " + std::to_string(d.grid) + " is already given to group '" + it->second->group + "' on line " +
                              std::to_string(it->second->line) + "; expected one node per id");
      if (id_of_[nodes[0]] != 0 && id_of_[nodes[0]] != d.grid)
        fail_directive(d, "the node already has id " + std::to_string(id_of_[nodes[0]]) + " from another group; expected one id per node");
      id_of_[nodes[0]] = d.grid;
      pinned_by.emplace(d.grid, &d);
      taken.insert(d.grid);
    }
    int next = 1;
    if (dir_.first_grid) {
      next = *dir_.first_grid;
    } else {
      for (const int id : taken) next = std::max(next, id < INT_MAX ? id + 1 : INT_MAX);
    }
    std::vector<std::size_t> order;
    for (std::size_t k = 0; k < n; ++k)
      if (needed[k] && id_of_[k] == 0) order.push_back(k);
    std::sort(order.begin(), order.end(), [&](std::size_t a, std::size_t b) { return mesh_.node_tags[a] < mesh_.node_tags[b]; });
    for (const std::size_t k : order) {
      while (next < INT_MAX && taken.count(next)) ++next;
      if (next == INT_MAX) fail_mesh("too many nodes for the grid ids left above first_grid; expected ids below 2^31 - 1");
      id_of_[k] = next++;
    }
    std::vector<std::size_t> all;
    for (std::size_t k = 0; k < n; ++k)
      if (needed[k]) all.push_back(k);
    std::sort(all.begin(), all.end(), [&](std::size_t a, std::size_t b) { return id_of_[a] < id_of_[b]; });
    m_.grids.reserve(m_.grids.size() + all.size());
    for (const std::size_t k : all) {
      fem::Grid grid;
      grid.id = id_of_[k];
      grid.x = {mesh_.coords[3 * k], mesh_.coords[3 * k + 1], mesh_.coords[3 * k + 2]};
      grid.ref = mesh_ref_;
      m_.grids.push_back(grid);
    }
    m_.card_counts["GRID"] += all.size();
  }

  int grid_id(std::size_t tag) const { return id_of_[nodes_.find(tag)]; }

  int next_element_id() {
    while (next_element_ < INT_MAX && element_taken_.count(next_element_)) ++next_element_;
    if (next_element_ == INT_MAX) fail_mesh("too many elements for the ids left above first_element; expected ids below 2^31 - 1");
    return next_element_++;
  }

  void start_element_ids() {
    int max_id = 0;
    auto take = [&](const auto& items) {
      for (const auto& e : items) {
        element_taken_.insert(e.id);
        max_id = std::max(max_id, e.id);
      }
    };
    take(m_.bars);
    take(m_.rods);
    take(m_.shells);
    take(m_.conm2);
    take(m_.springs);
    take(m_.rbe2);
    take(m_.rbars);
    take(m_.rbe3);
    take(m_.rigid_bodies);
    take(m_.rigid_rods);
    next_element_ = dir_.first_element ? *dir_.first_element : (max_id < INT_MAX ? max_id + 1 : INT_MAX);
  }

  void make_elements() {
    start_element_ids();
    std::map<std::pair<int, int>, std::size_t> owner;  // (dim, entity) -> group creating its elements
    for (std::size_t i = 0; i < mesh_.groups.size(); ++i) {
      const PhysicalGroup& g = mesh_.groups[i];
      const GroupDirective* d = plans_[i].element;
      if (!d) continue;
      for (const int e : g.entities) {
        const auto [it, inserted] = owner.emplace(std::make_pair(g.dim, e), i);
        if (!inserted)
          fail_mesh(std::string(dimension_name(g.dim)) + " " + std::to_string(e) + " is in " + group_label(mesh_.groups[it->second]) +
                    " and " + group_label(g) + ", both mapped to elements in " + props_ +
                    "; expected each entity in one mapped group (its elements would be doubled)");
      }
      for (const auto& b : g.blocks) add_block(*d, b);
    }
  }

  void add_block(const GroupDirective& d, const ElementBlock& b) {
    const std::size_t npe = static_cast<std::size_t>(b.nodes_per_element);
    for (std::size_t e = 0; e < b.count(); ++e) {
      const std::size_t* n = b.nodes.data() + e * npe;
      if (d.kind == Kind::Shell) {
        fem::Shell s;
        s.id = next_element_id();
        s.pid = d.pid;
        s.nnode = static_cast<std::uint8_t>(npe);
        for (std::size_t k = 0; k < npe; ++k) s.g[k] = grid_id(n[k]);
        s.ref = mesh_ref_;
        m_.shells.push_back(s);
      } else if (d.kind == Kind::Rod) {
        fem::Rod r;
        r.id = next_element_id();
        r.pid = d.pid;
        r.ga = grid_id(n[0]);
        r.gb = grid_id(n[1]);
        r.ref = mesh_ref_;
        m_.rods.push_back(r);
      } else {
        fem::Bar bar;
        bar.id = next_element_id();
        bar.pid = d.pid;
        bar.is_beam = d.kind == Kind::Beam;
        bar.ga = grid_id(n[0]);
        bar.gb = grid_id(n[1]);
        if (d.v) {
          bar.v = *d.v;
        } else {
          const fem::BarDefaults& def = bar.is_beam ? m_.beamor : m_.baror;
          bar.has_g0 = def.has_g0;
          bar.g0 = def.g0;
          bar.v = def.v;
          bar.offt = def.offt;
        }
        bar.ref = mesh_ref_;
        m_.bars.push_back(bar);
      }
    }
    const char* card = d.kind == Kind::Shell ? (npe == 4 ? "CQUAD4" : "CTRIA3") : d.kind == Kind::Rod ? "CROD"
                                                                              : d.kind == Kind::Beam ? "CBEAM"
                                                                                                     : "CBAR";
    m_.card_counts[card] += b.count();
  }

  void make_masses() {
    for (std::size_t i = 0; i < mesh_.groups.size(); ++i) {
      const GroupDirective* d = plans_[i].mass;
      if (!d) continue;
      for (const std::size_t k : group_nodes(mesh_.groups[i])) {
        fem::Conm2 c;
        c.id = next_element_id();
        c.grid = id_of_[k];
        c.m = d->mass;
        c.I11 = d->inertia[0], c.I21 = d->inertia[1], c.I22 = d->inertia[2];
        c.I31 = d->inertia[3], c.I32 = d->inertia[4], c.I33 = d->inertia[5];
        c.ref = mesh_ref_;
        m_.conm2.push_back(c);
        ++m_.card_counts["CONM2"];
      }
    }
  }

  void make_node_sets() {
    for (std::size_t i = 0; i < mesh_.groups.size(); ++i) {
      const PhysicalGroup& g = mesh_.groups[i];
      if ((g.dim != 0 && !plans_[i].set) || g.name.empty()) continue;
      std::vector<int>& ids = m_.node_sets[g.name];
      for (const std::size_t k : group_nodes(g)) ids.push_back(id_of_[k]);
      std::sort(ids.begin(), ids.end());
      ids.erase(std::unique(ids.begin(), ids.end()), ids.end());
    }
  }

  fem::Model& m_;
  const MeshData& mesh_;
  const Directives& dir_;
  std::string props_;
  NodeIndex nodes_;
  std::vector<GroupPlan> plans_;
  std::vector<int> id_of_;  ///< grid id per node position (0 = not in the model)
  std::unordered_set<int> element_taken_;
  fem::CardRef mesh_ref_;
  int next_element_ = 1;
};

}  // namespace

void add_named_sets(fem::Model& model, const std::vector<NamedSet>& sets, const std::string& file) {
  if (sets.empty()) return;
  std::unordered_set<int> grids;
  for (const auto& g : model.grids) grids.insert(g.id);
  for (const auto& s : sets) {
    for (const int id : s.ids)
      if (!grids.count(id))
        throw InputError(SourceRef{file, s.line}, "$seflex set " + s.name + ": grid " + std::to_string(id) +
                                                      " is not defined; expected grid ids of the model");
    std::vector<int>& ids = model.node_sets[s.name];
    ids.insert(ids.end(), s.ids.begin(), s.ids.end());
    std::sort(ids.begin(), ids.end());
    ids.erase(std::unique(ids.begin(), ids.end()), ids.end());
  }
}

}  // namespace gmsh

std::filesystem::path default_properties_path(const std::filesystem::path& mesh) {
  std::filesystem::path p = mesh;
  p.replace_extension(".props.bdf");
  return p;
}

fem::Model read_gmsh(const std::filesystem::path& mesh_path, const ModelReadOptions& options) {
  const std::filesystem::path props = options.properties ? *options.properties : default_properties_path(mesh_path);
  std::error_code ec;
  if (!std::filesystem::exists(props, ec))
    throw InputError(mesh_path.string() + ": no property file " + props.string() + "; expected the companion bulk-data file (" +
                     (options.properties ? std::string("as given") : "<mesh stem>.props.bdf beside the mesh, or --properties FILE") +
                     ") with the PSHELL/PBAR/MAT1 cards and '$seflex group' lines (docs/gmsh-input.md)");
  // The companion file first: its mistakes are found before any meshing.
  const gmsh::Directives directives = gmsh::parse_directives(nastran::load_text(props, ""), props.string());
  NastranReadOptions nastran_options;
  nastran_options.finalize = false;
  nastran_options.symbols = options.symbols;
  fem::Model model = read_nastran(props, nastran_options);
  const gmsh::MeshData mesh = gmsh::load_gmsh_mesh(mesh_path, options.parameters);
  const auto mesh_file = static_cast<std::uint32_t>(model.files.size());
  model.files.push_back(mesh.file);
  gmsh::ModelBuilder(model, mesh, directives, props.string(), mesh_file).run();
  gmsh::add_named_sets(model, directives.sets, props.string());
  if (options.finalize) fem::finalize(model);
  return model;
}

}  // namespace seflex::io
