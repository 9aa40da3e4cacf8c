// seflex.run: simulate a scene file as `seflex run` does (the same files written to a folder) and
// return the time histories as arrays by name, the locks and the summary.
// The run releases the GIL; the progress callback is called with the GIL held, at most every
// `progress_interval` seconds of wall time.
#include <pybind11/numpy.h>
#include <pybind11/pybind11.h>
#include <pybind11/stl.h>
#include <pybind11/stl/filesystem.h>

#include <algorithm>
#include <chrono>
#include <cmath>
#include <cstdlib>
#include <ctime>
#include <filesystem>
#include <optional>
#include <string>
#include <vector>

#include "bindings.hpp"
#include "seflex/common/error.hpp"
#include "seflex/mbd/solvers/simulate.hpp"
#include "seflex/scene/run_output.hpp"
#include "seflex/scene/scene.hpp"
#include "seflex/scene/solve_scene.hpp"

namespace py = pybind11;

namespace seflex::python {
namespace {

/// What a run returns: history rows (row-major, one row per sample) and their column names.
struct RunResult {
  std::vector<std::string> columns;
  std::vector<double> rows;
  std::vector<scene::LockRecord> locks;
  py::dict summary;
  std::filesystem::path folder;
  py::ssize_t samples() const { return columns.empty() ? 0 : static_cast<py::ssize_t>(rows.size() / columns.size()); }
};

/// Forwards to the run's files and keeps the history rows; calls the progress callback (GIL held)
/// at a bounded rate.
class Collector : public mbd::Observer {
 public:
  /// `progress` is borrowed (the caller's argument keeps it alive): no reference counting without the GIL.
  Collector(scene::RunOutput& out, RunResult& r, py::handle progress, double interval)
      : out_(out), r_(r), progress_(progress), interval_(interval) {}
  void on_sample(const mbd::Model& m, const mbd::Sample& s) override {
    out_.on_sample(m, s);
    scene::history_values(m, s, row_);
    r_.rows.insert(r_.rows.end(), row_.begin(), row_.end());
  }
  bool stop_requested() const override { return out_.stop_requested(); }
  void on_progress(double t, double t_end) override {
    out_.on_progress(t, t_end);
    if (progress_.is_none()) return;
    const auto now = std::chrono::steady_clock::now();
    if (now - last_ < std::chrono::duration<double>(interval_)) return;
    last_ = now;
    py::gil_scoped_acquire gil;
    progress_(t, t_end);  // an exception of the callback ends the run (py::error_already_set)
  }

 private:
  scene::RunOutput& out_;
  RunResult& r_;
  py::handle progress_;
  double interval_;
  std::vector<double> row_;
  std::chrono::steady_clock::time_point last_ = std::chrono::steady_clock::now();
};

mbd::Formulation parse_formulation(const std::string& f) {
  if (f == "aic") return mbd::Formulation::Aic;
  if (f == "ffrf-lm") return mbd::Formulation::FfrfLm;
  if (f == "rigid-lm" || f == "rigid") return mbd::Formulation::RigidLm;
  throw InputError("formulation expects aic, ffrf-lm or rigid-lm (also: rigid), got '" + f + "'");
}

std::filesystem::path temporary_folder() {
  std::string pattern = (std::filesystem::temp_directory_path() / "seflex-run-XXXXXX").string();
  if (mkdtemp(pattern.data()) == nullptr) throw InputError(pattern + ": cannot create a temporary folder");
  return pattern;
}

}  // namespace

void bind_run(py::module_& m) {
  py::class_<RunResult>(m, "RunResult", "The results of seflex.run: history, locks, summary (and the files in .folder)")
      .def_property_readonly("history", [](py::object self) {
            const RunResult& r = self.cast<const RunResult&>();
            py::dict d;
            const py::ssize_t n = r.samples(), stride = static_cast<py::ssize_t>(r.columns.size() * sizeof(double));
            for (std::size_t j = 0; j < r.columns.size(); ++j) {
              py::array_t<double> a({n}, {stride}, r.rows.data() + j, self);
              py::detail::array_proxy(a.ptr())->flags &= ~py::detail::npy_api::NPY_ARRAY_WRITEABLE_;
              d[py::str(r.columns[j])] = a;
            }
            return d;
          }, "{column of history.csv: array over the samples} (read-only views owned by the result)")
      .def_readonly("columns", &RunResult::columns, "the names of history.csv's columns, in its order")
      .def_property_readonly("locks", [](const RunResult& r) {
            py::list l;
            for (const auto& k : r.locks) {
              py::dict d;
              d["name"] = k.name;
              d["t_latch"] = k.t_latch ? py::cast(*k.t_latch) : py::none();
              d["peak_abs_torque_after_latch"] = k.t_latch ? py::cast(k.peak_abs_torque_after_latch) : py::none();
              l.append(d);
            }
            return l;
          }, "per lock: name, t_latch (None: never latched), peak |torque| after latching (N m)")
      .def_readonly("summary", &RunResult::summary, "status, final_t, steps, rejected_steps, newton_iterations, ...")
      .def_readonly("folder", &RunResult::folder, "where history.csv, events.csv, summary.json ... were written");

  m.def("run", [](const std::filesystem::path& scene_path, std::optional<std::filesystem::path> output, bool overwrite,
                  std::optional<double> t_end, std::optional<double> step, const std::string& formulation_arg,
                  bool animation, const py::object& progress, double progress_interval) {
        const mbd::Formulation formulation = parse_formulation(formulation_arg);
        for (const auto& [name, v] : {std::pair{"t_end", t_end}, std::pair{"step", step}})
          if (v && !(*v > 0 && std::isfinite(*v))) throw InputError(std::string(name) + " expects a time > 0 in seconds");
        auto r = std::make_unique<RunResult>();
        py::gil_scoped_release release;
        r->folder = output ? *output : temporary_folder();
        scene::RunOutput::check_folder(r->folder, overwrite || !output);
        scene::SceneDescription d = scene::read_scene(scene_path);
        if (const std::string why = mbd::integrator_unavailable(formulation, d.method); !why.empty())
          throw InputError("formulation " + formulation_arg + " integrates with generalized-alpha only; the scene asks for integrator.method " +
                           mbd::integrator_method_name(d.method));
        if (t_end) d.integrator.t_end = *t_end;
        if (step) {
          d.integrator.h_initial = *step;
          d.integrator.h_min = std::min(d.integrator.h_min, *step);
        }
        const auto t0 = std::chrono::steady_clock::now();
        const std::clock_t c0 = std::clock();
        scene::SceneBuildOptions bo;
        bo.keep_mesh = animation && d.output.animation_interval;
        bo.full_inertia_everywhere = formulation == mbd::Formulation::FfrfLm;
        const scene::Scene sc = scene::build_scene(d, bo);
        scene::RunOutputOptions oo;
        oo.folder = r->folder;
        oo.overwrite = true;  // checked above
        oo.animation = animation;
        scene::RunOutput out(sc, oo);
        r->columns = scene::history_columns(sc.model);
        Collector collector(out, *r, progress.ptr(), progress_interval);
        scene::RunEnd end;
        end.formulation = mbd::formulation_name(formulation);
        const auto finish = [&] {
          end.wall_seconds = std::chrono::duration<double>(std::chrono::steady_clock::now() - t0).count();
          end.cpu_seconds = static_cast<double>(std::clock() - c0) / CLOCKS_PER_SEC;
          out.finish(end);
        };
        try {
          const mbd::SimulationRun run = scene::solve_scene(sc, d.integrator, formulation, &collector);
          end.stats = run.run;
          if (run.ffrf) {
            end.coordinates = run.ffrf->coordinates;
            end.multipliers = run.ffrf->constraints;
          }
        } catch (const seflex::Error& e) {  // what was computed is on disk, as with the command
          end.ok = false;
          end.message = e.what();
          finish();
          throw;
        }
        finish();
        r->locks = out.locks();
        py::gil_scoped_acquire gil;
        r->summary["status"] = "ok";
        r->summary["final_t"] = out.t_last();
        r->summary["steps"] = end.stats->steps;
        r->summary["rejected_steps"] = end.stats->rejected_error + end.stats->rejected_newton;
        r->summary["newton_iterations"] = end.stats->newton_iterations;
        r->summary["formulation"] = end.formulation;
        r->summary["dofs"] = end.coordinates >= 0 ? end.coordinates : sc.model.num_dofs;
        r->summary["wall_seconds"] = end.wall_seconds;
        r->summary["cpu_seconds"] = end.cpu_seconds;
        return r;
      },
      py::arg("scene"), py::kw_only(), py::arg("output") = py::none(), py::arg("overwrite") = false,
      py::arg("t_end") = py::none(), py::arg("step") = py::none(), py::arg("formulation") = "aic",
      py::arg("animation") = false, py::arg("progress") = py::none(), py::arg("progress_interval") = 0.2,
      "Simulate a scene file as `seflex run SCENE -o OUTPUT` (t_end, step, formulation: the command's --t-end,\n"
      "--step, --formulation; animation=False: --no-animation). The files go to `output` (default: a new\n"
      "temporary folder; an existing one's results are replaced only with overwrite=True). progress(t, t_end)\n"
      "is called at most every progress_interval s. Returns a RunResult: history {column: array}, locks, summary.\n"
      "Raises seflex.InputError, seflex.ConvergenceError (the files hold the run up to the failure).");
}

}  // namespace seflex::python
