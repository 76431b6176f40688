#pragma once
/// @file A contact face of any type (tri3, tri6, quad4, quad8) in the current configuration, and
/// what the contact rows need of it: its points, normals and shape functions at reference
/// coordinates xi, the closest-point projection, whether xi lies inside, its size and its
/// slave nodal areas.
///
/// Reference faces (fem/reference_face.hpp): triangles on the unit triangle (corners (0,0),
/// (1,0), (0,1)), quadrilaterals on [-1, 1]^2. quad4 faces go through closest_point.hpp's
/// bilinear code unchanged (the arithmetic of hex8 runs before faces had types); the others
/// through the general Newton iteration of project_to_face, whose curvature term is a central
/// difference of the shape gradients (exact for tri3, whose map is linear).
///
/// Slave nodal areas. The contact pressure at a slave node is its normal force over its area.
/// For quadratic faces int N_a dA is zero at a tri6's corners and negative at a quad8's, so the
/// areas are lumped from linear sub-facets instead: a tri6 as its four corner-and-midpoint
/// triangles, a quad8 as its four corner triangles and the quadrilateral of its midpoints; each
/// triangle gives a third of its area to each of its nodes, each quadrilateral int N_a dA. Every
/// node gets a positive area and they sum to the face's (facet) area. An edge of a 2D cell
/// (line2, line3; mesh::Planar) is a face too: its normal x_,xi x e_z, its area its length
/// times the thickness (or 2 pi r, int N_a 2 pi r ds); a line3 lumps as its two halves.

#include "contact/closest_point.hpp"
#include "fem/reference_face.hpp"
#include "la/types.hpp"
#include "mesh/mesh.hpp"

#include <Eigen/Dense>

#include <vector>

namespace feticon::contact
{
/// Node coordinates of a face, one row per face node (at most 8).
using FaceNodeCoordinates = Eigen::Matrix<double, Eigen::Dynamic, 3, 0, 8, 3>;

struct FaceGeometry
{
  mesh::FaceKind kind = mesh::FaceKind::quad4;
  FaceNodeCoordinates x;
  mesh::Planar planar = {}; ///< the mesh's: an edge's area is its length times the out-of-plane measure

  int n_corners() const { return mesh::face_corners(kind); }
  /// The first four rows as a quad (quad4 only).
  QuadCoordinates quad() const { return x.topRows<4>(); }
};

/// @brief The face's node coordinates x = X + u (m); u empty for u = 0.
FaceGeometry current_face_geometry(const mesh::Mesh& mesh, const la::Vector& u, const mesh::Face& face);

/// Reference coordinates of corner k of a face type.
Eigen::Vector2d face_corner_xi(mesh::FaceKind kind, int k);
/// Reference coordinates of node a (corners, then edge midpoints) of a face type.
Eigen::Vector2d face_node_xi(mesh::FaceKind kind, int a);
/// Linear sub-facets of a face as local node lists, counter-clockwise seen from outside (file
/// comment): the face itself for tri3 and quad4.
const std::vector<std::vector<int>>& face_sub_facets(mesh::FaceKind kind);
/// How far xi lies outside the reference face, in reference units: max(|xi|, |eta|) - 1 for a
/// quadrilateral, max(-xi, -eta, xi + eta - 1) for a triangle; <= 0 inside.
double outside_distance(mesh::FaceKind kind, const Eigen::Vector2d& xi);
/// Whether xi lies within `extension` (reference units) of the reference face.
bool within_extension(mesh::FaceKind kind, const Eigen::Vector2d& xi, double extension);
/// Shape functions of the face's nodes at xi (quad4: quad_shape_functions).
fem::FaceValues face_weights(mesh::FaceKind kind, const Eigen::Vector2d& xi);
/// The point x(xi) (m).
Eigen::Vector3d face_point(const FaceGeometry& face, const Eigen::Vector2d& xi);
/// Unit normal x_,xi x x_,eta / |.| at xi, outward of the face's body; zero if degenerate there.
Eigen::Vector3d face_normal(const FaceGeometry& face, const Eigen::Vector2d& xi);
/// The longer diagonal of a quad (m).
double face_diagonal(const QuadCoordinates& quad);
/// The longest distance between two corners (a quad4's longer diagonal, face_diagonal) (m).
double face_size(const FaceGeometry& face);
/// @brief Closest point on the face to `point`, as project_to_quad (whose result type it
/// shares; `inside` means outside_distance <= options.inside_tolerance).
QuadProjection project_to_face(const FaceGeometry& face, const Eigen::Vector3d& point,
                               const ProjectionOptions& options = {});
/// The master face's area as CalculiX's node-to-face springs estimate it for a slave node
/// without an area (springforc_n2f.f) from dm = |x_,xi x x_,eta| at the closest point xi: 4 dm
/// on a quadrilateral, dm / 2 on a triangle (the area of a parallelogram or a flat triangle);
/// an edge's 2 |x_,xi| times the out-of-plane measure (its quadrilateral face in CalculiX's 3D
/// expansion). CalculiX takes 4 dm on a tri6 face too, 8 times its area: not followed.
double face_area_estimate(const FaceGeometry& face, const Eigen::Vector2d& xi);
/// Lumped slave nodal areas of the face's nodes (m^2), positive (see file comment).
Eigen::VectorXd face_lumped_areas(const FaceGeometry& face);
} // namespace feticon::contact
