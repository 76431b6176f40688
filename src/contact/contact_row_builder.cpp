#include "contact/contact_row_builder.hpp"

#include <cmath>

namespace feticon::contact
{
void ContactRowBuilder::append_fields(const ContactRowFields& fields, double norm)
{
  _out.slave_node.push_back(fields.slave_node);
  _out.normal.push_back(fields.normal);
  _out.gap.push_back(fields.gap);
  _out.row_norm.push_back(norm);
  _out.slave_area.push_back(fields.slave_area);
  _out.master_face.push_back(fields.master_face);
  _out.xi.push_back(fields.xi);
  _out.kind.push_back(fields.kind);
  _out.master_share.push_back(fields.master_share);
  _out.pair.push_back(fields.pair);
  _out.master_face_area.push_back(fields.master_face_area);
}

void ContactRowBuilder::add(const ContactRowFields& fields,
                            const std::vector<std::pair<int32_t, double>>& master_weights)
{
  const auto row = static_cast<int>(n_rows());
  double weights_squared = 0;
  for (const auto& [node, weight] : master_weights)
    weights_squared += weight * weight;
  const double norm = std::sqrt(1 + weights_squared);
  const Eigen::Vector3d& n = fields.normal;
  for (int k = 0; k < 3; ++k)
  {
    if (n(k) == 0)
      continue;
    _triplets.emplace_back(row, 3 * fields.slave_node + k, -n(k) / norm);
    for (const auto& [node, weight] : master_weights)
      if (weight != 0)
        _triplets.emplace_back(row, 3 * node + k, weight * n(k) / norm);
  }
  append_fields(fields, norm);
}

void ContactRowBuilder::copy(const ContactConstraints& from, la::Index i, double gap, int32_t pair)
{
  const auto row = static_cast<int>(n_rows());
  for (Eigen::SparseMatrix<double, Eigen::RowMajor>::InnerIterator it(from.B, i); it; ++it)
    _triplets.emplace_back(row, static_cast<int>(it.col()), it.value());
  append_fields({from.slave_node[i], from.normal[i], gap, from.slave_area[i], from.master_face[i], from.xi[i],
                 from.kind[i], from.master_share[i], pair, from.master_face_area[i]},
                from.row_norm[i]);
}

void ContactRowBuilder::finish(la::Index n_dofs, ContactConstraints& into)
{
  const auto rows = static_cast<la::Index>(n_rows());
  _out.B.resize(rows, n_dofs);
  _out.B.setFromTriplets(_triplets.begin(), _triplets.end());
  _out.c.resize(rows);
  for (la::Index i = 0; i < rows; ++i)
    _out.c(i) = _out.gap[i] / _out.row_norm[i];
  into.B = std::move(_out.B);
  into.c = std::move(_out.c);
  into.slave_node = std::move(_out.slave_node);
  into.normal = std::move(_out.normal);
  into.gap = std::move(_out.gap);
  into.row_norm = std::move(_out.row_norm);
  into.slave_area = std::move(_out.slave_area);
  into.master_face = std::move(_out.master_face);
  into.xi = std::move(_out.xi);
  into.kind = std::move(_out.kind);
  into.master_share = std::move(_out.master_share);
  into.master_face_area = std::move(_out.master_face_area);
  into.pair = std::move(_out.pair);
  _out = {};
  _triplets.clear();
}
} // namespace feticon::contact
