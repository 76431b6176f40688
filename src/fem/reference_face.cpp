#include "fem/reference_face.hpp"

#include "fem/reference_element.hpp"

#include <array>
#include <cmath>

namespace feticon::fem
{
namespace
{
using mesh::FaceKind;

constexpr std::array<std::array<double, 2>, 4> quad_corners = {{{-1, -1}, {1, -1}, {1, 1}, {-1, 1}}};
/// quad8's edge nodes: the midpoints of c0 c1, c1 c2, c2 c3, c3 c0.
constexpr std::array<std::array<double, 2>, 4> quad_edge_nodes = {{{0, -1}, {1, 0}, {0, 1}, {-1, 0}}};
/// tri6's edge nodes join the corners (a, b).
constexpr std::array<std::array<int, 2>, 3> tri_edges = {{{0, 1}, {1, 2}, {2, 0}}};

FaceQuadrature gauss_square(int n)
{
  const std::vector<double>& x = gauss_line(n).points;
  const std::vector<double>& w = gauss_line(n).weights;
  FaceQuadrature rule;
  for (int i = 0; i < n; ++i)
    for (int j = 0; j < n; ++j)
    {
      rule.points.emplace_back(x[i], x[j]);
      rule.weights.push_back(w[i] * w[j]);
    }
  return rule;
}

FaceQuadrature triangle_rule(bool degree4)
{
  FaceQuadrature rule;
  const auto add_orbit = [&](double a, double weight) {
    for (const Eigen::Vector2d& p :
         {Eigen::Vector2d(a, a), Eigen::Vector2d(1 - 2 * a, a), Eigen::Vector2d(a, 1 - 2 * a)})
    {
      rule.points.push_back(p);
      rule.weights.push_back(0.5 * weight);
    }
  };
  if (!degree4)
  {
    add_orbit(1.0 / 6, 1.0 / 3);
    return rule;
  }
  add_orbit(0.445948490915965, 0.223381589678011);
  add_orbit(0.091576213509771, 0.109951743655322);
  return rule;
}
} // namespace

FaceValues face_shape_values(FaceKind kind, const Eigen::Vector2d& xi)
{
  const double r = xi(0), s = xi(1);
  const Eigen::Vector3d L(1 - r - s, r, s);
  FaceValues N(mesh::face_nodes(kind));
  switch (kind)
  {
  case FaceKind::tri3:
    N = L;
    break;
  case FaceKind::tri6:
    for (int a = 0; a < 3; ++a)
      N(a) = L(a) * (2 * L(a) - 1);
    for (int e = 0; e < 3; ++e)
      N(3 + e) = 4 * L(tri_edges[e][0]) * L(tri_edges[e][1]);
    break;
  case FaceKind::quad4:
    for (int a = 0; a < 4; ++a)
      N(a) = 0.25 * (1 + quad_corners[a][0] * r) * (1 + quad_corners[a][1] * s);
    break;
  case FaceKind::line2:
    N << 0.5 * (1 - r), 0.5 * (1 + r);
    break;
  case FaceKind::line3:
    N << 0.5 * r * (r - 1), 0.5 * r * (r + 1), 1 - r * r;
    break;
  case FaceKind::quad8:
    for (int a = 0; a < 4; ++a)
    {
      const double ra = quad_corners[a][0], sa = quad_corners[a][1];
      N(a) = 0.25 * (1 + ra * r) * (1 + sa * s) * (ra * r + sa * s - 1);
      const double re = quad_edge_nodes[a][0], se = quad_edge_nodes[a][1];
      N(4 + a) = re == 0 ? 0.5 * (1 - r * r) * (1 + se * s) : 0.5 * (1 + re * r) * (1 - s * s);
    }
    break;
  }
  return N;
}

FaceGradients face_shape_gradients(FaceKind kind, const Eigen::Vector2d& xi)
{
  const double r = xi(0), s = xi(1);
  const Eigen::Vector3d L(1 - r - s, r, s);
  // dL_a / d(r, s)
  const std::array<Eigen::RowVector2d, 3> dL = {Eigen::RowVector2d(-1, -1), Eigen::RowVector2d(1, 0),
                                                Eigen::RowVector2d(0, 1)};
  FaceGradients dN = FaceGradients::Zero(mesh::face_nodes(kind), 2);
  switch (kind)
  {
  case FaceKind::line2:
    dN.col(0) << -0.5, 0.5;
    break;
  case FaceKind::line3:
    dN.col(0) << r - 0.5, r + 0.5, -2 * r;
    break;
  case FaceKind::tri3:
    for (int a = 0; a < 3; ++a)
      dN.row(a) = dL[a];
    break;
  case FaceKind::tri6:
    for (int a = 0; a < 3; ++a)
      dN.row(a) = (4 * L(a) - 1) * dL[a];
    for (int e = 0; e < 3; ++e)
    {
      const int a = tri_edges[e][0], b = tri_edges[e][1];
      dN.row(3 + e) = 4 * (dL[a] * L(b) + L(a) * dL[b]);
    }
    break;
  case FaceKind::quad4:
    for (int a = 0; a < 4; ++a)
    {
      const double ra = quad_corners[a][0], sa = quad_corners[a][1];
      dN.row(a) << 0.25 * ra * (1 + sa * s), 0.25 * sa * (1 + ra * r);
    }
    break;
  case FaceKind::quad8:
    for (int a = 0; a < 4; ++a)
    {
      const double ra = quad_corners[a][0], sa = quad_corners[a][1];
      dN.row(a) << 0.25 * ra * (1 + sa * s) * (2 * ra * r + sa * s), 0.25 * sa * (1 + ra * r) * (ra * r + 2 * sa * s);
      const double re = quad_edge_nodes[a][0], se = quad_edge_nodes[a][1];
      if (re == 0)
        dN.row(4 + a) << -r * (1 + se * s), 0.5 * se * (1 - r * r);
      else
        dN.row(4 + a) << 0.5 * re * (1 - s * s), -s * (1 + re * r);
    }
    break;
  }
  return dN;
}

/// The n-point Gauss rule on the segment [-1, 1] (eta = 0).
FaceQuadrature gauss_segment(int n)
{
  FaceQuadrature rule;
  for (int i = 0; i < n; ++i)
  {
    rule.points.emplace_back(gauss_line(n).points[i], 0);
    rule.weights.push_back(gauss_line(n).weights[i]);
  }
  return rule;
}

const FaceQuadrature& face_quadrature(FaceKind kind)
{
  static const std::array<FaceQuadrature, 6> rules = {triangle_rule(false), triangle_rule(true), gauss_square(2),
                                                      gauss_square(3),      gauss_segment(2),    gauss_segment(3)};
  return rules[static_cast<size_t>(kind)];
}
} // namespace feticon::fem
