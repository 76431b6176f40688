#include "nonlinear/contact_pressure.hpp"

#include "common/error.hpp"
#include "contact/contact_constraints.hpp"
#include "contact/tangential_rows.hpp"
#include "fem/loads.hpp"
#include "fem/reference_face.hpp"
#include "fem/stress.hpp"

#include <algorithm>
#include <cmath>
#include <map>
#include <optional>
#include <set>
#include <tuple>
#include <unordered_map>

namespace feticon::nonlinear
{
std::vector<double> row_pressure_per_node(const ContactSolution& solution, int32_t n_nodes)
{
  std::vector<double> pressure(n_nodes, 0.0);
  const auto& rows = solution.constraints;
  for (la::Index i = 0; i < solution.contact_lambda.size(); ++i)
    if (rows.slave_area[i] > 0)
      pressure[rows.slave_node[i]] += solution.contact_lambda(i) / rows.row_norm[i] / rows.slave_area[i];
  return pressure;
}

double total_normal_force(const ContactSolution& solution, int32_t pair)
{
  double total = 0;
  for (la::Index i = 0; i < solution.contact_lambda.size(); ++i)
    if (pair < 0 || solution.constraints.pair[i] == pair)
      total += solution.contact_lambda(i) / solution.constraints.row_norm[i] * solution.constraints.master_share[i];
  return total;
}

ContactSolution pair_solution(const ContactSolution& solution, int32_t p)
{
  ContactSolution out;
  out.u = solution.u;
  // The stress column of the pressures needs the body's state as the whole solution has it.
  out.temperature_change = solution.temperature_change;
  out.plastic = solution.plastic;
  const contact::ContactConstraints& rows = solution.constraints;
  out.constraints = contact::pair_rows(rows, p);
  out.contact_lambda.resize(out.constraints.n_rows());
  for (la::Index i = 0, k = 0; i < rows.n_rows(); ++i)
    if (rows.pair[i] == p)
      out.contact_lambda(k++) = solution.contact_lambda(i);
  out.tangential = contact::pair_rows(solution.tangential, p, solution.tangential_lambda, out.tangential_lambda);
  return out;
}

namespace
{
/// `solution` if all its rows are pair p's (one pair, or a solution pair_solution made), else
/// pair_solution of it in `storage`.
const ContactSolution& rows_of_pair(const ContactSolution& solution, int32_t p, std::optional<ContactSolution>& storage)
{
  if (std::ranges::all_of(solution.constraints.pair, [p](int32_t q) { return q == p; }))
    return solution;
  return storage.emplace(pair_solution(solution, p));
}
} // namespace

namespace
{
/// The slave surface in the configuration of the kinematics (see slave_tributary_areas).
mesh::Mesh pressure_surface(const fem::Problem& problem, const la::Vector& u, fem::Kinematics kinematics)
{
  mesh::Mesh surface = problem.mesh;
  if (kinematics == fem::Kinematics::total_lagrangian)
    for (int32_t n = 0; n < surface.n_nodes(); ++n)
      surface.nodes.row(n) += u.segment<3>(3 * n).transpose();
  return surface;
}

} // namespace

la::Vector slave_tributary_areas(const fem::Problem& problem, const la::Vector& u, fem::Kinematics kinematics,
                                 int32_t pair)
{
  // The x-component of the consistent load of a unit x-traction, on the surface the kinematics
  // has: the small-strain model has no deformed surface (dividing by it put the surface strain,
  // ~0.9 % at the Hertz centre, into the pressure).
  const mesh::Mesh surface = pressure_surface(problem, u, kinematics);
  // Quadratic faces' consistent loads vanish at corners (tri6): theirs are lumped from linear
  // sub-facets (contact/face_geometry.hpp), so that every slave node has a positive area.
  std::vector<mesh::Face> quad4, others;
  for (const mesh::Face& face : surface.face_set(problem.contacts[pair].slave))
    (face.kind == mesh::FaceKind::quad4 ? quad4 : others).push_back(face);
  la::Vector load = la::Vector::Zero(3 * surface.n_nodes());
  fem::add_face_traction(surface, quad4, Eigen::Vector3d(1, 0, 0), load);
  la::Vector areas(surface.n_nodes());
  for (int32_t n = 0; n < surface.n_nodes(); ++n)
    areas(n) = load(3 * n);
  for (const mesh::Face& face : others)
  {
    const Eigen::VectorXd lumped = contact::face_lumped_areas(contact::current_face_geometry(surface, {}, face));
    for (int a = 0; a < face.size(); ++a)
      areas(face[a]) += lumped(a);
  }
  return areas;
}

namespace
{
/// Face-averaged pressures at the nodes of the quadratic slave faces (slave_nodal_pressures),
/// written into `pressure` at those nodes.
void average_quadratic_face_pressures(const mesh::Mesh& surface, const std::vector<mesh::Face>& faces,
                                      const la::Vector& nodal_force, la::Vector& pressure)
{
  // Each node's force goes to its faces in proportion to its lumped area in each.
  std::vector<Eigen::VectorXd> lumped;
  std::map<int32_t, double> node_area;
  for (const mesh::Face& face : faces)
  {
    lumped.push_back(contact::face_lumped_areas(contact::current_face_geometry(surface, {}, face)));
    for (int a = 0; a < face.size(); ++a)
      node_area[face[a]] += lumped.back()(a);
  }
  std::map<int32_t, std::pair<double, double>> force_and_area; // over the faces around each node
  for (size_t f = 0; f < faces.size(); ++f)
  {
    double face_force = 0;
    for (int a = 0; a < faces[f].size(); ++a)
      face_force += nodal_force(faces[f][a]) * lumped[f](a) / node_area.at(faces[f][a]);
    for (int a = 0; a < faces[f].size(); ++a)
    {
      auto& [force, area] = force_and_area[faces[f][a]];
      force += face_force;
      area += lumped[f].sum();
    }
  }
  for (const auto& [node, force_area] : force_and_area)
    pressure(node) = force_area.first / force_area.second;
}
} // namespace

la::Vector slave_nodal_pressures(const fem::Problem& problem, const ContactSolution& all_pairs,
                                 fem::Kinematics kinematics, int32_t pair)
{
  std::optional<ContactSolution> storage;
  const ContactSolution& solution = rows_of_pair(all_pairs, pair, storage);
  const auto& rows = solution.constraints;
  la::Vector force = la::Vector::Zero(problem.mesh.n_nodes());
  for (size_t i = 0; i < rows.slave_node.size(); ++i)
    force(rows.slave_node[i]) += solution.contact_lambda(static_cast<la::Index>(i)) / rows.row_norm[i];
  const la::Vector areas = slave_tributary_areas(problem, solution.u, kinematics, pair);
  la::Vector pressure = la::Vector::Zero(problem.mesh.n_nodes());
  for (int32_t n = 0; n < problem.mesh.n_nodes(); ++n)
    pressure(n) = areas(n) > 0 ? force(n) / areas(n) : 0.0;
  std::vector<mesh::Face> quadratic;
  for (const mesh::Face& face : problem.mesh.face_set(problem.contacts[pair].slave))
    if (face.kind == mesh::FaceKind::tri6 || face.kind == mesh::FaceKind::quad8)
      quadratic.push_back(face);
  if (!quadratic.empty() && rows.formulation == contact::ContactFormulation::mortar)
  {
    // The dual traction's nodal values z_j = force / D~_j (mortar_constraints.hpp): the
    // pressure at every node, corners included, as the runs' VTU writes it.
    for (size_t i = 0; i < rows.slave_node.size(); ++i)
      pressure(rows.slave_node[i]) =
          solution.contact_lambda(static_cast<la::Index>(i)) / rows.row_norm[i] / rows.slave_area[i];
  }
  else if (!quadratic.empty())
    average_quadratic_face_pressures(pressure_surface(problem, solution.u, kinematics), quadratic, force, pressure);
  return pressure;
}

namespace
{
/// With mortar rows on quadratic faces the shear is the dual traction's nodal value as the
/// pressure is (force / D~_j per row), not the nodal force over the lumped area: the nodal
/// forces of a transformed basis are consistent loads, of either sign at the corners. The
/// tangential rows are matched to the normal rows by slave node (a tangential row has its
/// normal row's weights and norm |b|).
std::unordered_map<int32_t, Eigen::Vector3d> dual_traction_shear(const ContactSolution& solution)
{
  const auto& rows = solution.constraints;
  std::unordered_map<int32_t, double> norm_times_area;
  for (size_t i = 0; i < rows.slave_node.size(); ++i)
    norm_times_area[rows.slave_node[i]] = rows.row_norm[i] * rows.slave_area[i];
  std::unordered_map<int32_t, Eigen::Vector3d> shear;
  for (la::Index r = 0; r < solution.tangential_lambda.size(); ++r)
    if (const auto it = norm_times_area.find(solution.tangential.slave_node[r]); it != norm_times_area.end())
      shear[it->first] += solution.tangential_lambda(r) / it->second * solution.tangential.tangent[r];
  return shear;
}
} // namespace

std::vector<PressureSample> slave_pressure_by_x(const fem::Problem& problem, const ContactSolution& all_pairs,
                                                fem::Kinematics kinematics, const Friction& friction,
                                                int32_t pair_index)
{
  std::optional<ContactSolution> storage;
  const ContactSolution& solution = rows_of_pair(all_pairs, pair_index, storage);
  const auto& rows = solution.constraints;
  FETICON_CHECK(static_cast<la::Index>(rows.slave_node.size()) == solution.contact_lambda.size(),
                "contact multipliers do not match the contact rows");
  const la::Vector tributary = slave_tributary_areas(problem, solution.u, kinematics, pair_index);

  const auto stresses =
      fem::nodal_average(problem.mesh,
                         fem::cell_cauchy_stresses(problem.mesh, solution.u, problem.materials, kinematics,
                                                   solution.temperature_change, &solution.plastic));

  // Plane strain on a hex layer: the nodes of a line through the thickness (same reference x)
  // form one sample; in 3D and on 2D cells every node is its own sample.
  const bool plane_strain = problem.eliminated[2] && problem.mesh.planar.kind == mesh::PlanarKind::none;
  const double key_scale = 1e9; // nm resolution groups nodes through the thickness
  auto key_of = [&](int32_t node) {
    const auto& X = problem.mesh.nodes;
    return plane_strain ? std::make_tuple(std::lround(X(node, 0) * key_scale), 0L, 0L, 0)
                        : std::make_tuple(std::lround(X(node, 0) * key_scale), std::lround(X(node, 1) * key_scale),
                                          std::lround(X(node, 2) * key_scale), node);
  };
  std::map<std::tuple<long, long, long, int32_t>, PressureSample> by_x;
  std::map<std::tuple<long, long, long, int32_t>, int> nodes_in_sample, rows_in_sample;
  const fem::ContactPairNames& pair = problem.contacts[pair_index];
  for (int32_t node : contact::slave_nodes(problem.mesh, {pair.slave, pair.master, pair.slave_nodes}))
  {
    const auto key = key_of(node);
    auto& s = by_x[key];
    if (nodes_in_sample[key]++ == 0)
    {
      s.x = problem.mesh.nodes(node, 0);
      s.y = problem.mesh.nodes(node, 1);
      s.z = problem.mesh.nodes(node, 2);
    }
    s.area += tributary(node);
    s.deformed_x += problem.mesh.nodes(node, 0) + solution.u(3 * node);
    s.deformed_y += problem.mesh.nodes(node, 1) + solution.u(3 * node + 1);
  }
  for (size_t i = 0; i < rows.slave_node.size(); ++i)
  {
    const int32_t node = rows.slave_node[i];
    const auto key = key_of(node);
    auto& s = by_x[key];
    ++rows_in_sample[key];
    const double force = solution.contact_lambda(static_cast<la::Index>(i)) / rows.row_norm[i];
    const Eigen::Vector3d& n = rows.normal[i];
    s.force += force;
    s.normal_force += force * n;
    const auto& v = stresses[node];
    Eigen::Matrix3d sigma;
    sigma << v(0), v(3), v(5), v(3), v(1), v(4), v(5), v(4), v(2);
    // Average over the nodes of the line (weights: equal).
    s.stress_pressure += -n.dot(sigma * n);
  }
  if (solution.tangential_lambda.size() > 0)
  {
    const la::Vector f_T =
        contact::tangential_forces(solution.tangential, solution.tangential_lambda, 3 * problem.mesh.n_nodes());
    for (const int32_t node :
         std::set<int32_t>(solution.tangential.slave_node.begin(), solution.tangential.slave_node.end()))
      by_x[key_of(node)].friction_force += f_T.segment<3>(3 * node);
  }
  // 3D samples are nodes: those of quadratic faces take the L2 projection.
  std::optional<la::Vector> quadratic_pressure;
  if (!plane_strain && std::ranges::any_of(problem.mesh.face_set(pair.slave), [](const mesh::Face& f) {
        return f.kind == mesh::FaceKind::tri6 || f.kind == mesh::FaceKind::quad8;
      }))
    quadratic_pressure = slave_nodal_pressures(problem, solution, kinematics, pair_index);
  std::unordered_map<int32_t, Eigen::Vector3d> dual_shear;
  if (quadratic_pressure && rows.formulation == contact::ContactFormulation::mortar)
    dual_shear = dual_traction_shear(solution);
  std::vector<PressureSample> out;
  for (auto& [key, s] : by_x)
  {
    s.pair = pair_index;
    s.deformed_x /= nodes_in_sample[key];
    s.deformed_y /= nodes_in_sample[key];
    if (rows_in_sample[key] > 0)
      s.stress_pressure /= rows_in_sample[key];
    s.pressure = s.area > 0 ? s.force / s.area : 0;
    if (quadratic_pressure)
      s.pressure = (*quadratic_pressure)(std::get<3>(key));
    s.shear = s.area > 0 ? Eigen::Vector3d(s.friction_force / s.area) : Eigen::Vector3d::Zero();
    const double bound = friction.model == FrictionModel::tresca ? friction.slip_bound * s.area
        : friction.model == FrictionModel::coulomb               ? friction.coefficient * std::max(s.force, 0.0)
                                                                 : 0.0;
    s.slipping = bound > 0 && s.friction_force.norm() >= (1 - 1e-5) * bound;
    if (const auto it = dual_shear.find(std::get<3>(key)); it != dual_shear.end())
    {
      s.shear = it->second;
      const double traction_bound = friction.model == FrictionModel::tresca ? friction.slip_bound
          : friction.model == FrictionModel::coulomb ? friction.coefficient * std::max(s.pressure, 0.0)
                                                     : 0.0;
      s.slipping = traction_bound > 0 && s.shear.norm() >= (1 - 1e-5) * traction_bound;
    }
    out.push_back(s);
  }
  return out;
}

} // namespace feticon::nonlinear
