#pragma once
/// @file Two-body meshes for the contact tests: flat stacked boxes, wavy non-matching surfaces,
/// and a roof (convex ridge) under a flat block.

#include "mesh/box.hpp"

#include <cmath>
#include <numbers>
#include <random>

namespace feticon::contact::test
{
/// Box "lower" [0,1]^3 (4 x 4 x 2 cells) and box "upper" (3 x 3 x 1 cells, non-matching) of size
/// 1 x 1 x 0.5 at (shift_x, shift_y, 1 + gap). Sets are prefixed "lower_" and "upper_"; the slave
/// surface is "upper_zmin", the master "lower_zmax".
inline mesh::Mesh stacked_boxes(double gap, double shift_x = 0, double shift_y = 0)
{
  mesh::Mesh mesh;
  mesh::append_mesh(mesh, mesh::generate_box({.lengths = {1, 1, 1}, .nx = 4, .ny = 4, .nz = 2, .body_name = "lower"}),
                    "lower_");
  mesh::append_mesh(mesh,
                    mesh::generate_box({.origin = {shift_x, shift_y, 1 + gap},
                                        .lengths = {1, 1, 0.5},
                                        .nx = 3,
                                        .ny = 3,
                                        .nz = 1,
                                        .body_name = "upper"}),
                    "upper_");
  return mesh;
}

/// Lower block [0,1]^2 x [0, 1 + w_l(x, y)] (5 x 4 x 2 cells) with a wavy top
/// w_l = 0.06 sin(2 pi x) cos(pi y), so its top faces are warped, and an upper block (4 x 3 x 1)
/// from 1.02 + w_u to 1.4 over [0.05, 0.95] x [0.05, 0.95], w_u = 0.04 cos(2 pi y) sin(pi x).
inline mesh::Mesh wavy_blocks()
{
  using std::numbers::pi;
  mesh::Mesh mesh;
  const int nx = 5, ny = 4, nz = 2;
  mesh::append_mesh(mesh,
                    mesh::generate_mapped_block(
                        {nx, ny, nz},
                        [&](int32_t i, int32_t j, int32_t k) {
    const double x = double(i) / nx, y = double(j) / ny;
    const double top = 1 + 0.06 * std::sin(2 * pi * x) * std::cos(pi * y);
    return Eigen::Vector3d(x, y, top * k / nz);
                        },
                        "lower"),
                    "lower_");
  const int mx = 4, my = 3;
  mesh::append_mesh(mesh,
                    mesh::generate_mapped_block(
                        {mx, my, 1},
                        [&](int32_t i, int32_t j, int32_t k) {
    const double x = 0.05 + 0.9 * i / mx, y = 0.05 + 0.9 * j / my;
    const double bottom = 1.02 + 0.04 * std::cos(2 * pi * y) * std::sin(pi * x);
    return Eigen::Vector3d(x, y, k == 0 ? bottom : 1.4);
                        },
                        "upper"),
                    "upper_");
  return mesh;
}

/// Random displacement of size `amplitude` (m) on every node.
inline la::Vector random_displacement(const mesh::Mesh& mesh, double amplitude, unsigned seed)
{
  std::mt19937 rng(seed);
  std::uniform_real_distribution<double> unit(-1, 1);
  la::Vector u(3 * mesh.n_nodes());
  for (la::Index k = 0; k < u.size(); ++k)
    u(k) = amplitude * unit(rng);
  return u;
}

/// Lower body with a roof-shaped top: z = 0.8 at x = 0 and x = 1, z = 1 on the ridge x = 0.5
/// (2 x 1 x 1 cells, so the ridge is an interior edge of the top surface "lower_zmax"), and a flat
/// block "upper" [0.25, 0.75] x [0, 1] x [1.1, 1.3] (2 x 1 x 1 cells) above it, slave "upper_zmin".
inline mesh::Mesh roof_and_block()
{
  mesh::Mesh mesh;
  mesh::append_mesh(mesh,
                    mesh::generate_mapped_block(
                        {2, 1, 1},
                        [](int32_t i, int32_t j, int32_t k) {
    const double top = i == 1 ? 1.0 : 0.8;
    return Eigen::Vector3d(0.5 * i, j, k * top);
                        },
                        "lower"),
                    "lower_");
  mesh::append_mesh(
      mesh,
      mesh::generate_box(
          {.origin = {0.25, 0, 1.1}, .lengths = {0.5, 1, 0.2}, .nx = 2, .ny = 1, .nz = 1, .body_name = "upper"}),
      "upper_");
  return mesh;
}
/// The contact pair of stacked_boxes: the upper box's bottom on the lower box's top.
inline const ContactPair upper_on_lower{.slave = "upper_zmin", .master = "lower_zmax"};
} // namespace feticon::contact::test
