// The compiled half of seflex.run and seflex.Scene (python/seflex/scene.py is the other):
//   _run(file, text, output, ...)  simulate a scene as `seflex run SCENE -o OUTPUT` does (the same files
//                                  written to `output`) and keep the history rows in memory;
//   _check_scene(file, text)       read a scene (the library's checks and messages), build nothing;
//   _scene_tree(file)              a scene file's YAML as Python dicts, lists and scalars (after checking it).
// The run releases the GIL; the progress callback is called with the GIL held, at most every
// `progress_interval` seconds of wall time, and the interpreter's signals (Ctrl-C) are checked as often.
// An exception of the callback (or a signal) stops the run at its next step: the files are finished
// as for any stop, then the exception propagates.
#include <pybind11/numpy.h>
#include <pybind11/pybind11.h>
#include <pybind11/stl.h>
#include <pybind11/stl/filesystem.h>
#include <yaml-cpp/yaml.h>

#include <charconv>
#include <chrono>
#include <cmath>
#include <ctime>
#include <exception>
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

/// What _run returns: the history (row-major, one row per sample; columns as history.csv's).
struct RunData {
  std::vector<std::string> columns;
  std::vector<double> rows;
};

/// Forwards to the run's files, keeps the history rows, calls the progress callback (GIL held) at a
/// bounded rate and ends the run when the callback raises or a signal arrives.
class Collector : public mbd::Observer {
 public:
  /// `progress` is borrowed (the caller's argument keeps it alive): no reference counting without the GIL.
  Collector(scene::RunOutput& out, RunData& r, py::handle progress, double interval)
      : out_(out), r_(r), progress_(progress), interval_(interval) {}
  void on_sample(const mbd::Model& m, const mbd::Sample& s) override {
    out_.on_sample(m, s);
    scene::history_values(m, s, row_);
    r_.rows.insert(r_.rows.end(), row_.begin(), row_.end());
  }
  bool stop_requested() const override { return error_ || out_.stop_requested(); }
  void on_progress(double t, double t_end) override {
    out_.on_progress(t, t_end);
    if (error_) return;
    const auto now = std::chrono::steady_clock::now();
    if (now - last_ < interval_) return;
    last_ = now;
    py::gil_scoped_acquire gil;
    try {
      if (PyErr_CheckSignals() != 0) throw py::error_already_set();
      if (!progress_.is_none()) progress_(t, t_end);
    } catch (py::error_already_set& e) {
      error_ = std::current_exception();
      out_.event(t, "stop", "python", std::string("run stopped by an exception in Python: ") + e.what());
    }
  }
  /// The exception that stopped the run (null: none).
  std::exception_ptr error() const { return error_; }

 private:
  scene::RunOutput& out_;
  RunData& r_;
  py::handle progress_;
  std::chrono::duration<double> interval_;
  std::vector<double> row_;
  std::exception_ptr error_;
  std::chrono::steady_clock::time_point last_ = std::chrono::steady_clock::now();
};

mbd::Formulation parse_formulation(const std::string& f) {
  if (f == "aic") return mbd::Formulation::Aic;
  if (f == "ffrf-lm") return mbd::Formulation::FfrfLm;
  if (f == "rigid-lm" || f == "rigid") return mbd::Formulation::RigidLm;
  throw InputError("formulation expects aic, ffrf-lm or rigid-lm (also: rigid), got '" + f + "'");
}

scene::SceneDescription read(const std::filesystem::path& file, const std::optional<std::string>& text) {
  return text ? scene::parse_scene(*text, file) : scene::read_scene(file);
}

/// A YAML node as Python objects: maps -> dict (in the file's order), sequences -> list, plain
/// scalars -> bool / None / int / float where they read as one (YAML 1.2 core schema), else str.
py::object to_python(const YAML::Node& n) {
  if (n.IsMap()) {
    py::dict d;
    for (const auto& kv : n) d[py::str(kv.first.Scalar())] = to_python(kv.second);
    return d;
  }
  if (n.IsSequence()) {
    py::list l;
    for (const auto& v : n) l.append(to_python(v));
    return l;
  }
  if (!n.IsScalar()) return py::none();
  const std::string& s = n.Scalar();
  if (n.Tag() == "!") return py::str(s);  // quoted: a string whatever it reads as
  if (s == "true" || s == "True" || s == "TRUE") return py::bool_(true);
  if (s == "false" || s == "False" || s == "FALSE") return py::bool_(false);
  if (s.empty() || s == "~" || s == "null" || s == "Null" || s == "NULL") return py::none();
  const char* b = s.data() + (s[0] == '+' ? 1 : 0);
  const char* e = s.data() + s.size();
  long long i = 0;
  if (auto r = std::from_chars(b, e, i); r.ec == std::errc() && r.ptr == e) return py::int_(i);
  double x = 0.0;
  if (auto r = std::from_chars(b, e, x); r.ec == std::errc() && r.ptr == e && s.find_first_of("0123456789") != std::string::npos)
    return py::float_(x);
  return py::str(s);
}

}  // namespace

void bind_run(py::module_& m) {
  py::class_<RunData>(m, "_RunData", "history rows of a run (seflex.run wraps them in a RunResult)")
      .def_readonly("columns", &RunData::columns)
      .def_property_readonly("rows", [](py::object self) {
            const RunData& r = self.cast<const RunData&>();
            const auto nc = static_cast<py::ssize_t>(r.columns.size());
            const py::ssize_t n = nc ? static_cast<py::ssize_t>(r.rows.size()) / nc : 0;
            py::array_t<double> a({n, nc}, {nc * static_cast<py::ssize_t>(sizeof(double)), static_cast<py::ssize_t>(sizeof(double))},
                                  r.rows.data(), self);  // a view that keeps the RunData alive
            py::detail::array_proxy(a.ptr())->flags &= ~py::detail::npy_api::NPY_ARRAY_WRITEABLE_;
            return a;
          });

  m.def("_run", [](const std::filesystem::path& file, const std::optional<std::string>& text, const std::filesystem::path& output,
                   bool overwrite, std::optional<double> t_end, std::optional<double> step, const std::string& formulation_arg, bool animation,
                   const py::object& progress, double progress_interval) {
        const mbd::Formulation formulation = parse_formulation(formulation_arg);
        for (const auto& [name, v] : {std::pair{"t_end", t_end}, std::pair{"step", step}})
          if (v && !(*v > 0 && std::isfinite(*v))) throw InputError(std::string(name) + " expects a time > 0 in seconds");
        if (!(progress_interval >= 0)) throw InputError("progress_interval expects a time >= 0 in seconds");
        auto r = std::make_unique<RunData>();
        std::exception_ptr stopped_by;
        {
          py::gil_scoped_release release;
          scene::RunOutput::check_folder(output, overwrite);  // before the work, as the command
          scene::SceneDescription d = read(file, text);
          if (t_end) d.integrator.t_end = *t_end;
          if (step) {
            d.integrator.h_initial = *step;
            d.integrator.h_min = std::min(d.integrator.h_min, *step);
          }
          const auto t0 = std::chrono::steady_clock::now();
          const std::clock_t c0 = std::clock();
          scene::SceneBuildOptions bo;  // as `seflex run`: the mesh parts only for an animation
          bo.keep_mesh = (animation && d.output.animation_interval) || !d.output.static_subcases.empty();  // static subcases: inertia loads
          bo.full_inertia_everywhere = formulation == mbd::Formulation::FfrfLm;
          const scene::Scene sc = scene::build_scene(d, bo);
          scene::RunOutputOptions oo;
          oo.folder = output;
          oo.overwrite = overwrite;
          oo.animation = animation;
          scene::RunOutput out(sc, oo);
          r->columns = scene::history_columns(sc.model);
          Collector collector(out, *r, progress, progress_interval);
          scene::RunEnd end = scene::run_end(sc, formulation);
          const auto finish = [&] {
            end.wall_seconds = std::chrono::duration<double>(std::chrono::steady_clock::now() - t0).count();
            end.cpu_seconds = static_cast<double>(std::clock() - c0) / CLOCKS_PER_SEC;
            out.finish(end);
          };
          try {
            const mbd::SimulationRun run = scene::solve_scene(sc, d.integrator, formulation, &collector);
            scene::record_run(run, end);
          } catch (const seflex::Error& e) {  // what was computed is on disk, as with the command
            end.ok = false;
            end.message = e.what();
            finish();
            throw;
          }
          if ((stopped_by = collector.error())) {
            end.ok = false;
            end.message = "stopped by an exception in Python";
          }
          finish();
        }
        if (stopped_by) std::rethrow_exception(stopped_by);  // with the GIL: it holds a Python exception
        return r;
      },
      py::arg("file"), py::arg("text"), py::arg("output"), py::arg("overwrite"), py::arg("t_end"), py::arg("step"), py::arg("formulation"),
      py::arg("animation"), py::arg("progress"), py::arg("progress_interval"),
      "Run a scene (text: its YAML, or None to read `file`) writing `output`; seflex.run is the public call.");

  m.def("_check_scene", [](const std::filesystem::path& file, const std::optional<std::string>& text) {
        py::gil_scoped_release release;
        (void)read(file, text);
      },
      py::arg("file"), py::arg("text") = py::none(),
      "Read and check a scene (text: its YAML, or None to read `file`); raises InputError as `seflex run` reports it.");

  m.def("_scene_tree", [](const std::filesystem::path& file) {
        {
          py::gil_scoped_release release;
          (void)scene::read_scene(file);  // the library's checks and messages first
        }
        return to_python(YAML::LoadFile(file.string()));
      },
      py::arg("file"), "A checked scene file's YAML as dicts, lists and scalars.");
}

}  // namespace seflex::python
