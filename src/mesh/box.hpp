#pragma once
/// @file Structured hex meshes: mapped blocks, boxes, graded 1D spacings, and appending bodies.
///
/// A structured block has n_x * n_y * n_z cells; node (i, j, k), 0 <= i <= n_x etc., is placed by a
/// user map and gets the id i + (n_x + 1) * (j + (n_y + 1) * k). Cell (i, j, k) lists its nodes in
/// VTK hexahedron order with the reference axes xi, eta, zeta along i, j, k, so the map must
/// preserve orientation (x increasing with i, ... for a box) for the cells to have positive
/// Jacobians and the boundary faces to point outward. The six logical sides are the face sets (and
/// node sets) "xmin" (i = 0), "xmax" (i = n_x), "ymin", "ymax", "zmin", "zmax".
///
/// Usage (two blocks for a contact test):
///   Mesh mesh = generate_box({.lengths = {1, 1, 1}, .nx = 4, .ny = 4, .nz = 4, .body_name =
///   "lower"}); append_mesh(mesh, generate_box({.origin = {0, 0, 1}, .body_name = "upper"}),
///   "upper_");

#include "mesh/mesh.hpp"

#include <functional>
#include <string>
#include <vector>

#include <Eigen/Dense>

namespace feticon::mesh
{
/// Places node (i, j, k) of a structured block (m).
using GridMap = std::function<Eigen::Vector3d(int32_t i, int32_t j, int32_t k)>;

/// @brief Structured block of n_x * n_y * n_z hex8 cells placed by `point`, one body.
/// @param[in] n_cells   cells along i, j, k (each >= 1)
/// @param[in] point     node placement (m); must preserve orientation, checked at every cell centre
/// @param[in] body_name name of the single body
/// @return mesh with the six side sets "xmin" .. "zmax" (faces outward, and node sets)
Mesh generate_mapped_block(const std::array<int32_t, 3>& n_cells, const GridMap& point, const std::string& body_name);

/// Axis-aligned box [origin, origin + lengths] meshed by nx * ny * nz equal cells.
struct BoxParameters
{
  /// Corner with the smallest coordinates (m).
  Eigen::Vector3d origin{0, 0, 0};
  /// Edge lengths along x, y, z (m), each > 0.
  Eigen::Vector3d lengths{1, 1, 1};
  /// Cells along x, y, z, each >= 1.
  int nx = 1, ny = 1, nz = 1;
  std::string body_name = "box";
};

/// @brief Structured box mesh, one body, with the six side sets "xmin" .. "zmax" (see file
/// comment).
/// @throws feticon::Error for n < 1 or a non-positive length.
Mesh generate_box(const BoxParameters& parameters);

/// @brief Appends `other` as new bodies of `target`.
///
/// Node and cell ids of `other` are shifted by the current counts of `target`, its body indices by
/// target.n_bodies(), and its node and face sets are renamed `prefix + name`.
/// @throws feticon::Error if a body name or a renamed set already exists in `target`.
void append_mesh(Mesh& target, const Mesh& other, const std::string& prefix);

/// @brief Graded 1D node positions 0 = t_0 < t_1 < ... < t_n = length.
///
/// Spacing `spacing` on [0, fine_length] (rounded up to whole cells, so the fine region may end up
/// slightly longer), then cells growing geometrically up to `length`. The growth ratio is adjusted
/// from `ratio` to the nearby value whose geometric sequence ends exactly at `length`, so there is
/// no sliver cell and the sizes stay smooth. If the rest is too short to grade, the whole interval
/// is uniform with spacing at most `spacing`.
/// @param[in] length      interval length (m), > 0
/// @param[in] spacing     fine cell size (m), > 0
/// @param[in] fine_length length of the uniform region (m), >= 0
/// @param[in] ratio       growth ratio of consecutive cells beyond the fine region, >= 1
std::vector<double> graded_positions(double length, double spacing, double fine_length, double ratio);
} // namespace feticon::mesh
