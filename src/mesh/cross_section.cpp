#include "mesh/cross_section.hpp"

#include "mesh/gmsh_session.hpp"

#include "common/error.hpp"

#include <gmsh.h>

#include <algorithm>
#include <cmath>
#include <limits>
#include <set>
#include <unordered_map>
#include <utility>

namespace feticon::mesh
{
namespace
{
// Gmsh element types (Gmsh reference manual, "MSH file format": elm-type).
constexpr int gmsh_line = 1;
constexpr int gmsh_quadrangle = 3;

/// Gmsh's plane model of the section: one surface bounded by the loop; returns the curve tags.
std::vector<int> build_geometry(const CrossSection& section)
{
  gmsh::model::add(section.body);
  const int first = gmsh::model::geo::addPoint(section.start.x(), section.start.y(), 0);
  int previous = first;
  std::vector<int> curves;
  for (size_t k = 0; k < section.curves.size(); ++k)
  {
    const CrossSectionCurve& c = section.curves[k];
    const bool last = k + 1 == section.curves.size();
    FETICON_CHECK(!last || (c.end - section.start).norm() <= 1e-12 * (1 + section.start.norm()),
                  "cross section of " << section.body << ": the boundary loop does not close");
    const int end = last ? first : gmsh::model::geo::addPoint(c.end.x(), c.end.y(), 0);
    if (c.arc)
    {
      const int centre = gmsh::model::geo::addPoint(c.centre.x(), c.centre.y(), 0);
      curves.push_back(gmsh::model::geo::addCircleArc(previous, centre, end));
    }
    else
      curves.push_back(gmsh::model::geo::addLine(previous, end));
    previous = end;
  }
  const int loop = gmsh::model::geo::addCurveLoop(curves);
  gmsh::model::geo::addPlaneSurface({loop});
  gmsh::model::geo::synchronize();
  return curves;
}

/// The quadrilateral mesh of the section's surface: Gmsh's size callback evaluates `size`.
void generate_quadrilaterals(const SizeField& size)
{
  gmsh::option::setNumber("Mesh.MeshSizeFromPoints", 0);
  gmsh::option::setNumber("Mesh.MeshSizeFromCurvature", 0);
  gmsh::option::setNumber("Mesh.MeshSizeExtendFromBoundary", 0);
  // Frontal-Delaunay triangles recombined by blossom matching and smoothed once: of Gmsh
  // 4.8's algorithms the one with the best quadrilaterals on the Hertz sections (corners of
  // 46-139 degrees at 120 cells across 2a before straighten_corners with five smoothing
  // passes, against 32-170 without smoothing and 38-152 for Delaunay or packing of
  // parallelograms). One pass instead of five: after straighten_corners every cell is within
  // [50, 130] degrees and aspect ratio 2.8 either way (72 Hertz meshes, refinement 0.3-16,
  // growth 1.05-1.4, master_ratio 1-2), the node count is the same to 0.5 % and the meshing
  // takes 40-60 % less time; without any pass Gmsh 4.8 sometimes leaves triangles. Full-quad
  // recombination (algorithms 2, 3) is faster still but leaves 44-45 degree corners where a
  // domain corner is split and 6-15 % more nodes. Its frontal-Delaunay for quads (algorithm
  // 8) crashes in 4.8 when the size comes from a callback. Meshing the Hertz bodies' surfaces
  // on two threads (Mesh.MaxNumThreads2D) saved 0.03 s but crashes now and then in 4.8's
  // recombineIntoQuads, which is not thread-safe (gdb, 1 run in ~5): keep one thread.
  gmsh::option::setNumber("Mesh.Algorithm", 6);
  gmsh::option::setNumber("Mesh.RecombineAll", 1);
  gmsh::option::setNumber("Mesh.RecombinationAlgorithm", 1);
  gmsh::option::setNumber("Mesh.Smoothing", 1);
  gmsh::model::mesh::setSizeCallback([&size](int, int, double x, double y, double) { return size(x, y); });
  gmsh::model::mesh::generate(2);
}

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
  auto local_worst = [&](int32_t node)
  {
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
      auto try_at = [&](const Eigen::Vector2d& candidate)
      {
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

HexMesh extrude_cross_section(const CrossSection& section, const SizeField& size, double thickness)
{
  FETICON_CHECK(thickness > 0, "cross section of " << section.body << ": thickness " << thickness << " must be > 0");
  GmshSession session;
  const std::vector<int> curve_tags = build_geometry(section);
  generate_quadrilaterals(size);

  // Nodes of the cells, renumbered 0..n-1 in Gmsh's order: Gmsh also has a node at every
  // geometry point, among them the arcs' centres, which belong to no cell.
  std::vector<int> types;
  std::vector<std::vector<std::size_t>> element_tags, element_nodes;
  gmsh::model::mesh::getElements(types, element_tags, element_nodes, 2, -1);
  std::vector<std::size_t> tags;
  std::vector<double> all_coordinates, parametric;
  gmsh::model::mesh::getNodes(tags, all_coordinates, parametric, -1, -1, true, false);
  std::unordered_map<std::size_t, int32_t> index;
  for (const auto& nodes : element_nodes)
    for (std::size_t tag : nodes)
      index[tag] = -1;
  std::vector<double> coordinates;
  int32_t n = 0;
  for (size_t i = 0; i < tags.size(); ++i) // a node may be listed once per entity it bounds
    if (auto it = index.find(tags[i]); it != index.end() && it->second < 0)
    {
      it->second = n++;
      coordinates.insert(coordinates.end(), &all_coordinates[3 * i], &all_coordinates[3 * i] + 3);
    }

  std::vector<std::array<int32_t, 4>> quads;
  for (size_t t = 0; t < types.size(); ++t)
  {
    FETICON_CHECK(types[t] == gmsh_quadrangle, "cross section of " << section.body << ": Gmsh left "
                                                                   << element_tags[t].size()
                                                                   << " cells that are no quadrilaterals");
    for (size_t e = 0; e < element_tags[t].size(); ++e)
    {
      std::array<int32_t, 4> q;
      for (int k = 0; k < 4; ++k)
        q[k] = index.at(element_nodes[t][4 * e + k]);
      // Counter-clockwise in the plane (positive signed area), so the hex keeps its orientation.
      auto at = [&](int32_t i) { return Eigen::Vector2d(coordinates[3 * i], coordinates[3 * i + 1]); };
      const Eigen::Vector2d d1 = at(q[2]) - at(q[0]), d2 = at(q[3]) - at(q[1]);
      if (d1.x() * d2.y() - d1.y() * d2.x() < 0)
        std::swap(q[1], q[3]);
      quads.push_back(q);
    }
  }
  FETICON_CHECK(!quads.empty(), "cross section of " << section.body << ": Gmsh made no cells");

  // Boundary edges of every curve, before the nodes move: curve nodes stay on their curve.
  std::vector<Eigen::Vector2d> points(n);
  for (int32_t i = 0; i < n; ++i)
    points[i] = {coordinates[3 * i], coordinates[3 * i + 1]};
  std::vector<char> on_boundary(n, 0);
  std::vector<std::vector<std::pair<int32_t, int32_t>>> curve_edges(curve_tags.size());
  for (size_t c = 0; c < curve_tags.size(); ++c)
  {
    gmsh::model::mesh::getElements(types, element_tags, element_nodes, 1, curve_tags[c]);
    for (size_t t = 0; t < types.size(); ++t)
    {
      FETICON_CHECK(types[t] == gmsh_line, "cross section of " << section.body << ": unexpected boundary element");
      for (size_t e = 0; e < element_tags[t].size(); ++e)
      {
        const int32_t a = index.at(element_nodes[t][2 * e]), b = index.at(element_nodes[t][2 * e + 1]);
        curve_edges[c].push_back({a, b});
        on_boundary[a] = on_boundary[b] = 1;
      }
    }
  }
  straighten_corners(points, quads, on_boundary);

  HexMesh mesh;
  mesh.body_names = {section.body};
  mesh.nodes.resize(2 * n, 3);
  for (int32_t i = 0; i < n; ++i)
    for (int layer = 0; layer < 2; ++layer)
      mesh.nodes.row(i + layer * n) << points[i].x(), points[i].y(), layer * thickness;
  // Directed edges of the counter-clockwise quads: a boundary edge runs with its cell's order.
  std::set<std::pair<int32_t, int32_t>> directed;
  for (const auto& q : quads)
  {
    mesh.cells.push_back({q[0], q[1], q[2], q[3], q[0] + n, q[1] + n, q[2] + n, q[3] + n});
    for (int k = 0; k < 4; ++k)
      directed.insert({q[k], q[(k + 1) % 4]});
    mesh.face_sets["zmin"].push_back({q[0], q[3], q[2], q[1]});
    mesh.face_sets["zmax"].push_back({q[0] + n, q[1] + n, q[2] + n, q[3] + n});
  }
  mesh.cell_body.assign(mesh.cells.size(), 0);
  for (size_t c = 0; c < curve_tags.size(); ++c)
  {
    auto& faces = mesh.face_sets[section.curves[c].set];
    for (auto [a, b] : curve_edges[c])
    {
      if (!directed.count({a, b}))
        std::swap(a, b);
      FETICON_CHECK(directed.count({a, b}), "cross section of " << section.body << ": a boundary edge of '"
                                                                << section.curves[c].set << "' is no cell edge");
      // (x_b - x_a) x e_z points to the right of a -> b: out of the body.
      faces.push_back({a, b, b + n, a + n});
    }
  }
  for (const auto& [name, faces] : mesh.face_sets)
    mesh.add_node_set_from_faces(name, name);
  for (const Cell& cell : mesh.cells)
    FETICON_CHECK(centre_jacobian_determinant(mesh, cell) > 0,
                  "cross section of " << section.body << ": Gmsh made an inverted cell");
  return mesh;
}
} // namespace feticon::mesh
