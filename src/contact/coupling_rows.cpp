#include "contact/coupling_rows.hpp"

#include <sstream>

namespace feticon::contact
{
std::vector<CouplingReport> couple_surfaces(fem::Problem& problem)
{
  const int32_t n_nodes = problem.mesh.n_nodes();
  std::vector<char> taken(3 * static_cast<size_t>(n_nodes), 0);
  std::vector<int> holding(taken.size(), 0);
  for (size_t k = 0; k < problem.steps.size(); ++k)
    for (const int64_t dof : problem.all_constrained_dofs(k).dofs)
      if (dof < 3 * int64_t{n_nodes} && ++holding[dof] == std::ssize(problem.steps))
        taken[dof] = 1;
  for (const auto* block : {&problem.equations, &problem.tie_equations})
    for (const fem::LinearEquation& equation : *block)
      for (const auto& term : equation.terms)
        if (block == &problem.equations || &term == &equation.terms.front())
          taken[3 * static_cast<size_t>(term.node) + term.component] = 1;
  std::vector<CouplingReport> out;
  for (const fem::Coupling& coupling : problem.couplings)
  {
    if (coupling.kind != fem::CouplingKind::kinematic)
      continue;
    CouplingReport& report = out.emplace_back();
    report.name = coupling.name;
    report.nodes = std::ssize(fem::coupled_nodes(problem.mesh, coupling));
    const fem::KinematicRows rows = fem::kinematic_rows(problem.mesh, coupling, problem.eliminated);
    report.anchors = rows.rank;
    for (const fem::CouplingRow& row : rows.rows)
    {
      if (taken[row.slave])
      {
        ++report.skipped_dofs;
        continue;
      }
      taken[row.slave] = 1;
      fem::LinearEquation equation;
      equation.terms.push_back({static_cast<int32_t>(row.slave / 3), static_cast<int>(row.slave % 3), 1.0});
      for (size_t k = 0; k < row.anchors.dofs.size(); ++k)
        equation.terms.push_back({static_cast<int32_t>(row.anchors.dofs[k] / 3),
                                  static_cast<int>(row.anchors.dofs[k] % 3), -row.anchors.coefficients[k]});
      problem.tie_equations.push_back(std::move(equation));
      problem.tie_of_equation.push_back(-1);
      ++report.rows;
    }
  }
  return out;
}

std::string describe(const CouplingReport& r)
{
  std::ostringstream s;
  s << r.name << ": " << r.nodes << " nodes, rigid motion of rank " << r.anchors << ", " << r.rows << " rows";
  if (r.skipped_dofs > 0)
    s << " (" << r.skipped_dofs << " coupled components left to supports, equations or rows before)";
  return s.str();
}
} // namespace feticon::contact
