// seflex advise: variants of a scene run over a short horizon and compared on the hinge angles
// with the finest variant (io/advise.hpp).
#include "seflex/io/advise.hpp"

#include <algorithm>
#include <cmath>
#include <ctime>
#include <limits>
#include <map>
#include <set>

#include "seflex/io/solve_scene.hpp"

namespace seflex::io {

namespace {

constexpr double kInf = std::numeric_limits<double>::infinity();

struct Variant {
  std::string name;
  bool reference = false;
  SceneDescription scene;
  Formulation formulation = Formulation::Aic;
};

/// Hinge angles at every sample; optionally asks to stop at the first lock that latches.
class AngleRecorder : public mbd::Observer {
 public:
  explicit AngleRecorder(bool stop_at_lock) : stop_at_lock_(stop_at_lock) {}
  void on_sample(const mbd::Model& model, const mbd::Sample& s) override {
    if (names.empty())
      for (const auto& h : model.hinges) names.push_back(h.name);
    t.push_back(s.t);
    event.push_back(s.event);
    std::vector<double> p;
    for (const auto& h : s.hinges) p.push_back(h.phi);
    phi.push_back(std::move(p));
    if (s.event && first_lock.empty())
      for (std::size_t i = 0; i < s.elements.size(); ++i)
        if (s.elements[i].latched && s.elements[i].t_latch == s.t) {
          first_lock = model.force_elements[i].name;
          t_lock = s.t;
        }
  }
  bool stop_requested() const override { return stop_at_lock_ && !first_lock.empty(); }

  std::vector<std::string> names;
  std::vector<double> t;
  std::vector<bool> event;
  std::vector<std::vector<double>> phi;
  std::string first_lock;
  double t_lock = 0.0;

 private:
  bool stop_at_lock_;
};

/// Angle of hinge `h` at time `tq` by linear interpolation between the recorded samples.
double angle_at(const AngleRecorder& r, std::size_t h, double tq) {
  const auto it = std::lower_bound(r.t.begin(), r.t.end(), tq);
  if (it == r.t.end()) return std::numeric_limits<double>::quiet_NaN();
  const auto j = static_cast<std::size_t>(it - r.t.begin());
  if (*it == tq || j == 0) return r.phi[j][h];
  const double t0 = r.t[j - 1], t1 = r.t[j];
  const double w = (tq - t0) / (t1 - t0);
  return (1.0 - w) * r.phi[j - 1][h] + w * r.phi[j][h];
}

SceneDescription with_bodies(SceneDescription d, Fidelity f, mbd::InertiaModel inertia, const std::vector<int>& modes) {
  for (std::size_t b = 0; b < d.bodies.size(); ++b) {
    d.bodies[b].fidelity = f;
    d.bodies[b].inertia = inertia;
    d.bodies[b].internal_modes = modes.empty() ? -1 : modes[b];
  }
  return d;
}

std::vector<int> capped(const std::vector<int>& in_files, int k) {
  std::vector<int> m;
  for (int n : in_files) m.push_back(std::min(n, k));
  return m;
}

std::string modes_name(int k) { return k < 0 ? "all modes" : std::to_string(k) + (k == 1 ? " mode" : " modes"); }

/// Mode ladder 0, few..., all of one reduction (only the distinct, meaningful ones).
void add_ladder(std::vector<Variant>& out, const SceneDescription& d, const std::vector<int>& in_files,
                const std::vector<int>& few, const std::string& prefix, bool with_reference) {
  const int most = in_files.empty() ? 0 : *std::max_element(in_files.begin(), in_files.end());
  const auto full = mbd::InertiaModel::Full, simplified = mbd::InertiaModel::Simplified;
  out.push_back({prefix + "flexible / full inertia / all modes", with_reference, with_bodies(d, Fidelity::Flexible, full, {})});
  std::set<int> ks(few.begin(), few.end());
  for (auto it = ks.rbegin(); it != ks.rend(); ++it)
    if (*it > 0 && *it < most) out.push_back({prefix + "flexible / full inertia / " + modes_name(*it), false, with_bodies(d, Fidelity::Flexible, full, capped(in_files, *it))});
  if (most > 0) out.push_back({prefix + "flexible / full inertia / 0 modes", false, with_bodies(d, Fidelity::Flexible, full, capped(in_files, 0))});
  out.push_back({prefix + "flexible / simplified mass / all modes", false, with_bodies(d, Fidelity::Flexible, simplified, {})});
  if (most > 0) out.push_back({prefix + "flexible / simplified mass / 0 modes", false, with_bodies(d, Fidelity::Flexible, simplified, capped(in_files, 0))});
}

std::vector<int> modes_in_files(const Scene& s) {
  std::vector<int> m;
  for (std::size_t b = 0; b < s.superelements.size(); ++b) m.push_back(s.superelements[b].num_modes);
  return m;
}

double cpu_now() { return static_cast<double>(std::clock()) / CLOCKS_PER_SEC; }

}  // namespace

AdviseReport advise(const SceneDescription& scene, const AdviseOptions& o) {
  if (!(o.tolerance > 0.0) || !std::isfinite(o.tolerance)) throw InputError("advise: the tolerance must be a positive angle");
  if (o.t_end && !(*o.t_end > 0.0)) throw InputError("advise: the end time must be > 0 s");
  if (o.grid_points < 10) throw InputError("advise: at least 10 comparison points");
  AdviseReport rep;
  rep.tolerance = o.tolerance;

  // The finest variant first: it fixes the horizon and the comparison grid.
  const SceneDescription finest = with_bodies(scene, Fidelity::Flexible, mbd::InertiaModel::Full, {});
  const Scene ref_scene = build_scene(finest);
  std::vector<Variant> variants;
  add_ladder(variants, scene, modes_in_files(ref_scene), o.few_modes, "", true);
  variants.push_back({"rigid", false, with_bodies(scene, Fidelity::Rigid, mbd::InertiaModel::Simplified, {})});
  // The baselines of the classic floating frame with Lagrange multipliers (docs/ffrf.md): the
  // finest model's bodies and modes, and rigid bodies.
  variants.push_back({"FFRF-LM / flexible / all modes", false, finest, Formulation::FfrfLm});
  variants.push_back({"rigid-LM", false, finest, Formulation::RigidLm});
  if (o.alternative) {
    const Scene alt = build_scene(with_bodies(*o.alternative, Fidelity::Flexible, mbd::InertiaModel::Full, {}));
    for (const auto& h : ref_scene.model.hinges) {
      const bool found = std::any_of(alt.model.hinges.begin(), alt.model.hinges.end(), [&](const auto& a) { return a.name == h.name; });
      if (!found) throw InputError(o.alternative->file.string() + ": the alternative scene has no hinge '" + h.name + "' (it must model the same mechanism)");
    }
    add_ladder(variants, *o.alternative, modes_in_files(alt), {}, "alternative: ", false);
  }

  mbd::IntegratorSettings base = scene.integrator;
  if (o.t_end) base.t_end = *o.t_end;
  const double spacing = base.t_end / o.grid_points;
  base.output_interval = base.output_interval > 0.0 ? std::min(base.output_interval, spacing) : spacing;

  AngleRecorder ref(!o.t_end);
  {
    const double c0 = cpu_now();
    AdviseRow row;
    row.name = variants[0].name;
    row.reference = true;
    row.dofs = ref_scene.model.num_dofs;
    const mbd::RunStats st = solve_scene(ref_scene, base, Formulation::Aic, &ref).run;  // the reference must run
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
    AngleRecorder rec(false);
    try {
      const Scene s = build_scene(variants[v].scene);
      row.dofs = s.model.num_dofs;
      const double c0 = cpu_now();
      try {
        const SceneRun run = solve_scene(s, short_run, variants[v].formulation, &rec);
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
        const auto hv = static_cast<std::size_t>(std::find(rec.names.begin(), rec.names.end(), ref.names[h]) - rec.names.begin());
        for (std::size_t i = 0; i < ref.t.size(); ++i) {
          if (ref.event[i] || ref.t[i] > rep.horizon) continue;
          const double e = std::abs(angle_at(rec, hv, ref.t[i]) - ref.phi[i][h]);
          if (!(e <= worst)) {  // NaN counts as the worst
            worst = std::isfinite(e) ? e : kInf;
            row.worst_hinge = ref.names[h];
            row.worst_time = ref.t[i];
          }
        }
      }
      row.max_error = worst;
      row.within = worst <= o.tolerance;
    }
    rep.rows.push_back(row);
  }
  for (std::size_t i = 0; i < rep.rows.size(); ++i)
    if (rep.rows[i].within && (rep.recommended < 0 || rep.rows[i].cpu_seconds < rep.rows[static_cast<std::size_t>(rep.recommended)].cpu_seconds))
      rep.recommended = static_cast<int>(i);
  return rep;
}

}  // namespace seflex::io
