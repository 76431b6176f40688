#pragma once
/// @file Node-to-segment contact rows B_I, c_I (ALGORITHMS.md sections 0 and 4). The dual mortar
/// rows of mortar_constraints.hpp share this data layout (ContactOptions::formulation).
///
/// For every slave node s (a node of the slave face set) and its closest point xi_bar on a master
/// face with corners a = 0..3, in the current configuration x = X + u:
///   gap  g = n . (x_s - sum_a N_a(xi_bar) x_a),  n the unit outward normal of the master body,
///        g >= 0 open, g < 0 penetration;
///   row  b = -grad_u g: -n' on the three DOFs of s, +N_a(xi_bar) n' on those of master node a;
///   rhs  c = g.
/// The constraint on a displacement increment du is b du <= c, i.e. the linearized new gap
/// g + n . (du_s - sum_a N_a du_a) >= 0 (sign convention 2). Each row is stored normalized:
///   B_i = b / |b|,  c_i = g / |b|,  |b|^2 = 1 + sum_a N_a^2 (n is a unit vector),
/// so B_I B_I' has a unit diagonal; row_norm keeps |b| and gap keeps the unnormalized g.
///
/// Multipliers. With normalized rows the multiplier lambda_hat_i >= 0 of row i is a scaled force
/// (sign convention 1: the constraint forces on the structure are -B' lambda_hat):
///   - on the slave node:   +(lambda_hat_i / |b_i|) n_i   (pushes the slave away from the master)
///   - on master node a:    -(lambda_hat_i / |b_i|) N_a n_i,
/// which sum to zero. contact_forces() returns -B' lambda_hat (N, per global DOF);
/// slave_normal_forces() returns the magnitudes lambda_i = lambda_hat_i / |b_i| (N).
///
/// Search and projection (section 4). Candidate master faces come from SurfaceSearch on the face
/// boxes inflated by the search distance d_s; the slave node is projected onto the candidates
/// (project_to_quad) and the accepted projection (converged, |xi|, |eta| <= 1 + 1e-6) with the
/// smallest |g| is kept (first face id on ties); faces having the slave node as a corner are
/// skipped. Candidates are visited by increasing distance to their un-inflated box and the visit
/// stops once that distance exceeds the best |g|, which cannot change the result since
/// |g| = |x_s - x(xi_bar)| >= box distance. A row is created only if g < d_s.
///
/// Outside every face. If no candidate projection is accepted, the node lies either in the "blind
/// spot" next to a convex master edge, or beyond the rim (boundary) of the master surface. The
/// closest point x_e on the edges of the candidate faces (straight segments for bilinear faces) is
/// found, on face f:
///   - Beyond the rim: the node lies beyond a boundary side of f (a side no other master face
///     has), i.e. (x_s - x_k) . ((x_k+1 - x_k) x n_f) > 1e-6 * face size. If the projection on f
///     converges with |xi|, |eta| <= 1 + rim_extension, the node gets a row on the extended face
///     (kind rim: the bilinear map and normal of f continued past its side, N_a may be slightly
///     negative); this keeps rim nodes in contact when a tilted master normal moves the
///     projection of a slightly penetrating node just past the rim. Otherwise the node overhangs
///     the master surface and is skipped (counted in n_overhanging).
///   - Blind spot (not beyond the rim): a node-to-edge row (kind edge). The closest point is
///     x_e = sum_a N_a(xi_e) x_a with xi_e on the boundary of f's reference square (only the
///     edge's end nodes have N_a != 0, one node at a corner), the normal is the distance
///     direction n = sign(d . n_f) d / |d| with d = x_s - x_e and n_f the face normal at xi_e, and
///     g = n . d = sign(d . n_f) |d|. At the closest point of a segment the variations of x_e and
///     n drop out as for a face, so the row -n' / +N_a n' is again -grad_u g, and g is continuous
///     with the face gaps at the borders of the blind spot. If |d| is below 1e-12 of the face
///     size, n = n_f and g = 0.
/// Limitation: a node that is both beyond the rim and in the blind spot of a ridge reaching the
/// rim gets a row only if its projection on f lies within the rim extension.
///
/// Automatic search distance (options.search_distance = 0): the largest diagonal of the master
/// faces in the current configuration, i.e. one master element: any slave node within one element
/// of the master surface gets a row (a closed or nearly closed contact is never missed), at the
/// price of inactive rows for the nodes of that band.
///
/// Near contact (options.near_contact_fraction = f, finite): rows only for the nodes that touch
/// or nearly touch, g < max(g_min, 0) + f d_face, with g_min the smallest gap of the pair and
/// d_face the longer diagonal of the node's master face. For loops that rebuild the rows in the
/// current configuration (the outer loop of large displacements): a node that closes its gap
/// has g < 0, and so a row, at the next rebuild, and a load step ends only with an unchanged
/// active set. Bodies apart get rows where they are closest. A single linear solve needs the
/// rows of every node that can close its gap: f = infinity (default). On the graded Hertz and
/// hertz3d meshes the one-element band held hundreds of rows that were never active but sit in
/// G and the preconditioner's (B B')^-1 scaling (docs/contact.md, "Rows near contact").
///
/// Usage (rebuild in the current configuration at every outer iteration, section 8):
///   const ContactPair pair{.slave = "cylinder_contact", .master = "block_contact"};
///   const ContactConstraints rows = build_contact_constraints(mesh, u, pair);
///   // rows.B (global DOFs) and rows.c are B_I and c_I; after the solve:
///   const la::Vector f_contact = contact_forces(rows, lambda_I, 3 * mesh.n_nodes());
///   const la::Vector p_nodal = slave_normal_forces(rows, lambda_I);

#include "contact/closest_point.hpp"
#include "contact/face_geometry.hpp"
#include "contact/surface_search.hpp"

#include "fem/contact_interaction.hpp"
#include "la/types.hpp"
#include "mesh/mesh.hpp"

#include <cstdint>
#include <limits>
#include <string>
#include <vector>

namespace feticon::contact
{
/// A slave and a master surface, by face-set name in the mesh.
struct ContactPair
{
  std::string slave;
  std::string master;
  /// If not empty, the node set that restricts the slave nodes (fem::ContactPairNames).
  std::string slave_nodes = {};
};

/// The slave nodes of a pair, sorted: the slave faces' nodes, restricted to pair.slave_nodes.
std::vector<int32_t> slave_nodes(const mesh::Mesh& mesh, const ContactPair& pair);

/// How the rows are built (fem/contact_interaction.hpp): node_to_segment (this file) or mortar
/// (mortar_constraints.hpp).
using ContactFormulation = fem::ContactFormulation;

struct ContactOptions
{
  /// Search distance d_s (m): candidate faces are those whose box inflated by d_s contains the
  /// slave node, and a row is created only for g < d_s. 0 = automatic (see file comment); >= 0.
  double search_distance = 0;
  /// Rim extension (reference coordinates, >= 0): a node beyond the boundary of the master
  /// surface still gets a row on the nearest face if its projection there has
  /// |xi|, |eta| <= 1 + rim_extension (see file comment). 0.05 is 2.5 % of the face width.
  double rim_extension = 0.05;
  /// Row formulation; node_to_segment until the mortar rows are validated on the solvers.
  ContactFormulation formulation = ContactFormulation::node_to_segment;
  /// Mortar only, in (0, 1]: a slave node j gets a row only if the part of its support that
  /// projects onto the master surface has the overlap o_j = sum_a M_ja / D_j >= this (1 for full
  /// overlap; about 0.5 for a node on a straight master rim, 0.25 on a master corner). The
  /// weights M_ja / D_j are divided by o_j (mortar_constraints.hpp), at most 1 / 0.2 = 5 times.
  double mortar_min_overlap = 0.2;
  /// Rows only for g < max(g_min, 0) + near_contact_fraction * (diagonal of the node's master
  /// face), see file comment; > 0. Infinity (default): every node within d_s.
  double near_contact_fraction = std::numeric_limits<double>::infinity();
};

/// How the closest point of a row (for mortar rows: of its slave node) was found.
enum class ProjectionKind : uint8_t
{
  face = 0, ///< accepted projection inside a master face
  edge = 1, ///< outside every face: closest point on an interior master edge or node
  rim = 2,  ///< just beyond the boundary of the master surface: projection on the extended face
};

/// What identifies a contact row from one outer iteration to the next: its pair and its slave
/// node, (pair << 32) | node. For pair 0 the key is the node.
inline int64_t contact_key(int32_t pair, int32_t slave_node)
{
  return (static_cast<int64_t>(pair) << 32) | static_cast<uint32_t>(slave_node);
}
/// The slave node of a key.
inline int32_t key_node(int64_t key) { return static_cast<int32_t>(key & 0xffffffff); }
/// The pair of a key.
inline int32_t key_pair(int64_t key) { return static_cast<int32_t>(key >> 32); }

/// Contact rows B_I u <= c_I, normalized (see file comment). Row i belongs to slave_node[i] of
/// pair pair[i]; the rows of several pairs come pair after pair (concatenate_pairs).
struct ContactConstraints
{
  /// Normalized rows b_i / |b_i| over the global DOFs 3 * node + component: rows x 3 n_nodes.
  Eigen::SparseMatrix<double, Eigen::RowMajor> B;
  /// Normalized gaps g_i / |b_i| (m).
  la::Vector c;
  /// Slave node of each row.
  std::vector<int32_t> slave_node;
  /// Contact pair of each row (its index in fem::Problem::contacts; 0 for a single pair's rows).
  std::vector<int32_t> pair;
  /// Unit normal of each row, outward of the master body (points towards the slave).
  std::vector<Eigen::Vector3d> normal;
  /// Unnormalized geometric gap g_i (m): >= 0 open, < 0 penetration.
  std::vector<double> gap;
  /// |b_i| = sqrt(1 + sum_a w_a^2) before normalization; for node-to-segment rows w_a = N_a and
  /// |b_i| is in [sqrt(5)/2, sqrt(2)] (up to the slightly negative N_a of rim rows).
  std::vector<double> row_norm;
  /// Slave nodal area D_j = int N_j dA over the slave faces of the row's node, in the current
  /// configuration (m^2): the nodal contact pressure is slave_normal_forces / slave_area.
  std::vector<double> slave_area;
  /// Index of the master face (into the master face set) of each row.
  std::vector<int32_t> master_face;
  /// Reference coordinates (xi, eta) of the closest point on that face.
  std::vector<Eigen::Vector2d> xi;
  /// Face projection or edge fallback, per row.
  std::vector<ProjectionKind> kind;
  /// Sum of the master weights w_a of each row: the share of the row's force on its slave node
  /// that the master surface takes. 1, but for the rows of the edge nodes of quadratic slave
  /// faces in mortar, 1 - 2 alpha: their rows put the rest on their edge's corners
  /// (mortar_face_integration.hpp).
  std::vector<double> master_share;
  /// Node-to-segment rows of a slave node that is a corner of no slave face (an edge node of
  /// quadratic faces, any node of a 2D model): the master face's area at the closest point
  /// (face_area_estimate), the area of a law that acts on it (fem::NormalLaw::on_master_face);
  /// 0 for other rows and mortar rows.
  std::vector<double> master_face_area;
  /// How the rows were made: mortar rows' force over slave_area is the nodal pressure of the
  /// dual traction at every node, quadratic faces included.
  ContactFormulation formulation = ContactFormulation::node_to_segment;
  /// Rows of several pairs (concatenate_pairs): each pair's formulation, by pair, which
  /// pair_rows gives back to the rows of one pair; empty for one pair's rows (`formulation`).
  std::vector<ContactFormulation> pair_formulation;
  /// Mortar rows on tri6 / quad8 slave faces, with the transformed dual basis
  /// (mortar_face_integration.hpp), whose rows spread their weight wider than bilinear ones.
  bool transformed_basis = false;
  /// Search distance d_s actually used (m).
  double search_distance = 0;
  /// Slave nodes of the pair, and those skipped because they overhang the master surface.
  int32_t n_slave_nodes = 0;
  int32_t n_overhanging = 0;

  int64_t n_rows() const { return static_cast<int64_t>(slave_node.size()); }
  /// contact_key of row i.
  int64_t key(int64_t i) const { return contact_key(pair[i], slave_node[i]); }
  /// contact_key of every row.
  std::vector<int64_t> keys() const;
};

/// @brief Current corner coordinates x = X + u of a face (m).
/// @param[in] u global displacement (3 per node), or empty for u = 0
QuadCoordinates current_face_coordinates(const mesh::Mesh& mesh, const la::Vector& u, const mesh::Face& face);

/// @brief Largest size (face_size: a quad4's longer diagonal) of the faces of `faces` in the current configuration (m): the
/// automatic search distance.
double largest_face_diagonal(const mesh::Mesh& mesh, const la::Vector& u, const std::vector<mesh::Face>& faces);

/// @brief Contact rows of `pair` at the displacement `u`: build_node_to_segment_constraints or
/// build_mortar_constraints (mortar_constraints.hpp) according to options.formulation.
/// @param[in] mesh    mesh holding both face sets (faces oriented outward of their bodies)
/// @param[in] u       global displacement (m), 3 per node (3 * node + component), or empty for 0
/// @param[in] pair    slave and master face-set names
/// @param[in] options search distance, rim extension, formulation
/// @return rows sorted by slave node id
/// @throws feticon::Error for an unknown face set, an empty master set, a wrong size of u or a
///         negative search distance or rim extension, or mortar_min_overlap outside (0, 1].
ContactConstraints build_contact_constraints(const mesh::Mesh& mesh, const la::Vector& u, const ContactPair& pair,
                                             const ContactOptions& options = {});

/// @brief The rows of several pairs as one block, pair after pair: `parts[p]`'s rows get
/// pair p. The per-pair figures (search distance, slave counts) are the largest and the sums;
/// `formulation` is part 0's, `pair_formulation` every part's, `transformed_basis` any part's.
/// No parts: no rows over n_global_dofs DOFs.
ContactConstraints concatenate_pairs(std::vector<ContactConstraints> parts, la::Index n_global_dofs);

/// @brief The rows of pair p alone (in their order, with that pair's formulation), for the
/// outputs of one pair.
ContactConstraints pair_rows(const ContactConstraints& rows, int32_t p);

/// @brief No rows over n_global_dofs DOFs, of a pair of formulation `formulation` (a pair out of
/// force in a step, among the parts of concatenate_pairs).
ContactConstraints no_rows(ContactFormulation formulation, la::Index n_global_dofs);

/// @brief `rows` without its rows: the figures of the search (formulation, search distance,
/// slave counts), for a subset of its rows to be built into (ContactRowBuilder::finish).
ContactConstraints without_rows(const ContactConstraints& rows);

/// @brief Node-to-segment rows of `pair` (see file comment); options.formulation is ignored.
/// Arguments, result and errors as build_contact_constraints.
ContactConstraints build_node_to_segment_constraints(const mesh::Mesh& mesh, const la::Vector& u,
                                                     const ContactPair& pair, const ContactOptions& options = {});

/// @brief Constraint forces -B' lambda_hat on the structure (N, per global DOF), with lambda_hat
/// the multipliers of the normalized rows.
/// @param[in] n_global_dofs length of the result, = B.cols() (3 n_nodes)
la::Vector contact_forces(const ContactConstraints& constraints, const la::Vector& lambda_hat, int64_t n_global_dofs);

/// @brief Normal force magnitude on the slave node of each row, lambda_hat_i / |b_i| (N); the
/// force on slave_node[i] is this times normal[i].
la::Vector slave_normal_forces(const ContactConstraints& constraints, const la::Vector& lambda_hat);
} // namespace feticon::contact
