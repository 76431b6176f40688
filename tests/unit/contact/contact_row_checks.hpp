#pragma once
/// @file Checks of contact rows shared by the contact unit tests and the Hertz row tests.

#include "contact/contact_constraints.hpp"

#include <gtest/gtest.h>

namespace feticon::contact::row_checks
{
inline la::Vector dense_row(const ContactConstraints& rows, la::Index i)
{
  return la::Vector(rows.B.row(i).transpose());
}

/// Sum over the master DOFs of row i of the unnormalized weights: sum_a w_a (n . n) = sum_a w_a.
inline double weight_sum(const ContactConstraints& rows, la::Index i)
{
  const la::Vector row = dense_row(rows, i) * rows.row_norm[i];
  double sum = 0;
  for (la::Index dof = 0; dof < row.size(); ++dof)
    if (dof / 3 != rows.slave_node[i])
      sum += row(dof) * rows.normal[i](dof % 3);
  return sum;
}

inline void expect_rows_annihilate_translations(const ContactConstraints& rows, int32_t n_nodes)
{
  for (int component = 0; component < 3; ++component)
  {
    la::Vector translation = la::Vector::Zero(3 * n_nodes);
    for (int32_t node = 0; node < n_nodes; ++node)
      translation(3 * node + component) = 1.0;
    // Entries are O(1) after normalization: round-off of a sum of about 20 terms.
    EXPECT_LT((rows.B * translation).lpNorm<Eigen::Infinity>(), 1e-14) << "component " << component;
  }
}
} // namespace feticon::contact::row_checks
