#pragma once
/// @file Structured 2D meshes (issue 64): a mapped block of quadrilaterals (quad4, quad8) or of
/// triangles (tri3, tri6: each quadrilateral cut along its diagonal from (i, j) to
/// (i + 1, j + 1)), in the x-y plane, one body, for a planar formulation (mesh::Planar).
///
/// Grid point (i, j), 0 <= i <= 2 n_x and 0 <= j <= 2 n_y in half-cell steps, is placed by a
/// user map at (i / 2, j / 2) in cell units; corners are the even points, edge midpoints of
/// quadratic cells the others (the centre of a cell only for tri6, on its diagonal). The map
/// must keep the orientation (x growing with i, y with j for a rectangle) so that cells run
/// counter-clockwise. The four sides are edge sets (and node sets) "xmin" (i = 0), "xmax",
/// "ymin", "ymax", each edge oriented with the body on its left (outward normal
/// (x1 - x0) x e_z).
///
/// Usage (an axisymmetric ring, r in [1, 2], z in [0, 0.5]):
///   Mesh ring = generate_rectangle({.origin = {1, 0}, .lengths = {1, 0.5}, .nx = 8, .ny = 4,
///                                   .kind = CellKind::quad8, .planar = {PlanarKind::axisymmetric},
///                                   .body_name = "ring"});

#include "mesh/mesh.hpp"

#include <functional>
#include <string>

#include <Eigen/Dense>

namespace feticon::mesh
{
/// Places grid point (i, j) of a structured 2D block in half-cell steps (m; z must be 0).
using PlanarGridMap = std::function<Eigen::Vector2d(double i, double j)>;

/// @brief Structured block of n_x * n_y quadrilaterals (or twice as many triangles) of type
/// `kind`, placed by `point` (cell units: point(i, j) with i in [0, n_x], j in [0, n_y]).
/// @throws feticon::Error for a 3D cell kind, n < 1, or a cell the map inverts.
Mesh generate_mapped_rectangle(const std::array<int32_t, 2>& n_cells, const PlanarGridMap& point, CellKind kind,
                               const Planar& planar, const std::string& body_name);

/// Axis-aligned rectangle [origin, origin + lengths] meshed by nx * ny equal cells.
struct RectangleParameters
{
  Eigen::Vector2d origin{0, 0};  ///< corner with the smallest coordinates (m)
  Eigen::Vector2d lengths{1, 1}; ///< along x, y (m), each > 0
  int nx = 1, ny = 1;            ///< cells along x, y, each >= 1
  CellKind kind = CellKind::quad4;
  Planar planar = {PlanarKind::plane_strain, 1};
  std::string body_name = "rectangle";
};

/// @brief Structured rectangle mesh, one body, with the four side sets (file comment).
Mesh generate_rectangle(const RectangleParameters& parameters);
} // namespace feticon::mesh
