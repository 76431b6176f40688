#include "mesh/gmsh/gmsh_operations.hpp"
#include "mesh/gmsh/gmsh_session.hpp"

#include "common/error.hpp"

#include <gmsh.h>

#include <unordered_map>

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
  // 4.8's algorithms the one with the best quadrilaterals on the Hertz sections; more
  // smoothing passes change nothing after straighten_corners but cost time, and without any
  // Gmsh 4.8 sometimes leaves triangles. Full-quad recombination (algorithms 2, 3) leaves
  // flat corners where a domain corner is split; frontal-Delaunay for quads (algorithm 8)
  // crashes in 4.8 when the size comes from a callback. One thread: 4.8's
  // recombineIntoQuads is not thread-safe (Mesh.MaxNumThreads2D crashed now and then).
  // Figures: docs/measurements.md.
  gmsh::option::setNumber("Mesh.Algorithm", 6);
  gmsh::option::setNumber("Mesh.RecombineAll", 1);
  gmsh::option::setNumber("Mesh.RecombinationAlgorithm", 1);
  gmsh::option::setNumber("Mesh.Smoothing", 1);
  gmsh::model::mesh::setSizeCallback([&size](int, int, double x, double y, double) { return size(x, y); });
  gmsh::model::mesh::generate(2);
}

} // namespace

QuadSection mesh_cross_section_with_gmsh(const CrossSection& section, const SizeField& size)
{
  GmshSession session;
  const std::vector<int> curve_tags = build_geometry(section);
  generate_quadrilaterals(size);
  // The points and quads are what Gmsh made: the caller's straightening moves the nodes.

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

  QuadSection out;
  std::vector<std::array<int32_t, 4>>& quads = out.quads;
  for (size_t t = 0; t < types.size(); ++t)
  {
    FETICON_CHECK(types[t] == gmsh_quadrangle,
                  "cross section of " << section.body << ": Gmsh left " << element_tags[t].size()
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

  out.points.resize(n);
  for (int32_t i = 0; i < n; ++i)
    out.points[i] = {coordinates[3 * i], coordinates[3 * i + 1]};
  // Boundary edges of every curve.
  std::vector<std::vector<std::pair<int32_t, int32_t>>>& curve_edges = out.curve_edges;
  curve_edges.resize(curve_tags.size());
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
      }
    }
  }
  return out;
}
} // namespace feticon::mesh
