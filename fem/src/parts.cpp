// Part superelements merged into the residual (parts.hpp: what is done and why).
#include "seflex/fem/parts.hpp"

#include <Eigen/Geometry>
#include <algorithm>
#include <climits>
#include <cmath>
#include <numeric>
#include <tuple>
#include <string>
#include <unordered_map>
#include <unordered_set>

#include "seflex/common/error.hpp"
#include "seflex/fem/finalize.hpp"

namespace seflex::fem {
namespace {

std::string se_name(int seid) { return seid == 0 ? "the residual" : "part " + std::to_string(seid); }

/// The rigid move of a part (SELOC): x_assembled = R x_part + t.
struct Move {
  bool moved = false;
  Eigen::Matrix3d R = Eigen::Matrix3d::Identity();
  Eigen::Vector3d t = Eigen::Vector3d::Zero();
};

/// One superelement while the parts are assembled: index 0 is the residual.
struct Se {
  int seid = 0;
  Model* model = nullptr;
  CardRef begin;
  const PartBulk* bulk = nullptr;
  Move move;
  std::vector<Eigen::Vector3d> x;  ///< grid positions, assembled basic
  std::size_t base = 0;            ///< first node of its grids in the union-find
  long long grid_off = 0, elem_off = 0, prop_off = 0, mat_off = 0, coord_off = 0;
  int basic_cid = 0;               ///< the moved part's basic system in the assembled model (0: not moved)
  std::unordered_set<int> props, mats, elems;
  std::unordered_set<int> shared_coords;     ///< systems the residual defines alike (same id, same place): kept once
  std::unordered_map<int, int> spoint_to;    ///< scalar points joined by SECONCT: the part's id -> the residual's
  double tol() const { return bulk ? bulk->tol : 1e-5; }
  bool external() const { return bulk && bulk->type == "EXTOP4"; }
  bool manual() const { return bulk && bulk->manual; }
};

/// Index grids and coordinate systems of one superelement's model and resolve positions.
void locate(Model& m, const Se& se) {
  m.grid_index.clear();
  m.coord_index.clear();
  for (std::size_t i = 0; i < m.grids.size(); ++i) {
    const auto [it, inserted] = m.grid_index.emplace(m.grids[i].id, static_cast<std::uint32_t>(i));
    if (!inserted)
      throw InputError(where(m, m.grids[i].ref), "GRID " + std::to_string(m.grids[i].id) + ", field 2 (ID): duplicate grid id in " +
                                                     se_name(se.seid) + ", first defined at " +
                                                     where(m, m.grids[it->second].ref).str() + "; expected unique ids");
  }
  for (std::size_t i = 0; i < m.coords.size(); ++i) {
    const auto [it, inserted] = m.coord_index.emplace(m.coords[i].id, static_cast<std::uint32_t>(i));
    if (!inserted)
      throw InputError(where(m, m.coords[i].ref), "coordinate system " + std::to_string(m.coords[i].id) +
                                                      ": duplicate id in " + se_name(se.seid) + ", first defined at " +
                                                      where(m, m.coords[it->second].ref).str() + "; expected unique ids");
  }
  resolve_coordinates(m);
}

/// A GRID's or POINT's basic position in model m (found = false if neither has that id).
Eigen::Vector3d point_position(const Model& m, int id, bool& found) {
  found = true;
  if (const auto it = m.grid_index.find(id); it != m.grid_index.end()) return m.grids[it->second].x_basic;
  for (const auto& p : m.points)
    if (p.id == id) return to_basic(m, p.cp, p.x);
  found = false;
  return Eigen::Vector3d::Zero();
}

/// Axes of the frame with origin p[0], x along p[0] -> p[1], z normal to the plane of the three
/// points; false if the points are collinear (or two coincide).
bool frame(const Eigen::Vector3d p[3], Eigen::Matrix3d& F) {
  Eigen::Vector3d e1 = p[1] - p[0];
  const Eigen::Vector3d a = p[2] - p[0];
  const double l1 = e1.norm(), l2 = a.norm();
  Eigen::Vector3d n = e1.cross(a);
  if (l1 == 0 || l2 == 0 || n.norm() <= 1e-8 * l1 * l2) return false;
  e1 /= l1;
  n.normalize();
  F.col(0) = e1;
  F.col(1) = n.cross(e1);
  F.col(2) = n;
  return true;
}

Move seloc_move(const Model& res, const Se& se, const PartLocation& l) {
  Eigen::Vector3d a[3], b[3];
  static const char* fa[3] = {"field 3 (PA1)", "field 4 (PA2)", "field 5 (PA3)"};
  static const char* fb[3] = {"field 6 (PB1)", "field 7 (PB2)", "field 8 (PB3)"};
  const std::string card = "SELOC " + std::to_string(l.seid);
  for (int k = 0; k < 3; ++k) {
    bool found = false;
    a[k] = point_position(*se.model, l.pa[k], found);
    if (!found)
      throw InputError(where(res, l.ref), card + ", " + fa[k] + ": " + std::to_string(l.pa[k]) + " is no GRID or POINT of part " +
                                              std::to_string(l.seid) + "; expected a point of the part moved");
    b[k] = point_position(res, l.pb[k], found);
    if (!found)
      throw InputError(where(res, l.ref), card + ", " + fb[k] + ": " + std::to_string(l.pb[k]) +
                                              " is no GRID or POINT of the residual; expected a point of the residual (the bulk data after BEGIN BULK)");
  }
  Eigen::Matrix3d Fa, Fb;
  if (!frame(a, Fa))
    throw InputError(where(res, l.ref), card + ": the part's points PA1-PA3 (" + std::to_string(l.pa[0]) + ", " +
                                            std::to_string(l.pa[1]) + ", " + std::to_string(l.pa[2]) +
                                            ") are collinear; expected three points that define a plane");
  if (!frame(b, Fb))
    throw InputError(where(res, l.ref), card + ": the residual's points PB1-PB3 (" + std::to_string(l.pb[0]) + ", " +
                                            std::to_string(l.pb[1]) + ", " + std::to_string(l.pb[2]) +
                                            ") are collinear; expected three points that define a plane");
  Move m;
  m.moved = true;
  m.R = Fb * Fa.transpose();
  m.t = b[0] - m.R * a[0];
  return m;
}

struct UnionFind {
  std::vector<std::size_t> parent;
  explicit UnionFind(std::size_t n) : parent(n) { std::iota(parent.begin(), parent.end(), std::size_t{0}); }
  std::size_t find(std::size_t i) {
    while (parent[i] != i) i = parent[i] = parent[parent[i]];
    return i;
  }
  void unite(std::size_t a, std::size_t b) {
    a = find(a);
    b = find(b);
    if (a != b) parent[std::max(a, b)] = std::min(a, b);  // the root is the node of the lowest superelement
  }
};

/// Offsets for one id kind: none if no id is used by two superelements, else SEID * 10^k for every
/// part (10^k above every id of the kind).
void plan_offsets(const Model& res, std::vector<Se>& ses, const std::vector<std::vector<int>>& ids, long long Se::*off,
                  const char* kind) {
  std::unordered_map<int, std::size_t> owner;
  bool clash = false;
  long long max_id = 0;
  for (std::size_t s = 0; s < ses.size(); ++s)
    for (const int id : ids[s]) {
      max_id = std::max<long long>(max_id, id);
      const auto [it, inserted] = owner.emplace(id, s);
      if (!inserted && it->second != s) clash = true;
    }
  if (!clash) return;
  long long scale = 10;
  while (scale <= max_id) scale *= 10;
  for (std::size_t s = 1; s < ses.size(); ++s) {
    const long long o = static_cast<long long>(ses[s].seid) * scale;
    if (o + max_id > INT_MAX)
      throw InputError(where(res, ses[s].begin), "BEGIN SUPER = " + std::to_string(ses[s].seid) + ": its " + kind +
                                                     " ids, which other parts use too, cannot be renumbered as id + SEID * " +
                                                     std::to_string(scale) + " below 2^31; expected smaller part or " + kind + " ids");
    ses[s].*off = o;
  }
}

/// SEBULK types assembled: PRIMARY (the part's elements), EXTOP4 (its matrices from an OP4 file), and
/// MIRROR and REPEAT (made into parts of their own by expand_images before the assembly).
bool assembled_type(const std::string& type) {
  return type == "PRIMARY" || type == "EXTOP4" || type == "MIRROR" || type == "REPEAT";
}

class Assembler {
 public:
  Assembler(Model& res, std::vector<Part>& parts) : res_(res), parts_(parts), notes_(res.unsupported) {}

  void run() {
    collect();
    place();
    connect();
    plan();
    for (std::size_t s = 1; s < ses_.size(); ++s) merge(s);
    for (const auto& [l, ps] : pending_ps_) res_.grids[node_se_[l] == 0 ? node_grid_[l] : lead_position_.at(l)].ps |= ps;
    for (auto& c : res_.coords) c.resolved = false;
    res_.grid_index.clear();
    res_.coord_index.clear();
  }

 private:
  Model& res_;
  std::vector<Part>& parts_;
  UnsupportedNotes notes_;  ///< adds to res_.unsupported
  std::vector<Se> ses_;
  std::unordered_map<int, std::size_t> by_seid_;
  std::vector<std::size_t> node_se_, node_grid_;
  std::vector<std::size_t> lead_;      ///< per node: the node whose grid it becomes
  std::vector<char> differs_;          ///< per node: displacement directions differ from its lead's
  std::vector<char> boundary_;         ///< per node: in a group of two or more

  std::unordered_set<int> excluded_;   ///< parts not assembled (SEBULK TYPE other than PRIMARY)

  [[noreturn]] void fail(const CardRef& ref, const std::string& msg) const { throw InputError(where(res_, ref), msg); }

  /// Note `count` cards of a part that seflex does not assemble (listed as unsupported in the residual).
  void note(const std::string& name, std::size_t count, const CardRef& ref) {
    if (count > 0) notes_.add(name, ref, count);
  }
  template <class V>
  void note_kind(const V& items, const std::string& card) {
    if (!items.empty()) note("part superelement: " + card + " (not assembled)", items.size(), items.front().ref);
  }
  bool skipped(const PartConnection& c) const { return excluded_.count(c.seid_a) || excluded_.count(c.seid_b); }

  void collect() {
    ses_.push_back({});
    ses_[0].model = &res_;
    by_seid_[0] = 0;
    // Parts SEBULK makes something else than PRIMARY (a mirror or repeat of another part, external
    // matrices): listed, not assembled, and their SELOC and SECONCT cards not used.
    for (const auto& b : res_.part_bulks)
      if (!assembled_type(b.type)) {
        excluded_.insert(b.seid);
        note("part superelement: SEBULK TYPE = " + b.type + " (the part is not assembled)", 1, b.ref);
      }
    for (auto& p : parts_) {
      if (excluded_.count(p.seid)) continue;
      if (p.seid <= 0) fail(p.begin, "BEGIN SUPER = " + std::to_string(p.seid) + ": expected a part id > 0");
      p.model.files = res_.files;
      Se se;
      se.seid = p.seid;
      se.model = &p.model;
      se.begin = p.begin;
      by_seid_[p.seid] = ses_.size();
      ses_.push_back(se);
    }
    const auto part_of = [&](int seid, const CardRef& ref, const std::string& card, bool residual_ok) -> Se& {
      const auto it = by_seid_.find(seid);
      if (it == by_seid_.end() || (!residual_ok && seid == 0))
        fail(ref, card + ": no part " + std::to_string(seid) + " in the deck; expected the id of a BEGIN SUPER section" +
                      (residual_ok ? " (or 0, the residual)" : ""));
      return ses_[it->second];
    };
    for (const auto& b : res_.part_bulks) {
      if (!assembled_type(b.type)) continue;
      Se& se = part_of(b.seid, b.ref, "SEBULK " + std::to_string(b.seid), false);
      if (se.bulk) fail(b.ref, "SEBULK " + std::to_string(b.seid) + ": a second SEBULK for the part (the first at " +
                                   where(res_, se.bulk->ref).str() + "); expected one");
      se.bulk = &b;
    }
    for (const auto& c : res_.part_connections) {
      if (skipped(c)) continue;
      part_of(c.seid_a, c.ref, "SECONCT " + std::to_string(c.seid_a) + " " + std::to_string(c.seid_b) + ", field 2 (SEIDA)", true);
      part_of(c.seid_b, c.ref, "SECONCT " + std::to_string(c.seid_a) + " " + std::to_string(c.seid_b) + ", field 3 (SEIDB)", true);
    }
    for (const auto& l : res_.part_locations)
      if (!excluded_.count(l.seid)) part_of(l.seid, l.ref, "SELOC " + std::to_string(l.seid) + ", field 2 (SEID)", false);
  }

  void place() {
    for (auto& se : ses_) locate(*se.model, se);
    std::unordered_map<int, const PartLocation*> seen;
    for (const auto& l : res_.part_locations) {
      if (excluded_.count(l.seid)) continue;
      const auto [it, inserted] = seen.emplace(l.seid, &l);
      if (!inserted)
        fail(l.ref, "SELOC " + std::to_string(l.seid) + ": a second SELOC for the part (the first at " +
                        where(res_, it->second->ref).str() + "); expected one");
      Se& se = ses_[by_seid_.at(l.seid)];
      se.move = seloc_move(res_, se, l);
    }
    std::size_t n = 0;
    for (auto& se : ses_) {
      se.base = n;
      se.x.clear();
      for (const auto& g : se.model->grids) {
        se.x.push_back(se.move.R * g.x_basic + se.move.t);
        node_se_.push_back(static_cast<std::size_t>(&se - ses_.data()));
        node_grid_.push_back(se.x.size() - 1);
      }
      n += se.model->grids.size();
    }
  }

  std::size_t node_of(const Se& se, int grid, const PartConnection& c, const char* field) const {
    const auto it = se.model->grid_index.find(grid);
    if (it == se.model->grid_index.end())
      fail(c.ref, "SECONCT " + std::to_string(c.seid_a) + " " + std::to_string(c.seid_b) + ", " + field + ": grid " +
                      std::to_string(grid) + " is not a GRID of " + se_name(se.seid) + "; expected a grid of that part");
    return se.base + it->second;
  }

  Eigen::Vector3d node_x(std::size_t n) const { return ses_[node_se_[n]].x[node_grid_[n]]; }

  void connect() {
    const std::size_t n = node_se_.size();
    UnionFind uf(n);
    // Coincident grids of two superelements, neither MANUAL: a hash of cells as large as the largest tolerance.
    double h = 1e-5;
    for (const auto& se : ses_) h = std::max(h, se.tol());
    struct KeyHash {
      std::size_t operator()(const std::array<long long, 3>& k) const {
        return std::hash<long long>()(k[0] * 73856093LL ^ k[1] * 19349663LL ^ k[2] * 83492791LL);
      }
    };
    std::unordered_map<std::array<long long, 3>, std::vector<std::size_t>, KeyHash> cells;
    for (std::size_t a = 0; a < n; ++a) {
      const Se& sa = ses_[node_se_[a]];
      if (sa.manual()) continue;
      const Eigen::Vector3d xa = node_x(a);
      const std::array<long long, 3> k{static_cast<long long>(std::floor(xa.x() / h)), static_cast<long long>(std::floor(xa.y() / h)),
                                       static_cast<long long>(std::floor(xa.z() / h))};
      for (int dx = -1; dx <= 1; ++dx)
        for (int dy = -1; dy <= 1; ++dy)
          for (int dz = -1; dz <= 1; ++dz) {
            const auto it = cells.find({k[0] + dx, k[1] + dy, k[2] + dz});
            if (it == cells.end()) continue;
            for (const std::size_t b : it->second) {
              const Se& sb = ses_[node_se_[b]];
              if (node_se_[b] != node_se_[a] && (xa - node_x(b)).norm() <= std::max(sa.tol(), sb.tol())) uf.unite(a, b);
            }
          }
      cells[k].push_back(a);
    }
    for (const auto& c : res_.part_connections) {
      if (skipped(c)) continue;
      const Se& sa = ses_[by_seid_.at(c.seid_a)];
      const Se& sb = ses_[by_seid_.at(c.seid_b)];
      for (const auto& [ga, gb] : c.pairs) {
        if (!sa.model->grid_index.count(ga) && scalar_point_pair(c, ga, gb)) continue;
        const std::size_t a = node_of(sa, ga, c, "GIDA"), b = node_of(sb, gb, c, "GIDB");
        const double d = (node_x(a) - node_x(b)).norm();
        if (c.loc && d > c.tol)
          fail(c.ref, "SECONCT " + std::to_string(c.seid_a) + " " + std::to_string(c.seid_b) + ": grid " + std::to_string(ga) + " of " +
                          se_name(c.seid_a) + " and grid " + std::to_string(gb) + " of " + se_name(c.seid_b) + " are " +
                          std::to_string(d) + " apart; expected them to coincide within TOL = " + std::to_string(c.tol) +
                          " (field 4), or LOC = NO (field 5)");
        uf.unite(a, b);
      }
    }
    // Groups: each has at most one grid of each superelement. The grid of the residual leads (its id
    // and displacement system stay), else that of a part not moved, else the part of the lowest id.
    lead_.assign(n, 0);
    boundary_.assign(n, 0);
    differs_.assign(n, 0);
    std::vector<std::size_t> size(n, 0), best(n, n);
    const auto rank = [&](std::size_t a) {
      const Se& se = ses_[node_se_[a]];
      return std::tuple<bool, bool, int>(se.seid != 0, se.move.moved, se.seid);
    };
    for (std::size_t a = 0; a < n; ++a) {
      const std::size_t r = uf.find(a);
      ++size[r];
      if (best[r] == n || rank(a) < rank(best[r])) best[r] = a;
    }
    std::vector<std::size_t> root(n);
    for (std::size_t a = 0; a < n; ++a) root[a] = uf.find(a), lead_[a] = best[root[a]];
    std::unordered_map<std::size_t, std::size_t> seen;  // (root, superelement) -> node
    for (std::size_t a = 0; a < n; ++a) {
      if (size[root[a]] < 2) continue;
      boundary_[a] = 1;
      const std::size_t key = lead_[a] * ses_.size() + node_se_[a];
      const auto [it, inserted] = seen.emplace(key, a);
      if (!inserted) {
        const Se& se = ses_[node_se_[a]];
        const Grid& g1 = se.model->grids[node_grid_[it->second]];
        const Grid& g2 = se.model->grids[node_grid_[a]];
        const Grid& l = ses_[node_se_[lead_[a]]].model->grids[node_grid_[lead_[a]]];
        fail(g2.ref, "GRID " + std::to_string(g2.id) + " of " + se_name(se.seid) + " and its GRID " + std::to_string(g1.id) +
                         " both join grid " + std::to_string(l.id) + " of " + se_name(ses_[node_se_[lead_[a]]].seid) +
                         " at one boundary point; expected one grid of a part at each boundary point (name the pairs on "
                         "SECONCT with SEBULK METHOD = MANUAL)");
      }
      const std::size_t l = lead_[a];
      if (l != a) differs_[a] = (axes(a) - axes(l)).cwiseAbs().maxCoeff() > 1e-6;
    }
  }

  /// A SECONCT pair of scalar points (of an external part and the residual): recorded, true; false if
  /// GIDA is no scalar point of its part either (node_of then says the grid is missing).
  bool scalar_point_pair(const PartConnection& c, int ga, int gb) {
    const auto has = [](const Model& m, int id) {
      return std::any_of(m.spoints.begin(), m.spoints.end(), [&](const ScalarPoint& p) { return p.id == id; });
    };
    Se& sa = ses_[by_seid_.at(c.seid_a)];
    Se& sb = ses_[by_seid_.at(c.seid_b)];
    if (!has(*sa.model, ga)) return false;
    const std::string card = "SECONCT " + std::to_string(c.seid_a) + " " + std::to_string(c.seid_b);
    if (!has(*sb.model, gb))
      fail(c.ref, card + ", GIDB: " + std::to_string(gb) + " is not an SPOINT of " + se_name(c.seid_b) + "; expected the scalar point that " +
                      se_name(c.seid_a) + "'s SPOINT " + std::to_string(ga) + " joins");
    if ((c.seid_a == 0) == (c.seid_b == 0))
      fail(c.ref, card + ": scalar points " + std::to_string(ga) + " and " + std::to_string(gb) +
                      " join two parts; expected a part's scalar point joined to one of the residual's");
    Se& part = c.seid_a == 0 ? sb : sa;
    const int from = c.seid_a == 0 ? gb : ga, to = c.seid_a == 0 ? ga : gb;
    if (!part.spoint_to.emplace(from, to).second)
      fail(c.ref, card + ": SPOINT " + std::to_string(from) + " of " + se_name(part.seid) + " is joined twice; expected once");
    return true;
  }

  /// Displacement axes of node a's grid in the assembled basic system.
  Eigen::Matrix3d axes(std::size_t a) const {
    const Se& se = ses_[node_se_[a]];
    const Grid& g = se.model->grids[node_grid_[a]];
    return se.move.R * displacement_axes(*se.model, g.cd, g.x_basic);
  }

  /// Does the residual define a system of this id at the same place (origin and axes to 1e-9), once
  /// the part is moved? (External parts repeat the residual's systems, as Nastran writes them.)
  bool same_as_residual(const Se& se, const CoordSys& c) const {
    const auto it = res_.coord_index.find(c.id);
    if (it == res_.coord_index.end()) return false;
    const CoordSys& r = res_.coords[it->second];
    const Eigen::Vector3d o = se.move.R * c.origin + se.move.t;
    const double scale = 1.0 + r.origin.norm();
    return r.type == c.type && (o - r.origin).norm() <= 1e-9 * scale && (se.move.R * c.axes - r.axes).cwiseAbs().maxCoeff() <= 1e-9;
  }

  void plan() {
    const std::size_t count = ses_.size();
    std::vector<std::vector<int>> grids(count), elems(count), props(count), mats(count), coords(count);
    for (std::size_t s = 0; s < count; ++s) {
      Se& se = ses_[s];
      const Model& m = *se.model;
      for (std::size_t i = 0; i < m.grids.size(); ++i)
        if (lead_[se.base + i] == se.base + i) grids[s].push_back(m.grids[i].id);
      for (const auto& c : m.coords)
        if (s == 0 || !same_as_residual(se, c)) coords[s].push_back(c.id);
        else se.shared_coords.insert(c.id);
      const auto add = [](std::vector<int>& out, std::unordered_set<int>* set, const auto& items) {
        for (const auto& it : items) {
          out.push_back(it.id);
          if (set) set->insert(it.id);
        }
      };
      std::unordered_set<int>* e = s ? &se.elems : nullptr;
      std::unordered_set<int>* p = s ? &se.props : nullptr;
      std::unordered_set<int>* q = s ? &se.mats : nullptr;
      add(elems[s], e, m.bars), add(elems[s], e, m.rods), add(elems[s], e, m.shells), add(elems[s], e, m.shear_panels);
      add(elems[s], e, m.solids), add(elems[s], e, m.conm2), add(elems[s], e, m.springs), add(elems[s], e, m.bushes);
      add(elems[s], e, m.rbe2), add(elems[s], e, m.rbars), add(elems[s], e, m.rbe3);
      for (const auto& q8 : m.shells8) {
        elems[s].push_back(q8.shell.id);
        if (e) e->insert(q8.shell.id);
      }
      add(props[s], p, m.bar_props), add(props[s], p, m.rod_props), add(props[s], p, m.shell_props);
      add(props[s], p, m.composite_props), add(props[s], p, m.spring_props), add(props[s], p, m.bush_props);
      add(props[s], p, m.shear_props), add(props[s], p, m.solid_props);
      add(mats[s], q, m.mat1), add(mats[s], q, m.mat2), add(mats[s], q, m.mat8), add(mats[s], q, m.mat9);
    }
    plan_offsets(res_, ses_, grids, &Se::grid_off, "grid");
    plan_offsets(res_, ses_, elems, &Se::elem_off, "element");
    plan_offsets(res_, ses_, props, &Se::prop_off, "property");
    plan_offsets(res_, ses_, mats, &Se::mat_off, "material");
    plan_offsets(res_, ses_, coords, &Se::coord_off, "coordinate system");
    // A moved part's basic system: a new rectangular system, numbered after every other.
    long long next = 0;
    for (std::size_t s = 0; s < count; ++s)
      for (const int c : coords[s]) next = std::max(next, c + ses_[s].coord_off);
    for (std::size_t s = 1; s < count; ++s) {
      Se& se = ses_[s];
      if (!se.move.moved) continue;
      if (++next > INT_MAX) fail(se.begin, "BEGIN SUPER: no coordinate system id left for the moved part's basic system");
      se.basic_cid = static_cast<int>(next);
      CoordSys c;
      c.id = se.basic_cid;
      const Eigen::Vector3d a = se.move.t, b = se.move.t + se.move.R.col(2), cc = se.move.t + se.move.R.col(0);
      c.abc = {a.x(), a.y(), a.z(), b.x(), b.y(), b.z(), cc.x(), cc.y(), cc.z()};
      for (const auto& l : res_.part_locations)
        if (l.seid == se.seid) c.ref = l.ref;
      res_.coords.push_back(c);
    }
  }

  // ----- merging one part -----
  Se* se_ = nullptr;
  std::size_t s_ = 0;

  std::string what(const char* card, int id) const {
    return se_name(se_->seid) + ", " + card + " " + std::to_string(id);
  }

  /// A reference of the part's card `card` `id` to `kind` `ref_id`, which the part does not define.
  [[noreturn]] void undefined(const CardRef& ref, const char* card, int id, const char* kind, int ref_id,
                              const char* expected) const {
    fail(ref, what(card, id) + ": references " + kind + " " + std::to_string(ref_id) + ", which " + se_name(se_->seid) +
                  " does not define; expected " + expected);
  }

  /// The assembled id of the part's grid `id` (0 stays 0 where `zero_ok`).
  int grid(int id, const CardRef& ref, const char* card, int eid, bool zero_ok = false) const {
    if (id == 0 && zero_ok) return 0;
    const auto it = se_->model->grid_index.find(id);
    if (it == se_->model->grid_index.end())
      undefined(ref, card, eid, "grid", id, "a GRID of the same part (a part's cards name its own grids)");
    const std::size_t l = lead_[se_->base + it->second];
    const Se& owner = ses_[node_se_[l]];
    return static_cast<int>(owner.model->grids[node_grid_[l]].id + owner.grid_off);
  }
  /// Does the grid join a grid of another superelement whose displacement directions differ?
  bool directions_differ(int id) const {
    const auto it = se_->model->grid_index.find(id);
    return it != se_->model->grid_index.end() && differs_[se_->base + it->second];
  }
  int coord(int cid, const CardRef& ref, const char* card, int eid) const {
    if (cid == 0) return se_->basic_cid;
    if (cid < 0) return cid;
    if (se_->shared_coords.count(cid)) return cid;
    if (!se_->model->coord_index.count(cid))
      undefined(ref, card, eid, "coordinate system", cid, "a CORD1x or CORD2x of the same part (or 0)");
    return static_cast<int>(cid + se_->coord_off);
  }
  int prop(int pid, const CardRef& ref, const char* card, int eid) const {
    if (!se_->props.count(pid))
      undefined(ref, card, eid, "property", pid, "a property of the same part");
    return static_cast<int>(pid + se_->prop_off);
  }
  int mat(int mid, const CardRef& ref, const char* card, int id) const {
    if (mid <= 0) return mid;
    if (!se_->mats.count(mid))
      undefined(ref, card, id, "material", mid, "a material of the same part");
    return static_cast<int>(mid + se_->mat_off);
  }
  int elem(int eid) const { return static_cast<int>(eid + se_->elem_off); }
  /// A vector given in the part's basic system, into the assembled basic system.
  Eigen::Vector3d basic_vector(const Eigen::Vector3d& v) const { return se_->move.R * v; }
  void same_directions(int gid, const CardRef& ref, const char* card, int id, const char* field) const {
    if (directions_differ(gid))
      fail(ref, what(card, id) + ", " + field + ": grid " + std::to_string(gid) + " is a boundary grid whose displacement "
                    "directions differ from those of the grid it joins; expected its components given on a grid with "
                    "the same directions (Nastran refuses an SPC on such a grid too)");
  }

  void merge(std::size_t s) {
    s_ = s;
    se_ = &ses_[s];
    Model& m = *se_->model;
    PartSummary sum;
    sum.seid = se_->seid;
    sum.begin = se_->begin;
    sum.moved = se_->move.moved;
    sum.grid_offset = se_->grid_off;
    sum.element_offset = se_->elem_off;
    sum.property_offset = se_->prop_off;
    sum.material_offset = se_->mat_off;
    sum.grids = m.grids.size();
    for (std::size_t i = 0; i < m.grids.size(); ++i) sum.boundary_grids += boundary_[se_->base + i];
    merge_geometry(m);
    merge_materials(m);
    merge_elements(m, sum);
    merge_loads(m);
    if (se_->external()) merge_external(m);
    merge_rest(m);
    res_.parts.push_back(sum);
  }

  void merge_geometry(Model& m) {
    for (const auto& c0 : m.coords) {
      if (se_->shared_coords.count(c0.id)) continue;
      CoordSys c = c0;
      c.id = coord(c0.id, c0.ref, "coordinate system", c0.id);
      if (c.by_grids)
        for (auto& g : c.grids) g = grid(g, c0.ref, "CORD1", c0.id);
      else
        c.rid = coord(c0.rid, c0.ref, "CORD2", c0.id);
      c.resolved = false;
      res_.coords.push_back(c);
    }
    for (std::size_t i = 0; i < m.grids.size(); ++i) {
      const Grid& g0 = m.grids[i];
      const std::size_t node = se_->base + i;
      if (lead_[node] != node) {  // joins a grid of another superelement (merged before): its PS goes there
        if (g0.ps) {
          same_directions(g0.id, g0.ref, "GRID", g0.id, "field 8 (PS)");
          pending_ps_.emplace_back(lead_[node], g0.ps);
        }
        continue;
      }
      Grid g = g0;
      g.id = grid(g0.id, g0.ref, "GRID", g0.id);
      g.cp = coord(g0.cp, g0.ref, "GRID", g0.id);
      g.cd = coord(g0.cd, g0.ref, "GRID", g0.id);
      res_.grids.push_back(g);
      lead_position_[node] = res_.grids.size() - 1;
    }
    // A part's POINTs only place it (SELOC): not kept.
  }
  std::unordered_map<std::size_t, std::size_t> lead_position_;      ///< lead node -> its grid in res_.grids
  std::vector<std::pair<std::size_t, ComponentMask>> pending_ps_;  ///< PS of joined grids, for their lead

  void merge_materials(Model& m) {
    for (auto x : m.mat1) x.id = mat(x.id, x.ref, "MAT1", x.id), res_.mat1.push_back(x);
    for (auto x : m.mat2) x.id = mat(x.id, x.ref, "MAT2", x.id), res_.mat2.push_back(x);
    for (auto x : m.mat8) x.id = mat(x.id, x.ref, "MAT8", x.id), res_.mat8.push_back(x);
    for (auto x : m.mat9) x.id = mat(x.id, x.ref, "MAT9", x.id), res_.mat9.push_back(x);
    const auto pid = [&](int id) { return static_cast<int>(id + se_->prop_off); };
    for (auto p : m.bar_props) {
      p.mid = mat(p.mid, p.ref, card_name(p.source), p.id), p.id = pid(p.id);
      res_.bar_props.push_back(p);
    }
    for (auto p : m.rod_props) {
      p.mid = mat(p.mid, p.ref, rod_property_card(p), p.id), p.id = pid(p.id);
      res_.rod_props.push_back(p);
    }
    for (auto p : m.shell_props) {
      for (int* mid : {&p.mid1, &p.mid2, &p.mid3, &p.mid4}) *mid = mat(*mid, p.ref, "PSHELL", p.id);
      p.id = pid(p.id);
      res_.shell_props.push_back(p);
    }
    for (auto p : m.composite_props) {
      for (auto& ply : p.plies) ply.mid = mat(ply.mid, p.ref, p.global ? "PCOMPG" : "PCOMP", p.id);
      p.id = pid(p.id);
      res_.composite_props.push_back(p);
    }
    for (auto p : m.spring_props) p.id = pid(p.id), res_.spring_props.push_back(p);
    for (auto p : m.bush_props) p.id = pid(p.id), res_.bush_props.push_back(p);
    for (auto p : m.shear_props) {
      p.mid = mat(p.mid, p.ref, "PSHEAR", p.id), p.id = pid(p.id);
      res_.shear_props.push_back(p);
    }
    for (auto p : m.solid_props) {
      p.mid = mat(p.mid, p.ref, "PSOLID", p.id);
      if (p.cordm >= 0) p.cordm = coord(p.cordm, p.ref, "PSOLID", p.id);
      p.id = pid(p.id);
      res_.solid_props.push_back(p);
    }
  }

  void merge_elements(Model& m, PartSummary& sum) {
    for (auto b : m.bars) {
      const char* card = b.is_beam ? "CBEAM" : "CBAR";
      const bool v_in_ga = !b.has_g0 && !b.offt.empty() && b.offt[0] == 'G';
      if ((v_in_ga && b.v.squaredNorm() > 0) || (b.offt.size() > 1 && b.offt[1] == 'G' && b.wa.squaredNorm() > 0))
        same_directions(b.ga, b.ref, card, b.id, "field 4 (GA)");
      if (b.offt.size() > 2 && b.offt[2] == 'G' && b.wb.squaredNorm() > 0) same_directions(b.gb, b.ref, card, b.id, "field 5 (GB)");
      if (!b.has_g0 && !b.offt.empty() && b.offt[0] == 'B') b.v = basic_vector(b.v);
      if (b.offt.size() > 1 && b.offt[1] == 'B') b.wa = basic_vector(b.wa);
      if (b.offt.size() > 2 && b.offt[2] == 'B') b.wb = basic_vector(b.wb);
      b.pid = prop(b.pid, b.ref, card, b.id);
      b.ga = grid(b.ga, b.ref, card, b.id), b.gb = grid(b.gb, b.ref, card, b.id);
      if (b.has_g0) b.g0 = grid(b.g0, b.ref, card, b.id);
      b.id = elem(b.id);
      res_.bars.push_back(b);
    }
    for (auto r : m.rods) {
      if (r.inline_property) r.mid = mat(r.mid, r.ref, rod_card(r), r.id);
      else r.pid = prop(r.pid, r.ref, rod_card(r), r.id);
      r.ga = grid(r.ga, r.ref, rod_card(r), r.id), r.gb = grid(r.gb, r.ref, rod_card(r), r.id);
      r.id = elem(r.id);
      res_.rods.push_back(r);
    }
    const auto shell = [&](Shell& e, const char* card) {
      e.pid = prop(e.pid, e.ref, card, e.id);
      for (int k = 0; k < e.nnode; ++k) e.g[static_cast<std::size_t>(k)] = grid(e.g[static_cast<std::size_t>(k)], e.ref, card, e.id);
      if (e.theta_is_mcid && e.mcid >= 0) e.mcid = coord(e.mcid, e.ref, card, e.id);
      e.id = elem(e.id);
    };
    for (auto e : m.shells) shell(e, shell_card(e)), res_.shells.push_back(e);
    for (auto q : m.shells8) {
      const char* card = quadratic_shell_card(q);
      for (auto& g : q.mid) g = grid(g, q.shell.ref, card, q.shell.id, true);
      shell(q.shell, card);
      res_.shells8.push_back(q);
    }
    for (auto e : m.shear_panels) {
      e.pid = prop(e.pid, e.ref, "CSHEAR", e.id);
      for (auto& g : e.g) g = grid(g, e.ref, "CSHEAR", e.id);
      e.id = elem(e.id);
      res_.shear_panels.push_back(e);
    }
    for (auto e : m.solids) {
      e.pid = prop(e.pid, e.ref, e.card(), e.id);
      for (auto& g : e.g) g = grid(g, e.ref, e.card(), e.id, true);
      e.id = elem(e.id);
      res_.solids.push_back(e);
    }
    for (auto c : m.conm2) {
      c.grid = grid(c.grid, c.ref, "CONM2", c.id);
      if (c.cid == -1) c.x = se_->move.R * c.x + se_->move.t;
      else c.cid = coord(c.cid, c.ref, "CONM2", c.id);
      c.id = elem(c.id);
      res_.conm2.push_back(c);
    }
    for (auto e : m.springs) {
      if (e.scalar_points) continue;  // noted below
      const char* card = e.inline_property ? "CELAS2" : "CELAS1";
      if (!e.inline_property) e.pid = prop(e.pid, e.ref, card, e.id);
      if (e.g1) same_directions(e.g1, e.ref, card, e.id, "field 4 (G1)");
      if (e.g2) same_directions(e.g2, e.ref, card, e.id, "field 6 (G2)");
      e.g1 = grid(e.g1, e.ref, card, e.id, true), e.g2 = grid(e.g2, e.ref, card, e.id, true);
      e.id = elem(e.id);
      res_.springs.push_back(e);
    }
    for (auto b : m.bushes) {
      const char* card = bush_card(b);
      if (b.cid == -1 && b.has_v) same_directions(b.ga, b.ref, card, b.id, "field 4 (GA)");
      b.pid = prop(b.pid, b.ref, card, b.id);
      b.ga = grid(b.ga, b.ref, card, b.id), b.gb = grid(b.gb, b.ref, card, b.id, true);
      if (b.has_g0) b.g0 = grid(b.g0, b.ref, card, b.id);
      if (b.cid >= 0) b.cid = coord(b.cid, b.ref, card, b.id);
      if (b.ocid >= 0) b.ocid = coord(b.ocid, b.ref, card, b.id);
      b.id = elem(b.id);
      res_.bushes.push_back(b);
    }
    for (auto r : m.rbe2) {
      same_directions(r.gn, r.ref, "RBE2", r.id, "field 3 (GN)");
      for (const int g : r.gm) same_directions(g, r.ref, "RBE2", r.id, "GMi");
      r.gn = grid(r.gn, r.ref, "RBE2", r.id);
      for (auto& g : r.gm) g = grid(g, r.ref, "RBE2", r.id);
      r.id = elem(r.id);
      res_.rbe2.push_back(r);
    }
    for (auto r : m.rbars) {
      same_directions(r.ga, r.ref, "RBAR", r.id, "field 3 (GA)");
      same_directions(r.gb, r.ref, "RBAR", r.id, "field 4 (GB)");
      r.ga = grid(r.ga, r.ref, "RBAR", r.id), r.gb = grid(r.gb, r.ref, "RBAR", r.id);
      r.id = elem(r.id);
      res_.rbars.push_back(r);
    }
    for (auto r : m.rbe3) {
      same_directions(r.refgrid, r.ref, "RBE3", r.id, "field 4 (REFGRID)");
      for (const auto& g : r.groups)
        for (const int id : g.grids) same_directions(id, r.ref, "RBE3", r.id, "Gi,j");
      r.refgrid = grid(r.refgrid, r.ref, "RBE3", r.id);
      for (auto& g : r.groups)
        for (auto& id : g.grids) id = grid(id, r.ref, "RBE3", r.id);
      for (auto& u : r.um) same_directions(u.grid, r.ref, "RBE3", r.id, "GMi"), u.grid = grid(u.grid, r.ref, "RBE3", r.id);
      r.id = elem(r.id);
      res_.rbe3.push_back(r);
    }
    sum.elements = se_->elems.size();
  }

  void merge_loads(Model& m) {
    for (auto l : m.point_loads) {
      const char* card = point_load_card(l);
      l.grid = grid(l.grid, l.ref, card, l.sid);
      for (auto& g : l.g) g = grid(g, l.ref, card, l.sid, true);
      if (l.direction == PointLoad::Direction::Vector) l.cid = coord(l.cid, l.ref, card, l.sid);
      res_.point_loads.push_back(l);
    }
    for (auto l : m.pressure_loads) {
      if (!l.thru)
        for (const int e : l.elements)
          if (!se_->elems.count(e))
            undefined(l.ref, "PLOAD2", l.sid, "element", e, "an element of the same part");
      for (auto& e : l.elements) e = elem(e);
      res_.pressure_loads.push_back(l);
    }
    for (auto l : m.grid_pressure_loads) {
      for (auto& g : l.g) g = grid(g, l.ref, "PLOAD", l.sid, true);
      res_.grid_pressure_loads.push_back(l);
    }
    for (auto l : m.face_loads) {
      if (l.eid_last == 0 && !se_->elems.count(l.eid))
        undefined(l.ref, "PLOAD4", l.sid, "element", l.eid, "an element of the same part");
      l.eid = elem(l.eid);
      if (l.eid_last > 0) l.eid_last = elem(l.eid_last);
      l.g1 = grid(l.g1, l.ref, "PLOAD4", l.sid, true), l.g34 = grid(l.g34, l.ref, "PLOAD4", l.sid, true);
      if (l.cid >= 0) l.cid = coord(l.cid, l.ref, "PLOAD4", l.sid);
      res_.face_loads.push_back(l);
    }
    for (auto c : m.spcs) {
      same_directions(c.grid, c.ref, c.from_thru ? "SPC1" : "SPC", c.sid, "grid");
      c.grid = grid(c.grid, c.ref, "SPC", c.sid);
      res_.spcs.push_back(c);
    }
    for (auto c : m.enforced_motions) {
      same_directions(c.grid, c.ref, "SPCD", c.sid, "grid");
      c.grid = grid(c.grid, c.ref, "SPCD", c.sid);
      res_.enforced_motions.push_back(c);
    }
  }

  /// An external part: its scalar points (joined by SECONCT, else new ones) and its matrices on the
  /// assembled dofs, turned into the displacement axes of the grids its boundary grids join.
  void merge_external(Model& m) {
    const std::string card = "SEBULK " + std::to_string(se_->seid);
    for (const ScalarPoint& p : m.spoints) {
      if (se_->spoint_to.count(p.id)) continue;
      for (const ScalarPoint& q : res_.spoints)
        if (q.id == p.id)
          fail(p.ref, se_name(se_->seid) + ", SPOINT " + std::to_string(p.id) + ": the residual has a scalar point of that id, which "
                      "SECONCT does not join to it; expected the pair on SECONCT, or another id");
      res_.spoints.push_back({p.id, p.ref});
    }
    for (ExternalMatrices x : m.external_parts) {
      const auto n = static_cast<Eigen::Index>(x.dofs.size());
      Eigen::MatrixXd T = Eigen::MatrixXd::Identity(n, n);  // u_part = T u_assembled
      for (Eigen::Index i = 0; i < n; ++i) {
        auto& [id, c] = x.dofs[static_cast<std::size_t>(i)];
        if (c == 0) {
          const auto it = se_->spoint_to.find(id);
          if (it != se_->spoint_to.end()) id = it->second;
          continue;
        }
        const int part_id = id;
        id = grid(part_id, x.ref, "SEBULK", se_->seid);
        if (!directions_differ(part_id) || (c != 1 && c != 4)) continue;
        // a triple of components whose axes differ from those of the grid it joins: rotated
        const auto gi = se_->model->grid_index.at(part_id);
        const std::size_t node = se_->base + gi;
        const Eigen::Matrix3d Q = axes(node).transpose() * axes(lead_[node]);
        if (i + 2 >= n || x.dofs[static_cast<std::size_t>(i + 2)] != std::pair<int, int>(part_id, c + 2))
          fail(x.ref, card + ": grid " + std::to_string(part_id) + " of " + se_name(se_->seid) + " joins a grid whose displacement "
                      "directions differ, but EXTRN gives it only some of components " + std::to_string(c) + "-" + std::to_string(c + 2) +
                      "; expected all three (or the same directions)");
        T.block(i, i, 3, 3) = Q;
      }
      if (!T.isIdentity(0.0)) {
        x.K = T.transpose() * x.K * T;
        x.M = T.transpose() * x.M * T;
      }
      res_.external_parts.push_back(std::move(x));
    }
  }

  void merge_rest(Model& m) {
    const std::string part = se_name(se_->seid);
    // Used by the part's own static reduction only: dropped, said once per part.
    std::string dropped;
    const auto drop = [&](std::size_t n, const char* what) {
      if (n) dropped += (dropped.empty() ? "" : ", ") + std::to_string(n) + " " + what;
    };
    drop(m.aset.size(), "ASET/ASET1 entries");
    drop(m.omit.size(), "OMIT/OMIT1 entries");
    drop(m.bset.size(), "BSET/BSET1 entries");
    drop(m.eigen_methods.size(), "EIGR/EIGRL cards");
    // An external part's q-set and data-recovery table describe its matrices, which are read already.
    const auto external_only = [&](const std::string& name) {
      return se_->external() && (name == "QSET" || name == "QSET1" || name == "DTI");
    };
    for (const auto& u : m.unsupported)
      if (external_only(u.name)) drop(u.count, (u.name + " cards").c_str());
    if (!dropped.empty())
      res_.read_warnings.push_back(where(res_, se_->begin).str() + ": " + part + ": " + dropped +
                                   " not used: they set the part's own reduction, and seflex solves the assembled model in full");
    // Parameters: the residual's value holds for the assembled model (the first PARAM of a name: the
    // case control's, if any). A part's PARAM that sets what the residual sets (its value, or the
    // default when the residual has none: flyswatter's parts repeat AUTOSPC YES) changes nothing; one
    // that the residual lacks or sets otherwise is listed.
    for (const auto& p : m.params) {
      const Param* r = nullptr;
      for (const auto& q : res_.params)
        if (q.name == p.name) {
          r = &q;
          break;
        }
      const bool same = r ? r->values == p.values : param_at_default(m, p);
      if (!same)
        note("PARAM of a part superelement other than the residual's (the residual's value or the default used)", 1, p.ref);
    }
    if (!se_->external()) note_kind(m.spoints, "SPOINT");
    if (!se_->external()) note_kind(m.external_points, "EXTRN");
    note_kind(m.mass_props, "PMASS");
    note_kind(m.scalar_masses, "CMASSi");
    note_kind(m.conm1, "CONM1");
    note_kind(m.genels, "GENEL");
    note_kind(m.bends, "CBEND");
    note_kind(m.bend_props, "PBEND");
    note_kind(m.rigid_bodies, "RBE1/CRIGDi");
    note_kind(m.rigid_rods, "RROD/CRIGDR");
    note_kind(m.spcadds, "SPCADD");
    note_kind(m.mpcs, "MPC");
    note_kind(m.mpcadds, "MPCADD");
    note_kind(m.scalar_loads, "SLOAD");
    note_kind(m.bar_line_loads, "PLOAD1");
    note_kind(m.gravity_loads, "GRAV");
    note_kind(m.rotational_loads, "RFORCE");
    note_kind(m.load_combinations, "LOAD");
    note_kind(m.grid_temperatures, "TEMP");
    note_kind(m.default_temperatures, "TEMPD");
    note_kind(m.bar_temperatures, "TEMPRB");
    note_kind(m.dmigs, "DMIG");
    note_kind(m.material_tables, "TABLEMi");
    note_kind(m.suport, "SUPORT");
    note_kind(m.part_locations, "SELOC");
    note_kind(m.part_bulks, "SEBULK");
    note_kind(m.part_connections, "SECONCT");
    note_kind(m.mirror_planes, "SEMPLN");
    std::size_t scalar_springs = 0;
    for (const auto& e : m.springs) scalar_springs += e.scalar_points;
    for (const auto& e : m.springs)
      if (e.scalar_points) {
        note("part superelement: CELAS3/CELAS4 (not assembled)", scalar_springs, e.ref);
        break;
      }
    if (!m.suport1.empty()) note("part superelement: SUPORT1 (not assembled)", m.suport1.size(), m.suport1.front().dofs.ref);
    for (const auto& u : m.unsupported) {
      if (external_only(u.name)) continue;
      note(u.name, u.count, u.first);
      if (UnsupportedCard* r = notes_.find(u.name)) r->members.insert(r->members.end(), u.members.begin(), u.members.end());
    }
    for (auto& w : m.read_warnings) res_.read_warnings.push_back(std::move(w));
    for (const auto& [name, n] : m.card_counts) res_.card_counts[name] += n;
  }
};

// ----- SEBULK MIRROR and REPEAT: the copy as a part of its own -----

/// Throw for a card of the primary that a mirror image cannot carry.
[[noreturn]] void not_mirrored(const Model& res, const PartBulk& b, const CardRef& ref, const std::string& what) {
  throw InputError(where(res, ref), "SEBULK " + std::to_string(b.seid) + " MIRROR of part " + std::to_string(b.rseid) + ": " + what +
                                        " of part " + std::to_string(b.rseid) + " (" + where(res, ref).str() +
                                        ") is not mirrored by seflex; expected grids in basic displacement axes (CD 0) and "
                                        "CBAR/CBEAM, CROD, CQUAD4/CTRIA3, linear solids, CONM2 (CID 0 or -1), CELAS, CBUSH (no CID), RBE2, RBAR");
}

/// The mirror image through the plane with unit normal n through p: x -> H (x - p) + p, H = I - 2 n n^T.
/// Shells and solids have their connectivity reversed so that each is the image of its primary
/// element, normal included (with the order kept, a reflected element's normal points the other
/// way); vectors (orientation, offsets) are reflected.
void mirror(const Model& res, const PartBulk& b, Model& m, const Move& move, const Eigen::Vector3d& p, const Eigen::Vector3d& n) {
  const Eigen::Matrix3d H = Eigen::Matrix3d::Identity() - 2.0 * n * n.transpose();
  const Eigen::Matrix3d HR = H * move.R;
  for (auto& g : m.grids) {
    if (g.cd != 0) not_mirrored(res, b, g.ref, "GRID " + std::to_string(g.id) + " with CD " + std::to_string(g.cd));
    g.x = H * (move.R * g.x_basic + move.t - p) + p;
    g.x_basic = g.x;
    g.cp = 0;
  }
  for (auto& e : m.bars) {
    if (!e.has_g0) e.v = HR * e.v;
    e.wa = HR * e.wa, e.wb = HR * e.wb;
  }
  const auto reverse = [&](Shell& e, const char* card) {
    if (e.theta_is_mcid && e.mcid > 0) not_mirrored(res, b, e.ref, std::string(card) + " " + std::to_string(e.id) + " with MCID");
    if (e.nnode == 4) std::swap(e.g[1], e.g[3]), std::swap(e.t[1], e.t[3]);
    else std::swap(e.g[1], e.g[2]), std::swap(e.t[1], e.t[2]);
  };
  for (auto& e : m.shells) reverse(e, shell_card(e));
  for (auto& q : m.shells8) {  // mid-side grid k on edge k - k+1: the reversed edges take them backwards
    reverse(q.shell, quadratic_shell_card(q));
    if (q.shell.nnode == 4) std::swap(q.mid[0], q.mid[3]), std::swap(q.mid[1], q.mid[2]);
    else std::swap(q.mid[0], q.mid[2]);
  }
  for (auto& e : m.solids) {
    if (e.nnode != e.corners()) not_mirrored(res, b, e.ref, std::string(e.card()) + " " + std::to_string(e.id) + " with mid-side grids");
    auto& g = e.g;
    switch (e.shape) {
      case Solid::Shape::Hexa: std::swap(g[1], g[3]), std::swap(g[5], g[7]); break;
      case Solid::Shape::Penta: std::swap(g[1], g[2]), std::swap(g[4], g[5]); break;
      case Solid::Shape::Tetra: std::swap(g[1], g[2]); break;
      case Solid::Shape::Pyram: std::swap(g[1], g[3]); break;
    }
  }
  for (auto& c : m.conm2) {
    if (c.cid > 0) not_mirrored(res, b, c.ref, "CONM2 " + std::to_string(c.id) + " with CID " + std::to_string(c.cid));
    c.x = c.cid == -1 ? Eigen::Vector3d(H * (move.R * c.x + move.t - p) + p) : Eigen::Vector3d(HR * c.x);
    Eigen::Matrix3d I;
    I << c.I11, -c.I21, -c.I31, -c.I21, c.I22, -c.I32, -c.I31, -c.I32, c.I33;
    I = HR * I * HR.transpose();
    c.I11 = I(0, 0), c.I22 = I(1, 1), c.I33 = I(2, 2), c.I21 = -I(1, 0), c.I31 = -I(2, 0), c.I32 = -I(2, 1);
  }
  for (auto& e : m.bushes) {
    if (e.cid >= 0 || e.ocid >= 0) not_mirrored(res, b, e.ref, std::string(bush_card(e)) + " " + std::to_string(e.id) + " with CID or OCID");
    if (e.has_v) e.v = HR * e.v;
  }
  for (const auto& p2 : m.solid_props)
    if (p2.cordm > 0) not_mirrored(res, b, p2.ref, "PSOLID " + std::to_string(p2.id) + " with CORDM " + std::to_string(p2.cordm));
  if (!m.shear_panels.empty()) not_mirrored(res, b, m.shear_panels.front().ref, "CSHEAR");
  if (!m.bends.empty()) not_mirrored(res, b, m.bends.front().ref, "CBEND");
  if (!m.genels.empty()) not_mirrored(res, b, m.genels.front().ref, "GENEL");
  if (!m.rbe3.empty()) not_mirrored(res, b, m.rbe3.front().ref, "RBE3");
  for (auto& q : m.points) {
    q.x = H * (move.R * to_basic(m, q.cp, q.x) + move.t - p) + p;
    q.cp = 0;
  }
  m.coords.clear();  // every position is basic now, every displacement system basic
}

/// The loads, constraints and set cards of a model (a part's own: a copy does not inherit them).
void clear_loads(Model& m) {
  m.point_loads.clear(), m.pressure_loads.clear(), m.face_loads.clear(), m.grid_pressure_loads.clear();
  m.gravity_loads.clear(), m.rotational_loads.clear(), m.bar_line_loads.clear(), m.scalar_loads.clear();
  m.load_combinations.clear(), m.enforced_motions.clear(), m.spcs.clear(), m.spcadds.clear();
  m.grid_temperatures.clear(), m.default_temperatures.clear(), m.bar_temperatures.clear();
  m.aset.clear(), m.omit.clear(), m.bset.clear(), m.eigen_methods.clear(), m.params.clear();
  m.unsupported.clear(), m.read_warnings.clear(), m.card_counts.clear();
}

template <class V>
void append(V& to, const V& from) {
  to.insert(to.end(), from.begin(), from.end());
}

/// Each SEBULK MIRROR / REPEAT part as a part of its own: the structure of its primary (RSEID: its
/// grids, elements, properties and materials, with their ids), mirrored through the SEMPLN plane
/// (where the primary sits, after its SELOC) or copied as the primary wrote it, plus the cards of
/// its own BEGIN SUPER section (its loads and constraints: a copy has none of its primary's).
/// Its own SELOC then moves it like any part.
void expand_images(Model& res, std::vector<Part>& parts) {
  bool any = false;
  for (const auto& b : res.part_bulks) any = any || b.type == "MIRROR" || b.type == "REPEAT";
  if (!any) return;
  Se se0;
  se0.model = &res;
  locate(res, se0);
  std::vector<Part> images;
  for (const auto& b : res.part_bulks) {
    if (b.type != "MIRROR" && b.type != "REPEAT") continue;
    const std::string card = "SEBULK " + std::to_string(b.seid);
    const auto primary = std::find_if(parts.begin(), parts.end(), [&](const Part& p) { return p.seid == b.rseid; });
    if (primary == parts.end() || b.rseid == b.seid)
      throw InputError(where(res, b.ref), card + ", field 4 (RSEID): no part " + std::to_string(b.rseid) +
                                               " in the deck; expected the id of the BEGIN SUPER section that TYPE = " + b.type + " copies");
    for (const auto& o : res.part_bulks)
      if (o.seid == b.rseid && o.type != "PRIMARY")
        throw InputError(where(res, b.ref), card + ", field 4 (RSEID): part " + std::to_string(b.rseid) + " is of TYPE " + o.type +
                                                 "; expected a PRIMARY part to copy");
    Part image;
    image.seid = b.seid;
    image.begin = b.ref;
    image.model = primary->model;
    Model& m = image.model;
    m.files = res.files;
    clear_loads(m);
    if (b.type == "MIRROR") {
      Se sp;
      sp.seid = b.rseid;
      sp.model = &m;
      locate(m, sp);
      for (const auto& l : res.part_locations)
        if (l.seid == b.rseid) sp.move = seloc_move(res, sp, l);
      const MirrorPlane* plane = nullptr;
      for (const auto& q : res.mirror_planes)
        if (q.seid == b.seid) plane = &q;
      if (!plane)
        throw InputError(where(res, b.ref), card + " MIRROR: no SEMPLN " + std::to_string(b.seid) +
                                                 "; expected SEMPLN " + std::to_string(b.seid) + " PLANE P1 P2 P3 (GRIDs or POINTs of the residual)");
      Eigen::Vector3d x[3];
      for (int k = 0; k < 3; ++k) {
        bool found = false;
        x[k] = point_position(res, plane->p[static_cast<std::size_t>(k)], found);
        if (!found)
          throw InputError(where(res, plane->ref), "SEMPLN " + std::to_string(plane->seid) + ", field " + std::to_string(4 + k) + " (P" +
                                                       std::to_string(k + 1) + "): " + std::to_string(plane->p[static_cast<std::size_t>(k)]) +
                                                       " is no GRID or POINT of the residual; expected a point of the residual");
      }
      Eigen::Matrix3d F;
      if (!frame(x, F))
        throw InputError(where(res, plane->ref), "SEMPLN " + std::to_string(plane->seid) +
                                                     ": its points are collinear; expected three points that define a plane");
      mirror(res, b, m, sp.move, x[0], F.col(2));
    }
    // the part's own section: its loads and constraints
    const auto own = std::find_if(parts.begin(), parts.end(), [&](const Part& p) { return p.seid == b.seid; });
    if (own != parts.end()) {
      const Model& o = own->model;
      image.begin = own->begin;
      if (!o.grids.empty() || !o.shells.empty() || !o.bars.empty() || !o.solids.empty() || !o.rods.empty())
        throw InputError(where(res, own->begin), "BEGIN SUPER = " + std::to_string(b.seid) + ": the section of a " + b.type +
                                                     " part holds grids or elements; expected its loads and constraints only (its "
                                                     "structure is part " + std::to_string(b.rseid) + "'s)");
      append(m.point_loads, o.point_loads), append(m.pressure_loads, o.pressure_loads), append(m.face_loads, o.face_loads);
      append(m.grid_pressure_loads, o.grid_pressure_loads), append(m.gravity_loads, o.gravity_loads);
      append(m.rotational_loads, o.rotational_loads), append(m.bar_line_loads, o.bar_line_loads);
      append(m.scalar_loads, o.scalar_loads), append(m.load_combinations, o.load_combinations);
      append(m.enforced_motions, o.enforced_motions), append(m.spcs, o.spcs), append(m.spcadds, o.spcadds);
      append(m.grid_temperatures, o.grid_temperatures), append(m.default_temperatures, o.default_temperatures);
      append(m.bar_temperatures, o.bar_temperatures), append(m.aset, o.aset), append(m.omit, o.omit), append(m.bset, o.bset);
      append(m.eigen_methods, o.eigen_methods), append(m.params, o.params), append(m.unsupported, o.unsupported);
      append(m.read_warnings, o.read_warnings), append(m.points, o.points);
      for (const auto& [name, count] : o.card_counts) m.card_counts[name] += count;
      parts.erase(own);
    }
    images.push_back(std::move(image));
  }
  for (auto& p : images) parts.push_back(std::move(p));
}

}  // namespace

void assemble_parts(Model& residual, std::vector<Part>& parts) {
  if (parts.empty() && residual.part_locations.empty() && residual.part_bulks.empty() && residual.part_connections.empty()) return;
  expand_images(residual, parts);
  Assembler(residual, parts).run();
}

}  // namespace seflex::fem
