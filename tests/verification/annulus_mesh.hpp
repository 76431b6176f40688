#pragma once
/// Quarter annuli of hex8 or hex20 cells for the verification tests of rings, hubs and discs.

#include "mesh/box.hpp"
#include "mesh/cell_conversion.hpp"

#include <cmath>
#include <numbers>
#include <string>

namespace feticon::test
{
/// Edge nodes of quadratic cells on the circle through both ends when they are at one radius
/// (the rims stay round), at the midpoint otherwise.
inline Eigen::Vector3d on_circle(const Eigen::Vector3d& p, const Eigen::Vector3d& q)
{
  Eigen::Vector3d m = 0.5 * (p + q);
  const double rp = std::hypot(p.x(), p.y()), rq = std::hypot(q.x(), q.y());
  if (std::abs(rp - rq) < 1e-12 * rp)
    m.head<2>() *= rp / m.head<2>().norm();
  return m;
}

/// A quarter annulus r in [r0, r1], theta in [0, pi/2], z in [0, thickness], one cell through
/// z, of hex8 or hex20 cells: side "xmin" is r = r0, "xmax" r = r1, "ymin" the plane y = 0,
/// "ymax" the plane x = 0, "zmin" and "zmax" the faces.
inline mesh::Mesh quarter_annulus(double r0, double r1, double thickness, int n_r, int n_theta, mesh::CellKind kind,
                                  const std::string& name)
{
  const mesh::Mesh hex = mesh::generate_mapped_block(
      {n_r, n_theta, 1},
      [&](int32_t i, int32_t j, int32_t k) {
    const double r = r0 + (r1 - r0) * i / n_r, theta = std::numbers::pi / 2 * j / n_theta;
    return Eigen::Vector3d(r * std::cos(theta), r * std::sin(theta), thickness * k);
      },
      name);
  return kind == mesh::CellKind::hex8 ? hex : mesh::convert_hex8_mesh(hex, kind, on_circle);
}
} // namespace feticon::test
