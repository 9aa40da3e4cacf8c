#pragma once
// The pybind11 module seflex._seflex, split by area: errors (module.cpp), models and their
// solutions (model.cpp), superelements (superelement.cpp), scene runs (run.cpp). Each area registers its classes and
// functions on the module. Depends on the libraries only (never on apps/).
#include <pybind11/pybind11.h>

namespace seflex::python {

void bind_model(pybind11::module_& m);
void bind_superelement(pybind11::module_& m);
void bind_run(pybind11::module_& m);

}  // namespace seflex::python
