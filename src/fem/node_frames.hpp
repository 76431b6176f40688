#pragma once
/// @file Local coordinate systems of nodes (CalculiX / Abaqus *TRANSFORM): the supports and
/// concentrated forces of a node with a frame act along its local axes, e'_1, e'_2, e'_3.
///
/// A support on a local axis e is the constraint e . u = value: a unit DOF when e is a global
/// axis (up to sign), else a row with the components of e (CalculiX turns it into a
/// non-homogeneous multi-point constraint the same way). Held DOFs (fem::ConstrainedDofs,
/// fem::LoadHistory) number such local components past the global ones: DOF 3 N + 3 k + c is
/// local component c of the node with frame k (N mesh nodes), so a history holds, ramps and
/// restarts them as it does global DOFs. `extended(u)` appends their values to a displacement.

#include "la/types.hpp"

#include <Eigen/Dense>

#include <cstdint>
#include <vector>

namespace feticon::fem
{
/// The axes of CalculiX's rectangular system (TYPE=R): e'_1 along a (from the origin), e'_2 in
/// the plane of a and b, e'_3 = e'_1 x e'_2. Rows of the result are the axes.
/// @throws feticon::Error if a is zero or b is parallel to it
Eigen::Matrix3d rectangular_axes(const Eigen::Vector3d& a, const Eigen::Vector3d& b);

/// The axes of CalculiX's cylindrical system (TYPE=C) at point x: e'_3 along the axis from a to
/// b, e'_1 radial (from the axis to x), e'_2 = e'_3 x e'_1 tangential. On the axis (distance
/// below 1e-10) e'_1 is the perpendicular CalculiX's transformatrix.f picks.
/// @throws feticon::Error if a and b coincide
Eigen::Matrix3d cylindrical_axes(const Eigen::Vector3d& a, const Eigen::Vector3d& b, const Eigen::Vector3d& x);

struct NodeFrames
{
  std::vector<int32_t> nodes;        ///< mesh nodes with a frame, increasing
  std::vector<Eigen::Matrix3d> axes; ///< per node: row c is local axis c (orthonormal, right-handed)

  bool empty() const { return nodes.empty(); }
  /// The frame index of `node`, or -1.
  int32_t index_of(int32_t node) const;
  /// The held DOF of local component `component` of frame `k` (file comment).
  static int64_t local_dof(int32_t n_mesh_nodes, int32_t k, int component)
  {
    return 3 * (int64_t{n_mesh_nodes} + k) + component;
  }
  /// Whether held DOF `dof` is a local component (not a global one).
  static bool is_local(int32_t n_mesh_nodes, int64_t dof) { return dof >= 3 * int64_t{n_mesh_nodes}; }
  /// The node and the global direction of the local held DOF `dof`.
  int32_t node_of(int32_t n_mesh_nodes, int64_t dof) const;
  Eigen::Vector3d direction_of(int32_t n_mesh_nodes, int64_t dof) const;
  /// Held DOF and value of local component `component` = `value` of `node` (with a frame): the
  /// global DOF and signed value when the local axis is a global one (its other components below
  /// 1e-14), else the local DOF and the value.
  std::pair<int64_t, double> held(int32_t n_mesh_nodes, int32_t node, int component, double value) const;
  /// u (3 per mesh node) followed by the local components of every frame's node.
  la::Vector extended(const la::Vector& u) const;
};
} // namespace feticon::fem
