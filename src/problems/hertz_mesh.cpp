#include "problems/hertz_mesh.hpp"

#include "mesh/box.hpp"
#include "mesh/cross_section.hpp"
#include "mesh/rectangle.hpp"
#include "mesh/mesh_cache.hpp"

#include "common/error.hpp"

#include <algorithm>
#include <array>
#include <cmath>
#include <iomanip>
#include <iterator>
#include <limits>
#include <sstream>
#include <utility>
#include <vector>

namespace feticon::problems
{
using mesh::CrossSection;
using mesh::Face;
using mesh::Mesh;

namespace
{
void check_parameters(const HertzMeshParameters& p)
{
  auto check_positive = [](double value, const char* name) {
    FETICON_CHECK(std::isfinite(value) && value > 0, "Hertz mesh: " << name << " = " << value << " must be > 0");
  };
  check_positive(p.cylinder_radius, "cylinder_radius");
  check_positive(p.cylinder_width, "cylinder_width");
  check_positive(p.block_width, "block_width");
  check_positive(p.block_depth, "block_depth");
  check_positive(p.thickness, "thickness");
  check_positive(p.element_size, "element_size");
  check_positive(p.master_ratio, "master_ratio");
  check_positive(p.fine_width, "fine_width");
  check_positive(p.fine_depth, "fine_depth");
  check_positive(p.refinement, "refinement");
  FETICON_CHECK(std::isfinite(p.growth_ratio) && p.growth_ratio >= 1,
                "Hertz mesh: growth_ratio = " << p.growth_ratio << " must be >= 1");
  FETICON_CHECK(p.cylinder_width < p.cylinder_radius,
                "Hertz mesh: cylinder_width = " << p.cylinder_width
                                                << " m must be < cylinder_radius = " << p.cylinder_radius << " m");
  FETICON_CHECK(p.fine_width < std::min(p.cylinder_width, p.block_width),
                "Hertz mesh: fine_width = " << p.fine_width << " m must be < cylinder_width and block_width");
  FETICON_CHECK(p.fine_depth < std::min(p.cylinder_radius, p.block_depth),
                "Hertz mesh: fine_depth = " << p.fine_depth << " m must be < cylinder_radius and block_depth");
  FETICON_CHECK(!p.full || p.kind == HertzMeshKind::graded,
                "Hertz mesh: the full model (a tangential load or displacement) is meshed by the graded mesh only: "
                "hertz.mesh = graded");
  FETICON_CHECK(!p.axisymmetric || p.cells == HertzCells::quad4,
                "Hertz mesh: an axisymmetric model has quad4 cells, not a hex8 layer");
  FETICON_CHECK(!(p.axisymmetric && p.full), "Hertz mesh: an axisymmetric model has no full (two-sided) form");
  const double h_max = std::max(1.0, p.master_ratio) * p.element_size / p.refinement;
  FETICON_CHECK(std::min(p.fine_width, p.fine_depth) >= h_max,
                "Hertz mesh: the fine region (fine_width, fine_depth >= "
                    << std::min(p.fine_width, p.fine_depth) << " m) must hold at least one cell of " << h_max
                    << " m; decrease element_size or master_ratio");
}

/// The 2D formulation of the quad4 cells: plane strain of the thickness, or axisymmetric.
mesh::Planar formulation(const HertzMeshParameters& p)
{
  if (p.axisymmetric)
    return {mesh::PlanarKind::axisymmetric, 1};
  return {mesh::PlanarKind::plane_strain, p.thickness};
}

/// Replaces the face sets `sources` by their union `target` (with its node set).
void merge_sets(Mesh& mesh, const std::vector<std::string>& sources, const std::string& target)
{
  std::vector<Face> faces;
  for (const std::string& source : sources)
  {
    const std::vector<Face>& part = mesh.face_set(source);
    faces.insert(faces.end(), part.begin(), part.end());
    mesh.face_sets.erase(source);
    mesh.node_sets.erase(source);
  }
  mesh.face_sets[target] = std::move(faces);
  mesh.add_node_set_from_faces(target, target);
}

/// The two bodies of the tensor mesh with the sets named as in hertz_mesh.hpp (but zmin, zmax and
/// symmetry, which generate_hertz adds for both kinds).
Mesh tensor_bodies(const HertzMeshParameters& p)
{
  const double radius = p.cylinder_radius;
  const double h_slave = p.element_size / p.refinement;
  const double h_master = p.master_ratio * h_slave;
  const double ratio = std::pow(p.growth_ratio, 1 / p.refinement);
  const double thickness = p.thickness;

  const std::vector<double> cylinder_x = mesh::graded_positions(p.cylinder_width, h_slave, p.fine_width, ratio);
  const std::vector<double> cylinder_t = mesh::graded_positions(radius, h_slave, p.fine_depth, ratio);
  const std::vector<double> block_x = mesh::graded_positions(p.block_width, h_master, p.fine_width, ratio);
  const std::vector<double> block_d = mesh::graded_positions(p.block_depth, h_master, p.fine_depth, ratio);
  auto n_cells = [](const std::vector<double>& positions) { return static_cast<int32_t>(positions.size()) - 1; };

  // Column at abscissa x spans from the arc to the axis plane, height sqrt(R1^2 - x^2).
  const auto cylinder_point = [&](int32_t i, int32_t j) {
    const double x = cylinder_x[i];
    const double height = std::sqrt(radius * radius - x * x);
    return Eigen::Vector2d(x, (radius - height) + cylinder_t[j] / radius * height);
  };
  // j counts upward, while the graded depths start at the contact surface y = 0.
  const int32_t block_ny = n_cells(block_d);
  const auto block_point = [&](int32_t i, int32_t j) { return Eigen::Vector2d(block_x[i], -block_d[block_ny - j]); };
  const std::array<int32_t, 2> cylinder_cells{n_cells(cylinder_x), n_cells(cylinder_t)};
  const std::array<int32_t, 2> block_cells{n_cells(block_x), block_ny};
  const auto layer = [&](const auto& point, const std::array<int32_t, 2>& cells, const char* name) {
    return mesh::generate_mapped_block(
        {cells[0], cells[1], 1},
        [&](int32_t i, int32_t j, int32_t k) {
      const Eigen::Vector2d xy = point(i, j);
      return Eigen::Vector3d(xy.x(), xy.y(), k * thickness);
        },
        name);
  };
  const auto planar = [&](const auto& point, const std::array<int32_t, 2>& cells, const char* name) {
    // Quad4 cells have only corners, at whole grid points.
    const auto at = [&](double i, double j) { return point(static_cast<int32_t>(i), static_cast<int32_t>(j)); };
    return mesh::generate_mapped_rectangle(cells, at, mesh::CellKind::quad4, formulation(p), name);
  };
  const bool hex = p.cells == HertzCells::hex8_layer;
  const Mesh cylinder =
      hex ? layer(cylinder_point, cylinder_cells, "cylinder") : planar(cylinder_point, cylinder_cells, "cylinder");
  const Mesh block = hex ? layer(block_point, block_cells, "block") : planar(block_point, block_cells, "block");

  Mesh mesh;
  mesh::append_mesh(mesh, cylinder, "cylinder_");
  mesh::append_mesh(mesh, block, "block_");
  const std::vector<std::pair<std::string, std::string>> renames = {
      {"cylinder_ymin", "cylinder_contact"}, {"cylinder_ymax", "load"},       {"cylinder_xmin", "cylinder_symmetry"},
      {"cylinder_xmax", "cylinder_side"},    {"block_ymax", "block_contact"}, {"block_ymin", "support"},
      {"block_xmin", "block_symmetry"},      {"block_xmax", "block_side"},
  };
  for (const auto& [from, to] : renames)
    merge_sets(mesh, {from}, to);
  return mesh;
}

/// Cell size of the graded mesh with size h at the contact band [0, fine_width] x {0}:
/// h + (q - 1) d at the distance d from the band, i.e. cells growing by about q from one to
/// the next, up to a tenth of the largest body dimension.
auto graded_size(const HertzMeshParameters& p, double h)
{
  const double largest = 0.1 * std::max({p.block_width, p.block_depth, p.cylinder_radius});
  return [&p, h, largest](double x, double y) {
    return std::min(largest, h + (p.growth_ratio - 1) * std::hypot(std::max(std::abs(x) - p.fine_width, 0.0), y));
  };
}

/// The two bodies of the graded mesh (see hertz_mesh.hpp): each body's cross-section meshed by Gmsh with
/// quadrilaterals whose size is h_b at the distance d = 0 from the contact band
/// [0, fine_width] x {0} and h_b + (q - 1) d beyond, i.e. cells growing by about q from one
/// to the next: quad4 cells of a 2D model, or extruded into one hex8 layer.
Mesh graded_bodies(const HertzMeshParameters& p)
{
  const double radius = p.cylinder_radius;
  const double h_slave = p.element_size / p.refinement;
  const double x_arc = p.cylinder_width;
  const double y_arc = radius - std::sqrt(radius * radius - x_arc * x_arc);
  CrossSection cylinder{"cylinder", {0, 0}, {}};
  cylinder.curves = {{{x_arc, y_arc}, "contact", true, {0, radius}},
                     {{x_arc, radius}, "side"},
                     {{0, radius}, "load"},
                     {{0, 0}, "symmetry"}};
  CrossSection block{"block", {0, -p.block_depth}, {}};
  block.curves = {{{p.block_width, -p.block_depth}, "support"},
                  {{p.block_width, 0}, "side"},
                  {{0, 0}, "contact"},
                  {{0, -p.block_depth}, "symmetry"}};
  if (p.full) // the mirror images of the curves replace the symmetry line
  {
    cylinder = {"cylinder", {-x_arc, y_arc}, {}};
    cylinder.curves = {{{x_arc, y_arc}, "contact", true, {0, radius}},
                       {{x_arc, radius}, "side"},
                       {{-x_arc, radius}, "load"},
                       {{-x_arc, y_arc}, "side"}};
    block = {"block", {-p.block_width, -p.block_depth}, {}};
    block.curves = {{{p.block_width, -p.block_depth}, "support"},
                    {{p.block_width, 0}, "side"},
                    {{-p.block_width, 0}, "contact"},
                    {{-p.block_width, -p.block_depth}, "side"}};
  }
  const auto cross_section = [&](const CrossSection& section, double h) {
    if (p.cells == HertzCells::hex8_layer)
      return mesh::extrude_cross_section(section, graded_size(p, h), p.thickness);
    return mesh::mesh_cross_section(section, graded_size(p, h), formulation(p));
  };
  Mesh mesh;
  mesh::append_mesh(mesh, cross_section(cylinder, h_slave), "cylinder_");
  mesh::append_mesh(mesh, cross_section(block, p.master_ratio * h_slave), "block_");
  merge_sets(mesh, {"cylinder_load"}, "load");
  merge_sets(mesh, {"block_support"}, "support");
  return mesh;
}
/// Every input of graded_bodies, exactly (the mesh cache's key).
std::string graded_cache_key(const HertzMeshParameters& p)
{
  std::ostringstream key;
  key << std::setprecision(17) << "hertz graded: radius " << p.cylinder_radius << " cylinder_width " << p.cylinder_width
      << " block_width " << p.block_width << " block_depth " << p.block_depth << " thickness " << p.thickness
      << " element_size " << p.element_size << " master_ratio " << p.master_ratio << " fine_width " << p.fine_width
      << " fine_depth " << p.fine_depth << " growth_ratio " << p.growth_ratio << " refinement " << p.refinement
      << (p.full ? " full" : "") << (p.cells == HertzCells::quad4 ? " quad4" : "")
      << (p.axisymmetric ? " axisymmetric" : "");
  return key.str();
}

/// Cells of a graded_positions spacing along `length`, counted without building it.
double graded_cell_count(double length, double spacing, double fine_length, double ratio)
{
  const double fine = std::min(length, fine_length) / spacing;
  const double rest = std::max(0.0, length - fine_length);
  return fine + (ratio == 1 ? rest / spacing : std::log1p(rest * (ratio - 1) / spacing) / std::log(ratio));
}

/// Integral of 1 / size(x, y)^2 over [0, width] x [0, height] where inside(x, y): the cell
/// count a mesher following `size` produces there. Midpoint rule on grids that start at
/// `finest` / 4 and grow by 5 % per point, resolving the sizes near the origin at any
/// refinement with a few hundred points per direction.
template <class Size, class Inside>
double cells_by_size(double width, double height, double finest, Size size, Inside inside)
{
  auto grid = [finest](double length) {
    std::vector<double> edges{0.0};
    for (double step = 0.25 * finest; edges.back() < length; step *= 1.05)
      edges.push_back(std::min(length, edges.back() + step));
    return edges;
  };
  const std::vector<double> xs = grid(width), ys = grid(height);
  double cells = 0;
  for (size_t i = 1; i < xs.size(); ++i)
    for (size_t j = 1; j < ys.size(); ++j)
    {
      const double x = 0.5 * (xs[i - 1] + xs[i]), y = 0.5 * (ys[j - 1] + ys[j]);
      if (inside(x, y))
        cells += (xs[i] - xs[i - 1]) * (ys[j] - ys[j - 1]) / std::pow(size(x, y), 2);
    }
  return cells;
}
} // namespace

int64_t hertz_node_estimate(const HertzMeshParameters& p)
{
  check_parameters(p);
  const double R = p.cylinder_radius;
  const double h_slave = p.element_size / p.refinement, h_master = p.master_ratio * h_slave;
  double cells = 0; // of both cross-sections
  if (p.kind == HertzMeshKind::tensor)
  {
    const double q = std::pow(p.growth_ratio, 1 / p.refinement);
    cells =
        graded_cell_count(p.cylinder_width, h_slave, p.fine_width, q) * graded_cell_count(R, h_slave, p.fine_depth, q) +
        graded_cell_count(p.block_width, h_master, p.fine_width, q) *
            graded_cell_count(p.block_depth, h_master, p.fine_depth, q);
  }
  else
  {
    // The size field of graded_bodies, integrated over each body's cross-section.
    cells = cells_by_size(p.cylinder_width, R, h_slave, graded_size(p, h_slave),
                          [R](double x, double y) { return y >= R - std::sqrt(R * R - x * x); }) +
        cells_by_size(p.block_width, p.block_depth, h_master, graded_size(p, h_master),
                      [](double, double) { return true; });
  }
  // Quadrilaterals have about as many nodes as cells; the hex8 layer doubles them. Gmsh's
  // recombined quadrilaterals come out smaller than the size field asks, by a steady factor
  // (nodes built / integral 1.35, 1.34, 1.29 at refinement 0.5, 1, 4.4): 1.3 corrects it.
  const double quad_factor = p.kind == HertzMeshKind::graded ? 1.3 : 1.0;
  const double halves = p.full ? 2.0 : 1.0;
  const double layers = p.cells == HertzCells::hex8_layer ? 2.0 : 1.0;
  return static_cast<int64_t>(std::min(layers * quad_factor * halves * cells, 4e18));
}

Mesh generate_hertz(const HertzMeshParameters& parameters, bool* from_cache)
{
  check_parameters(parameters);
  if (from_cache)
    *from_cache = false;
  Mesh mesh = parameters.kind == HertzMeshKind::graded
      ? mesh::cached_mesh(
            graded_cache_key(parameters), [&] { return graded_bodies(parameters); }, from_cache)
      : tensor_bodies(parameters);
  if (parameters.cells == HertzCells::hex8_layer)
  {
    merge_sets(mesh, {"cylinder_zmin", "block_zmin"}, "zmin");
    merge_sets(mesh, {"cylinder_zmax", "block_zmax"}, "zmax");
  }
  if (parameters.full)
    return mesh;
  std::vector<int32_t> symmetry;
  std::ranges::set_union(mesh.node_set("cylinder_symmetry"), mesh.node_set("block_symmetry"),
                         std::back_inserter(symmetry));
  mesh.node_sets["symmetry"] = std::move(symmetry);
  return mesh;
}

ContactZoneSummary summarize_contact_zone(const Mesh& mesh, const std::string& face_set, double half_width)
{
  ContactZoneSummary summary;
  summary.min_size = std::numeric_limits<double>::infinity();
  for (const Face& face : mesh.face_set(face_set))
  {
    double min_x = std::numeric_limits<double>::infinity();
    double size = 0;
    for (int a = 0; a < face.size(); ++a)
    {
      min_x = std::min(min_x, mesh.nodes(face[a], 0));
      for (int b = 0; b < a; ++b)
        size = std::max(size, (mesh.nodes.row(face[a]).head<2>() - mesh.nodes.row(face[b]).head<2>()).norm());
    }
    if (min_x >= half_width)
      continue;
    ++summary.n_faces;
    summary.min_size = std::min(summary.min_size, size);
    summary.max_size = std::max(summary.max_size, size);
  }
  FETICON_CHECK(summary.n_faces > 0, "face set '" << face_set << "' has no face with x < " << half_width << " m");
  return summary;
}
} // namespace feticon::problems
