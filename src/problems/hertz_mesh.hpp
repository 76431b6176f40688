#pragma once
/// @file Mesh of the Hertz line-contact problem (ALGORITHMS.md section 9): a cylinder of radius R1
/// pressed on a half-space, plane strain, modelled by quad4 cells of a 2D model (the default,
/// thickness `thickness`, line2 edges as faces) or by one hex8 layer in z with u_z eliminated
/// (the model of the paper and of feticon before 2D cells, kept for comparison).
///
/// Geometry (m). The contact point is the origin, the cylinder axis is (0, R1) and only x >= 0 is
/// meshed: the plane x = 0 is a symmetry plane (u_x = 0 there, which also removes the sideways
/// rigid motion that frictionless contact cannot resist).
///  - body 0 "cylinder": the part of the lower half of the cylinder with 0 <= x <= Xc, between the
///    arc y_b(x) = R1 - sqrt(R1^2 - x^2) and the plane y = R1 through the axis, where the line load
///    is applied; bounded on the right by the plane x = Xc.
///  - body 1 "block": the half-space truncated to 0 <= x <= W, -D <= y <= 0, supported at y = -D.
///  - hex8 layer: z in [0, thickness], one cell layer.
///
/// Mesh `graded` (the default). Each body's cross-section is meshed by Gmsh with
/// quadrilaterals (mesh/cross_section.hpp) of size h_b (h_slave = h, h_master = master_ratio * h)
/// in the contact band [0, fine_width] x {0} and h_b + (q - 1) d at the distance d from it, so
/// that cells grow by about q from one to the next in every direction, up to a tenth of the
/// largest body dimension; the arc is meshed as Gmsh's circle. No needle cells: the sizes
/// vary smoothly in both directions, unlike the tensor grading, which carries the contact
/// spacing out to the boundary along rows and columns. `refinement` r scales h only, so the
/// far field is refined only as far as the grading reaches.
///
/// Mesh `tensor`. Each body is a mapped structured block (mesh/box.hpp). Along x the cells have the size h on
/// [0, x_fine] and then grow geometrically with ratio q (graded_positions). The cylinder uses
/// h_slave = h and the block h_master = master_ratio * h, so the two contact surfaces do not match
/// (node-to-segment contact is exercised; with master_ratio = 13/10 every 13th slave node in the
/// uniform zone still lands on a master node, which is harmless). Vertically the distance from
/// the contact surface is graded by the same rule: for the cylinder on [0, R1], scaled in the
/// column at abscissa x to its height R1 - y_b(x), i.e. y = y_b(x) + s (R1 - y_b(x)) with
/// s in [0, 1]; for the block y = -d with d on [0, D] and the spacing h_master near the top. The
/// arc nodes lie exactly on the circle; the arc is approximated by chords. `refinement` r scales
/// every cell size: h -> h / r and q -> q^(1/r), so the graded region refines too.
///
/// Defaults. With the steel data of section 9 the contact half-width is a = 68 mm. h = 5 mm, below
/// the a/10 = 6.8 mm asked for, gives a / h = 13.6 cells across the modelled half (27 across 2a).
/// W = D = 1.5 m is more than 20 a: Hertz assumes half-spaces, and the finite block perturbs the
/// contact pressure by O((a / L)^2) = (0.068 / 1.5)^2 = 0.2 %, below the discretization error
/// (verify numerically by doubling W and D). Xc = 0.6 m (about 9 a) keeps the load plane far from
/// the contact zone, and the cylinder height R1 = 1 m is about 15 a.
///
/// Sets (face set and node set of the same name, faces outward from their body):
///   "cylinder_contact" arc faces (slave surface)     "block_contact" y = 0 (master surface)
///   "load"             cylinder top y = R1            "support"       block bottom y = -D
///   "cylinder_symmetry", "block_symmetry" x = 0       "cylinder_side" x = Xc, "block_side" x = W
///   "zmin", "zmax"     the z faces of both bodies (hex8 layer only)
/// and the node set "symmetry" = cylinder_symmetry + block_symmetry nodes. The full model
/// (HertzMeshParameters::full) has no symmetry sets; its "cylinder_side" and "block_side" are
/// both sides.

#include "mesh/mesh.hpp"

#include <cstdint>
#include <string>

namespace feticon::problems
{
enum class HertzMeshKind
{
  graded, ///< Gmsh quadrilaterals with a size field (shape-regular)
  tensor  ///< mapped blocks with tensor-product grading (needle cells far from the contact)
};

enum class HertzCells
{
  quad4,     ///< 2D plane-strain cells (mesh::Planar)
  hex8_layer ///< one hex8 layer through the thickness
};

/// Dimensions (m) and grading of the Hertz mesh; defaults as in the file comment.
struct HertzMeshParameters
{
  HertzMeshKind kind = HertzMeshKind::graded;
  HertzCells cells = HertzCells::quad4;
  /// The quad4 cells axisymmetric about x = 0 (the axis; y along it) instead of plane strain:
  /// the cylinder becomes a sphere of radius cylinder_radius (hertz_axi.hpp).
  bool axisymmetric = false;
  /// Cylinder radius R1 (m).
  double cylinder_radius = 1.0;
  /// Half-width Xc of the modelled cylinder segment (m), < R1.
  double cylinder_width = 0.6;
  /// Width W of the modelled block, x in [0, W] (m).
  double block_width = 1.5;
  /// Depth D of the block, y in [-D, 0] (m).
  double block_depth = 1.5;
  /// Thickness of the model (m): of the 2D cells, or in z of the single hex8 layer.
  double thickness = 0.01;
  /// Cell size h on the cylinder near the contact, before refinement (m).
  double element_size = 0.005;
  /// Block cell size near the contact relative to the cylinder's (h_master = master_ratio * h).
  double master_ratio = 1.3;
  /// Extent x_fine of the uniform cells along x (m).
  double fine_width = 0.1;
  /// Extent y_fine of the uniform cells in distance from the contact surface (m; tensor).
  double fine_depth = 0.1;
  /// Growth ratio q of consecutive cells beyond the fine region, before refinement.
  double growth_ratio = 1.1;
  /// Refinement factor r: h -> h / r; for the tensor mesh also q -> q^(1/r).
  double refinement = 1.0;
  /// Both halves, -Xc <= x <= Xc and -W <= x <= W, without the symmetry sets: a tangential load
  /// breaks the symmetry (graded mesh only).
  bool full = false;
};

/// @brief Builds the Hertz mesh described in the file comment.
/// @throws feticon::Error naming the offending parameter if one is out of range.
/// The graded mesh comes from the mesh cache when it was made before (mesh/mesh_cache.hpp).
/// @param[out] from_cache whether it did (may be null)
mesh::Mesh generate_hertz(const HertzMeshParameters& parameters, bool* from_cache = nullptr);

/// Nodes of the mesh generate_hertz would build, estimated without building it (memory guard):
/// exact up to rounding for `tensor`, the integral of the size field for `graded`.
/// @throws feticon::Error as generate_hertz for parameters out of range
int64_t hertz_node_estimate(const HertzMeshParameters& parameters);

/// Cell sizes of a contact surface near the first contact point x = 0.
struct ContactZoneSummary
{
  /// Faces of the set that reach into 0 <= x < half_width (all z layers).
  int32_t n_faces = 0;
  /// Smallest and largest in-plane (x-y) size of those faces (m).
  double min_size = 0;
  double max_size = 0;
};

/// @brief Sizes of the faces of `face_set` within x < half_width, e.g. the Hertz half-width a.
///
/// The in-plane size of a face is the largest x-y distance between two of its nodes, i.e. the
/// chord length for faces extruded along z.
/// @throws feticon::Error if no face of the set reaches into x < half_width.
ContactZoneSummary summarize_contact_zone(const mesh::Mesh& mesh, const std::string& face_set, double half_width);
} // namespace feticon::problems
