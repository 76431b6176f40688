/// The Python module's compiled part, `feticon._feticon`: one function that runs a problem
/// through app::run_problem on one rank and returns its results as a dict of Python objects
/// and NumPy arrays. python/feticon/__init__.py wraps it (feticon.run).

#include "app/run.hpp"
#include "common/error.hpp"
#include "fem/hex8_element.hpp"
#include "fem/stress.hpp"

#include <pybind11/numpy.h>
#include <pybind11/pybind11.h>
#include <pybind11/stl.h>

#include <optional>
#include <string>
#include <vector>

namespace py = pybind11;
using namespace feticon;

namespace
{
/// A rows x columns array of doubles filled by value(row, column).
template <typename Value>
py::array_t<double> table(py::ssize_t rows, py::ssize_t columns, const Value& value)
{
  py::array_t<double> array({rows, columns});
  auto view = array.mutable_unchecked<2>();
  for (py::ssize_t r = 0; r < rows; ++r)
    for (py::ssize_t c = 0; c < columns; ++c)
      view(r, c) = value(r, c);
  return array;
}

/// The contact pressure samples as columns (contact_pressure.csv's).
py::dict contact_columns(const std::vector<nonlinear::PressureSample>& samples)
{
  const auto n = static_cast<py::ssize_t>(samples.size());
  py::array_t<int32_t> pair(n);
  py::array_t<double> x(n), y(n), z(n), force(n), area(n), pressure(n), stress_pressure(n);
  for (py::ssize_t i = 0; i < n; ++i)
  {
    const nonlinear::PressureSample& s = samples[i];
    pair.mutable_at(i) = s.pair;
    x.mutable_at(i) = s.x;
    y.mutable_at(i) = s.y;
    z.mutable_at(i) = s.z;
    force.mutable_at(i) = s.force;
    area.mutable_at(i) = s.area;
    pressure.mutable_at(i) = s.pressure;
    stress_pressure.mutable_at(i) = s.stress_pressure;
  }
  py::dict columns;
  columns["pair"] = pair;
  columns["x"] = x;
  columns["y"] = y;
  columns["z"] = z;
  columns["normal_force"] = force;
  columns["area"] = area;
  columns["pressure"] = pressure;
  columns["pressure_from_stress"] = stress_pressure;
  return columns;
}

py::dict run(const std::string& problem_file, const std::optional<std::string>& problem_text,
             const std::vector<std::string>& overrides, const std::string& output, bool quiet, bool verbose,
             bool overwrite)
{
  app::RunOptions options;
  options.problem_file = problem_file;
  options.problem_text = problem_text;
  options.overrides = overrides;
  options.output = output;
  options.quiet = quiet;
  options.verbose = verbose;
  options.overwrite = overwrite;
  app::RunResult result;
  std::vector<Eigen::Matrix<double, 6, 1>> stresses;
  {
    py::gil_scoped_release free_python; // the solve touches no Python object
    result = app::run_problem(options);
    stresses = fem::cell_cauchy_stresses(result.problem->mesh, result.solution.u, result.problem->materials,
                                         result.kinematics);
  }
  const mesh::Mesh& mesh = result.problem->mesh;
  const la::Vector& u = result.solution.u;
  const auto n_nodes = static_cast<py::ssize_t>(mesh.n_nodes());
  const auto n_cells = static_cast<py::ssize_t>(stresses.size());
  py::dict out;
  out["summary"] = result.summary.dump();
  out["coordinates"] = table(n_nodes, 3, [&](py::ssize_t n, py::ssize_t c) { return mesh.nodes(n, c); });
  out["displacements"] = table(n_nodes, 3, [&](py::ssize_t n, py::ssize_t c) { return u[3 * n + c]; });
  out["cell_stress"] = table(n_cells, 6, [&](py::ssize_t e, py::ssize_t c) { return stresses[e][c]; });
  out["von_mises"] = table(n_cells, 1, [&](py::ssize_t e, py::ssize_t) { return fem::von_mises(stresses[e]); });
  out["contact"] = contact_columns(result.pressures);
  return out;
}
} // namespace

PYBIND11_MODULE(_feticon, m)
{
  m.doc() = "feticon's solver (use the feticon package's run())";
  py::register_exception<feticon::Error>(m, "Error", PyExc_RuntimeError);
  m.def("run", &run, py::arg("problem_file"), py::arg("problem_text"), py::arg("overrides"), py::arg("output"),
        py::arg("quiet"), py::arg("verbose"), py::arg("overwrite"));
}
