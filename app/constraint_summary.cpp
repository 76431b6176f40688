#include "app/constraint_summary.hpp"

#include "app/calculix_results.hpp"

namespace feticon::app
{
std::vector<fem::ReferenceResult> reference_results(const fem::Problem& problem, const la::Vector& u,
                                                    const la::Vector& reaction, fem::Kinematics kinematics)
{
  std::vector<fem::ReferenceResult> out;
  const std::vector<fem::ReferenceDofs> dofs = problem.reference_dofs();
  for (size_t j = 0; j < problem.couplings.size(); ++j)
  {
    const fem::Coupling& c = problem.couplings[j];
    out.push_back(kinematics != fem::Kinematics::linear &&
                          fem::has_finite_kinematics(problem.mesh, c, problem.eliminated)
                      ? fem::finite_reference_result(problem.mesh, c, problem.eliminated, u, reaction)
                      : fem::reference_result(dofs[j], u, reaction));
  }
  return out;
}

nlohmann::ordered_json coupling_summary(const fem::Problem& problem, const nonlinear::ContactSolution& solution,
                                        fem::Kinematics kinematics)
{
  nlohmann::ordered_json out = nlohmann::ordered_json::array();
  if (problem.couplings.empty() || solution.u.size() != 3 * problem.mesh.n_nodes())
    return out;
  const la::Vector reaction = calculix_reaction(problem, solution, kinematics);
  const std::vector<fem::ReferenceResult> results = reference_results(problem, solution.u, reaction, kinematics);
  static constexpr const char* kinds[] = {"kinematic", "distributing", "mean", "pretension"};
  for (size_t j = 0; j < problem.couplings.size(); ++j)
  {
    const fem::ReferenceResult& r = results[j];
    const auto part = [&](const std::array<double, 6>& v, int first) {
      return nlohmann::ordered_json::array({v[first], v[first + 1], v[first + 2]});
    };
    out.push_back({{"name", problem.couplings[j].name},
                   {"kind", kinds[static_cast<int>(problem.couplings[j].kind)]},
                   {"displacement", part(r.value, 0)},
                   {"rotation", part(r.value, 3)},
                   {"force", part(r.reaction, 0)},
                   {"moment", part(r.reaction, 3)}});
  }
  return out;
}

nlohmann::ordered_json tie_summary(const fem::Problem& problem, const nonlinear::ContactSolution& solution,
                                   fem::Kinematics kinematics)
{
  nlohmann::ordered_json out = nlohmann::ordered_json::array();
  if (problem.ties.empty() || solution.u.size() != 3 * problem.mesh.n_nodes())
    return out;
  const la::Vector reaction = calculix_reaction(problem, solution, kinematics);
  std::vector<Eigen::Vector3d> force(problem.ties.size(), Eigen::Vector3d::Zero());
  std::vector<int64_t> rows(problem.ties.size(), 0);
  for (size_t k = 0; k < problem.tie_equations.size(); ++k)
  {
    const int32_t tie = problem.tie_of_equation[k];
    if (tie < 0) // a kinematic coupling's row (contact/coupling_rows.hpp)
      continue;
    const fem::LinearEquation::Term& slave = problem.tie_equations[k].terms.front();
    force[static_cast<size_t>(tie)](slave.component) += reaction(3 * la::Index{slave.node} + slave.component);
    ++rows[static_cast<size_t>(tie)];
  }
  for (size_t t = 0; t < problem.ties.size(); ++t)
    out.push_back({{"name", problem.ties[t].name},
                   {"rows", rows[t]},
                   {"in_force", !std::ranges::count(problem.steps.back().removed_ties, static_cast<int32_t>(t))},
                   {"force", {force[t](0), force[t](1), force[t](2)}}});
  return out;
}
} // namespace feticon::app
