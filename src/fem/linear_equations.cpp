#include "fem/linear_equations.hpp"

#include "common/error.hpp"

#include <algorithm>
#include <cmath>
#include <map>
#include <sstream>

namespace feticon::fem
{
std::vector<ReducedEquation> reduce_equations(const std::vector<LinearEquation>& equations, int64_t n_dofs,
                                              const ConstrainedDofs& prescribed, const std::array<bool, 3>& eliminated,
                                              const mesh::Mesh* mesh)
{
  std::vector<ReducedEquation> out;
  out.reserve(equations.size());
  for (size_t e = 0; e < equations.size(); ++e)
  {
    // Summed per DOF, with the sum of magnitudes that decides whether a sum cancelled.
    std::map<int64_t, std::pair<double, double>> free_terms;
    ReducedEquation reduced;
    reduced.rhs = equations[e].rhs;
    for (const LinearEquation::Term& term : equations[e].terms)
    {
      FETICON_CHECK(term.node >= 0 && 3 * static_cast<int64_t>(term.node) < n_dofs && term.component >= 0 &&
                        term.component < 3,
                    describe_equation(equations, e, mesh)
                        << " names node " << term.node << ", component " << term.component << ", outside the mesh");
      const int64_t dof = 3 * static_cast<int64_t>(term.node) + term.component;
      if (eliminated[term.component])
        continue; // identically zero
      const auto it = std::lower_bound(prescribed.dofs.begin(), prescribed.dofs.end(), dof);
      if (it != prescribed.dofs.end() && *it == dof)
      {
        reduced.rhs -= term.coefficient * prescribed.values(it - prescribed.dofs.begin());
        continue;
      }
      auto& [sum, magnitude] = free_terms[dof];
      sum += term.coefficient;
      magnitude += std::abs(term.coefficient);
    }
    for (const auto& [dof, term] : free_terms)
      if (std::abs(term.first) > 1e-14 * term.second)
      {
        reduced.dofs.push_back(dof);
        reduced.coefficients.push_back(term.first);
      }
    FETICON_CHECK(!reduced.dofs.empty(),
                  describe_equation(equations, e, mesh)
                      << " has no term on a free degree of freedom: every term lies on a prescribed (support) or "
                         "eliminated (plane strain) component or the terms cancel, so it repeats the supports or "
                         "contradicts them; remove it or the support");
    out.push_back(std::move(reduced));
  }
  return out;
}

std::string describe_equation(const std::vector<LinearEquation>& equations, size_t index, const mesh::Mesh* mesh)
{
  static constexpr const char* component_name[] = {"u_x", "u_y", "u_z"};
  std::ostringstream os;
  os << "linear equation " << index + 1 << " of " << equations.size() << " (";
  const auto& terms = equations[index].terms;
  constexpr size_t shown = 4;
  for (size_t k = 0; k < std::min(terms.size(), shown); ++k)
  {
    const auto& t = terms[k];
    const bool known_component = t.component >= 0 && t.component < 3;
    const bool known_node = mesh && t.node >= 0 && t.node < mesh->n_nodes();
    if (k > 0)
      os << (t.coefficient < 0 ? " - " : " + ");
    else if (t.coefficient < 0)
      os << "-";
    os << std::abs(t.coefficient) << " " << (known_component ? component_name[t.component] : "u_?") << " at node "
       << t.node;
    if (known_node)
      os << " (" << mesh->nodes(t.node, 0) << ", " << mesh->nodes(t.node, 1) << ", " << mesh->nodes(t.node, 2) << ")";
  }
  if (terms.size() > shown)
    os << " + " << terms.size() - shown << " more terms";
  os << " = 0)";
  return os.str();
}

std::string dependent_equation_message(const std::vector<LinearEquation>& equations, size_t index,
                                       const mesh::Mesh* mesh)
{
  return describe_equation(equations, index, mesh) +
      " is linearly dependent on the supports and the equations before it (a repeated or redundant "
      "constraint): remove it";
}
} // namespace feticon::fem
