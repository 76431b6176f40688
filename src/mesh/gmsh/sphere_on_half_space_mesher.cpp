/// @file The hertz3d quarter model built as OpenCASCADE solids and meshed by Gmsh with
/// tetrahedra (mesh/gmsh_module.hpp, SphereOnHalfSpace): the sphere cut to a ball about the
/// contact point and to x, y, z >= 0; the half-space cut to a ball and to x, y >= 0, z <= 0.

#include "mesh/gmsh/gmsh_operations.hpp"
#include "mesh/gmsh/gmsh_session.hpp"

#include "common/error.hpp"

#include <gmsh.h>

#include <cmath>
#include <cstdio>
#include <map>
#include <numbers>
#include <string>
#include <vector>

namespace feticon::mesh
{
namespace
{
using DimTags = std::vector<std::pair<int, int>>;

/// A ball whose poles (where OpenCASCADE has a degenerate edge) lie on the axis (-1, 1, 1)
/// through its centre, outside the octant x, y >= 0 the model keeps: the rotation about
/// (-1, -1, 0) by acos(1 / sqrt 3) takes the z axis there.
int turned_ball(double x, double y, double z, double radius)
{
  const int tag = gmsh::model::occ::addSphere(x, y, z, radius);
  gmsh::model::occ::rotate({{3, tag}}, x, y, z, -1, -1, 0, std::acos(1 / std::sqrt(3.0)));
  return tag;
}

/// The volumes of `object` cut by `tool` (both deleted).
DimTags intersection(const DimTags& object, const DimTags& tool)
{
  DimTags out;
  std::vector<DimTags> map;
  gmsh::model::occ::intersect(object, tool, out, map);
  FETICON_CHECK(!out.empty(), "hertz3d (Gmsh): an intersection of solids is empty");
  return out;
}

std::vector<int> tags_of(const DimTags& dim_tags)
{
  std::vector<int> tags;
  for (const auto& [dim, tag] : dim_tags)
    tags.push_back(tag);
  return tags;
}

void add_group(int dim, const std::vector<int>& tags, const std::string& name)
{
  FETICON_CHECK(!tags.empty(), "hertz3d (Gmsh): no entity for the set '" << name << "'");
  const int group = gmsh::model::addPhysicalGroup(dim, tags);
  gmsh::model::setPhysicalName(dim, group, name);
}

/// The faces of the two bodies sorted into the hertz3d sets by their centres of mass: the
/// planes x = 0 and y = 0, the block's top z = 0, and the spherical faces by height (the
/// sphere's contact face lies below the rim where it meets the cap ball, z = cap^2 / (2 R)).
std::map<std::string, std::vector<int>> face_sets(const DimTags& sphere, const DimTags& block,
                                                  const SphereOnHalfSpace& g)
{
  const double eps = 1e-9 * g.block_radius;
  const double rim = g.cap_radius * g.cap_radius / (2 * g.radius);
  std::map<std::string, std::vector<int>> sets;
  for (const bool is_sphere : {true, false})
  {
    DimTags faces;
    gmsh::model::getBoundary(is_sphere ? sphere : block, faces, true, false, false);
    for (const auto& [dim, signed_tag] : faces)
    {
      const int tag = std::abs(signed_tag);
      double x = 0, y = 0, z = 0;
      gmsh::model::occ::getCenterOfMass(2, tag, x, y, z);
      const std::string name = std::abs(x) < eps ? "symmetry_x"
          : std::abs(y) < eps                    ? "symmetry_y"
          : is_sphere                            ? (z < rim ? "sphere_contact" : "sphere_load")
          : std::abs(z) < eps                    ? "block_contact"
                                                 : "block_support";
      sets[name].push_back(tag);
    }
  }
  return sets;
}
} // namespace

Mesh mesh_sphere_on_half_space_with_gmsh(const SphereOnHalfSpace& g)
{
  FETICON_CHECK(g.radius > 0 && g.cap_radius > 0 && g.cap_radius <= 0.5 * g.radius && g.block_radius > 0 &&
                    g.size > 0 && g.max_size >= g.size && g.growth >= 0 && (g.order == 1 || g.order == 2),
                "hertz3d (Gmsh): inconsistent geometry or sizes");
  try
  {
    GmshSession session;
    gmsh::model::add("hertz3d");
    using gmsh::model::occ::addBox;
    const double Rc = g.cap_radius, Rb = g.block_radius;
    const DimTags cap = intersection({{3, turned_ball(0, 0, g.radius, g.radius)}}, {{3, turned_ball(0, 0, 0, Rc)}});
    const DimTags sphere = intersection(cap, {{3, addBox(0, 0, 0, Rc, Rc, Rc)}});
    const DimTags block = intersection({{3, turned_ball(0, 0, 0, Rb)}}, {{3, addBox(0, 0, -Rb, Rb, Rb, Rb)}});
    gmsh::model::occ::synchronize();

    add_group(3, tags_of(sphere), "sphere");
    add_group(3, tags_of(block), "block");
    for (const auto& [name, tags] : face_sets(sphere, block, g))
      add_group(2, tags, name);

    const int field = gmsh::model::mesh::field::add("MathEval");
    char expression[256];
    std::snprintf(expression, sizeof expression, "Min(%.17g + %.17g * Max(Sqrt(x^2 + y^2 + z^2) - %.17g, 0), %.17g)",
                  g.size, g.growth, g.core, g.max_size);
    gmsh::model::mesh::field::setString(field, "F", expression);
    gmsh::model::mesh::field::setAsBackgroundMesh(field);
    gmsh::option::setNumber("Mesh.MeshSizeExtendFromBoundary", 0);
    gmsh::option::setNumber("Mesh.MeshSizeFromPoints", 0);
    gmsh::option::setNumber("Mesh.MeshSizeFromCurvature", 0);
    gmsh::option::setNumber("Mesh.ElementOrder", g.order);
    gmsh::option::setNumber("Mesh.HighOrderOptimize", 0);
    gmsh::option::setNumber("Mesh.Algorithm3D", 1);
    gmsh::model::mesh::generate(3);
    return read_open_model("hertz3d (Gmsh mesh)");
  }
  catch (const Error&)
  {
    throw;
  }
  catch (const std::string& message)
  {
    throw Error("hertz3d (Gmsh mesh): " + message);
  }
}
} // namespace feticon::mesh
