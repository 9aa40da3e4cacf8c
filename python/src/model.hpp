#pragma once
// The Python side of an FE model: the library's fem::Model with the path it was read from (as the
// caller named it: a superelement reduced from it records that path, as `seflex reduce` does) and
// whether solutions may ignore the cards seflex does not know.
#include <string>

#include "seflex/fem/model.hpp"

namespace seflex::python {

struct PyModel {
  fem::Model model;
  std::string path;
  bool ignore_unknown = false;
};

}  // namespace seflex::python
