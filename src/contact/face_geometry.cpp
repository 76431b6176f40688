#include "contact/face_geometry.hpp"

#include "contact/closest_point.hpp"
#include "contact/mortar_integration.hpp"
#include "fem/reference_face.hpp"

#include <algorithm>
#include <array>
#include <cmath>

namespace feticon::contact
{
namespace
{
using mesh::FaceKind;

/// Tangents x_,xi and x_,eta at xi, columns of a 3 x 2 matrix; an edge of a 2D cell (line2,
/// line3) has x_,eta = e_z, so that x_,xi x x_,eta is its outward normal and the projection's
/// Newton iteration leaves eta at 0.
Eigen::Matrix<double, 3, 2> tangents(const FaceGeometry& face, const Eigen::Vector2d& xi)
{
  Eigen::Matrix<double, 3, 2> t = face.x.transpose() * fem::face_shape_gradients(face.kind, xi);
  if (mesh::is_line(face.kind))
    t.col(1) = Eigen::Vector3d::UnitZ();
  return t;
}

/// Step of the central differences of the tangents that give the curvature term.
constexpr double difference_step = 1e-5;

} // namespace

const std::vector<std::vector<int>>& face_sub_facets(FaceKind kind)
{
  static const std::vector<std::vector<int>> tri3 = {{0, 1, 2}};
  static const std::vector<std::vector<int>> quad4 = {{0, 1, 2, 3}};
  static const std::vector<std::vector<int>> tri6 = {{0, 3, 5}, {3, 1, 4}, {5, 4, 2}, {3, 4, 5}};
  static const std::vector<std::vector<int>> quad8 = {{0, 4, 7}, {4, 1, 5}, {5, 2, 6}, {7, 6, 3}, {4, 5, 6, 7}};
  static const std::vector<std::vector<int>> line2 = {{0, 1}};
  static const std::vector<std::vector<int>> line3 = {{0, 2}, {2, 1}};
  switch (kind)
  {
  case FaceKind::line2:
    return line2;
  case FaceKind::line3:
    return line3;
  case FaceKind::tri3:
    return tri3;
  case FaceKind::quad4:
    return quad4;
  case FaceKind::tri6:
    return tri6;
  case FaceKind::quad8:
    return quad8;
  }
  return quad4;
}

Eigen::Vector2d face_node_xi(FaceKind kind, int a)
{
  const int corners = mesh::face_corners(kind);
  if (a < corners)
    return face_corner_xi(kind, a);
  // Edge node e joins corners e and e + 1.
  const int e = a - corners;
  return 0.5 * (face_corner_xi(kind, e) + face_corner_xi(kind, (e + 1) % corners));
}

FaceGeometry current_face_geometry(const mesh::Mesh& mesh, const la::Vector& u, const mesh::Face& face)
{
  FaceGeometry out;
  out.kind = face.kind;
  out.planar = mesh.planar_of_node(face[0]);
  out.x.resize(face.size(), 3);
  for (int a = 0; a < face.size(); ++a)
  {
    out.x.row(a) = mesh.nodes.row(face[a]);
    if (u.size() > 0)
      out.x.row(a) += u.segment<3>(3 * static_cast<la::Index>(face[a])).transpose();
  }
  return out;
}

Eigen::Vector2d face_corner_xi(FaceKind kind, int k)
{
  if (mesh::is_line(kind))
    return {k == 0 ? -1.0 : 1.0, 0.0};
  if (mesh::face_corners(kind) == 4)
    return quad_corner(k);
  static const std::array<Eigen::Vector2d, 3> corners = {Eigen::Vector2d(0, 0), Eigen::Vector2d(1, 0),
                                                         Eigen::Vector2d(0, 1)};
  return corners[k];
}

bool within_extension(FaceKind kind, const Eigen::Vector2d& xi, double extension)
{
  if (mesh::is_line(kind))
    return std::abs(xi(0)) <= 1 + extension;
  if (mesh::face_corners(kind) == 4)
    return xi.lpNorm<Eigen::Infinity>() <= 1 + extension;
  return outside_distance(kind, xi) <= extension;
}

double outside_distance(FaceKind kind, const Eigen::Vector2d& xi)
{
  if (mesh::is_line(kind))
    return std::abs(xi(0)) - 1;
  if (mesh::face_corners(kind) == 4)
    return xi.lpNorm<Eigen::Infinity>() - 1;
  return std::max({-xi(0), -xi(1), xi(0) + xi(1) - 1});
}

fem::FaceValues face_weights(FaceKind kind, const Eigen::Vector2d& xi)
{
  if (kind == FaceKind::quad4)
    return quad_shape_functions(xi);
  return fem::face_shape_values(kind, xi);
}

Eigen::Vector3d face_point(const FaceGeometry& face, const Eigen::Vector2d& xi)
{
  if (face.kind == FaceKind::quad4)
    return quad_point(face.quad(), xi);
  return face.x.transpose() * face_weights(face.kind, xi);
}

Eigen::Vector3d face_normal(const FaceGeometry& face, const Eigen::Vector2d& xi)
{
  if (face.kind == FaceKind::quad4)
    return quad_normal(face.quad(), xi);
  const Eigen::Matrix<double, 3, 2> t = tangents(face, xi);
  const Eigen::Vector3d cross = t.col(0).cross(t.col(1));
  const double length = cross.norm();
  return length > 0 ? Eigen::Vector3d(cross / length) : Eigen::Vector3d::Zero();
}

double face_area_estimate(const FaceGeometry& face, const Eigen::Vector2d& xi)
{
  const Eigen::Matrix<double, 3, 2> t = tangents(face, xi);
  if (mesh::is_line(face.kind))
    return 2 * t.col(0).norm() * face.planar.measure(face_point(face, xi));
  const double dm = t.col(0).cross(t.col(1)).norm();
  return mesh::face_corners(face.kind) == 3 ? dm / 2 : 4 * dm;
}

double face_diagonal(const QuadCoordinates& quad)
{
  return std::max((quad.row(2) - quad.row(0)).norm(), (quad.row(3) - quad.row(1)).norm());
}

double face_size(const FaceGeometry& face)
{
  if (face.kind == FaceKind::quad4)
    return face_diagonal(face.quad());
  double size = 0;
  for (int a = 0; a < face.n_corners(); ++a)
    for (int b = a + 1; b < face.n_corners(); ++b)
      size = std::max(size, (face.x.row(a) - face.x.row(b)).norm());
  return size;
}

QuadProjection project_to_face(const FaceGeometry& face, const Eigen::Vector3d& point, const ProjectionOptions& options)
{
  if (face.kind == FaceKind::quad4)
    return project_to_quad(face.quad(), point, options);
  QuadProjection p;
  p.xi = face.n_corners() == 3 ? Eigen::Vector2d(1.0 / 3, 1.0 / 3) : Eigen::Vector2d(0, 0);
  for (p.iterations = 0; p.iterations < options.max_iterations;)
  {
    const Eigen::Vector3d distance = face_point(face, p.xi) - point;
    const Eigen::Matrix<double, 3, 2> t = tangents(face, p.xi);
    const Eigen::Vector2d r = t.transpose() * distance;
    Eigen::Matrix2d J = t.transpose() * t;
    Eigen::Matrix2d curvature;
    for (int b = 0; b < 2; ++b)
    {
      const Eigen::Vector2d h = difference_step * Eigen::Vector2d::Unit(b);
      const Eigen::Matrix<double, 3, 2> dt =
          (tangents(face, p.xi + h) - tangents(face, p.xi - h)) / (2 * difference_step);
      curvature.col(b) = dt.transpose() * distance;
    }
    const Eigen::Matrix2d full = J + 0.5 * (curvature + curvature.transpose());
    const bool newton = full.determinant() > 0 && full.trace() > 0;
    if (newton)
      J = full;
    else
      ++p.gauss_newton_steps;
    if (!(J.determinant() > 0))
      break; // degenerate face
    Eigen::Vector2d step = -J.inverse() * r;
    ++p.iterations;
    if (step.norm() > max_projection_step)
      step *= max_projection_step / step.norm();
    p.xi += step;
    if (step.norm() < options.step_tolerance)
    {
      p.converged = true;
      break;
    }
  }
  p.point = face_point(face, p.xi);
  p.normal = face_normal(face, p.xi);
  p.gap = p.normal.dot(point - p.point);
  p.converged = p.converged && p.normal.squaredNorm() > 0;
  p.inside = outside_distance(face.kind, p.xi) <= options.inside_tolerance;
  return p;
}

Eigen::VectorXd face_lumped_areas(const FaceGeometry& face)
{
  switch (face.kind)
  {
  case FaceKind::quad4:
    return face_nodal_areas(face.quad());
  case FaceKind::tri3:
  {
    const double area = 0.5 * (face.x.row(1) - face.x.row(0)).cross(face.x.row(2) - face.x.row(0)).norm();
    return Eigen::Vector3d::Constant(area / 3);
  }
  case FaceKind::line2:
  {
    // int N_a times the out-of-plane measure (thickness, 2 pi r) ds: Gauss' 2 points are exact.
    Eigen::Vector2d areas = Eigen::Vector2d::Zero();
    const double half_length = 0.5 * (face.x.row(1) - face.x.row(0)).norm();
    for (const double t : {-1 / std::sqrt(3.0), 1 / std::sqrt(3.0)})
    {
      const Eigen::Vector2d N(0.5 * (1 - t), 0.5 * (1 + t));
      const Eigen::Vector3d x = face.x.topRows<2>().transpose() * N;
      areas += N * half_length * face.planar.measure(x);
    }
    return areas;
  }
  case FaceKind::tri6:
  case FaceKind::quad8:
  case FaceKind::line3:
    break;
  }
  Eigen::VectorXd areas = Eigen::VectorXd::Zero(face.x.rows());
  for (const std::vector<int>& facet : face_sub_facets(face.kind))
  {
    FaceGeometry sub;
    sub.kind = facet.size() == 2 ? FaceKind::line2 : facet.size() == 3 ? FaceKind::tri3 : FaceKind::quad4;
    sub.planar = face.planar;
    sub.x.resize(static_cast<Eigen::Index>(facet.size()), 3);
    for (size_t k = 0; k < facet.size(); ++k)
      sub.x.row(static_cast<Eigen::Index>(k)) = face.x.row(facet[k]);
    const Eigen::VectorXd sub_areas = face_lumped_areas(sub);
    for (size_t k = 0; k < facet.size(); ++k)
      areas(facet[k]) += sub_areas(static_cast<Eigen::Index>(k));
  }
  return areas;
}
} // namespace feticon::contact
