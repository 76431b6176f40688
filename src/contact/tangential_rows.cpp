#include "contact/tangential_rows.hpp"

#include "common/error.hpp"

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

TangentialRows build_tangential_rows(const ContactConstraints& normal, const std::array<bool, 3>& eliminated)
{
  TangentialRows out;
  std::vector<Eigen::Triplet<double>> triplets;
  for (int64_t i = 0; i < normal.n_rows(); ++i)
  {
    const Eigen::Vector3d& n = normal.normal[i];
    // The row's entries are w_node n_c / |b| (w = -1 on the slave): w_node / |b| = sum_c entry_c n_c.
    std::map<int64_t, double> weight;
    for (Eigen::SparseMatrix<double, Eigen::RowMajor>::InnerIterator it(normal.B, i); it; ++it)
      weight[it.col() / 3] += it.value() * n(it.col() % 3);
    const std::vector<Eigen::Vector3d> tangents = unit_tangents(n, eliminated);
    out.n_tangents = static_cast<int>(tangents.size());
    for (const Eigen::Vector3d& t : tangents)
    {
      const int64_t row = out.n_rows();
      for (const auto& [node, w] : weight)
        for (int c = 0; c < 3; ++c)
          if (t(c) != 0)
            triplets.emplace_back(row, 3 * node + c, w * t(c));
      out.tangent.push_back(t);
      out.slave_node.push_back(normal.slave_node[i]);
    }
  }
  if (normal.n_rows() == 0)
    out.n_tangents = eliminated[0] || eliminated[1] || eliminated[2] ? 1 : 2;
  out.B.resize(out.n_rows(), normal.B.cols());
  out.B.setFromTriplets(triplets.begin(), triplets.end());
  return out;
}

la::Vector tangential_forces(const TangentialRows& rows, const la::Vector& lambda_hat, la::Index n_dofs)
{
  FETICON_CHECK(lambda_hat.size() == rows.n_rows() && rows.B.cols() == n_dofs,
                "tangential_forces: " << lambda_hat.size() << " multipliers for " << rows.n_rows() << " rows");
  return -(rows.B.transpose() * lambda_hat);
}
} // namespace feticon::contact
