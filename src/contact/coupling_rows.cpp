#include "contact/coupling_rows.hpp"

#include <algorithm>
#include <map>
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
  for (size_t j = 0; j < problem.couplings.size(); ++j)
  {
    const fem::Coupling& coupling = problem.couplings[j];
    if (coupling.kind != fem::CouplingKind::kinematic && coupling.kind != fem::CouplingKind::pretension)
      continue;
    CouplingReport& report = out.emplace_back();
    report.name = coupling.name;
    report.pretension = coupling.kind == fem::CouplingKind::pretension;
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
      problem.tie_of_equation.push_back(-1 - static_cast<int32_t>(j));
      ++report.rows;
    }
  }
  return out;
}

CouplingLinearization linearize_couplings(const fem::Problem& problem, std::vector<fem::LinearEquation> ties,
                                          const la::Vector& u)
{
  CouplingLinearization out{std::move(ties), problem.held_combinations()};
  const size_t first_reference = out.held.size() - 6 * problem.couplings.size();
  // The coupling rows close both lists in couple_surfaces' order (a step removes tie rows only,
  // which come before them): row k of `ties` is row k + shift of problem.tie_equations.
  const size_t shift = problem.tie_equations.size() - out.ties.size();
  for (size_t j = 0; j < problem.couplings.size(); ++j)
  {
    const fem::Coupling& coupling = problem.couplings[j];
    if (!fem::has_finite_kinematics(problem.mesh, coupling, problem.eliminated))
      continue;
    const fem::FiniteKinematics finite = fem::finite_kinematics(problem.mesh, coupling, problem.eliminated, u);
    for (int d = 0; d < 6; ++d)
      out.held[first_reference + 6 * j + static_cast<size_t>(d)] = finite.value[d];
    std::map<int64_t, const fem::CouplingRow*> by_slave;
    for (const fem::CouplingRow& r : finite.rows.rows)
      by_slave.emplace(r.slave, &r);
    for (size_t k = 0; k < out.ties.size(); ++k)
    {
      if (problem.tie_of_equation[k + shift] != -1 - static_cast<int32_t>(j))
        continue;
      fem::LinearEquation& equation = out.ties[k];
      const fem::LinearEquation::Term slave = equation.terms.front();
      const fem::CouplingRow& r = *by_slave.at(3 * int64_t{slave.node} + slave.component);
      equation.terms.resize(1);
      for (size_t a = 0; a < r.anchors.dofs.size(); ++a)
        equation.terms.push_back({static_cast<int32_t>(r.anchors.dofs[a] / 3), static_cast<int>(r.anchors.dofs[a] % 3),
                                  -r.anchors.coefficients[a]});
      equation.rhs = r.rhs;
    }
  }
  return out;
}

std::string describe(const CouplingReport& r)
{
  std::ostringstream s;
  if (r.pretension)
    s << r.name << ": " << r.nodes << " node pairs, " << r.rows << " rows";
  else
    s << r.name << ": " << r.nodes << " nodes, rigid motion of rank " << r.anchors << ", " << r.rows << " rows";
  if (r.skipped_dofs > 0)
    s << " (" << r.skipped_dofs << " coupled components left to supports, equations or rows before)";
  return s.str();
}
} // namespace feticon::contact
