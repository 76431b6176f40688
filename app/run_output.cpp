#include "app/run_output.hpp"

#include "fem/stress.hpp"
#include "fem/hex8_element.hpp"
#include "fem/loads.hpp"
#include "io/atomic_file.hpp"

#include <cstdio>
#include <sstream>

namespace feticon::app
{
void write_step_vtu(const std::filesystem::path& path, const fem::Problem& problem,
                    const nonlinear::ContactSolution& solution, fem::Kinematics kinematics)
{
  const mesh::HexMesh& mesh = problem.mesh;
  io::VtuField displacement{"displacement", 3, std::vector<double>(solution.u.data(),
                                                                   solution.u.data() + solution.u.size())};
  const auto stresses = fem::cell_cauchy_stresses(mesh, solution.u, problem.materials, kinematics);
  io::VtuField cauchy{"cauchy_stress", 6, {}}, mises{"von_mises", 1, {}};
  for (const auto& s : stresses)
  {
    // VTK's symmetric tensor order: xx, yy, zz, xy, yz, xz (feticon Voigt: 11,22,33,12,23,31).
    for (int k = 0; k < 6; ++k)
      cauchy.values.push_back(s(k));
    mises.values.push_back(fem::von_mises(s));
  }
  io::VtuField pressure{"contact_pressure", 1, std::vector<double>(mesh.n_nodes(), 0.0)};
  if (!problem.contacts.empty() && solution.contact_lambda.size() > 0)
  {
    // Per node force over the node's own tributary area (not grouped by x).
    la::Vector area = la::Vector::Zero(3 * mesh.n_nodes());
    fem::add_face_traction(mesh, mesh.face_set(problem.contacts[0].slave), Eigen::Vector3d(1, 0, 0), area);
    const auto& rows = solution.constraints;
    for (size_t i = 0; i < rows.slave_node.size(); ++i)
    {
      const int32_t node = rows.slave_node[i];
      if (area(3 * node) > 0)
        pressure.values[node] += solution.contact_lambda(static_cast<la::Index>(i)) /
                                 rows.row_norm[i] / area(3 * node);
    }
  }
  if (kinematics == fem::Kinematics::total_lagrangian)
  {
    io::PointMatrix x = mesh.nodes;
    for (int32_t n = 0; n < mesh.n_nodes(); ++n)
      x.row(n) += solution.u.segment<3>(3 * n).transpose();
    const Eigen::Ref<const io::PointMatrix> ref(x);
    io::write_vtu(path, mesh, &ref, {displacement, pressure}, {cauchy, mises});
  }
  else
    io::write_vtu(path, mesh, nullptr, {displacement, pressure}, {cauchy, mises});
}

void write_pressure_csv(const std::filesystem::path& path,
                        const std::vector<nonlinear::PressureSample>& samples)
{
  std::ostringstream os;
  os << "x_m,force_N,area_m2,pressure_multipliers_Pa,pressure_stress_Pa,pressure_mcewen_Pa\n";
  char line[256];
  for (const auto& s : samples)
  {
    std::snprintf(line, sizeof line, "%.9e,%.9e,%.9e,%.9e,%.9e,%.9e\n", s.x, s.force, s.area,
                  s.pressure, s.stress_pressure, s.analytic);
    os << line;
  }
  io::write_file_atomically(path, os.str());
}

void write_history_csv(const std::filesystem::path& path,
                       const std::vector<nonlinear::OuterIteration>& history)
{
  std::ostringstream os;
  os << "load_step,outer_iteration,mprgp_iterations,hessian_multiplications,smalbe_outer,"
        "residual_norm,displacement_change,active_contacts,feasibility_error,seconds\n";
  for (const auto& it : history)
    os << it.load_step << ',' << it.iteration << ',' << it.qp_iterations << ','
       << it.hessian_multiplications << ',' << it.smalbe_outer << ',' << it.residual_norm << ','
       << it.displacement_change << ',' << it.active_contacts << ',' << it.feasibility_error << ','
       << it.seconds << '\n';
  io::write_file_atomically(path, os.str());
}

void write_json(const std::filesystem::path& path, const nlohmann::ordered_json& json)
{
  io::write_file_atomically(path, json.dump(2) + "\n");
}
} // namespace feticon::app
