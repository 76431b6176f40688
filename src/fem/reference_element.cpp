#include "fem/reference_element.hpp"

#include "fem/hex8.hpp"
#include "fem/reference_face.hpp"

#include <array>
#include <cmath>

namespace feticon::fem
{
namespace
{
using mesh::CellKind;

/// Values (column 0) and reference gradients (columns 1-3) of each node's shape function.
using ShapeTable = Eigen::Matrix<double, Eigen::Dynamic, 4>;

/// hex8's shape functions are fem/hex8.hpp's, which the hex8 element uses.
ShapeTable hex8(const Eigen::Vector3d& xi)
{
  ShapeTable t(8, 4);
  t.col(0) = hex8_shape(xi);
  t.rightCols<3>() = hex8_reference_gradients(xi);
  return t;
}

/// 20-node serendipity hexahedron: corners N = 1/8 (1 + s xi)(1 + e eta)(1 + z zeta)
/// (s xi + e eta + z zeta - 2), edge nodes (one reference coordinate 0, say xi)
/// N = 1/4 (1 - xi^2)(1 + e eta)(1 + z zeta).
ShapeTable hex20(const Eigen::Vector3d& xi)
{
  ShapeTable t(20, 4);
  const auto& nodes = mesh::cell_type(CellKind::hex20).reference_nodes;
  for (int a = 0; a < 20; ++a)
  {
    const Eigen::Vector3d p(nodes[a][0], nodes[a][1], nodes[a][2]);
    if (a < 8)
    {
      const Eigen::Vector3d f = Eigen::Vector3d::Ones() + p.cwiseProduct(xi);
      const double g = p.dot(xi) - 2;
      t(a, 0) = f.prod() * g / 8;
      for (int j = 0; j < 3; ++j)
      {
        const double others = f((j + 1) % 3) * f((j + 2) % 3); // not f.prod() / f(j): f(j) may be 0
        t(a, 1 + j) = p(j) * others * (g + f(j)) / 8;
      }
      continue;
    }
    int zero = 0; // the reference direction along the node's edge
    while (p(zero) != 0)
      ++zero;
    const int j1 = (zero + 1) % 3, j2 = (zero + 2) % 3;
    const double bubble = 1 - xi(zero) * xi(zero);
    const double f1 = 1 + p(j1) * xi(j1), f2 = 1 + p(j2) * xi(j2);
    t(a, 0) = bubble * f1 * f2 / 4;
    t(a, 1 + zero) = -2 * xi(zero) * f1 * f2 / 4;
    t(a, 1 + j1) = bubble * p(j1) * f2 / 4;
    t(a, 1 + j2) = bubble * f1 * p(j2) / 4;
  }
  return t;
}

/// Barycentric coordinates of the unit tetrahedron and their (constant) gradients.
std::array<double, 4> barycentric(const Eigen::Vector3d& xi) { return {1 - xi.sum(), xi.x(), xi.y(), xi.z()}; }
Eigen::Vector3d barycentric_gradient(int a)
{
  return a == 0 ? Eigen::Vector3d(-1, -1, -1) : Eigen::Vector3d::Unit(a - 1);
}

ShapeTable tet4(const Eigen::Vector3d& xi)
{
  ShapeTable t(4, 4);
  const auto L = barycentric(xi);
  for (int a = 0; a < 4; ++a)
    t.row(a) << L[a], barycentric_gradient(a).transpose();
  return t;
}

ShapeTable tet10(const Eigen::Vector3d& xi)
{
  ShapeTable t(10, 4);
  const auto L = barycentric(xi);
  for (int a = 0; a < 4; ++a)
    t.row(a) << L[a] * (2 * L[a] - 1), (4 * L[a] - 1) * barycentric_gradient(a).transpose();
  const auto& edges = mesh::cell_type(CellKind::tet10).edges;
  for (int e = 0; e < 6; ++e)
  {
    const int a = edges[e][0], b = edges[e][1];
    t.row(4 + e) << 4 * L[a] * L[b], 4 * (L[b] * barycentric_gradient(a) + L[a] * barycentric_gradient(b)).transpose();
  }
  return t;
}

/// The linear triangle (1 - xi - eta, xi, eta) times (1 -+ zeta) / 2.
ShapeTable wedge6(const Eigen::Vector3d& xi)
{
  ShapeTable t(6, 4);
  const std::array<double, 3> L = {1 - xi.x() - xi.y(), xi.x(), xi.y()};
  const std::array<Eigen::Vector2d, 3> dL = {Eigen::Vector2d(-1, -1), Eigen::Vector2d(1, 0), Eigen::Vector2d(0, 1)};
  for (int level = 0; level < 2; ++level)
  {
    const double sign = level == 0 ? -1 : 1;
    const double h = (1 + sign * xi.z()) / 2;
    for (int k = 0; k < 3; ++k)
      t.row(3 * level + k) << L[k] * h, dL[k].x() * h, dL[k].y() * h, L[k] * sign / 2;
  }
  return t;
}

/// A 2D cell's shape functions are those of the face of the same shape (its node order is
/// the face's: fem/reference_face.hpp); nothing varies with zeta.
ShapeTable planar(mesh::FaceKind shape, const Eigen::Vector3d& xi)
{
  const Eigen::Vector2d p = xi.head<2>();
  const Eigen::VectorXd N = face_shape_values(shape, p);
  ShapeTable t = ShapeTable::Zero(N.size(), 4);
  t.col(0) = N;
  t.middleCols<2>(1) = face_shape_gradients(shape, p);
  return t;
}

ShapeTable shape_table(CellKind kind, const Eigen::Vector3d& xi)
{
  switch (kind)
  {
  case CellKind::tri3:
    return planar(mesh::FaceKind::tri3, xi);
  case CellKind::quad4:
    return planar(mesh::FaceKind::quad4, xi);
  case CellKind::tri6:
    return planar(mesh::FaceKind::tri6, xi);
  case CellKind::quad8:
    return planar(mesh::FaceKind::quad8, xi);
  case CellKind::hex8:
    return hex8(xi);
  case CellKind::hex20:
    return hex20(xi);
  case CellKind::tet4:
    return tet4(xi);
  case CellKind::tet10:
    return tet10(xi);
  case CellKind::wedge6:
    return wedge6(xi);
  }
  return {};
}

/// The tensor product of an n-point Gauss rule on [-1, 1] with itself, three times.
QuadratureRule gauss_cube(int n)
{
  const std::vector<double>& x = gauss_line(n).points;
  const std::vector<double>& w = gauss_line(n).weights;
  QuadratureRule rule;
  for (int k = 0; k < n; ++k)
    for (int j = 0; j < n; ++j)
      for (int i = 0; i < n; ++i)
      {
        rule.points.emplace_back(x[i], x[j], x[k]);
        rule.weights.push_back(w[i] * w[j] * w[k]);
      }
  return rule;
}

QuadratureRule tet_rule(int points)
{
  if (points == 1)
    return {{Eigen::Vector3d(0.25, 0.25, 0.25)}, {1.0 / 6}};
  // Degree 2 (Keast; Zienkiewicz & Taylor table 6.4): a = (5 + 3 sqrt 5) / 20, b = (5 - sqrt 5) / 20.
  const double a = (5 + 3 * std::sqrt(5.0)) / 20, b = (5 - std::sqrt(5.0)) / 20;
  return {{Eigen::Vector3d(b, b, b), Eigen::Vector3d(a, b, b), Eigen::Vector3d(b, a, b), Eigen::Vector3d(b, b, a)},
          {1.0 / 24, 1.0 / 24, 1.0 / 24, 1.0 / 24}};
}

/// A face's rule at zeta = 0: the rule of the 2D cell of its shape (quad4's 2x2 Gauss, quad8's
/// 3x3, tri3's 3 points of degree 2, fem/reference_face.hpp).
QuadratureRule planar_rule(mesh::FaceKind shape)
{
  const FaceQuadrature& face = face_quadrature(shape);
  QuadratureRule rule;
  for (size_t q = 0; q < face.points.size(); ++q)
    rule.points.emplace_back(face.points[q].x(), face.points[q].y(), 0);
  rule.weights = face.weights;
  return rule;
}

QuadratureRule wedge_rule()
{
  // The triangle's degree-2 rule at the edge midpoints' inward points (1/6, 1/6), (2/3, 1/6),
  // (1/6, 2/3), weights 1/6, times Gauss at zeta = -+1/sqrt(3).
  QuadratureRule rule;
  const std::array<Eigen::Vector2d, 3> t = {Eigen::Vector2d(1.0 / 6, 1.0 / 6), Eigen::Vector2d(2.0 / 3, 1.0 / 6),
                                            Eigen::Vector2d(1.0 / 6, 2.0 / 3)};
  for (const double z : {-1 / std::sqrt(3.0), 1 / std::sqrt(3.0)})
    for (const Eigen::Vector2d& p : t)
    {
      rule.points.emplace_back(p.x(), p.y(), z);
      rule.weights.push_back(1.0 / 6);
    }
  return rule;
}
} // namespace

const GaussLine& gauss_line(int n)
{
  static const GaussLine two{{-1 / std::sqrt(3.0), 1 / std::sqrt(3.0)}, {1.0, 1.0}};
  static const GaussLine three{{-std::sqrt(0.6), 0.0, std::sqrt(0.6)}, {5.0 / 9, 8.0 / 9, 5.0 / 9}};
  return n == 2 ? two : three;
}

Eigen::VectorXd shape_values(mesh::CellKind kind, const Eigen::Vector3d& xi) { return shape_table(kind, xi).col(0); }

Eigen::MatrixX3d shape_gradients(mesh::CellKind kind, const Eigen::Vector3d& xi)
{
  return shape_table(kind, xi).rightCols<3>();
}

const QuadratureRule& quadrature(mesh::CellKind kind, Integration integration)
{
  static const QuadratureRule cube2 = gauss_cube(2), cube3 = gauss_cube(3), tet1 = tet_rule(1), tet4 = tet_rule(4),
                              wedge = wedge_rule(), square2 = planar_rule(mesh::FaceKind::quad4),
                              square3 = planar_rule(mesh::FaceKind::quad8),
                              triangle = planar_rule(mesh::FaceKind::tri3);
  switch (kind)
  {
  case CellKind::tri3:
  case CellKind::tri6:
    return triangle;
  case CellKind::quad4:
    return square2;
  case CellKind::quad8:
    return integration == Integration::reduced ? square2 : square3;
  case CellKind::hex8:
    return cube2;
  case CellKind::hex20:
    return integration == Integration::reduced ? cube2 : cube3;
  case CellKind::tet4:
    return tet1;
  case CellKind::tet10:
    return tet4;
  case CellKind::wedge6:
    return wedge;
  }
  return cube2;
}

const std::vector<PointShapes>& quadrature_shapes(mesh::CellKind kind, Integration integration)
{
  using Tables = std::array<std::array<std::vector<PointShapes>, 2>, mesh::all_cell_kinds.size()>;
  static const Tables tables = [] {
    Tables t;
    for (const CellKind k : mesh::all_cell_kinds)
      for (const Integration i : {Integration::full, Integration::reduced})
        for (const Eigen::Vector3d& xi : quadrature(k, i).points)
          t[static_cast<size_t>(k)][i == Integration::reduced].push_back({shape_values(k, xi), shape_gradients(k, xi)});
    return t;
  }();
  return tables[static_cast<size_t>(kind)][integration == Integration::reduced];
}
} // namespace feticon::fem
