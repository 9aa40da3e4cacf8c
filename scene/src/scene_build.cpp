// Scene -> mbd::Model: loads the superelement files, merges interface nodes (connections, ground),
// and creates nodes, hinges and bodies in an order the node forest accepts (parents first).
#include <Eigen/Geometry>
#include <algorithm>
#include <cmath>
#include <cstdio>
#include <set>
#include <map>
#include <numeric>
#include <sstream>

#include "seflex/scene/scene.hpp"
#include "seflex/io/superelement_file.hpp"
#include "seflex/mbd/forces/drive_profile.hpp"
#include "seflex/superelement/inertia_invariants.hpp"

namespace seflex::scene {

namespace {

constexpr double kCoincidence = 1e-6;  // [m] interface nodes that are one node / a hinge's two nodes

std::string fmt(const Eigen::Vector3d& p) {
  std::ostringstream os;
  os.precision(9);
  os << "(" << p.x() << ", " << p.y() << ", " << p.z() << ")";
  return os.str();
}

/// Re-throw an InputError of the builder or the file reader with the scene item's location.
template <class Fn>
auto at(const SceneWhere& w, Fn&& fn) {
  try {
    return fn();
  } catch (const InputError& e) {
    throw InputError(w.prefix() + e.what());
  }
}

struct Builder {
  const SceneDescription& d;
  Scene scene;
  mbd::ModelBuilder mb;
  std::vector<mbd::Pose> X_WB;                       // per body
  std::vector<int> first;                            // per body: first slot of its interfaces
  std::vector<int> uf;                               // union-find over slots
  std::vector<std::pair<int, int>> slot_of;          // slot -> (body, interface)
  std::map<int, mbd::NodeIndex> created;             // class root -> node
  std::map<int, int> child_of_hinge;                 // class root -> hinge
  std::map<int, SceneWhere> grounded;                // class root -> where
  std::vector<mbd::HingeIndex> hinge_ids;
  std::vector<int> leader_of;                        // per scene hinge: the hinge it follows, or -1
  std::map<int, int> rigid_of;                       // class root -> the rigid scene body with a node there
  std::map<std::pair<std::string, int>, mbd::SuperelementIndex> se_ids;  // shared AIC data

  SceneBuildOptions options;

  Builder(const SceneDescription& desc, const SceneBuildOptions& o) : d(desc), options(o) { scene.description = desc; }

  int find(int s) { return uf[static_cast<std::size_t>(s)] == s ? s : uf[static_cast<std::size_t>(s)] = find(uf[static_cast<std::size_t>(s)]); }
  const se::Superelement& se_of(int b) const { return *scene.superelements[static_cast<std::size_t>(b)]; }
  int body_of(const std::string& name) const {
    for (std::size_t b = 0; b < d.bodies.size(); ++b)
      if (d.bodies[b].name == name) return static_cast<int>(b);
    return -1;
  }
  mbd::Pose pose(int slot) const {
    const auto [b, j] = slot_of[static_cast<std::size_t>(slot)];
    return mbd::interface_pose(se_of(b), j, X_WB[static_cast<std::size_t>(b)]);
  }
  std::string slot_name(int slot) const {
    const auto [b, j] = slot_of[static_cast<std::size_t>(slot)];
    return d.bodies[static_cast<std::size_t>(b)].name + "." + std::to_string(se_of(b).interfaces[static_cast<std::size_t>(j)].id);
  }

  /// The slot of `body.node`; error naming the body's interface grids when the grid is not one.
  int slot(const SceneNodeRef& r) const {
    const int b = body_of(r.body);
    SEFLEX_DEMAND(b >= 0, "body references are checked when reading");
    const se::Superelement& s = se_of(b);
    std::string ids;
    for (int j = 0; j < s.num_interfaces(); ++j) {
      if (s.interfaces[static_cast<std::size_t>(j)].id == r.grid) return first[static_cast<std::size_t>(b)] + j;
      ids += (j ? ", " : "") + std::to_string(s.interfaces[static_cast<std::size_t>(j)].id);
    }
    r.where.fail("grid " + std::to_string(r.grid) + " is not an interface node of body '" + r.body + "' (its interface grids: " + ids + ")");
  }

  /// A superelement file with the parts the run needs. `full_inertia`: the first body that uses the
  /// file with full inertia (nullptr: none does).
  se::Superelement load_file(const SceneBody& b, const SceneBody* full_inertia, se::StressModes& stress) const {
    const auto load = [&](io::SuperelementParts parts) {
      return at(b.file_where, [&] { return io::load_superelement(b.superelement, io::LoadOptions{parts, &stress}); });
    };
    se::Superelement s = load(options.keep_mesh ? io::SuperelementParts::All : io::SuperelementParts::Dynamics);
    if (!full_inertia || s.invariants.present()) return s;
    // Full inertia from a file without invariants (format 1.0/1.1, or a reduction that did not
    // compute them): compute them from the mesh part when the file has one.
    if (!options.keep_mesh) s = load(io::SuperelementParts::All);
    if (s.recovery.size() == 0 || s.M_fe.size() == 0)
      full_inertia->where.fail(
          "inertia: full needs the inertia invariants of superelement " + b.superelement.string() +
          " or its mesh part (recovery matrix and FE mass), and the file has neither (format written by seflex " +
          s.seflex_version + (s.fe_node_ids.empty() ? ", reduced with --no-mesh" : ", reduced without recovery and FE mass") +
          "); re-run `seflex reduce` with this seflex (superelement format 1.2 stores the inertia invariants, with or "
          "without --no-mesh), or use inertia: simplified for this body");
    s.invariants = at(b.file_where, [&] { return se::compute_inertia_invariants(s); });
    if (!options.keep_mesh && s.invariants.present()) io::drop_mesh(s);
    return s;
  }

  void load_bodies() {
    std::map<std::string, const SceneBody*> full_inertia;  // file -> first body that needs its full inertia
    for (const SceneBody& b : d.bodies)
      if (b.fidelity == Fidelity::Flexible && (b.inertia == mbd::InertiaModel::Full || options.full_inertia_everywhere))
        full_inertia.emplace(b.superelement.string(), &b);
    // One copy per file, shared by the bodies that use it with all its modes; one per file and number
    // of modes for bodies that keep fewer.
    std::map<std::string, std::shared_ptr<const se::Superelement>> files;
    std::map<std::pair<std::string, int>, std::shared_ptr<const se::Superelement>> truncated;
    std::map<std::string, std::shared_ptr<const se::StressModes>> file_stress;
    std::map<std::pair<std::string, int>, std::shared_ptr<const se::StressModes>> truncated_stress;
    for (const SceneBody& b : d.bodies) {
      const std::string key = b.superelement.string();
      if (!files.count(key)) {
        const auto it = full_inertia.find(key);
        se::StressModes stress;
        files[key] = std::make_shared<const se::Superelement>(load_file(b, it == full_inertia.end() ? nullptr : it->second, stress));
        if (stress.present()) file_stress[key] = std::make_shared<const se::StressModes>(std::move(stress));
      }
      const se::Superelement& full = *files[key];
      int m = full.num_modes;
      if (b.internal_modes >= 0 && b.fidelity == Fidelity::Flexible) {
        if (b.internal_modes > full.num_modes)
          b.where.fail("internal_modes: " + std::to_string(b.internal_modes) + " asked, but " + key + " has only " +
                       std::to_string(full.num_modes) + " fixed-interface modes");
        m = b.internal_modes;
      }
      const auto st = file_stress.find(key);
      if (m == full.num_modes) {
        scene.superelements.push_back(files[key]);
        scene.stress.push_back(st == file_stress.end() ? nullptr : st->second);
      } else {
        auto& kept = truncated[{key, m}];
        if (!kept) kept = std::make_shared<const se::Superelement>(io::keep_internal_modes(full, m));
        scene.superelements.push_back(kept);
        auto& kept_stress = truncated_stress[{key, m}];
        if (!kept_stress && st != file_stress.end())
          kept_stress = std::make_shared<const se::StressModes>(st->second->first_columns(kept->size()));
        scene.stress.push_back(kept_stress);
      }
      const se::Superelement& s = *scene.superelements.back();
      X_WB.push_back(mbd::Pose{b.X_WF.R, b.X_WF.p + b.X_WF.R * s.p_OBo});
      first.push_back(static_cast<int>(slot_of.size()));
      for (int j = 0; j < s.num_interfaces(); ++j) slot_of.emplace_back(static_cast<int>(X_WB.size()) - 1, j);
    }
    uf.resize(slot_of.size());
    std::iota(uf.begin(), uf.end(), 0);
  }

  void check_coincident(int a, int b, const SceneWhere& w, const std::string& what) const {
    const double dist = (pose(a).p - pose(b).p).norm();
    if (!(dist <= kCoincidence))
      w.fail(slot_name(b) + " is at " + fmt(pose(b).p) + " but " + slot_name(a) + " at " + fmt(pose(a).p) + " (" +
             std::to_string(dist) + " m apart); " + what + " must coincide within 1e-6 m");
  }

  void merge_nodes() {
    for (const auto& group : d.connections) {
      const int s0 = slot(group[0]);
      for (std::size_t k = 1; k < group.size(); ++k) {
        const int s = slot(group[k]);
        check_coincident(s0, s, group[k].where, "connected nodes");
        uf[static_cast<std::size_t>(find(s))] = find(s0);
      }
    }
    for (const auto& g : d.ground) grounded.emplace(find(slot(g)), g.where);
    for (std::size_t h = 0; h < d.hinges.size(); ++h) {
      const SceneHinge& hg = d.hinges[h];
      const int c = find(slot(hg.child));
      if (grounded.count(c)) hg.child.where.fail(hg.child.str() + " is welded to ground; a hinge's child must be free to turn");
      if (child_of_hinge.count(c))
        hg.child.where.fail(hg.child.str() + " is already the child of hinge '" + d.hinges[static_cast<std::size_t>(child_of_hinge[c])].name +
                            "'; a node turns about one parent only");
      if (!hg.parent.ground) {
        const int p = slot(hg.parent);
        if (find(p) == c) hg.child.where.fail(hg.child.str() + " and the parent " + hg.parent.str() + " are the same node");
        check_coincident(p, slot(hg.child), hg.child.where, "a hinge's parent and child nodes");
      }
      child_of_hinge[c] = static_cast<int>(h);
    }
  }

  mbd::HingeOptions hinge_options(const SceneHinge& hg) const {
    mbd::HingeOptions o;
    o.phi0 = hg.phi0;
    o.phidot0 = hg.phidot0;
    for (const SceneDrive& dr : d.drives) {
      if (dr.hinge != hg.name) continue;
      const double w = dr.rate, T = dr.ramp_time;
      if (dr.kind == "spin_up") o.drive = [w, T](double t) { return mbd::spin_up_drive(w, T, t); };
      else o.drive = [w](double t) { return mbd::DriveValue{w * t, w, 0.0}; };
    }
    return o;
  }

  bool has(int cls) const { return created.count(cls) > 0; }

  void build_nodes_and_bodies() {
    for (const auto& g : grounded) {
      const int cls = g.first;  // not a structured binding: clang 14 cannot capture one in a lambda
      created[cls] = at(g.second, [&] { return mb.add_ground(slot_name(cls), pose(cls)); });
    }
    const std::size_t nb = d.bodies.size();
    std::vector<bool> hinge_done(d.hinges.size(), false), body_done(nb, false);
    hinge_ids.assign(d.hinges.size(), mbd::HingeIndex());
    leader_of.assign(d.hinges.size(), -1);
    scene.bodies.assign(nb, SceneBodyRef{});
    auto slots = [&](std::size_t b) {
      std::vector<int> v;
      for (int j = 0; j < se_of(static_cast<int>(b)).num_interfaces(); ++j) v.push_back(find(first[b] + j));
      return v;
    };
    for (std::size_t b = 0; b < nb; ++b)
      if (d.bodies[b].fidelity == Fidelity::Rigid)
        for (int c : slots(b)) rigid_of.emplace(c, static_cast<int>(b));
    // A rigid body with a node placed and another one still to come from a hinge: placed first, so
    // that the hinge finds its child placed and closes the loop (close_rigid_loop).
    auto rigid_pending_with_anchor = [&](int c) {
      const auto it = rigid_of.find(c);
      if (it == rigid_of.end() || body_done[static_cast<std::size_t>(it->second)]) return false;
      const std::vector<int> cls = slots(static_cast<std::size_t>(it->second));
      return std::any_of(cls.begin(), cls.end(), [&](int x) { return has(x); });
    };
    for (;;) {
      bool progress = true;
      while (progress) {
        progress = false;
        for (std::size_t h = 0; h < d.hinges.size(); ++h) {
          const SceneHinge& hg = d.hinges[h];
          if (hinge_done[h]) continue;
          const int c = find(slot(hg.child));
          if (!hg.parent.ground && !has(find(slot(hg.parent)))) continue;
          if (!has(c) && rigid_pending_with_anchor(c)) continue;
          if (has(c)) {
            close_rigid_loop(h);
            hinge_done[h] = progress = true;
            continue;
          }
          at(hg.where, [&] {
            const mbd::NodeIndex parent = hg.parent.ground ? mb.add_ground("ground:" + hg.name, mbd::Pose{Eigen::Matrix3d::Identity(), pose(c).p})
                                                           : created[find(slot(hg.parent))];
            hinge_ids[h] = mb.add_hinge(hg.name, parent, hg.axis_W, pose(c).R, hinge_options(hg));
            return 0;
          });
          created[c] = mb.hinge_child(hinge_ids[h]);
          hinge_done[h] = progress = true;
        }
        for (std::size_t b = 0; b < nb; ++b) {
          if (body_done[b]) continue;
          const SceneBody& body = d.bodies[b];
          const std::vector<int> cls = slots(b);
          if (body.fidelity == Fidelity::Rigid) {
            int anchor = -1;
            for (std::size_t j = 0; j < cls.size() && anchor < 0; ++j)
              if (has(cls[j])) anchor = static_cast<int>(j);
            if (anchor < 0) continue;
            add_rigid(b, anchor, cls);
          } else {
            bool ready = true;
            for (int c : cls) ready = ready && has(c);
            if (!ready) continue;
            add_flexible(b, cls);
          }
          body_done[b] = progress = true;
        }
      }
      if (std::all_of(body_done.begin(), body_done.end(), [](bool x) { return x; }) &&
          std::all_of(hinge_done.begin(), hinge_done.end(), [](bool x) { return x; }))
        break;
      if (!seed_free_node(body_done, slots)) {
        for (std::size_t h = 0; h < d.hinges.size(); ++h)
          if (!hinge_done[h])
            d.hinges[h].where.fail("cannot be placed: its parent " + d.hinges[h].parent.str() +
                                   " belongs to no body that can be placed first (hinges form a loop)");
        SEFLEX_DEMAND(false, "scene ordering made no progress");
      }
    }
  }

  /// A free node where the tree can grow: the first interface of a rigid body none of whose nodes
  /// a hinge places, else the free interface nodes of a flexible body (not those of a rigid body
  /// still to come, which will place them).
  template <class Slots>
  bool seed_free_node(const std::vector<bool>& body_done, Slots&& slots) {
    std::set<int> rigid_pending;
    for (std::size_t b = 0; b < body_done.size(); ++b)
      if (!body_done[b] && d.bodies[b].fidelity == Fidelity::Rigid)
        for (int c : slots(b)) rigid_pending.insert(c);
    for (std::size_t b = 0; b < body_done.size(); ++b) {
      if (body_done[b] || d.bodies[b].fidelity != Fidelity::Rigid) continue;
      const std::vector<int> cls = slots(b);
      if (std::any_of(cls.begin(), cls.end(), [&](int c) { return child_of_hinge.count(c) > 0; })) continue;
      created[cls[0]] = at(d.bodies[b].where, [&] { return mb.add_node(slot_name(cls[0]), pose(cls[0])); });
      return true;
    }
    bool seeded = false;
    for (std::size_t b = 0; b < body_done.size() && !seeded; ++b) {
      if (body_done[b] || d.bodies[b].fidelity == Fidelity::Rigid) continue;
      for (int c : slots(b)) {
        if (has(c) || child_of_hinge.count(c) || rigid_pending.count(c)) continue;
        created[c] = at(d.bodies[b].where, [&] { return mb.add_node(slot_name(c), pose(c)); });
        seeded = true;
      }
    }
    return seeded;
  }

  /// Hinge h's child is already placed by a rigid body: the hinge closes a loop. Redundant (and built
  /// as a follower of `leader`) when another hinge joins the same two rigid bodies (or ground) about
  /// the same line: its position and the rotations across its axis are then fixed by the leader, and
  /// its angle is the leader's. Anything else needs constraint equations the absolute interface
  /// coordinates do not have: refused, naming the hinge.
  void close_rigid_loop(std::size_t h) {
    const SceneHinge& hg = d.hinges[h];
    const int c = find(slot(hg.child));
    auto body_of_class = [&](int cls) { const auto it = rigid_of.find(cls); return it == rigid_of.end() ? -1 : it->second; };
    auto parent_side = [&](const SceneHinge& x) { return x.parent.ground ? -2 : body_of_class(find(slot(x.parent))); };
    const int child_body = body_of_class(c), parent_body = parent_side(hg);
    const std::string refuse = "closes a kinematic loop of rigid bodies: " + hg.child.str() + " is already placed by rigid body '" +
                               (child_body >= 0 ? d.bodies[static_cast<std::size_t>(child_body)].name : std::string("?")) + "'";
    const std::string remedy = " (the absolute interface coordinates have no constraint equations; make one body of the loop "
                               "flexible, or run the rigid bodies with multipliers: --formulation rigid-lm)";
    if (child_body < 0 || parent_body == -1) hg.where.fail(refuse + remedy);
    const Eigen::Vector3d a = hg.axis_W.normalized(), p = pose(c).p;
    for (std::size_t m = 0; m < d.hinges.size(); ++m) {
      const SceneHinge& lm = d.hinges[m];
      if (m == h || leader_of[m] >= 0 || !hinge_ids[m].valid()) continue;
      if (body_of_class(find(slot(lm.child))) != child_body || parent_side(lm) != parent_body) continue;
      const Eigen::Vector3d al = lm.axis_W.normalized(), pl = pose(find(slot(lm.child))).p;
      const double misalign = a.cross(al).norm(), off_axis = (p - pl - (p - pl).dot(al) * al).norm();
      char geo[160];
      std::snprintf(geo, sizeof geo, "axes %.3g rad apart, %.3g m off its axis", std::asin(std::min(1.0, misalign)), off_axis);
      if (misalign > 1e-6 || off_axis > 1e-6)
        hg.where.fail(refuse + "; it is not coaxial with hinge '" + lm.name + "' between the same bodies (" + geo +
                      "), so the loop is not redundant" + remedy);
      const double sign = a.dot(al) > 0.0 ? 1.0 : -1.0;
      if (sign < 0.0 || std::abs(hg.phi0 - lm.phi0) > 1e-12)
        hg.where.fail(refuse + "; it is coaxial with hinge '" + lm.name +
                      "' but turns the other way or starts at another angle, so its force elements cannot be moved to it" + remedy);
      for (const SceneDrive& dr : d.drives)
        if (dr.hinge == hg.name) hg.where.fail(refuse + "; it is driven, and its angle is hinge '" + lm.name + "''s" + remedy);
      hinge_ids[h] = at(hg.where, [&] { return mb.add_follower_hinge(hg.name, hinge_ids[m], sign, hg.phi0); });
      leader_of[h] = static_cast<int>(m);
      scene.redundant_hinges.push_back("hinge '" + hg.name + "' follows hinge '" + lm.name + "' (coaxial between rigid bodies: " + geo +
                                       "; its 3 translations and 2 rotations across the axis are redundant, its force elements act on '" +
                                       lm.name + "')");
      return;
    }
    hg.where.fail(refuse + "; no other hinge joins the same two bodies about the same line" + remedy);
  }

  mbd::SuperelementIndex se_index(std::size_t b) {
    const auto key = std::make_pair(d.bodies[b].superelement.string(), se_of(static_cast<int>(b)).num_modes);
    auto it = se_ids.find(key);
    if (it == se_ids.end()) it = se_ids.emplace(key, mb.add_superelement(scene.superelements[b])).first;
    return it->second;
  }

  void add_rigid(std::size_t b, int anchor, const std::vector<int>& cls) {
    const SceneBody& body = d.bodies[b];
    for (std::size_t j = 0; j < cls.size(); ++j) {
      if (static_cast<int>(j) == anchor) continue;
      if (has(cls[j]))
        body.where.fail("rigid body '" + body.name + "' is attached at both " + slot_name(cls[static_cast<std::size_t>(anchor)]) +
                        " and " + slot_name(cls[j]) +
                        ": a closed kinematic loop of rigid bodies, which the absolute interface coordinates cannot close "
                        "(they have no constraint equations; make one body of the loop flexible, or run the rigid bodies with "
                        "multipliers: --formulation rigid-lm, which removes the loop's redundant equations)");
    }
    const mbd::SuperelementIndex sei = se_index(b);
    const mbd::RigidBodyIndex rb = at(body.where, [&] {
      return mb.add_rigid_body(body.name, sei, created[cls[static_cast<std::size_t>(anchor)]], anchor, X_WB[b]);
    });
    for (std::size_t j = 0; j < cls.size(); ++j) created[cls[j]] = mb.rigid_body(rb).nodes[j];
    scene.bodies[b] = SceneBodyRef{true, rb.value};
  }

  void add_flexible(std::size_t b, const std::vector<int>& cls) {
    const SceneBody& body = d.bodies[b];
    std::vector<mbd::NodeIndex> nodes;
    for (int c : cls) nodes.push_back(created[c]);
    mbd::FlexibleBodyOptions o;
    o.inertia = body.inertia;
    o.stiffness_damping = body.stiffness_damping;
    o.modal_damping = body.modal_damping;
    o.interface_loads = d.output.interface_loads;  // interface_loads.csv (run_output.hpp)
    const bool has_stiffening = se_of(static_cast<int>(b)).stiffening.present();
    if (body.geometric_stiffening.value_or(false) && !has_stiffening)
      body.where.fail("geometric_stiffening: on, but " + body.superelement.string() +
                      " carries no geometric-stiffness invariants (reduced with --no-stiffening, or by a seflex "
                      "before format 1.3); re-run `seflex reduce` without --no-stiffening, or "
                      "set geometric_stiffening: off");
    o.geometric_stiffening = body.geometric_stiffening.value_or(true) && has_stiffening;
    const mbd::FlexibleBodyIndex fb = at(body.where, [&] {
      return mb.add_flexible_body(body.name, se_index(b), nodes, X_WB[b], o);
    });
    scene.bodies[b] = SceneBodyRef{false, fb.value};
  }

  mbd::HingeIndex hinge_id(const std::string& name) const {
    for (std::size_t h = 0; h < d.hinges.size(); ++h)
      if (d.hinges[h].name == name) return leader_of[h] >= 0 ? hinge_ids[static_cast<std::size_t>(leader_of[h])] : hinge_ids[h];
    SEFLEX_DEMAND(false, "hinge references are checked when reading");
    return {};
  }

  void add_forces_and_loads() {
    for (const SceneForce& f : d.forces) {
      mbd::ForceElement e = f.element;
      std::visit(
          [&](auto& el) {
            using T = std::decay_t<decltype(el)>;
            if constexpr (std::is_same_v<T, mbd::CableLoop>) {
              el.hinges_a.clear();
              el.hinges_b.clear();
              for (std::size_t k = 0; k < f.hinges.size(); ++k)
                (static_cast<int>(k) < f.hinges_a ? el.hinges_a : el.hinges_b).push_back(hinge_id(f.hinges[k]));
            } else {
              el.hinge = hinge_id(f.hinges.at(0));
            }
          },
          e);
      at(f.where, [&] { return mb.add_force_element(f.name, e); });
    }
    for (const SceneLoad& l : d.loads) {
      mbd::NodeLoad nl;
      nl.name = l.name;
      nl.node = created.at(find(slot(l.node)));
      nl.force = l.force;
      nl.moment = l.moment;
      nl.follower = l.follower;
      at(l.where, [&] { return mb.add_load(nl); });
    }
    mb.set_gravity(d.gravity);
  }
};

}  // namespace

Scene build_scene(const SceneDescription& d, const SceneBuildOptions& options) {
  Builder b(d, options);
  b.load_bodies();
  b.merge_nodes();
  b.build_nodes_and_bodies();
  b.add_forces_and_loads();
  b.scene.model = at(SceneWhere{SourceRef{d.file.string(), 0}, ""}, [&] { return b.mb.build(); });
  return std::move(b.scene);
}

}  // namespace seflex::scene
