#pragma once
/// @file Geometry of hex8 cells computed independently of src/mesh, for the mesh tests: the
/// trilinear map x(xi) = sum_a N_a(xi) x_a with N_a = (1 + xi xi_a)(1 + eta eta_a)(1 + zeta
/// zeta_a)/8 and the VTK corner order written out again here.

#include "mesh/mesh.hpp"

#include <algorithm>
#include <array>
#include <cmath>
#include <map>
#include <vector>

#include <Eigen/Dense>

namespace feticon::mesh::test
{
/// Reference coordinates of the VTK hexahedron corners (VTK file format documentation).
inline constexpr std::array<std::array<double, 3>, 8> reference_corners = {{
    {-1, -1, -1},
    {1, -1, -1},
    {1, 1, -1},
    {-1, 1, -1},
    {-1, -1, 1},
    {1, -1, 1},
    {1, 1, 1},
    {-1, 1, 1},
}};

/// Jacobian d x / d xi of the trilinear map of `cell` at reference point `xi`.
inline Eigen::Matrix3d jacobian(const Mesh& mesh, std::span<const int32_t> cell, const Eigen::Vector3d& xi)
{
  Eigen::Matrix3d result = Eigen::Matrix3d::Zero();
  for (int a = 0; a < 8; ++a)
  {
    const auto& c = reference_corners[a];
    const double f0 = 1 + xi[0] * c[0], f1 = 1 + xi[1] * c[1], f2 = 1 + xi[2] * c[2];
    const Eigen::Vector3d gradient(c[0] * f1 * f2 / 8, f0 * c[1] * f2 / 8, f0 * f1 * c[2] / 8);
    result += mesh.nodes.row(cell[a]).transpose() * gradient.transpose();
  }
  return result;
}

/// The 2 x 2 x 2 Gauss points +-1/sqrt(3) (unit weights).
inline std::vector<Eigen::Vector3d> gauss_points()
{
  const double g = 1 / std::sqrt(3.0);
  std::vector<Eigen::Vector3d> points;
  for (int k = 0; k < 2; ++k)
    for (int j = 0; j < 2; ++j)
      for (int i = 0; i < 2; ++i)
        points.emplace_back(i ? g : -g, j ? g : -g, k ? g : -g);
  return points;
}

/// Cell volume by 2x2x2 Gauss quadrature of det J, exact for trilinear cells (det J has degree
/// at most 2 in each reference coordinate).
inline double cell_volume(const Mesh& mesh, std::span<const int32_t> cell)
{
  double volume = 0;
  for (const Eigen::Vector3d& xi : gauss_points())
    volume += jacobian(mesh, cell, xi).determinant();
  return volume;
}

inline Eigen::Vector3d point(const Mesh& mesh, int32_t id) { return mesh.nodes.row(id).transpose(); }

/// Unit normal (x1 - x0) x (x3 - x0) of a face (the orientation convention of Mesh).
inline Eigen::Vector3d face_normal(const Mesh& mesh, const Face& face)
{
  const Eigen::Vector3d x0 = point(mesh, face[0]);
  return (point(mesh, face[1]) - x0).cross(point(mesh, face[3]) - x0).normalized();
}

inline Eigen::Vector3d face_centroid(const Mesh& mesh, const Face& face)
{
  Eigen::Vector3d sum = Eigen::Vector3d::Zero();
  for (const int32_t id : face)
    sum += point(mesh, id);
  return sum / 4;
}

inline Eigen::Vector3d cell_centroid(const Mesh& mesh, std::span<const int32_t> cell)
{
  Eigen::Vector3d sum = Eigen::Vector3d::Zero();
  for (const int32_t id : cell)
    sum += point(mesh, id);
  return sum / 8;
}

using SortedFace = std::array<int32_t, 4>;
inline SortedFace sorted(SortedFace face)
{
  std::sort(face.begin(), face.end());
  return face;
}
inline SortedFace sorted(const Face& face)
{
  SortedFace corners{};
  std::copy(face.begin(), face.end(), corners.begin());
  return sorted(corners);
}

/// The 6 faces of every cell keyed by their sorted node ids, from the corner order alone: a face
/// is the 4 corners sharing one reference coordinate value. Maps each face to its cells.
inline std::map<SortedFace, std::vector<int32_t>> faces_to_cells(const Mesh& mesh)
{
  std::map<SortedFace, std::vector<int32_t>> result;
  for (int32_t c = 0; c < mesh.n_cells(); ++c)
    for (int d = 0; d < 3; ++d)
      for (const double side : {-1.0, 1.0})
      {
        SortedFace face{};
        int n = 0;
        for (int a = 0; a < 8; ++a)
          if (reference_corners[a][d] == side)
            face[n++] = mesh.cells[c][a];
        result[sorted(face)].push_back(c);
      }
  return result;
}
} // namespace feticon::mesh::test
