// seflex.read_model, seflex.modes, seflex.static and their results.
// Results own their numbers (C++ vectors inside the result object); the numpy arrays their properties
// return are read-only views of them, which keep the result alive (pybind11 reference_internal).
#include <pybind11/eigen.h>
#include <pybind11/numpy.h>
#include <pybind11/pybind11.h>
#include <pybind11/stl.h>
#include <pybind11/stl/filesystem.h>

#include <optional>
#include <string>
#include <unordered_map>
#include <vector>

#include "bindings.hpp"
#include "model.hpp"
#include "seflex/common/error.hpp"
#include "seflex/fem/dof_map.hpp"
#include "seflex/fem/element_counts.hpp"
#include "seflex/fem/mass_properties.hpp"
#include "seflex/io/model_reader.hpp"
#include "seflex/solutions/card_usage.hpp"
#include "seflex/solutions/grid_results.hpp"
#include "seflex/solutions/normal_modes.hpp"
#include "seflex/solutions/statics.hpp"

namespace py = pybind11;

namespace seflex::python {
namespace {

/// One value per grid and component (T1 T2 T3 R1 R2 R3, basic axes): `.grids` (ids), `.values`
/// (n x 6), `table[grid_id]` (the grid's 6 values).
struct GridValues {
  Eigen::VectorXi grids;
  solutions::GridTable values;
  std::unordered_map<int, Eigen::Index> row_of;

  GridValues(const fem::Model& model, solutions::GridTable v) : grids(static_cast<Eigen::Index>(model.grids.size())), values(std::move(v)) {
    for (Eigen::Index i = 0; i < grids.size(); ++i) {
      grids(i) = model.grids[static_cast<std::size_t>(i)].id;
      row_of.emplace(grids(i), i);
    }
  }
};

Eigen::VectorXi grid_ids(const fem::Model& model) {
  Eigen::VectorXi ids(static_cast<Eigen::Index>(model.grids.size()));
  for (Eigen::Index i = 0; i < ids.size(); ++i) ids(i) = model.grids[static_cast<std::size_t>(i)].id;
  return ids;
}

/// The warnings a command prints about the cards of `model` for `solution` (the reader's, then the
/// unused and approximated cards), one line each without the "warning: " prefix.
std::vector<std::string> card_warnings(const fem::Model& model, const solutions::CardUsage& usage) {
  std::vector<std::string> w = model.read_warnings;
  for (const solutions::CardUse& u : usage.uses)
    if (u.kind != solutions::CardUse::Kind::Refused) w.push_back(solutions::describe(model, u));
  return w;
}

struct ModesResult {
  solutions::NormalModes r;
  Eigen::VectorXd hz, rad;
  Eigen::VectorXi grids;
  std::vector<double> shapes;  // m x n_grids x 6, C order
  std::vector<std::string> warnings;
};

struct StaticResult {
  int subcase = 0;
  double backward_error = 0;
  GridValues displacements, loads, spc_forces;
  std::vector<std::string> warnings;
};

const char* kComponents = "components T1 T2 T3 R1 R2 R3 along the basic axes";

}  // namespace

void bind_model(py::module_& m) {
  py::class_<PyModel>(m, "Model", "An FE model read by seflex.read_model (Nastran deck or gmsh mesh with its property file).")
      .def_readonly("path", &PyModel::path, "the path the model was read from, as given")
      .def_readonly("ignore_unknown", &PyModel::ignore_unknown, "solutions leave out the cards seflex does not know")
      .def_property_readonly("files", [](const PyModel& p) { return p.model.files; }, "every file read (the deck, then its INCLUDEs)")
      .def_property_readonly("grid_ids", [](const PyModel& p) { return grid_ids(p.model); }, "GRID ids in the model's order")
      .def_property_readonly("counts", [](const PyModel& p) {
            const fem::Model& x = p.model;
            py::dict d;
            d["grids"] = x.grids.size();
            d["scalar_points"] = x.spoints.size();
            d["elements"] = fem::element_count(x);
            d["materials"] = x.mat1.size() + x.mat2.size() + x.mat8.size() + x.mat9.size();
            return d;
          }, "numbers of grids, scalar points, elements (rigid elements included) and materials (MAT1, MAT2, MAT8, MAT9)")
      .def_property_readonly("element_counts", [](const PyModel& p) {
            py::dict d;
            for (const auto& [card, n] : fem::element_counts(p.model)) d[py::str(card)] = n;
            return d;
          }, "{card name: count} of every element kind present, as `seflex info` lists them")
      .def_property_readonly("warnings", [](const PyModel& p) { return p.model.read_warnings; },
                             "what the reader chose and says so (e.g. an INCLUDE found in two places)")
      .def("mass_properties", [](const PyModel& p, std::optional<int> reference_grid) {
            const fem::MassProperties mp = fem::mass_properties(p.model, reference_grid);
            py::dict d;
            d["mass"] = mp.mass;
            d["cg"] = Eigen::Vector3d(mp.cg);
            d["I_cg"] = Eigen::Matrix3d(mp.I_cg);
            d["M0"] = Eigen::Matrix<double, 6, 6>(mp.M0);
            d["reference"] = Eigen::Vector3d(mp.reference);
            d["wtmass"] = mp.wtmass;
            d["principal_moments"] = Eigen::Vector3d(mp.principal_moments);
            d["principal_axes"] = Eigen::Matrix3d(mp.principal_axes);
            return d;
          }, py::arg("reference_grid") = py::none(),
          "Mass properties as Nastran's grid point weight generator prints them (mass divided by WTMASS): "
          "dict with mass, cg (basic), I_cg (about the cg, basic axes), M0 (6x6 about the reference point), "
          "reference, wtmass, principal_moments, principal_axes (columns)")
      .def("__repr__", [](const PyModel& p) {
        return "<seflex.Model '" + p.path + "': " + std::to_string(p.model.grids.size()) + " grids>";
      });

  m.def("read_model", [](const std::filesystem::path& path, const std::optional<std::vector<std::string>>& symbols,
                         const std::optional<std::filesystem::path>& properties, const std::optional<py::dict>& parameters,
                         bool ignore_unknown) {
        io::ModelReadOptions o;
        o.properties = properties;
        if (symbols)
          for (const std::string& s : *symbols) o.symbols.push_back(io::parse_nastran_symbol(s));
        if (parameters)
          for (const auto& [k, v] : *parameters) o.parameters.push_back({py::cast<std::string>(k), py::cast<double>(v)});
        auto p = std::make_unique<PyModel>();
        p->path = path.string();
        p->ignore_unknown = ignore_unknown;
        {
          py::gil_scoped_release release;
          p->model = io::read_model(path, o);
        }
        return p;
      },
      py::arg("path"), py::kw_only(), py::arg("symbols") = py::none(), py::arg("properties") = py::none(),
      py::arg("parameters") = py::none(), py::arg("ignore_unknown") = false,
      "Read a Nastran deck or a gmsh model (.msh/.geo with its property file), as the command line does.\n\n"
      "symbols: ['NAME=DIR', ...] for INCLUDE 'NAME:path' (the command's --symbol); properties: a gmsh\n"
      "model's bulk-data file (default <stem>.props.bdf); parameters: {name: value} of a .geo file (--set);\n"
      "ignore_unknown: solutions leave out the cards seflex does not know (--ignore-unknown).\n"
      "Raises seflex.InputError with the command line's message (file:line, card, field, what was expected).");

  py::class_<GridValues>(m, "GridValues", (std::string("Values per grid, ") + kComponents + ": .grids (ids), .values (n x 6), [grid_id] (6 values)").c_str())
      .def_property_readonly("grids", [](const GridValues& g) -> const Eigen::VectorXi& { return g.grids; },
                             py::return_value_policy::reference_internal, "grid ids (read-only view)")
      .def_property_readonly("values", [](const GridValues& g) -> const solutions::GridTable& { return g.values; },
                             py::return_value_policy::reference_internal, "n_grids x 6 (read-only view, owned by this object)")
      .def("__len__", [](const GridValues& g) { return g.grids.size(); })
      .def("__getitem__", [](py::object self, int grid) {
            const GridValues& g = self.cast<const GridValues&>();
            const auto it = g.row_of.find(grid);
            if (it == g.row_of.end()) throw py::key_error("no grid " + std::to_string(grid));
            py::array_t<double> row({py::ssize_t{6}}, {py::ssize_t{sizeof(double)}}, g.values.row(it->second).data(), self);
            py::detail::array_proxy(row.ptr())->flags &= ~py::detail::npy_api::NPY_ARRAY_WRITEABLE_;
            return row;
          }, py::arg("grid"), "the 6 values of a grid (read-only view)");

  py::class_<ModesResult>(m, "ModesResult", "Normal modes (SOL 103) of a model: frequencies and mode shapes")
      .def_property_readonly("eigenvalues", [](const ModesResult& r) -> const Eigen::VectorXd& { return r.r.eigenvalues; },
                             py::return_value_policy::reference_internal, "(rad/s)^2, ascending")
      .def_property_readonly("frequencies", [](const ModesResult& r) -> const Eigen::VectorXd& { return r.hz; },
                             py::return_value_policy::reference_internal, "Hz")
      .def_property_readonly("radians", [](const ModesResult& r) -> const Eigen::VectorXd& { return r.rad; },
                             py::return_value_policy::reference_internal, "rad/s")
      .def_property_readonly("generalized_mass", [](const ModesResult& r) -> const Eigen::VectorXd& { return r.r.generalized_mass; },
                             py::return_value_policy::reference_internal)
      .def_property_readonly("generalized_stiffness", [](const ModesResult& r) -> const Eigen::VectorXd& { return r.r.generalized_stiffness; },
                             py::return_value_policy::reference_internal)
      .def_property_readonly("grids", [](const ModesResult& r) -> const Eigen::VectorXi& { return r.grids; },
                             py::return_value_policy::reference_internal, "grid ids, the second axis of shapes")
      .def_property_readonly("shapes", [](py::object self) {
            const ModesResult& r = self.cast<const ModesResult&>();
            const py::ssize_t modes = r.r.eigenvalues.size(), n = r.grids.size(), d = sizeof(double);
            py::array_t<double> a({modes, n, py::ssize_t{6}}, {n * 6 * d, 6 * d, d}, r.shapes.data(), self);
            py::detail::array_proxy(a.ptr())->flags &= ~py::detail::npy_api::NPY_ARRAY_WRITEABLE_;
            return a;
          }, (std::string("modes x grids x 6, ") + kComponents + ", normalised as the deck asks (read-only view)").c_str())
      .def_property_readonly("subcase", [](const ModesResult& r) { return r.r.selection.subcase_id; }, "0: the global selections")
      .def_readonly("warnings", &ModesResult::warnings, "the warnings the command prints (cards unused or approximated)")
      .def("__len__", [](const ModesResult& r) { return r.r.eigenvalues.size(); });

  m.def("modes", [](const PyModel& p, std::optional<int> count, std::optional<int> subcase) {
        solutions::ModesOptions o;
        o.count = count;
        o.subcase = subcase;
        o.ignore_unknown_cards = p.ignore_unknown;
        if (count && *count < 1) throw InputError("count must be at least 1, got " + std::to_string(*count));
        auto r = std::make_unique<ModesResult>();
        {
          py::gil_scoped_release release;
          r->r = solutions::solve_normal_modes(p.model, o);
          r->warnings = card_warnings(p.model, solutions::check_card_usage(p.model, solutions::Solution::NormalModes,
                                                                          {r->r.selection}, solutions::kInterfaceNone, o.ignore_unknown_cards));
          r->hz = r->r.cycles();
          r->rad = r->r.radians();
          r->grids = grid_ids(p.model);
          const Eigen::Index nm = r->r.eigenvalues.size(), n = r->grids.size();
          r->shapes.resize(static_cast<std::size_t>(nm * n * 6));
          for (Eigen::Index k = 0; k < nm; ++k) {
            const solutions::GridTable t = solutions::grid_vectors_basic(p.model, r->r.dofs, r->r.shapes_g.col(k));
            std::copy(t.data(), t.data() + t.size(), r->shapes.data() + k * n * 6);
          }
        }
        return r;
      },
      py::arg("model"), py::arg("count") = py::none(), py::kw_only(), py::arg("subcase") = py::none(),
      "Normal modes (SOL 103), as `seflex modes`: count overrides the EIGRL's ND (and lifts the need for a\n"
      "METHOD); subcase defaults to the first. Raises seflex.InputError, seflex.ConvergenceError.");

  py::class_<StaticResult>(m, "StaticResult", "Linear statics (SOL 101) of one subcase")
      .def_readonly("subcase", &StaticResult::subcase)
      .def_readonly("displacements", &StaticResult::displacements, "GridValues (basic axes)")
      .def_readonly("loads", &StaticResult::loads, "GridValues of the applied loads")
      .def_readonly("spc_forces", &StaticResult::spc_forces, "GridValues of the forces of single-point constraint")
      .def_readonly("backward_error", &StaticResult::backward_error)
      .def_readonly("warnings", &StaticResult::warnings);

  m.def("static", [](const PyModel& p, std::optional<int> subcase) {
        solutions::StaticOptions o;
        o.subcase = subcase;
        o.ignore_unknown_cards = p.ignore_unknown;
        std::unique_ptr<StaticResult> r;
        {
          py::gil_scoped_release release;
          const solutions::StaticSolution s = solutions::solve_static(p.model, o);
          r.reset(new StaticResult{s.selection.subcase_id, s.backward_error,
                                   GridValues(p.model, solutions::grid_vectors_basic(p.model, s.dofs, s.u_g)),
                                   GridValues(p.model, solutions::grid_vectors_basic(p.model, s.dofs, s.p_g)),
                                   GridValues(p.model, solutions::grid_vectors_basic(p.model, s.dofs, s.q_g)),
                                   card_warnings(p.model, solutions::check_card_usage(p.model, solutions::Solution::Statics,
                                                                                      {s.selection}, solutions::kInterfaceNone,
                                                                                      o.ignore_unknown_cards))});
        }
        return r;
      },
      py::arg("model"), py::kw_only(), py::arg("subcase") = py::none(),
      "Linear statics (SOL 101) of one subcase (default the first), as `seflex static`. Raises seflex.InputError.");
}

}  // namespace seflex::python
