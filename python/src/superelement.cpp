// seflex.reduce, seflex.load_superelement and the Superelement class.
// A Superelement owns its matrices (se::Superelement); K, M, Phi_f, recovery, ... are read-only numpy
// views of them (column-major, no copy) that keep the Superelement alive.
#include <pybind11/eigen.h>
#include <pybind11/pybind11.h>
#include <pybind11/stl.h>
#include <pybind11/stl/filesystem.h>

#include <algorithm>
#include <cctype>
#include <cmath>
#include <filesystem>
#include <optional>
#include <string>
#include <variant>
#include <vector>

#include "bindings.hpp"
#include "model.hpp"
#include "seflex/common/error.hpp"
#include "seflex/io/provenance.hpp"
#include "seflex/linalg/eigensolver.hpp"
#include "seflex/io/superelement_file.hpp"
#include "seflex/reduction/craig_bampton_superelement.hpp"
#include "seflex/solutions/card_usage.hpp"

namespace py = pybind11;

namespace seflex::python {
namespace {

namespace red = reduction;
using Item = std::variant<int, std::string>;

std::string lower(std::string s) {
  for (char& c : s) c = static_cast<char>(std::tolower(static_cast<unsigned char>(c)));
  return s;
}

/// The interface grids, as `seflex reduce --interface`: "aset" | "bset" | "suport" (the grids of
/// those cards), or a list of grid ids and node set names (gmsh physical groups), in that order.
/// Sets interface_ids and interface_cards of `o`.
void resolve_interface(const fem::Model& model, const std::variant<std::string, std::vector<Item>>& spec,
                       red::SuperelementOptions& o) {
  if (const auto* s = std::get_if<std::string>(&spec)) {
    const std::string l = lower(*s);
    if (l == "aset") o.interface_cards = solutions::kInterfaceAset;
    else if (l == "bset") o.interface_cards = solutions::kInterfaceBset;
    else if (l == "suport" || l == "support") o.interface_cards = solutions::kInterfaceSuport;
    if (o.interface_cards != solutions::kInterfaceNone) {
      o.interface_ids = red::interface_nodes_from_cards(
          model, o.interface_cards == solutions::kInterfaceAset   ? red::InterfaceCards::Aset
                 : o.interface_cards == solutions::kInterfaceBset ? red::InterfaceCards::Bset
                                                                  : red::InterfaceCards::Suport);
      return;
    }
    o.interface_ids = red::interface_nodes_from_set(model, *s);
    return;
  }
  for (const Item& item : std::get<std::vector<Item>>(spec)) {
    if (const int* id = std::get_if<int>(&item)) {
      o.interface_ids.push_back(*id);
    } else {
      const std::vector<int> set = red::interface_nodes_from_set(model, std::get<std::string>(item));
      o.interface_ids.insert(o.interface_ids.end(), set.begin(), set.end());
    }
  }
}

int frame_id(const fem::Model& model, const Item& spec) {
  if (const int* id = std::get_if<int>(&spec)) return *id;
  const std::string& name = std::get<std::string>(spec);
  const std::vector<int> set = red::interface_nodes_from_set(model, name);
  if (set.size() != 1)
    throw InputError(SourceRef{model.files.empty() ? std::string() : model.files[0], 0},
                     "node set '" + name + "' holds " + std::to_string(set.size()) + " nodes; expected one for --frame");
  return set.front();
}

template <class T>
auto view(T se::Superelement::*member) {
  return [member](const se::Superelement& s) -> const T& { return s.*member; };
}

}  // namespace

void bind_superelement(py::module_& m) {
  const auto ref = py::return_value_policy::reference_internal;
  py::class_<se::Superelement>(m, "Superelement",
                               "A Craig-Bampton superelement (absolute interface coordinates): reduced K and M of size\n"
                               "n = 6 N + m (N interface grids, m fixed-interface modes), as stored in a .se file.\n"
                               "Matrix properties are read-only numpy views owned by this object (no copy).")
      .def_readonly("name", &se::Superelement::name)
      .def_readonly("seflex_version", &se::Superelement::seflex_version)
      .def_readonly("source_file", &se::Superelement::source_file)
      .def_readonly("source_hash", &se::Superelement::source_hash)
      .def_readwrite("created", &se::Superelement::created, "ISO-8601 UTC time of the reduction (the one field two reductions differ in)")
      .def_readonly("source_warnings", &se::Superelement::source_warnings)
      .def_readonly("frame_node", &se::Superelement::frame_node_id)
      .def_readonly("num_modes", &se::Superelement::num_modes)
      .def_property_readonly("size", &se::Superelement::size, "n = 6 N + m")
      .def_property_readonly("K", view(&se::Superelement::K), ref, "reduced stiffness, n x n")
      .def_property_readonly("M", view(&se::Superelement::M), ref, "reduced mass, n x n")
      .def_property_readonly("Phi_f", view(&se::Superelement::Phi_f), ref, "6 x n: the frame node's rows of the basis")
      .def_property_readonly("mode_frequencies", view(&se::Superelement::mode_frequencies_hz), ref, "fixed-interface modes, Hz")
      .def_property_readonly("interface", [](const se::Superelement& s) {
            Eigen::VectorXi ids(s.num_interfaces());
            for (int j = 0; j < s.num_interfaces(); ++j) ids(j) = s.interfaces[static_cast<std::size_t>(j)].id;
            return ids;
          }, "interface grid ids, in the order of the coordinates")
      .def_property_readonly("interface_positions", [](const se::Superelement& s) {
            Eigen::Matrix<double, Eigen::Dynamic, 3, Eigen::RowMajor> p(s.num_interfaces(), 3);
            for (int j = 0; j < s.num_interfaces(); ++j) p.row(j) = s.interfaces[static_cast<std::size_t>(j)].p_BoN_B.transpose();
            return p;
          }, "N x 3, from the frame node (body axes = basic axes)")
      .def_property_readonly("frame_position", view(&se::Superelement::p_OBo), ref, "frame node in the FE model's basic system")
      .def_readonly("mass", &se::Superelement::mass)
      .def_property_readonly("center_of_mass", view(&se::Superelement::p_BoCm_B), ref, "from the frame node")
      .def_property_readonly("inertia", view(&se::Superelement::I_Cm_B), ref, "about the centre of mass")
      .def_property_readonly("fe_node_ids", [](const se::Superelement& s) { return s.fe_node_ids; }, "empty without the mesh part")
      .def_property_readonly("recovery", view(&se::Superelement::recovery), ref, "6 n_fe x n: FE displacements = recovery @ q")
      .def("save", [](const se::Superelement& s, const std::filesystem::path& path, bool overwrite) {
            py::gil_scoped_release release;
            io::save_superelement(s, path, io::SaveOptions{overwrite});
          }, py::arg("path"), py::kw_only(), py::arg("overwrite") = false,
          "Write the .se file (what `seflex reduce -o` writes). Raises seflex.InputError if it exists and not overwrite.")
      .def("__repr__", [](const se::Superelement& s) {
        return "<seflex.Superelement '" + s.name + "': " + std::to_string(s.num_interfaces()) + " interface grids, " +
               std::to_string(s.num_modes) + " modes>";
      });

  m.def("load_superelement", [](const std::filesystem::path& path) {
        py::gil_scoped_release release;
        return io::load_superelement(path);
      }, py::arg("path"), "Read a .se file (checksum, sizes, finiteness checked). Raises seflex.InputError.");

  m.def("reduce", [](const PyModel& p, const std::variant<std::string, std::vector<Item>>& interface, std::optional<int> modes,
                     std::optional<double> fmax, std::optional<Item> frame, std::optional<std::string> name,
                     const std::string& eigensolver, bool stiffening, bool mesh) {
        if (modes && fmax) throw InputError("give either modes or fmax, not both");
        if (modes && *modes < 0) throw InputError("modes expects a number >= 0, got " + std::to_string(*modes));
        if (fmax && !(*fmax > 0 && std::isfinite(*fmax))) throw InputError("fmax expects a frequency > 0 (Hz)");
        const auto backend = linalg::parse_eigen_backend(eigensolver);
        if (!backend)
          throw InputError("eigensolver expects " + std::string(linalg::eigen_backend_names()) + ", got '" + eigensolver + "'");
        red::SuperelementOptions o;
        resolve_interface(p.model, interface, o);
        if (frame) o.frame_node = frame_id(p.model, *frame);
        if (fmax) o.modes.fmax_hz = fmax;
        else o.modes.modes = modes.value_or(0);
        o.modes.backend = *backend;
        o.ignore_unknown_cards = p.ignore_unknown;
        o.name = name ? *name : std::filesystem::path(p.path).stem().string();
        o.full_mesh = true;  // as the command: the invariants come from the mesh before mesh=False drops it
        o.stiffening = stiffening;
        py::gil_scoped_release release;
        se::Superelement s = red::reduce_to_superelement(p.model, o);
        io::record_source(s, p.model, p.path);
        if (!mesh) io::drop_mesh(s);
        return s;
      },
      py::arg("model"), py::kw_only(), py::arg("interface"), py::arg("modes") = py::none(), py::arg("fmax") = py::none(),
      py::arg("frame") = py::none(), py::arg("name") = py::none(), py::arg("eigensolver") = "spectra",
      py::arg("stiffening") = true, py::arg("mesh") = true,
      "Craig-Bampton reduction, as `seflex reduce`: the same options give the same .se file (but `created`).\n\n"
      "interface: 'aset' | 'bset' | 'suport', a node set name, or a list of grid ids and node set names;\n"
      "modes=N or fmax=Hz fixed-interface modes (neither: constraint modes only); frame: grid id or node set\n"
      "of one grid (default: the free grid nearest the centre of mass); name: default the model file's stem;\n"
      "stiffening=False: no geometric-stiffness invariants (--no-stiffening); mesh=False: dynamics only (--no-mesh).\n"
      "Raises seflex.InputError (bad interface or frame, an interior the interface does not hold).");
}

}  // namespace seflex::python
