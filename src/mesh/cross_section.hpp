#pragma once
/// @file One hex8 layer extruded from a quadrilateral mesh of a plane region (z = 0), which
/// Gmsh builds with a size field: graded, shape-regular meshes of plane-strain bodies without
/// the needle cells of tensor-product grading.
///
/// The region is bounded by one closed loop of straight segments and circular arcs,
/// counter-clockwise. Gmsh meshes it with triangles (frontal-Delaunay) and recombines them
/// into quadrilaterals (blossom matching), then smooths; a mesh that keeps a triangle is an
/// error. Every boundary curve carries a name; the extruded faces of all curves of one name
/// form the face set of that name (outward), and "zmin" / "zmax" are the layer's two faces.
/// Each face set also becomes the node set of the same name.

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
} // namespace feticon::mesh
