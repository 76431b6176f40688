#include "fem/node_frames.hpp"

#include "common/error.hpp"

#include <algorithm>
#include <cmath>

namespace feticon::fem
{
Eigen::Matrix3d rectangular_axes(const Eigen::Vector3d& a, const Eigen::Vector3d& b)
{
  FETICON_CHECK(a.norm() > 0, "point a (on the local x axis) is the origin");
  const Eigen::Vector3d e1 = a.normalized();
  const Eigen::Vector3d in_plane = b - b.dot(e1) * e1;
  FETICON_CHECK(in_plane.norm() > 1e-10 * b.norm() && b.norm() > 0,
                "point b lies on the local x axis (through the origin and a)");
  Eigen::Matrix3d axes;
  axes.row(0) = e1;
  axes.row(1) = in_plane.normalized();
  axes.row(2) = e1.cross(Eigen::Vector3d(axes.row(1)));
  return axes;
}

Eigen::Matrix3d cylindrical_axes(const Eigen::Vector3d& a, const Eigen::Vector3d& b, const Eigen::Vector3d& x)
{
  FETICON_CHECK((b - a).norm() > 0, "the cylinder axis needs two different points a and b");
  const Eigen::Vector3d e3 = (b - a).normalized();
  Eigen::Vector3d e1 = x - a;
  e1 -= e1.dot(e3) * e3;
  if (e1.norm() < 1e-10)
  {
    // On the axis: a perpendicular chosen as CalculiX's transformatrix.f chooses it.
    if (std::abs(e3(0)) > 1e-10)
      e1 = {-e3(1) / e3(0), 1, 0};
    else if (std::abs(e3(1)) > 1e-10)
      e1 = {0, -e3(2) / e3(1), 1};
    else
      e1 = {1, 0, -e3(0) / e3(2)};
  }
  e1.normalize();
  Eigen::Matrix3d axes;
  axes.row(0) = e1;
  axes.row(1) = e3.cross(e1);
  axes.row(2) = e3;
  return axes;
}

int32_t NodeFrames::index_of(int32_t node) const
{
  const auto it = std::lower_bound(nodes.begin(), nodes.end(), node);
  return it != nodes.end() && *it == node ? static_cast<int32_t>(it - nodes.begin()) : -1;
}

int32_t NodeFrames::node_of(int32_t n_mesh_nodes, int64_t dof) const
{
  return nodes[static_cast<size_t>(dof / 3 - n_mesh_nodes)];
}

Eigen::Vector3d NodeFrames::direction_of(int32_t n_mesh_nodes, int64_t dof) const
{
  return axes[static_cast<size_t>(dof / 3 - n_mesh_nodes)].row(static_cast<int>(dof % 3)).transpose();
}

std::pair<int64_t, double> NodeFrames::held(int32_t n_mesh_nodes, int32_t node, int component, double value) const
{
  const int32_t k = index_of(node);
  FETICON_ASSERT(k >= 0, "node " << node << " has no frame");
  const Eigen::Vector3d e = axes[static_cast<size_t>(k)].row(component).transpose();
  for (int g = 0; g < 3; ++g)
    if (std::abs(e((g + 1) % 3)) < 1e-14 && std::abs(e((g + 2) % 3)) < 1e-14)
      return {3 * int64_t{node} + g, e(g) > 0 ? value : -value};
  return {local_dof(n_mesh_nodes, k, component), value};
}

la::Vector NodeFrames::extended(const la::Vector& u) const
{
  la::Vector out(u.size() + 3 * static_cast<la::Index>(nodes.size()));
  out.head(u.size()) = u;
  for (size_t k = 0; k < nodes.size(); ++k)
    out.segment<3>(u.size() + 3 * static_cast<la::Index>(k)) = axes[k] * u.segment<3>(3 * la::Index{nodes[k]});
  return out;
}
} // namespace feticon::fem
