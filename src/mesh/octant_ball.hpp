#pragma once
/// @file A graded, shape-regular all-hex mesh of one octant of a ball {x, y, d >= 0, |p| <= R}:
/// the neighbourhood of a point load or of a 3D contact point (issue 20).
///
/// A uniform core cube [0, c]^3 (c = n h) holds the fine cells; around it, layers of cells
/// follow rays from the origin through the nodes of the core's three outer faces, so every
/// layer has the same 3 n^2 cells and their size grows in proportion to the distance from the
/// origin (the grading a point load asks for, with no needle cells: the radial size is a fixed
/// multiple, `radial_aspect`, of the tangential size). The first layers blend the cube's
/// faces into a sphere (cubed-sphere panels), so the outer boundary is the sphere |p| = R.
/// Points of the planes x = 0, y = 0 and d = 0 stay in their plane, so the octant's three
/// flat faces are exact (symmetry planes and a flat contact face).
///
/// Built directly rather than with Gmsh: Gmsh 4.8's all-hex routes are transfinite volumes
/// (the same blocks, assembled by hand in a .geo) or subdivision of tetrahedra (four cells per
/// tetrahedron, unstructured contact faces); this is the structured one, exact and instant.

#include <Eigen/Dense>

#include <cstdint>
#include <vector>

#include "mesh/mesh.hpp"

namespace feticon::mesh
{
struct OctantBallParameters
{
  double cell_size = 1;     ///< h: edge of the core's cells
  int core_cells = 8;       ///< n: core cells along each edge, core = [0, n h]^3
  double radius = 10;       ///< R: outer radius, at least 2.5 times the core width
  double radial_aspect = 2; ///< radial over mean tangential cell size in the shell layers
};

/// The mesh in its local coordinates (x, y, d); cells and faces oriented positively there.
struct OctantBall
{
  Eigen::Matrix<double, Eigen::Dynamic, 3, Eigen::RowMajor> nodes;
  std::vector<Hex8Nodes> cells;
  std::vector<Face> flat;       ///< boundary faces on d = 0, oriented outward (-d)
  std::vector<Face> outer;      ///< boundary faces on the sphere |p| = R
  std::vector<Face> symmetry_x; ///< boundary faces on x = 0
  std::vector<Face> symmetry_y; ///< boundary faces on y = 0
  int layers = 0;               ///< shell layers between the core and the sphere
};

/// Counts of the mesh octant_ball would build, without building it (memory estimates).
struct OctantBallSize
{
  int layers = 0;       ///< shell layers
  int blend_layers = 0; ///< the first layers, which blend the core's faces into the sphere
  int64_t nodes = 0;
  int64_t cells = 0;
  int64_t plane_nodes = 0; ///< nodes on each of the planes x = 0 and y = 0
};

/// @throws feticon::Error when a parameter is out of range (the message names it).
OctantBallSize octant_ball_size(const OctantBallParameters& parameters);

/// @throws feticon::Error when a parameter is out of range (the message names it).
OctantBall octant_ball(const OctantBallParameters& parameters);

/// The ball's half {y, d >= 0}: `ball` and its mirror image across x = 0, sharing the nodes of
/// that plane (numbered first as in `ball`, the images after them). Cells and faces stay
/// positive and outward; `symmetry_x` is empty (the plane is inside), the other face lists
/// gain their images. For a load that breaks the symmetry x -> -x (hertz3d's tangential load).
OctantBall mirrored_across_x(const OctantBall& ball);
} // namespace feticon::mesh
