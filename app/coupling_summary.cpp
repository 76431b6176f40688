#include "app/coupling_summary.hpp"

#include "app/calculix_results.hpp"

namespace feticon::app
{
nlohmann::ordered_json coupling_summary(const fem::Problem& problem, const nonlinear::ContactSolution& solution,
                                        fem::Kinematics kinematics)
{
  nlohmann::ordered_json out = nlohmann::ordered_json::array();
  if (problem.couplings.empty() || solution.u.size() != 3 * problem.mesh.n_nodes())
    return out;
  const la::Vector reaction = calculix_reaction(problem, solution, kinematics);
  const std::vector<fem::ReferenceDofs> dofs = problem.reference_dofs();
  static constexpr const char* kinds[] = {"kinematic", "distributing", "mean"};
  for (size_t j = 0; j < problem.couplings.size(); ++j)
  {
    const fem::ReferenceResult r = fem::reference_result(dofs[j], solution.u, reaction);
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
} // namespace feticon::app
