#include "contact/tangential_rows.hpp"

#include "common/error.hpp"

#include <algorithm>
#include <cmath>
#include <map>

namespace feticon::contact
{
std::vector<Eigen::Vector3d> unit_tangents(const Eigen::Vector3d& n, const std::array<bool, 3>& eliminated)
{
  const int n_eliminated = eliminated[0] + eliminated[1] + eliminated[2];
  FETICON_CHECK(n_eliminated <= 1,
                "friction: tangential rows need a 3D model or plane strain (one eliminated "
                "displacement component), not "
                    << n_eliminated << " eliminated components");
  if (n_eliminated == 1)
  {
    Eigen::Vector3d axis = Eigen::Vector3d::Zero();
    axis(eliminated[0] ? 0 : eliminated[1] ? 1 : 2) = 1;
    return {axis.cross(n).normalized()};
  }
  Eigen::Index least;
  n.cwiseAbs().minCoeff(&least);
  const Eigen::Vector3d t1 = Eigen::Vector3d::Unit(least).cross(n).normalized();
  return {t1, n.cross(t1)};
}

namespace
{
/// The directions along which supports hold `node`: the global axes of its held DOFs, and the
/// local axes of its local ones (fem/node_frames.hpp), in that order.
std::vector<Eigen::Vector3d> held_directions(int64_t node, const std::vector<int64_t>& supported,
                                             const fem::NodeFrames* frames, int32_t n_mesh_nodes)
{
  std::vector<Eigen::Vector3d> out;
  for (int e = 0; e < 3; ++e)
    if (std::ranges::binary_search(supported, 3 * node + e))
      out.push_back(Eigen::Vector3d::Unit(e));
  const int32_t k = frames ? frames->index_of(static_cast<int32_t>(node)) : -1;
  for (int c = 0; c < 3 && k >= 0; ++c)
  {
    const int64_t dof = fem::NodeFrames::local_dof(n_mesh_nodes, k, c);
    if (std::ranges::binary_search(supported, dof))
      out.push_back(frames->direction_of(n_mesh_nodes, dof));
  }
  return out;
}

/// The held directions d of symmetry planes through the contact at this row: supports hold its
/// slave node along d, n is nearly normal to d (|n . d| < 0.05), and the row's weight on nodes
/// not held along d (within 8 degrees: the nodes of a thin sector whose circumferential
/// direction a cylindrical *TRANSFORM holds) is below `spread` (5 %, 15 % for the transformed
/// dual basis of quadratic faces) of its norm. By symmetry the friction traction across such a
/// plane vanishes, whatever those remainders are; they are not zero because the dual mortar
/// basis of a slave node on the plane reaches master nodes one cell row beside it (0.17 % of the
/// row's norm on hertz3d's quarter model, and slivers of 1e-6), and because a plane node's
/// normal in the current configuration averages the faces on one side of the plane only (|n_y|
/// = 1.5e-3 on hertz3d's half model with large displacements). Kept in the QP, such a row is
/// (nearly) a combination of the supports' rows: (B B')_CC had an eigenvalue of 4e-7 (small
/// displacements) and of 4e-16 (large) and its inverse, the preconditioner's scaling, stalled
/// MPGP or was dropped (docs/friction.md).
std::vector<Eigen::Vector3d> supported_directions(const std::map<int64_t, double>& weight, int64_t slave,
                                                  const Eigen::Vector3d& n, const std::vector<int64_t>& supported,
                                                  const fem::NodeFrames* frames, int32_t n_mesh_nodes, double spread)
{
  const auto held = [&](int64_t node) { return held_directions(node, supported, frames, n_mesh_nodes); };
  std::vector<Eigen::Vector3d> out;
  for (const Eigen::Vector3d& d : held(slave))
  {
    if (std::abs(n.dot(d)) >= 0.05)
      continue;
    double norm2 = 0, unheld2 = 0;
    for (const auto& [node, w] : weight)
    {
      norm2 += w * w;
      const std::vector<Eigen::Vector3d> other = held(node);
      const bool along =
          std::ranges::any_of(other, [&](const Eigen::Vector3d& e) { return std::abs(e.dot(d)) > 0.99; });
      unheld2 += along ? 0.0 : w * w;
    }
    if (unheld2 < spread * spread * norm2)
      out.push_back(d);
  }
  return out;
}
} // namespace

TangentialRows build_tangential_rows(const ContactConstraints& normal, const std::array<bool, 3>& eliminated,
                                     const std::vector<int64_t>& supported, const fem::NodeFrames* frames)
{
  const auto n_mesh_nodes = static_cast<int32_t>(normal.B.cols() / 3);
  TangentialRows out;
  std::vector<Eigen::Triplet<double>> triplets;
  const bool plane_strain = eliminated[0] || eliminated[1] || eliminated[2];
  // The transformed basis of quadratic faces gives master nodes one cell row beside the plane
  // up to 11.2 % of a plane node's row (hertz3d hex20's half model; bilinear faces 0.17 %):
  // under 5 %, a third of those rows stayed in the QP, (B B')_CC had the eigenvalue 2.8e-5 and
  // the solve stalled (docs/elements.md).
  const double spread = normal.transformed_basis ? 0.15 : 0.05;
  for (int64_t i = 0; i < normal.n_rows(); ++i)
  {
    const Eigen::Vector3d& n = normal.normal[i];
    // The row's entries are w_node n_c / |b| (w = -1 on the slave): w_node / |b| = sum_c entry_c n_c.
    std::map<int64_t, double> weight;
    for (Eigen::SparseMatrix<double, Eigen::RowMajor>::InnerIterator it(normal.B, i); it; ++it)
      weight[it.col() / 3] += it.value() * n(it.col() % 3);
    std::vector<Eigen::Vector3d> tangents = unit_tangents(n, eliminated);
    // Held tangents: t_2 along a supported direction; t_1 too where a second one holds it (the
    // line where two symmetry planes meet).
    const std::vector<Eigen::Vector3d> planes = plane_strain || supported.empty()
        ? std::vector<Eigen::Vector3d>{}
        : supported_directions(weight, normal.slave_node[i], n, supported, frames, n_mesh_nodes, spread);
    std::array<bool, 2> held{false, false};
    if (!planes.empty())
    {
      const Eigen::Vector3d t1 = planes.front().cross(n).normalized();
      tangents = {t1, n.cross(t1)};
      held[1] = true;
      for (size_t e = 1; e < planes.size(); ++e)
        held[0] = held[0] || std::abs(t1.dot(planes[e])) > 1 - 1e-3;
    }
    out.n_tangents = static_cast<int>(tangents.size());
    for (size_t k = 0; k < tangents.size(); ++k)
    {
      const Eigen::Vector3d& t = tangents[k];
      const int64_t row = out.n_rows();
      for (const auto& [node, w] : weight)
        for (int c = 0; c < 3; ++c)
          if (t(c) != 0)
            triplets.emplace_back(row, 3 * node + c, w * t(c));
      out.tangent.push_back(t);
      out.slave_node.push_back(normal.slave_node[i]);
      out.pair.push_back(normal.pair[i]);
      out.held.push_back(held[k]);
    }
  }
  if (normal.n_rows() == 0)
    out.n_tangents = plane_strain ? 1 : 2;
  out.B.resize(out.n_rows(), normal.B.cols());
  out.B.setFromTriplets(triplets.begin(), triplets.end());
  return out;
}

TangentialRows pair_rows(const TangentialRows& rows, int32_t p, const la::Vector& lambda, la::Vector& lambda_p)
{
  TangentialRows out;
  out.n_tangents = rows.n_tangents;
  std::vector<Eigen::Triplet<double>> triplets;
  std::vector<double> values;
  for (int64_t r = 0; r < rows.n_rows(); ++r)
    if (rows.pair[r] == p)
    {
      for (Eigen::SparseMatrix<double, Eigen::RowMajor>::InnerIterator it(rows.B, r); it; ++it)
        triplets.emplace_back(static_cast<int>(out.n_rows()), static_cast<int>(it.col()), it.value());
      out.tangent.push_back(rows.tangent[r]);
      out.slave_node.push_back(rows.slave_node[r]);
      out.pair.push_back(p);
      out.held.push_back(rows.held[r]);
      if (r < lambda.size())
        values.push_back(lambda(r));
    }
  out.B.resize(out.n_rows(), rows.B.cols());
  out.B.setFromTriplets(triplets.begin(), triplets.end());
  lambda_p = Eigen::Map<const la::Vector>(values.data(), static_cast<la::Index>(values.size()));
  return out;
}

la::Vector tangential_forces(const TangentialRows& rows, const la::Vector& lambda_hat, la::Index n_dofs)
{
  FETICON_CHECK(lambda_hat.size() == rows.n_rows() && rows.B.cols() == n_dofs,
                "tangential_forces: " << lambda_hat.size() << " multipliers for " << rows.n_rows() << " rows");
  return -(rows.B.transpose() * lambda_hat);
}
} // namespace feticon::contact
