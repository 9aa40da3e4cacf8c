// seflex._seflex: the compiled part of the `seflex` package (python/seflex/__init__.py re-exports it).
// Errors of the library become Python exceptions carrying what() unchanged, which is the text the
// command line prints after "error: ":
//   seflex::InputError       -> seflex.InputError       (subclass of ValueError)
//   seflex::ConvergenceError -> seflex.ConvergenceError (subclass of RuntimeError)
//   other seflex::Error      -> seflex.Error            (subclass of RuntimeError)
#include <pybind11/pybind11.h>

#include "bindings.hpp"
#include "seflex/common/error.hpp"

namespace py = pybind11;

PYBIND11_MODULE(_seflex, m) {
  m.doc() = "seflex: FE models, normal modes, statics, Craig-Bampton superelements and scene runs from Python";
  // pybind11 tries the translators in the reverse order of registration: the base class first.
  py::register_exception<seflex::Error>(m, "Error", PyExc_RuntimeError);
  py::register_exception<seflex::InputError>(m, "InputError", PyExc_ValueError);
  py::register_exception<seflex::ConvergenceError>(m, "ConvergenceError", PyExc_RuntimeError);
  seflex::python::bind_model(m);
  seflex::python::bind_superelement(m);
  seflex::python::bind_run(m);
}
