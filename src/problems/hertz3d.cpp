#include "problems/hertz3d.hpp"

#include "common/error.hpp"
#include "fem/loads.hpp"
#include "mesh/cell_conversion.hpp"
#include "mesh/gmsh_module.hpp"
#include "mesh/octant_ball.hpp"

#include <algorithm>
#include <cmath>
#include <numbers>

namespace feticon::problems
{
namespace
{
/// Appends `ball` as body `body` of `mesh`, each local node (x, y, d) placed by `place`;
/// `reflect` when `place` reverses the orientation (then cells and faces are reordered so
/// that they stay positive and outward).
template <class Place>
void append_body(mesh::Mesh& mesh, const mesh::OctantBall& ball, const std::string& name, bool reflect, Place place,
                 const std::string& flat_set, const std::string& outer_set)
{
  const int32_t offset = mesh.n_nodes();
  const int32_t body = mesh.n_bodies();
  mesh.body_names.push_back(name);
  mesh.nodes.conservativeResize(offset + ball.nodes.rows(), 3);
  for (Eigen::Index i = 0; i < ball.nodes.rows(); ++i)
    mesh.nodes.row(offset + i) = place(Eigen::Vector3d(ball.nodes.row(i))).transpose();
  for (const mesh::Hex8Nodes& c : ball.cells)
  {
    mesh::Hex8Nodes cell;
    for (int k = 0; k < 8; ++k)
      cell[k] = offset + c[reflect ? (k + 4) % 8 : k];
    mesh.cells.add(mesh::CellKind::hex8, cell);
    mesh.cell_body.push_back(body);
  }
  auto add_faces = [&](const std::vector<mesh::Face>& faces, const std::string& set) {
    auto& out = mesh.face_sets[set];
    for (const mesh::Face& f : faces)
      out.push_back(reflect ? mesh::Face{offset + f[0], offset + f[3], offset + f[2], offset + f[1]}
                            : mesh::Face{offset + f[0], offset + f[1], offset + f[2], offset + f[3]});
  };
  add_faces(ball.flat, flat_set);
  add_faces(ball.outer, outer_set);
  if (!ball.symmetry_x.empty())
    add_faces(ball.symmetry_x, "symmetry_x");
  add_faces(ball.symmetry_y, "symmetry_y");
}
/// Tributary areas of the sphere's loaded face: the consistent nodal load of a unit traction
/// in z (3 entries per node, the z entry holds the area).
la::Vector load_face_weights(const mesh::Mesh& mesh)
{
  la::Vector weights = la::Vector::Zero(3 * static_cast<la::Index>(mesh.n_nodes()));
  fem::add_face_traction(mesh, mesh.face_set("sphere_load"), Eigen::Vector3d(0, 0, 1), weights);
  return weights;
}

/// Cattaneo and Mindlin's tangential load acts in the contact plane; ours, the traction
/// `traction_x` on the sphere's far face (consistent nodal forces traction_x w_i, w_i the
/// face's `weights`), has the moment sum_i z_i traction_x w_i about the contact point, which
/// the contact would take as a tilted pressure. Nodal forces f_z = k x_i w_i (a normal traction
/// k x) cancel it exactly: k sum_i x_i^2 w_i equals that moment, and their resultant
/// k sum_i x_i w_i vanishes on the face, symmetric across x = 0 (the 2D model's
/// moment_free_couple, hertz.cpp).
std::vector<fem::NodalForce> moment_free_couple(const mesh::Mesh& mesh, const la::Vector& weights, double traction_x)
{
  double moment = 0, second_moment = 0;
  for (int32_t n = 0; n < mesh.n_nodes(); ++n)
  {
    moment += mesh.nodes(n, 2) * traction_x * weights(3 * n + 2);
    second_moment += mesh.nodes(n, 0) * mesh.nodes(n, 0) * weights(3 * n + 2);
  }
  const double k = moment / second_moment;
  std::vector<fem::NodalForce> out;
  for (int32_t n = 0; n < mesh.n_nodes(); ++n)
    if (weights(3 * n + 2) != 0)
      out.push_back({n, 2, k * mesh.nodes(n, 0) * weights(3 * n + 2)});
  return out;
}
} // namespace

double hertz3d_approach(const fem::Problem& problem, const la::Vector& u)
{
  const la::Vector weights = load_face_weights(problem.mesh);
  double sum = 0, area = 0;
  for (la::Index n = 0; 3 * n < u.size(); ++n)
    sum -= weights(3 * n + 2) * u(3 * n + 2), area += weights(3 * n + 2);
  return sum / area;
}

Hertz3dAnalytic hertz3d_analytic(const Hertz3dParameters& parameters)
{
  Hertz3dAnalytic h;
  h.effective_modulus = fem::contact_modulus(parameters.material, parameters.block());
  h.contact_radius = std::cbrt(3 * parameters.load * parameters.radius / (4 * h.effective_modulus));
  h.peak_pressure = 3 * parameters.load / (2 * M_PI * h.contact_radius * h.contact_radius);
  h.approach = h.contact_radius * h.contact_radius / parameters.radius;
  return h;
}

double Hertz3dAnalytic::pressure(double r) const
{
  const double q = r / contact_radius;
  return q < 1 ? peak_pressure * std::sqrt(1 - q * q) : 0.0;
}

namespace
{
/// The two octant balls of the hertz3d mesh (sphere, block), after checking the parameters.
std::pair<mesh::OctantBallParameters, mesh::OctantBallParameters> octant_balls(const Hertz3dParameters& parameters)
{
  const double R = parameters.radius;
  FETICON_CHECK(std::isfinite(R) && R > 0, "hertz3d: radius = " << R << " m must be positive");
  FETICON_CHECK(std::isfinite(parameters.load) && parameters.load > 0,
                "hertz3d: load = " << parameters.load << " N must be positive");
  // Beyond R / 2 the lift onto the sphere shears the rim's cells past aspect ratio 3 (5.6 at
  // 0.8 R), and the Hertz figures do not need it (0.25 R and 0.5 R agree to 0.1 % of p0).
  FETICON_CHECK(parameters.cap_radius > 0 && parameters.cap_radius <= 0.5 * R,
                "hertz3d: cap_radius = " << parameters.cap_radius << " m must be in (0, radius / 2 = " << 0.5 * R
                                         << " m]");
  const Hertz3dAnalytic analytic = hertz3d_analytic(parameters);
  const double h = parameters.element_size / parameters.refinement;
  // The uniform core covers the contact zone with a margin: 1.25 a, in whole cells.
  const int slave_cells = static_cast<int>(std::ceil(1.25 * analytic.contact_radius / h - 1e-9));
  const double h_master = parameters.master_ratio * h;
  const int master_cells = static_cast<int>(std::ceil(slave_cells * h / h_master - 1e-9));
  FETICON_CHECK(slave_cells <= 400,
                "hertz3d: " << slave_cells << " core cells per edge (contact radius " << analytic.contact_radius
                            << " m over element size " << h << " m) is more than 400; lower hertz3d.refinement");
  const double core = std::max(slave_cells * h, master_cells * h_master);
  FETICON_CHECK(parameters.cap_radius >= 2.5 * core && parameters.block_radius >= 2.5 * core,
                "hertz3d: cap_radius and block_radius must be at least 2.5 times the contact core width "
                    << core << " m (1.25 contact radii)");
  return {{h, slave_cells, parameters.cap_radius, parameters.radial_aspect},
          {h_master, master_cells, parameters.block_radius, parameters.radial_aspect}};
}

/// The sizes of the Gmsh mesh (gmsh_mesh).
mesh::SphereOnHalfSpace gmsh_geometry(const Hertz3dParameters& parameters)
{
  mesh::SphereOnHalfSpace g;
  g.radius = parameters.radius;
  g.cap_radius = parameters.cap_radius;
  g.block_radius = parameters.block_radius;
  g.order = parameters.cell == mesh::CellKind::tet10 ? 2 : 1;
  g.size = g.order * parameters.element_size / parameters.refinement;
  g.core = 1.25 * hertz3d_analytic(parameters).contact_radius;
  g.growth = parameters.gmsh_growth;
  g.max_size = std::max(g.size, 0.25 * parameters.cap_radius);
  return g;
}

/// Nodes of the Gmsh mesh, from the integral I of 1 / h^3 over the two bodies (each about an
/// eighth of its ball): the memory guard's input, an upper bound of what was measured at
/// gmsh_growth 1.5 (eighteenth session). Small meshes have more nodes than I says (Gmsh
/// cannot follow the size field across a few cells), hence the constant: tet10 measured
/// 3 044 to 53 863 nodes at refinements 0.7 to 4 (13.6 to 7.0 per unit of I), taken as
/// 7.6 I + 1 600 (0.4 to 12 % over); tet4 901 to 21 310 at 0.7 to 3, as 0.95 I + 500.
int64_t gmsh_node_estimate(const Hertz3dParameters& parameters)
{
  const mesh::SphereOnHalfSpace g = gmsh_geometry(parameters);
  double integral = 0;
  for (const double outer : {g.cap_radius, g.block_radius})
  {
    constexpr int n = 2000;
    const double dr = outer / n;
    for (int i = 0; i < n; ++i)
    {
      const double r = (i + 0.5) * dr;
      const double h = std::min(g.size + g.growth * std::max(0.0, r - g.core), g.max_size);
      integral += 0.5 * std::numbers::pi * r * r / (h * h * h) * dr;
    }
  }
  return std::llround(g.order == 2 ? 7.6 * integral + 1600 : 0.95 * integral + 500);
}
/// The graded octant balls of the sphere and the block (file comment), in the cells of
/// parameters.cell.
mesh::Mesh octant_mesh(const Hertz3dParameters& parameters, const mesh::OctantBallParameters& sphere_parameters,
                       const mesh::OctantBallParameters& block_parameters)
{
  const double R = parameters.radius;
  const auto ball = [&](const mesh::OctantBallParameters& b) {
    return parameters.half_model() ? mesh::mirrored_across_x(mesh::octant_ball(b)) : mesh::octant_ball(b);
  };
  const mesh::OctantBall sphere = ball(sphere_parameters);
  const mesh::OctantBall block = ball(block_parameters);

  mesh::Mesh out;
  out.nodes.resize(0, 3);
  // The sphere's flat face is lifted onto the sphere by z = d + s(rho) (1 - d / cap_radius),
  // s(rho) = R - sqrt(R^2 - rho^2): exact on the contact face, fading with depth so that the
  // shear of the map (slope s' up to 0.58 at the rim) does not stretch the interior cells;
  // dz/dd = 1 - s / cap_radius > 0 since s(rho) < rho <= cap_radius.
  const double Rc = parameters.cap_radius;
  append_body(
      out, sphere, "sphere", false,
      [R, Rc](const Eigen::Vector3d& q) {
    const double lift = R - std::sqrt(R * R - q(0) * q(0) - q(1) * q(1));
    return Eigen::Vector3d(q(0), q(1), q(2) + lift * (1 - q(2) / Rc));
      },
      "sphere_contact", "sphere_load");
  append_body(
      out, block, "block", true, [](const Eigen::Vector3d& q) { return Eigen::Vector3d(q(0), q(1), -q(2)); },
      "block_contact", "block_support");
  if (parameters.cell != mesh::CellKind::hex8)
  {
    // An edge between two nodes on the sphere |x - c| = R keeps its node on the sphere.
    const Eigen::Vector3d centre(0, 0, R);
    out = mesh::convert_hex8_mesh(out, parameters.cell, [&](const Eigen::Vector3d& a, const Eigen::Vector3d& b) {
      const Eigen::Vector3d middle = 0.5 * (a + b);
      const auto on_sphere = [&](const Eigen::Vector3d& x) { return std::abs((x - centre).norm() - R) < 1e-9 * R; };
      return on_sphere(a) && on_sphere(b) ? Eigen::Vector3d(centre + R * (middle - centre).normalized()) : middle;
    });
  }
  return out;
}

/// The sphere and the block as solids meshed by Gmsh with graded tetrahedra (gmsh_mesh).
mesh::Mesh gmsh_mesh(const Hertz3dParameters& parameters)
{
  FETICON_CHECK(parameters.cell == mesh::CellKind::tet10 || parameters.cell == mesh::CellKind::tet4,
                "hertz3d: mesh=gmsh meshes tetrahedra: set hertz3d.cell to tet10 or tet4, not "
                    << mesh::cell_type(parameters.cell).name);
  FETICON_CHECK(!parameters.half_model(),
                "hertz3d: mesh=gmsh builds the quarter model only (no tangential load "
                "or displacement)");
  mesh::Mesh out;
  const std::string failure = mesh::gmsh_module().mesh_sphere_on_half_space(gmsh_geometry(parameters), out);
  FETICON_CHECK(failure.empty(), failure);
  return out;
}

} // namespace

int64_t hertz3d_node_count(const Hertz3dParameters& parameters)
{
  const auto [sphere, block] = octant_balls(parameters); // checks the parameters
  if (parameters.gmsh_mesh)
    return gmsh_node_estimate(parameters);
  auto ball_nodes = [&](const mesh::OctantBallParameters& ball) {
    const mesh::OctantBallSize size = mesh::octant_ball_size(ball);
    return parameters.half_model() ? 2 * size.nodes - size.plane_nodes : size.nodes;
  };
  const int64_t corners = ball_nodes(sphere) + ball_nodes(block);
  // Edges per node of a hex mesh: 3; with Kuhn's tetrahedra 7 (face and cell diagonals).
  return parameters.cell == mesh::CellKind::hex20 ? 4 * corners
      : parameters.cell == mesh::CellKind::tet10  ? 8 * corners
                                                  : corners;
}

fem::Problem hertz3d_problem(const Hertz3dParameters& parameters)
{
  const auto [sphere_parameters, block_parameters] = octant_balls(parameters);
  FETICON_CHECK(std::isfinite(parameters.tangential_load) && parameters.tangential_load >= 0,
                "hertz3d: tangential_load = " << parameters.tangential_load << " N must be >= 0");
  FETICON_CHECK(std::isfinite(parameters.tangential_displacement) && parameters.tangential_displacement >= 0,
                "hertz3d: tangential_displacement = " << parameters.tangential_displacement << " m must be >= 0");
  const bool slid = parameters.tangential_displacement > 0;
  FETICON_CHECK(!(slid && parameters.tangential_load > 0),
                "hertz3d: give a tangential load or a tangential displacement, not both");
  FETICON_CHECK(!slid || parameters.friction_coefficient > 0,
                "hertz3d: a tangential displacement needs Coulomb friction (its couple balances the full "
                "slide's force mu F)");
  fem::Problem p;
  p.name = "hertz3d";
  if (parameters.gmsh_mesh)
    p.mesh = gmsh_mesh(parameters);
  else
    p.mesh = octant_mesh(parameters, sphere_parameters, block_parameters);
  for (const auto& [name, faces] : p.mesh.face_sets)
    p.mesh.add_node_set_from_faces(name, name);

  p.materials = {parameters.material, parameters.block()}; // bodies "sphere", "block"
  fem::Step& pressed = p.steps.front();
  pressed.dirichlet = {
      {"symmetry_y", {std::nullopt, 0.0, std::nullopt}},
      {"block_support", {0.0, 0.0, 0.0}},
  };
  if (!parameters.half_model())
    pressed.dirichlet.insert(pressed.dirichlet.begin(), {"symmetry_x", {0.0, std::nullopt, std::nullopt}});
  if (slid) // held along x while pressed, then moved
    pressed.dirichlet.push_back({"sphere_load", {0.0, std::nullopt, std::nullopt}});
  // A downward traction on the sphere's far face with resultant F / 4 (F / 2): its area from
  // the consistent load of a unit traction, so the resultant is exact for the discrete face.
  const la::Vector weights = load_face_weights(p.mesh);
  double area = 0;
  for (int32_t n = 0; n < p.mesh.n_nodes(); ++n)
    area += weights(3 * n + 2);
  const double normal = parameters.modelled() * parameters.load / area;
  pressed.tractions = {{"sphere_load", Eigen::Vector3d(0, 0, -normal)}};
  if (slid)
  {
    fem::Step sliding;
    sliding.dirichlet = pressed.dirichlet;
    sliding.dirichlet.back() = {"sphere_load", {parameters.tangential_displacement, std::nullopt, std::nullopt}};
    sliding.tractions = {{"sphere_load", Eigen::Vector3d(0, 0, -normal)}};
    sliding.nodal_forces = moment_free_couple(
        p.mesh, weights, parameters.modelled() * parameters.friction_coefficient * parameters.load / area);
    sliding.increments = 1;
    p.steps.push_back(std::move(sliding));
  }
  else if (parameters.half_model()) // a second step: the normal load held, the tangential one added
  {
    fem::Step pulling;
    pulling.dirichlet = pressed.dirichlet;
    pulling.tractions = {
        {"sphere_load", Eigen::Vector3d(parameters.modelled() * parameters.tangential_load / area, 0, -normal)}};
    pulling.nodal_forces =
        moment_free_couple(p.mesh, weights, parameters.modelled() * parameters.tangential_load / area);
    pulling.increments = 1;
    p.steps.push_back(std::move(pulling));
  }
  p.contacts = {{"sphere_contact", "block_contact"}};
  p.validate();
  return p;
}

Hertz3dComparison compare_with_hertz3d(const Hertz3dParameters& parameters, const std::vector<ProfilePoint>& samples)
{
  const Hertz3dAnalytic analytic = hertz3d_analytic(parameters);
  Hertz3dComparison c;
  c.a_analytic = analytic.contact_radius;
  c.p0_analytic = analytic.peak_pressure;
  c.approach_analytic = analytic.approach;
  c.p_peak_computed = peak_pressure(samples);
  c.a_computed = fitted_half_width(samples);
  double sum_sq = 0;
  for (const ProfilePoint& s : samples)
    if (s.r <= analytic.contact_radius)
    {
      const double e = s.pressure - analytic.pressure(s.r);
      sum_sq += e * e;
      ++c.nodes_in_rms;
    }
  c.rms_error_over_p0 = c.nodes_in_rms > 0 ? std::sqrt(sum_sq / c.nodes_in_rms) / analytic.peak_pressure : 0;
  return c;
}
} // namespace feticon::problems
