#pragma once
/// @file The one way contact rows are made (node-to-segment, dual mortar, and the subset a
/// linear run selects): row i of slave node s with master nodes a and weights w_a,
///
///   b_i = (-n at s, w_a n at each a) / |b|,  |b| = sqrt(1 + sum_a w_a^2),  c_i = g_i / |b|,
///
/// and its fields (normal, gap, slave area, closest point) appended together, so that the
/// parallel arrays of ContactConstraints cannot fall out of step.

#include "contact/contact_constraints.hpp"

#include <utility>
#include <vector>

namespace feticon::contact
{
/// A row's fields beside B: what the caller knows of the slave node and its closest point.
struct ContactRowFields
{
  int32_t slave_node = 0;
  Eigen::Vector3d normal = Eigen::Vector3d::Zero(); ///< unit, outward of the master body
  double gap = 0;                                   ///< unnormalized, >= 0 open
  double slave_area = 0;                            ///< D_j (m^2); 0 if set later
  int32_t master_face = 0;
  Eigen::Vector2d xi = Eigen::Vector2d::Zero();
  ProjectionKind kind = ProjectionKind::face;
  double master_share = 1;     ///< ContactConstraints::master_share
  int32_t pair = 0;            ///< ContactConstraints::pair
  double master_face_area = 0; ///< ContactConstraints::master_face_area
};

class ContactRowBuilder
{
public:
  /// Appends the row of `fields` with master nodes and weights (w_a; zero weights are skipped).
  void add(const ContactRowFields& fields, const std::vector<std::pair<int32_t, double>>& master_weights);
  /// Appends row i of `from` unchanged but for its gap and its pair.
  void copy(const ContactConstraints& from, la::Index i, double gap, int32_t pair);
  int64_t n_rows() const { return static_cast<int64_t>(_out.slave_node.size()); }
  /// The rows over n_dofs DOFs, with B and c formed; `into` keeps its other fields (search
  /// distance, slave counts) and gets the rows.
  void finish(la::Index n_dofs, ContactConstraints& into);

private:
  ContactConstraints _out;
  std::vector<Eigen::Triplet<double>> _triplets;
  void append_fields(const ContactRowFields& fields, double norm);
};
} // namespace feticon::contact
