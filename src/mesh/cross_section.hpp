#pragma once
/// @file A quadrilateral mesh of a plane region (z = 0), which Gmsh builds with a size field:
/// graded, shape-regular meshes of plane-strain bodies without the needle cells of
/// tensor-product grading; as quad4 cells of a 2D model (mesh::Planar) or extruded into one
/// hex8 layer.
///
/// The region is bounded by one closed loop of straight segments and circular arcs,
/// counter-clockwise. Gmsh meshes it with triangles (frontal-Delaunay) and recombines them
/// into quadrilaterals (blossom matching), then smooths; a mesh that keeps a triangle is an
/// error. Every boundary curve carries a name; the edges (2D) or extruded faces (hex8 layer) of
/// all curves of one name form the face set of that name (outward); the layer's two faces are
/// "zmin" / "zmax". Each face set also becomes the node set of the same name.

#include "mesh/mesh.hpp"

#include <functional>
#include <string>
#include <vector>

namespace feticon::mesh
{
/// A boundary curve from the previous curve's end to `end`: straight, or a circular arc about
/// `centre` (shorter than half a circle, as Gmsh requires).
struct CrossSectionCurve
{
  Eigen::Vector2d end;
  std::string set;
  bool arc = false;
  Eigen::Vector2d centre{0, 0};
};

struct CrossSection
{
  std::string body;
  Eigen::Vector2d start;                 ///< first point of the loop (m)
  std::vector<CrossSectionCurve> curves; ///< counter-clockwise, the last ends at `start`
};

/// Target cell size (m) at a point (x, y) of the plane.
using SizeField = std::function<double(double x, double y)>;

/// @brief Meshes `section` with quadrilaterals of the size `size` and extrudes them into one
/// layer of hex8 cells of thickness `thickness` (m) along z.
/// @throws feticon::Error if Gmsh fails or leaves a cell that is not a quadrilateral.
Mesh extrude_cross_section(const CrossSection& section, const SizeField& size, double thickness);

/// @brief Meshes `section` with quad4 cells of the size `size` for the 2D formulation `planar`
/// (its line2 edges as the curves' face sets).
/// @throws feticon::Error as extrude_cross_section, or if planar is not 2D.
Mesh mesh_cross_section(const CrossSection& section, const SizeField& size, const Planar& planar);
} // namespace feticon::mesh
