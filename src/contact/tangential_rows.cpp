#include "contact/tangential_rows.hpp"

#include "common/error.hpp"

#include <algorithm>
#include <bit>
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
/// The axes e (bit e set) of symmetry planes through the contact at this row: supports hold
/// its slave node along e, n is nearly normal to e (|n_e| < 0.05), and the row's weight on
/// nodes not held along e is below `spread` (5 %, 15 % for the transformed dual basis of
/// quadratic faces) of its norm. By symmetry the friction traction across
/// such a plane vanishes, whatever those remainders are; they are not zero because the dual
/// mortar basis of a slave node on the plane reaches master nodes one cell row beside it (0.17 %
/// of the row's norm on hertz3d's quarter model, and slivers of 1e-6), and because a plane
/// node's normal in the current configuration averages the faces on one side of the plane only
/// (|n_y| = 1.5e-3 on hertz3d's half model with large displacements). Kept in the QP, such a
/// row is (nearly) a combination of the supports' rows: (B B')_CC had an eigenvalue of 4e-7
/// (small displacements) and of 4e-16 (large) and its inverse, the preconditioner's scaling,
/// stalled MPGP or was dropped (docs/friction.md).
int supported_axes(const std::map<int64_t, double>& weight, int64_t slave, const Eigen::Vector3d& n,
                   const std::vector<int64_t>& supported, double spread)
{
  int axes = 0;
  for (int e = 0; e < 3 && !supported.empty(); ++e)
  {
    const auto held = [&](int64_t node) { return std::ranges::binary_search(supported, 3 * node + e); };
    if (std::abs(n(e)) >= 0.05 || !held(slave))
      continue;
    double norm2 = 0, unheld2 = 0;
    for (const auto& [node, w] : weight)
    {
      norm2 += w * w;
      unheld2 += held(node) ? 0.0 : w * w;
    }
    if (unheld2 < spread * spread * norm2)
      axes |= 1 << e;
  }
  return axes;
}
} // namespace

TangentialRows build_tangential_rows(const ContactConstraints& normal, const std::array<bool, 3>& eliminated,
                                     const std::vector<int64_t>& supported)
{
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
    // Held tangents: t_2 along a supported axis; t_1 too where a second one holds it (the
    // line where two symmetry planes meet).
    const int axes = plane_strain ? 0 : supported_axes(weight, normal.slave_node[i], n, supported, spread);
    std::array<bool, 2> held{false, false};
    if (axes != 0)
    {
      const int axis = std::countr_zero(static_cast<unsigned>(axes));
      const Eigen::Vector3d t1 = Eigen::Vector3d::Unit(axis).cross(n).normalized();
      tangents = {t1, n.cross(t1)};
      held[1] = true;
      for (int e = axis + 1; e < 3; ++e)
        held[0] = held[0] || ((axes >> e & 1) && std::abs(t1(e)) > 1 - 1e-3);
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
      out.held.push_back(axes != 0 && held[k]);
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
