#include "contact/adjust.hpp"

#include "contact/contact_constraints.hpp"

#include <algorithm>
#include <cmath>
#include <limits>

namespace feticon::contact
{
int64_t adjust_slave_nodes(fem::Problem& problem)
{
  int64_t moved = 0;
  for (const fem::ContactPairNames& pair : problem.contacts)
  {
    if (pair.adjust <= 0 && pair.adjust_nodes.empty())
      continue;
    ContactOptions options;
    options.formulation = ContactFormulation::node_to_segment; // one closest point per node
    // Candidates within one master element (the automatic distance: penetrations too, whose
    // nodes lie inside the master body) or the distance if farther; rows only for g < d_s,
    // so d_s is just above the distance and g = adjust is moved too.
    options.search_distance = std::max(largest_face_diagonal(problem.mesh, {}, problem.mesh.face_set(pair.master)),
                                       std::nextafter(pair.adjust, std::numeric_limits<double>::infinity()));
    const ContactConstraints rows =
        build_node_to_segment_constraints(problem.mesh, {}, {pair.slave, pair.master, pair.slave_nodes}, options);
    const std::vector<int32_t>* set = pair.adjust_nodes.empty() ? nullptr : &problem.mesh.node_set(pair.adjust_nodes);
    for (int64_t i = 0; i < rows.n_rows(); ++i)
    {
      const int32_t node = rows.slave_node[i];
      const bool chosen = set ? std::binary_search(set->begin(), set->end(), node) : rows.gap[i] <= pair.adjust;
      if (!chosen || rows.gap[i] == 0)
        continue;
      problem.mesh.nodes.row(node) -= rows.gap[i] * rows.normal[i].transpose();
      ++moved;
    }
  }
  return moved;
}
} // namespace feticon::contact
