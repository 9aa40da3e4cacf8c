// seflex advise: variants of a scene run over a short horizon and compared on the hinge angles
// with the finest variant (scene/advise.hpp).
#include "seflex/scene/advise.hpp"

#include <algorithm>
#include <cmath>
#include <ctime>
#include <limits>
#include <map>
#include <memory>
#include <set>
#include <sstream>

#include "seflex/fem/element_results.hpp"
#include "seflex/scene/solve_scene.hpp"

namespace seflex::scene {

namespace {

constexpr double kInf = std::numeric_limits<double>::infinity();

struct Variant {
  std::string name;
  bool reference = false;
  SceneDescription scene;
  mbd::Formulation formulation = mbd::Formulation::Aic;
  bool alternative = false;  ///< another reduction: compared nodes matched by position
};

/// Hinge angles (and the positions of the tracked nodes) at every sample; optionally asks to stop
/// at the first lock that latches.
class AngleRecorder : public mbd::Observer {
 public:
  AngleRecorder(bool stop_at_lock, std::vector<std::size_t> track) : stop_at_lock_(stop_at_lock), track_(std::move(track)) {}
  void on_sample(const mbd::Model& model, const mbd::Sample& s) override {
    if (names.empty())
      for (const auto& h : model.hinges) names.push_back(h.name);
    t.push_back(s.t);
    event.push_back(s.event);
    std::vector<double> p;
    for (const auto& h : s.hinges) p.push_back(h.phi);
    phi.push_back(std::move(p));
    std::vector<Eigen::Vector3d> x;
    for (std::size_t k : track_) x.push_back(s.nodes[k].p);
    pos.push_back(std::move(x));
    update_stress_peaks(s);
    if (s.event && first_lock.empty())
      for (std::size_t i = 0; i < s.elements.size(); ++i)
        if (s.elements[i].latched && s.elements[i].t_latch == s.t) {
          first_lock = model.force_elements[i].name;
          t_lock = s.t;
        }
  }
  bool stop_requested() const override { return stop_at_lock_ && !first_lock.empty(); }

  /// Track the peak element results of the bodies of `scene` that carry stress modes.
  void track_stresses(const Scene& scene) { stress_scene_ = &scene; }
  void update_stress_peaks(const mbd::Sample& s) {
    if (!stress_scene_) return;
    for (std::size_t b = 0; b < stress_scene_->bodies.size(); ++b) {
      const SceneBodyRef& r = stress_scene_->bodies[b];
      if (r.rigid || b >= stress_scene_->stress.size() || !stress_scene_->stress[b]) continue;
      const se::StressModes& st = *stress_scene_->stress[b];
      const Eigen::VectorXd res = st.S * s.flexible[static_cast<std::size_t>(r.index)].xi;
      for (std::size_t e = 0; e < st.element_ids.size(); ++e) {
        double& p = peak[{b, st.element_ids[e]}];
        p = std::max(p, fem::element_result_peak(static_cast<fem::ResultKind>(st.kinds[e]), res.data() + st.rows[e]).value);
      }
    }
  }

  std::vector<std::string> names;
  std::vector<double> t;
  std::vector<bool> event;
  std::vector<std::vector<double>> phi;
  std::vector<std::vector<Eigen::Vector3d>> pos;  ///< per sample, per tracked node
  std::string first_lock;
  double t_lock = 0.0;
  std::map<std::pair<std::size_t, int>, double> peak;  ///< (scene body, element id) -> peak over the run

 private:
  const Scene* stress_scene_ = nullptr;
  bool stop_at_lock_;
  std::vector<std::size_t> track_;
};

/// Linear interpolation of the recorded quantity `f(j)` (sample j) at time `tq`; `none` past the end.
template <class T, class F>
T interpolate(const AngleRecorder& r, double tq, F f, const T& none) {
  const auto it = std::lower_bound(r.t.begin(), r.t.end(), tq);
  if (it == r.t.end()) return none;
  const auto j = static_cast<std::size_t>(it - r.t.begin());
  if (*it == tq || j == 0) return f(j);
  const double t0 = r.t[j - 1], t1 = r.t[j];
  const double w = (tq - t0) / (t1 - t0);
  return (1.0 - w) * f(j - 1) + w * f(j);
}

/// Angle of hinge `h` at time `tq` by linear interpolation between the recorded samples.
double angle_at(const AngleRecorder& r, std::size_t h, double tq) {
  return interpolate(r, tq, [&](std::size_t j) { return r.phi[j][h]; }, std::numeric_limits<double>::quiet_NaN());
}

/// Position of tracked node `k` at time `tq`.
Eigen::Vector3d position_at(const AngleRecorder& r, std::size_t k, double tq) {
  return interpolate(r, tq, [&](std::size_t j) -> Eigen::Vector3d { return r.pos[j][k]; },
                     Eigen::Vector3d::Constant(std::numeric_limits<double>::quiet_NaN()).eval());
}

/// The model nodes of the compared nodes: the node at the same initial position, the one of the same
/// name if there are several (a hinge's two nodes). Another reduction names its nodes differently.
std::vector<std::size_t> match_nodes(const mbd::Model& m, const std::vector<std::string>& names, const std::vector<Eigen::Vector3d>& p0,
                                     const std::filesystem::path& file) {
  std::vector<std::size_t> out;
  for (std::size_t k = 0; k < names.size(); ++k) {
    const double close = 1e-6 * std::max(1.0, p0[k].norm());
    std::size_t found = m.nodes.size();
    for (std::size_t i = 0; i < m.nodes.size(); ++i)
      if ((m.nodes[i].X_WN0.p - p0[k]).norm() <= close && (found == m.nodes.size() || m.nodes[i].name == names[k])) found = i;
    if (found == m.nodes.size()) {
      std::ostringstream os;
      os << file.string() << ": no node at the initial position (" << p0[k].x() << ", " << p0[k].y() << ", " << p0[k].z()
         << ") of the compared node '" << names[k] << "' (an alternative must model the same mechanism)";
      throw InputError(os.str());
    }
    out.push_back(found);
  }
  return out;
}

/// Every body of `d` with fidelity f, the inertia model and the internal modes (empty: all the files
/// have); geometric stiffening where the file carries its invariants (the scene's keys replaced).
SceneDescription with_bodies(SceneDescription d, Fidelity f, mbd::InertiaModel inertia, const std::vector<int>& modes) {
  for (std::size_t b = 0; b < d.bodies.size(); ++b) {
    d.bodies[b].fidelity = f;
    d.bodies[b].inertia = inertia;
    d.bodies[b].internal_modes = modes.empty() ? -1 : modes[b];
    d.bodies[b].geometric_stiffening.reset();
  }
  return d;
}

SceneDescription without_stiffening(SceneDescription d) {
  for (auto& b : d.bodies) b.geometric_stiffening = false;
  return d;
}

/// Some flexible body of the built scene uses geometric stiffening.
bool stiffened(const Scene& s) {
  for (std::size_t b = 0; b < s.description.bodies.size(); ++b)
    if (s.description.bodies[b].fidelity == Fidelity::Flexible && s.description.bodies[b].geometric_stiffening.value_or(true) &&
        s.superelements[b]->stiffening.present())
      return true;
  return false;
}

std::vector<int> capped(const std::vector<int>& in_files, int k) {
  std::vector<int> m;
  for (int n : in_files) m.push_back(std::min(n, k));
  return m;
}

std::string modes_name(int k) { return k < 0 ? "all modes" : std::to_string(k) + (k == 1 ? " mode" : " modes"); }

/// Mode ladder 0, few..., all of one reduction (only the distinct, meaningful ones), and the finest
/// model without geometric stiffening when the files carry its invariants.
void add_ladder(std::vector<Variant>& out, const SceneDescription& d, const std::vector<int>& in_files, bool has_stiffening,
                const std::vector<int>& few, const std::string& prefix, bool with_reference) {
  const int most = in_files.empty() ? 0 : *std::max_element(in_files.begin(), in_files.end());
  const auto full = mbd::InertiaModel::Full, simplified = mbd::InertiaModel::Simplified;
  const bool alt = !with_reference;
  out.push_back({prefix + "flexible / full inertia / all modes", with_reference, with_bodies(d, Fidelity::Flexible, full, {}), mbd::Formulation::Aic, alt});
  if (has_stiffening)
    out.push_back({prefix + "flexible / full inertia / all modes / no stiffening", false,
                   without_stiffening(with_bodies(d, Fidelity::Flexible, full, {})), mbd::Formulation::Aic, alt});
  std::set<int> ks(few.begin(), few.end());
  for (auto it = ks.rbegin(); it != ks.rend(); ++it)
    if (*it > 0 && *it < most)
      out.push_back({prefix + "flexible / full inertia / " + modes_name(*it), false, with_bodies(d, Fidelity::Flexible, full, capped(in_files, *it)),
                     mbd::Formulation::Aic, alt});
  if (most > 0)
    out.push_back({prefix + "flexible / full inertia / 0 modes", false, with_bodies(d, Fidelity::Flexible, full, capped(in_files, 0)), mbd::Formulation::Aic, alt});
  out.push_back({prefix + "flexible / simplified mass / all modes", false, with_bodies(d, Fidelity::Flexible, simplified, {}), mbd::Formulation::Aic, alt});
  if (most > 0)
    out.push_back({prefix + "flexible / simplified mass / 0 modes", false, with_bodies(d, Fidelity::Flexible, simplified, capped(in_files, 0)),
                   mbd::Formulation::Aic, alt});
}

/// "alternative NAME: " with NAME the file stem (numbered when two alternatives share a stem).
std::string alternative_prefix(const std::vector<SceneDescription>& alts, std::size_t i) {
  std::string stem = alts[i].file.stem().string();
  if (stem.empty()) stem = std::to_string(i + 1);
  int same = 0;
  for (const auto& a : alts) same += a.file.stem().string() == alts[i].file.stem().string();
  if (same > 1) stem += " (" + std::to_string(i + 1) + ")";
  return "alternative " + stem + ": ";
}

std::vector<int> modes_in_files(const Scene& s) {
  std::vector<int> m;
  for (std::size_t b = 0; b < s.superelements.size(); ++b) m.push_back(s.superelements[b]->num_modes);
  return m;
}

double cpu_now() { return static_cast<double>(std::clock()) / CLOCKS_PER_SEC; }

}  // namespace

AdviseReport advise(const SceneDescription& scene, const AdviseOptions& o) {
  if (!(o.tolerance > 0.0) || !std::isfinite(o.tolerance)) throw InputError("advise: the tolerance must be a positive angle");
  if (o.t_end && !(*o.t_end > 0.0)) throw InputError("advise: the end time must be > 0 s");
  if (o.grid_points < 10) throw InputError("advise: at least 10 comparison points");
  if (!o.nodes.empty() && (!(o.position_tolerance > 0.0) || !std::isfinite(o.position_tolerance)))
    throw InputError("advise: comparing node positions needs a position tolerance > 0 m");
  if (o.nodes.empty() && o.position_tolerance != 0.0) throw InputError("advise: a position tolerance needs the nodes to compare");
  AdviseReport rep;
  rep.tolerance = o.tolerance;
  rep.position_tolerance = o.position_tolerance;
  rep.nodes = o.nodes;
  if (!(o.stress_tolerance >= 0.0) || !std::isfinite(o.stress_tolerance)) throw InputError("advise: the stress tolerance must be >= 0");
  rep.stress_tolerance = o.stress_tolerance;

  // The finest variant first: it fixes the horizon and the comparison grid.
  const SceneDescription finest = with_bodies(scene, Fidelity::Flexible, mbd::InertiaModel::Full, {});
  const Scene ref_scene = build_scene(finest);
  std::vector<Eigen::Vector3d> p0;  // initial positions of the compared nodes
  for (const auto& name : o.nodes) {
    const auto& ns = ref_scene.model.nodes;
    const auto it = std::find_if(ns.begin(), ns.end(), [&](const auto& n) { return n.name == name; });
    if (it == ns.end()) {
      std::string known;
      for (std::size_t i = 0; i < ns.size() && i < 12; ++i) {
        if (i) known += ", ";
        known += ns[i].name;
      }
      if (ns.size() > 12) known += ", ...";
      throw InputError(scene.file.string() + ": advise: no node '" + name + "' to compare (nodes: " + known + ")");
    }
    p0.push_back(it->X_WN0.p);
  }
  std::vector<Variant> variants;
  add_ladder(variants, scene, modes_in_files(ref_scene), stiffened(ref_scene), o.few_modes, "", true);
  variants.push_back({"rigid", false, with_bodies(scene, Fidelity::Rigid, mbd::InertiaModel::Simplified, {})});
  // The baselines of the classic floating frame with Lagrange multipliers (docs/ffrf.md): the
  // finest model's bodies and modes, and rigid bodies.
  variants.push_back({"FFRF-LM / flexible / all modes", false, finest, mbd::Formulation::FfrfLm});
  variants.push_back({"rigid-LM", false, finest, mbd::Formulation::RigidLm});
  for (std::size_t a = 0; a < o.alternatives.size(); ++a) {
    const SceneDescription& alt_d = o.alternatives[a];
    const Scene alt = build_scene(with_bodies(alt_d, Fidelity::Flexible, mbd::InertiaModel::Full, {}));
    for (const auto& h : ref_scene.model.hinges) {
      const bool found = std::any_of(alt.model.hinges.begin(), alt.model.hinges.end(), [&](const auto& x) { return x.name == h.name; });
      if (!found) throw InputError(alt_d.file.string() + ": the alternative scene has no hinge '" + h.name + "' (it must model the same mechanism)");
    }
    match_nodes(alt.model, o.nodes, p0, alt_d.file);
    add_ladder(variants, alt_d, modes_in_files(alt), stiffened(alt), {}, alternative_prefix(o.alternatives, a), false);
  }

  mbd::IntegratorSettings base = scene.integrator;
  if (o.t_end) base.t_end = *o.t_end;
  const double spacing = base.t_end / o.grid_points;
  base.output_interval = base.output_interval > 0.0 ? std::min(base.output_interval, spacing) : spacing;

  AngleRecorder ref(!o.t_end, match_nodes(ref_scene.model, o.nodes, p0, scene.file));
  if (o.stress_tolerance > 0.0) {
    ref.track_stresses(ref_scene);
    bool any = false;
    for (const auto& sp : ref_scene.stress) any = any || (sp && sp->present());
    if (!any) throw InputError(scene.file.string() + ": advise: a stress tolerance needs bodies reduced with --stresses (stress modes)");
  }
  {
    const double c0 = cpu_now();
    AdviseRow row;
    row.name = variants[0].name;
    row.reference = true;
    row.dofs = ref_scene.model.num_dofs;
    row.stiffening = stiffened(ref_scene);
    const mbd::RunStats st = solve_scene(ref_scene, base, mbd::Formulation::Aic, &ref).run;  // the reference must run
    row.cpu_seconds = cpu_now() - c0;
    row.steps = st.steps;
    row.ran = true;
    row.within = true;
    rep.rows.push_back(row);
  }
  rep.horizon = ref.t.back();
  rep.horizon_at_lock = !o.t_end && !ref.first_lock.empty();
  rep.horizon_lock = ref.first_lock;

  mbd::IntegratorSettings short_run = base;
  short_run.t_end = rep.horizon;
  for (std::size_t v = 1; v < variants.size(); ++v) {
    AdviseRow row;
    row.name = variants[v].name;
    row.max_error = kInf;
    row.max_position_error = o.nodes.empty() ? 0.0 : kInf;
    row.max_stress_error = o.stress_tolerance > 0.0 ? kInf : 0.0;
    std::unique_ptr<AngleRecorder> rec;
    try {
      const Scene s = build_scene(variants[v].scene);
      row.dofs = s.model.num_dofs;
      row.stiffening = stiffened(s) && variants[v].formulation == mbd::Formulation::Aic;
      rec = std::make_unique<AngleRecorder>(false, match_nodes(s.model, o.nodes, p0, variants[v].scene.file));
      if (o.stress_tolerance > 0.0) rec->track_stresses(s);
      const double c0 = cpu_now();
      try {
        const mbd::SimulationRun run = solve_scene(s, short_run, variants[v].formulation, rec.get());
        const mbd::RunStats& st = run.run;
        if (run.ffrf) {
          row.dofs = run.ffrf->coordinates;
          row.multipliers = run.ffrf->constraints;
        }
        row.steps = st.steps;
        row.ran = true;
      } catch (const ConvergenceError& e) {
        row.failure = e.what();
      }
      row.cpu_seconds = cpu_now() - c0;
    } catch (const InputError& e) {
      row.failure = std::string("cannot be built: ") + e.what();
    }
    if (row.ran) {
      // Compare on the reference's grid (event samples excluded: they are not on the grid).
      double worst = 0.0;
      for (std::size_t h = 0; h < ref.names.size(); ++h) {
        const auto hv = static_cast<std::size_t>(std::find(rec->names.begin(), rec->names.end(), ref.names[h]) - rec->names.begin());
        for (std::size_t i = 0; i < ref.t.size(); ++i) {
          if (ref.event[i] || ref.t[i] > rep.horizon) continue;
          const double e = std::abs(angle_at(*rec, hv, ref.t[i]) - ref.phi[i][h]);
          if (!(e <= worst)) {  // NaN counts as the worst
            worst = std::isfinite(e) ? e : kInf;
            row.worst_hinge = ref.names[h];
            row.worst_time = ref.t[i];
          }
        }
      }
      row.max_error = worst;
      double worst_p = 0.0;
      for (std::size_t k = 0; k < o.nodes.size(); ++k)
        for (std::size_t i = 0; i < ref.t.size(); ++i) {
          if (ref.event[i] || ref.t[i] > rep.horizon) continue;
          const double e = (position_at(*rec, k, ref.t[i]) - ref.pos[i][k]).norm();
          if (!(e <= worst_p)) {
            worst_p = std::isfinite(e) ? e : kInf;
            row.worst_node = o.nodes[k];
            row.worst_node_time = ref.t[i];
          }
        }
      row.max_position_error = worst_p;
      if (o.stress_tolerance > 0.0) {  // peak element results against the reference's, per body
        std::map<std::size_t, double> scale;
        for (const auto& [key, p] : ref.peak) scale[key.first] = std::max(scale[key.first], p);
        double worst_s = 0.0;
        for (const auto& [key, p] : ref.peak) {
          const auto it = rec->peak.find(key);
          const double e = std::abs((it == rec->peak.end() ? 0.0 : it->second) - p) / std::max(scale[key.first], 1e-300);
          if (!(e <= worst_s)) {
            worst_s = std::isfinite(e) ? e : kInf;
            row.worst_element = scene.bodies[key.first].name + " element " + std::to_string(key.second);
          }
        }
        row.max_stress_error = worst_s;
      }
      row.within = worst <= o.tolerance && (o.nodes.empty() || worst_p <= o.position_tolerance) &&
                   (o.stress_tolerance == 0.0 || row.max_stress_error <= o.stress_tolerance);
    }
    rep.rows.push_back(row);
  }
  for (std::size_t i = 0; i < rep.rows.size(); ++i)
    if (rep.rows[i].within && (rep.recommended < 0 || rep.rows[i].cpu_seconds < rep.rows[static_cast<std::size_t>(rep.recommended)].cpu_seconds))
      rep.recommended = static_cast<int>(i);
  return rep;
}

}  // namespace seflex::scene
