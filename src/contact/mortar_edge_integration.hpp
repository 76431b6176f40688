#pragma once
/// @file Dual mortar integrals on the edges of 2D cells (line2, line3; mesh::Planar): the 2D
/// analogue of mortar_face_integration.hpp (Popp, Gee & Wall 2009, IJNME 79, for 2D).
///
/// Measure (face_dual_basis and integrate_edge_segment). An edge's "area" element is ds times the out-of-plane measure of the model
/// (mesh::Planar::measure: the thickness, or 2 pi r in axisymmetry, evaluated at the point),
/// so D_j = int N~_j measure ds and M_ja = int Phi_j N_a^m measure ds: the dual basis is
/// biorthogonal in that weighted product, and the master forces sum_j M_ja z_j n_j are still
/// the consistent loads of the traction sum_j Phi_j z_j.
///
/// line3 slave edges take the transformed functions of mortar_face_integration.hpp (alpha =
/// quadratic_dual_alpha, the edge node's function shared with its two corners). On a straight
/// edge of constant measure the standard ones would do (int N_c ds = L/6 > 0), but in
/// axisymmetry a corner on the axis has int N_c 2 pi r ds = 0 (N_c changes sign where r grows
/// linearly from 0): no dual basis exists there, and the seal or sphere whose contact surface
/// reaches the axis is the common case. With alpha = 1/5 a straight edge of constant measure
/// has D~ = 0.3 L at the corners and 0.4 L at the edge node.
///
/// Segmentation. The slave edge's auxiliary line runs through its centre point along its
/// tangent there; each edge is cut into its chords (line2 one, line3 two: corner to edge node),
/// the chords are projected on the line, and every (slave chord, master chord) overlap is
/// integrated by Gauss points of the overlap interval, each mapped linearly to the chords' own
/// parent coordinates. Exact for straight edges (the patch test); on curved line3 edges the
/// chords are O(h^2) in the geometry, as the sub-facets of quadratic faces.
///
/// Usage:
///   const FaceDualBasis dual = face_dual_basis(slave_edge);
///   if (auto m = integrate_edge_segment(slave_edge, dual, master_edge)) coupling(j, a) += (*m)(j, a);

#include "contact/mortar_face_integration.hpp"

#include <optional>

namespace feticon::contact
{
/// @brief int Phi_j N_a^m measure ds of the slave edge against the master edge: rows the slave
/// edge's nodes, columns the master edge's (standard functions).
/// @return nothing if they do not overlap on the slave's auxiliary line, or the master edge
/// does not face the slave (SegmentOptions::min_facing).
/// @throws feticon::Error if a slave line3 folds back on its auxiliary line.
std::optional<Eigen::MatrixXd> integrate_edge_segment(const FaceGeometry& slave, const FaceDualBasis& dual,
                                                      const FaceGeometry& master, const SegmentOptions& options = {});
} // namespace feticon::contact
