/// The node orders of mesh/cell_type.hpp against Gmsh itself (issue 38): Gmsh meshes a box with
/// each element type, and every element, its nodes taken through gmsh_to_local, must be
/// positively oriented (the corner frame of the reference cell has a positive determinant) and
/// have each edge node at the midpoint of its edge's corners (the box's faces are flat, so
/// Gmsh puts them there). Reference: Gmsh's own meshes, independent of our tables.

#include "mesh/cell_type.hpp"

#include <Eigen/Dense>
#include <gmsh.h>
#include <gtest/gtest.h>

namespace feticon::mesh
{
namespace
{
struct GmshSession
{
  GmshSession()
  {
    gmsh::initialize(0, nullptr, false);
    gmsh::option::setNumber("General.Terminal", 0);
    gmsh::model::add("cell_types");
  }
  ~GmshSession() { gmsh::finalize(); }
};

/// Checks every 3D element of Gmsh type `gmsh_type` in the current model; returns their count.
int check_elements(const CellType& type)
{
  std::vector<std::size_t> node_tags;
  std::vector<double> coords, parametric;
  gmsh::model::mesh::getNodes(node_tags, coords, parametric);
  std::map<std::size_t, Eigen::Vector3d> position;
  for (size_t k = 0; k < node_tags.size(); ++k)
    position[node_tags[k]] = Eigen::Vector3d(coords[3 * k], coords[3 * k + 1], coords[3 * k + 2]);
  std::vector<std::size_t> element_tags, element_nodes;
  gmsh::model::mesh::getElementsByType(type.gmsh_type, element_tags, element_nodes);
  const auto n = static_cast<size_t>(type.n_nodes);
  for (size_t e = 0; e < element_tags.size(); ++e)
  {
    std::vector<Eigen::Vector3d> x(n);
    for (size_t k = 0; k < n; ++k)
      x[type.gmsh_to_local[k]] = position.at(element_nodes[e * n + k]);
    // The corner frame at node 0 along the reference axes: nodes 1, 3, 4 of a hexahedron,
    // 1, 2, 3 of a tetrahedron and of a wedge.
    const bool hex = type.kind == CellKind::hex8 || type.kind == CellKind::hex20;
    const Eigen::Vector3d a = x[1] - x[0], b = x[hex ? 3 : 2] - x[0], c = x[hex ? 4 : 3] - x[0];
    EXPECT_GT(a.cross(b).dot(c), 0) << type.name << " element " << element_tags[e] << " is inverted";
    if (type.order == 2)
      for (size_t edge = 0; edge < type.edges.size(); ++edge)
      {
        const Eigen::Vector3d mid = 0.5 * (x[type.edges[edge][0]] + x[type.edges[edge][1]]);
        EXPECT_LT((x[type.n_corners + edge] - mid).norm(), 1e-12)
            << type.name << " element " << element_tags[e] << ", edge node " << type.n_corners + edge;
      }
  }
  return static_cast<int>(element_tags.size());
}

/// An OCC unit box, hexahedra by transfinite meshing and recombination if `hexahedra`, else
/// tetrahedra; meshed at `order` (serendipity hex20 for order 2).
void mesh_box(bool hexahedra, int order)
{
  const int volume = gmsh::model::occ::addBox(0, 0, 0, 1, 1, 1);
  gmsh::model::occ::synchronize();
  gmsh::option::setNumber("Mesh.MeshSizeMax", 0.4);
  if (hexahedra)
  {
    gmsh::model::mesh::setTransfiniteAutomatic();
    gmsh::option::setNumber("Mesh.RecombineAll", 1);
    gmsh::option::setNumber("Mesh.Recombine3DAll", 1);
  }
  (void)volume;
  gmsh::option::setNumber("Mesh.SecondOrderIncomplete", 1);
  gmsh::model::mesh::generate(3);
  if (order == 2)
    gmsh::model::mesh::setOrder(2);
}

TEST(CellTypeGmsh, TetrahedraInGmshsOrderArePositiveWithEdgeNodesAtMidpoints)
{
  for (const CellKind kind : {CellKind::tet4, CellKind::tet10})
  {
    GmshSession session;
    mesh_box(false, cell_type(kind).order);
    EXPECT_GT(check_elements(cell_type(kind)), 10);
  }
}

TEST(CellTypeGmsh, HexahedraInGmshsOrderArePositiveWithEdgeNodesAtMidpoints)
{
  for (const CellKind kind : {CellKind::hex8, CellKind::hex20})
  {
    GmshSession session;
    mesh_box(true, cell_type(kind).order);
    EXPECT_GT(check_elements(cell_type(kind)), 10);
  }
}

TEST(CellTypeGmsh, PrismsInGmshsOrderArePositive)
{
  GmshSession session;
  // Triangles on the unit square extruded in two recombined layers: prisms.
  const int p0 = gmsh::model::geo::addPoint(0, 0, 0), p1 = gmsh::model::geo::addPoint(1, 0, 0),
            p2 = gmsh::model::geo::addPoint(1, 1, 0), p3 = gmsh::model::geo::addPoint(0, 1, 0);
  const int loop =
      gmsh::model::geo::addCurveLoop({gmsh::model::geo::addLine(p0, p1), gmsh::model::geo::addLine(p1, p2),
                                      gmsh::model::geo::addLine(p2, p3), gmsh::model::geo::addLine(p3, p0)});
  const int square = gmsh::model::geo::addPlaneSurface({loop});
  gmsh::vectorpair extruded;
  gmsh::model::geo::extrude({{2, square}}, 0, 0, 1, extruded, {2}, {}, true);
  gmsh::model::geo::synchronize();
  gmsh::option::setNumber("Mesh.MeshSizeMax", 0.4);
  gmsh::model::mesh::generate(3);
  EXPECT_GT(check_elements(cell_type(CellKind::wedge6)), 10);
}
} // namespace
} // namespace feticon::mesh
