#include "mesh/cross_section.hpp"

#include "mesh/gmsh_module.hpp"

#include "common/error.hpp"

#include <algorithm>
#include <cmath>
#include <limits>
#include <set>
#include <utility>

namespace feticon::mesh
{
namespace
{
/// Shape cost of quad `q` in degrees: the largest deviation of a corner angle from 90, or
/// 22.5 (r - 1) for the aspect ratio r (longest / shortest edge) if that is larger, so that
/// r = 3 costs as much as a corner of 45 or 135 degrees; 180 if a corner is not convex.
double shape_cost(const std::vector<Eigen::Vector2d>& points, const std::array<int32_t, 4>& q)
{
  double worst = 0, shortest = std::numeric_limits<double>::infinity(), longest = 0;
  for (int k = 0; k < 4; ++k)
  {
    const Eigen::Vector2d a = points[q[(k + 1) % 4]] - points[q[k]];
    const Eigen::Vector2d b = points[q[(k + 3) % 4]] - points[q[k]];
    const double cross = a.x() * b.y() - a.y() * b.x();
    if (cross <= 0)
      return 180;
    worst = std::max(worst, std::abs(std::atan2(cross, a.dot(b)) * 180 / M_PI - 90));
    shortest = std::min(shortest, a.norm());
    longest = std::max(longest, a.norm());
  }
  return std::max(worst, 22.5 * (longest / shortest - 1));
}

/// Moves interior nodes whose cells have a corner outside [50, 130] degrees or an aspect ratio
/// above 2.8, one at a time and only where that lowers the largest shape cost of the node's
/// cells: first towards the
/// mean of their edge neighbours in steps of a quarter, then by a small pattern search. Gmsh's
/// recombination leaves a few corners of 136-140 degrees that its Laplacian smoothing does not
/// remove, while an unguarded Laplacian pulls nodes of a graded mesh to the coarse side.
void straighten_corners(std::vector<Eigen::Vector2d>& points, const std::vector<std::array<int32_t, 4>>& quads,
                        const std::vector<char>& on_boundary)
{
  std::vector<std::vector<int32_t>> cells_of(points.size()), neighbours(points.size());
  for (int32_t c = 0; c < static_cast<int32_t>(quads.size()); ++c)
    for (int k = 0; k < 4; ++k)
    {
      cells_of[quads[c][k]].push_back(c);
      neighbours[quads[c][k]].push_back(quads[c][(k + 1) % 4]);
      neighbours[quads[c][k]].push_back(quads[c][(k + 3) % 4]);
    }
  auto local_worst = [&](int32_t node) {
    double worst = 0;
    for (int32_t c : cells_of[node])
      worst = std::max(worst, shape_cost(points, quads[c]));
    return worst;
  };
  constexpr double target = 40; // corners within [50, 130] degrees and r <= 2.8 need no move
  for (int pass = 0; pass < 20; ++pass)
  {
    int moved = 0;
    for (int32_t node = 0; node < static_cast<int32_t>(points.size()); ++node)
    {
      if (on_boundary[node] || cells_of[node].empty())
        continue;
      const double before = local_worst(node);
      if (before <= target)
        continue;
      Eigen::Vector2d mean = Eigen::Vector2d::Zero();
      for (int32_t n : neighbours[node])
        mean += points[n];
      mean /= static_cast<double>(neighbours[node].size());
      const Eigen::Vector2d start = points[node];
      Eigen::Vector2d best = start;
      double best_worst = before;
      auto try_at = [&](const Eigen::Vector2d& candidate) {
        points[node] = candidate;
        const double worst = local_worst(node);
        if (worst < best_worst - 1e-9)
        {
          best_worst = worst;
          best = candidate;
        }
      };
      for (double t : {0.25, 0.5, 0.75, 1.0})
        try_at(start + t * (mean - start));
      // Where the mean does not help: a pattern search in 8 directions, steps of 10, 5 and 2 %
      // of the mean edge length.
      double edge = 0;
      for (int32_t n : neighbours[node])
        edge += (points[n] - start).norm();
      edge /= static_cast<double>(neighbours[node].size());
      for (double step : {0.1, 0.05, 0.02})
        for (int k = 0; k < 8; ++k)
        {
          const Eigen::Vector2d centre = best;
          try_at(centre + step * edge * Eigen::Vector2d(std::cos(k * M_PI / 4), std::sin(k * M_PI / 4)));
        }
      points[node] = best;
      moved += best != start;
    }
    if (moved == 0)
      break;
  }
}
} // namespace

namespace
{
/// Gmsh's quadrilaterals of `section` with their corners straightened (the boundary nodes stay).
QuadSection straightened_quadrilaterals(const CrossSection& section, const SizeField& size)
{
  QuadSection gmsh_mesh;
  const std::string failure = gmsh_module().mesh_cross_section(section, size, gmsh_mesh);
  FETICON_CHECK(failure.empty(), failure);
  // Curve nodes stay on their curve.
  std::vector<char> on_boundary(gmsh_mesh.points.size(), 0);
  for (const auto& edges : gmsh_mesh.curve_edges)
    for (const auto& [a, b] : edges)
      on_boundary[a] = on_boundary[b] = 1;
  straighten_corners(gmsh_mesh.points, gmsh_mesh.quads, on_boundary);
  return gmsh_mesh;
}

/// The boundary edges of every curve of `section`, each as (a, b) running with its cell's
/// counter-clockwise order, so that (x_b - x_a) x e_z points out of the body.
std::vector<std::vector<std::pair<int32_t, int32_t>>> outward_curve_edges(const CrossSection& section,
                                                                          const QuadSection& quads)
{
  std::set<std::pair<int32_t, int32_t>> directed;
  for (const auto& q : quads.quads)
    for (int k = 0; k < 4; ++k)
      directed.insert({q[k], q[(k + 1) % 4]});
  std::vector<std::vector<std::pair<int32_t, int32_t>>> out(section.curves.size());
  for (size_t c = 0; c < section.curves.size(); ++c)
    for (auto [a, b] : quads.curve_edges[c])
    {
      if (!directed.count({a, b}))
        std::swap(a, b);
      FETICON_CHECK(directed.count({a, b}),
                    "cross section of " << section.body << ": a boundary edge of '" << section.curves[c].set
                                        << "' is no cell edge");
      out[c].push_back({a, b});
    }
  return out;
}

/// Each face set also a node set; every cell counter-clockwise.
void finish_sets_and_check(Mesh& mesh, const CrossSection& section)
{
  for (const auto& [name, faces] : mesh.face_sets)
    mesh.add_node_set_from_faces(name, name);
  for (int32_t c = 0; c < mesh.n_cells(); ++c)
    FETICON_CHECK(centre_jacobian_determinant(mesh, c) > 0,
                  "cross section of " << section.body << ": Gmsh made an inverted cell");
}
} // namespace

Mesh extrude_cross_section(const CrossSection& section, const SizeField& size, double thickness)
{
  FETICON_CHECK(thickness > 0, "cross section of " << section.body << ": thickness " << thickness << " must be > 0");
  const QuadSection quads = straightened_quadrilaterals(section, size);
  const auto n = static_cast<int32_t>(quads.points.size());
  Mesh mesh;
  mesh.body_names = {section.body};
  mesh.nodes.resize(2 * n, 3);
  for (int32_t i = 0; i < n; ++i)
    for (int layer = 0; layer < 2; ++layer)
      mesh.nodes.row(i + layer * n) << quads.points[i].x(), quads.points[i].y(), layer * thickness;
  for (const auto& q : quads.quads)
  {
    mesh.cells.add(CellKind::hex8, Hex8Nodes{q[0], q[1], q[2], q[3], q[0] + n, q[1] + n, q[2] + n, q[3] + n});
    mesh.face_sets["zmin"].push_back(Face{q[0], q[3], q[2], q[1]});
    mesh.face_sets["zmax"].push_back(Face{q[0] + n, q[1] + n, q[2] + n, q[3] + n});
  }
  mesh.cell_body.assign(mesh.cells.size(), 0);
  const auto edges = outward_curve_edges(section, quads);
  for (size_t c = 0; c < section.curves.size(); ++c)
    for (const auto& [a, b] : edges[c])
      mesh.face_sets[section.curves[c].set].push_back(Face{a, b, b + n, a + n});
  finish_sets_and_check(mesh, section);
  return mesh;
}

Mesh mesh_cross_section(const CrossSection& section, const SizeField& size, const Planar& planar)
{
  FETICON_CHECK(planar.kind != PlanarKind::none, "cross section of " << section.body << " needs a 2D formulation");
  const QuadSection quads = straightened_quadrilaterals(section, size);
  Mesh mesh;
  mesh.planar = planar;
  mesh.body_names = {section.body};
  mesh.nodes.resize(static_cast<Eigen::Index>(quads.points.size()), 3);
  for (size_t i = 0; i < quads.points.size(); ++i)
    mesh.nodes.row(static_cast<Eigen::Index>(i)) << quads.points[i].x(), quads.points[i].y(), 0;
  for (const auto& q : quads.quads)
    mesh.cells.add(CellKind::quad4, std::vector<int32_t>(q.begin(), q.end()));
  mesh.cell_body.assign(mesh.cells.size(), 0);
  const auto edges = outward_curve_edges(section, quads);
  for (size_t c = 0; c < section.curves.size(); ++c)
    for (const auto& [a, b] : edges[c])
      mesh.face_sets[section.curves[c].set].emplace_back(FaceKind::line2, std::vector<int32_t>{a, b});
  finish_sets_and_check(mesh, section);
  return mesh;
}
} // namespace feticon::mesh
