#pragma once
/// @file Dual mortar contact rows (Wohlmuth 2000; Popp, Gee, Wall 2009, IJNME 79), in the same
/// form as the node-to-segment rows of contact_constraints.hpp so that nothing downstream changes.
///
/// Coupling. With the dual basis Phi_j of the slave faces (mortar_integration.hpp), for every
/// slave node j of the slave face set and master node a, in the current configuration x = X + u:
///   D_j  = int_slave Phi_j N_j dA = int_slave N_j dA            (m^2, sum over j's faces),
///   M_ja = int_slave Phi_j N_a^m(pi(x)) dA                       (m^2),
/// with pi(x) the projection of the slave point x onto the master surface along the normal n_0 of
/// the slave face at its centre (auxiliary plane; exactly the closest point for flat parallel
/// surfaces, and consistent with the segmentation: every integration point of a segment maps
/// into its master face). M is integrated per (slave face, master face) segment: candidate master
/// faces are those whose box inflated by the search distance d_s meets the slave face's box
/// (SurfaceSearch); master faces sharing a node with the slave face are skipped.
///
/// Rows. Slave node j gets a row where the node-to-segment formulation gives one (same d_s, rim
/// extension and edge handling), with the node-to-segment normal n_j: the master normal at the
/// closest point of node j (for an edge row the distance direction). With the overlap
///   o_j = sum_a M_ja / D_j   (1 for a support entirely over the master surface, because
///                             sum_a N_a^m = 1 and int Phi_j dA = D_j),
/// the row needs o_j >= ContactOptions::mortar_min_overlap (else the node is counted in
/// n_overhanging), and gets the weights
///   w_ja = M_ja / sum_b M_jb,  i.e. M_ja / D_j renormalized to sum_a w_ja = 1 where the support
///                              of j covers the master surface only in part (at the rim);
///                              entries |M_ja| <= 1e-13 D_j (round-off) are left out;
///   g_j  = n_j . (x_j - sum_a w_ja x_a)        (weighted gap, m; the row exists if g_j < d_s),
///   b    = -n_j' on the slave DOFs of j, +w_ja n_j' on those of master node a,
/// stored normalized exactly as node-to-segment rows: B_i = b / |b|, c_i = g_j / |b|,
/// |b|^2 = 1 + sum_a w_ja^2 (row_norm = |b|). Where o_j = 1 the renormalization changes nothing;
/// where o_j < 1 it keeps the partition of unity (rigid translations stay free) at the price of
/// the exact force balance of the boundary node, and the dual functions being signed, o_j -> 0
/// would amplify the weights without bound: hence the minimum overlap.
///
/// Multipliers. The force magnitude of row i, lambda_i = lambda_hat_i / |b_i|
/// (slave_normal_forces), acts as +lambda_i n_j on the slave node and -lambda_i w_ja n_j on master
/// node a. With the nodal pressure z_j = lambda_i / D_j (slave_area holds D_j) the master forces
/// are sum_j M_ja z_j n_j = int N_a^m t dA for the traction t = sum_j Phi_j z_j: a uniform
/// pressure (z_j = p, t = p because sum_j Phi_j = 1) gives the consistent nodal forces of p on
/// both surfaces, which is what makes the contact patch test pass on non-matching meshes.
///
/// Face types. Faces of every type (tri3, tri6, quad4, quad8) are integrated
/// (mortar_face_integration.hpp; quad4 against quad4 by mortar_integration.hpp), and so are the
/// line2 and line3 edges of 2D cells (mortar_edge_integration.hpp). On tri6, quad8 and line3
/// slave faces D_j and M_ja are those of the transformed basis, and the row of an edge
/// node m is that of its transformed value x~_m = (x_m - alpha (x_c1 + x_c2)) / (1 - 2 alpha):
/// the master weights above times 1 - 2 alpha, plus alpha on each corner c1, c2 of its edge
/// (master_share = 1 - 2 alpha), slave_area = D~_m / (1 - 2 alpha). On faces other than quad4
/// n_j is the master's nodal normals interpolated at the closest point (row_normal in the .cpp).
///
/// Linearization. The row is -grad_u g_j with w_ja and n_j held fixed (their variations are
/// dropped, as for the modified Newton method of ALGORITHMS.md section 8, which rebuilds the rows
/// in the current configuration at every outer iteration); Popp et al. 2009 linearize them too.
///
/// Fields of a mortar row: slave_node, normal (n_j), gap (g_j), row_norm, slave_area (D_j), and
/// master_face, xi, kind of the node-to-segment closest point that gave n_j.
///
/// Limitations: one master layer within d_s of each slave face (a folded master surface, or two
/// master sheets within d_s, would be counted twice and then renormalized away); master faces
/// seen edge-on from the slave face (SegmentOptions::min_facing) are not integrated.
///
/// Usage:
///   ContactOptions options;
///   options.formulation = ContactFormulation::mortar;
///   const ContactConstraints rows = build_contact_constraints(mesh, u, pair, options);

#include "contact/contact_constraints.hpp"
#include "contact/mortar_integration.hpp"

#include "la/types.hpp"
#include "mesh/mesh.hpp"

#include <array>
#include <cstdint>
#include <optional>
#include <string>
#include <vector>

namespace feticon::contact
{
/// Nodes of a slave face set with their nodal areas D_j.
struct SlaveNodalAreas
{
  /// Sorted unique node ids of the face set; position j is the slave index.
  std::vector<int32_t> nodes;
  /// D_j = int N_j dA over the faces of node j in the current configuration (m^2).
  la::Vector area;

  /// Slave index of `node`, or -1 if it is not a node of the set.
  int32_t index_of(int32_t node) const;
  /// D_j of `node` (m^2); throws feticon::Error if it is not a node of the set.
  double of(int32_t node) const;
};

/// @brief Nodal areas D_j of the face set `slave` at the displacement `u` (m, or empty for 0).
SlaveNodalAreas slave_nodal_areas(const mesh::Mesh& mesh, const la::Vector& u, const std::string& slave);

/// Raw dual mortar coupling of a contact pair (file comment), before any row selection.
struct MortarCoupling
{
  /// Slave nodes and D_j; row j of M belongs to slave.nodes[j].
  SlaveNodalAreas slave;
  /// M_ja (m^2): n_slave_nodes x n_nodes, column = global master node id.
  Eigen::SparseMatrix<double, Eigen::RowMajor> M;
  /// Search distance used for the candidate master faces (m).
  double search_distance = 0;
  /// (slave face, master face) pairs integrated with a nonzero intersection.
  int64_t n_segments = 0;
  /// Per slave index: the corners at the ends of its edge if it is an edge node of a quadratic
  /// slave face (tri6, quad8, line3), else {-1, -1}.
  std::vector<std::array<int32_t, 2>> edge_ends;
};

/// The master side of slave node j's row (file comment, "Rows"): the nodes and weights w with
/// sum w = 1 such that the row says x_j = sum w x (its transformed value's corners included).
struct MortarRowWeights
{
  std::vector<std::pair<int32_t, double>> weights;
  double share = 1; ///< of the master nodes: 1 - 2 alpha for an edge node of a quadratic face
};

/// @brief The weights of slave index j of `coupling` (file comment), or nothing if its overlap
/// o_j is below min_overlap.
std::optional<MortarRowWeights> mortar_row_weights(const MortarCoupling& coupling, la::Index j, double min_overlap);

/// @brief D and M of `pair` at the displacement `u`.
/// @param[in] search_distance candidate master faces are those within this distance of a slave
///            face's box (m, > 0)
/// @param[in] options         quadrature and filters of each segment
/// @param[in] row_nodes       if given, only the slave faces with a corner among these nodes are
///            integrated: D_j and row j of M are those of the full computation, bit for bit, for
///            these nodes (their support is integrated whole) and partial for the others
/// @throws feticon::Error for an unknown or empty face set, a wrong size of u, a nonpositive
///         search distance, or a degenerate or non-convex slave face (of those integrated).
MortarCoupling compute_mortar_coupling(const mesh::Mesh& mesh, const la::Vector& u, const ContactPair& pair,
                                       double search_distance, const SegmentOptions& options = {},
                                       const std::vector<int32_t>* row_nodes = nullptr);

/// @brief Dual mortar rows of `pair` (file comment); options.formulation is ignored.
/// Arguments, result and errors as build_contact_constraints.
ContactConstraints build_mortar_constraints(const mesh::Mesh& mesh, const la::Vector& u, const ContactPair& pair,
                                            const ContactOptions& options = {});
} // namespace feticon::contact
