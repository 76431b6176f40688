#include "app/qp_counters_json.hpp"

namespace feticon::app
{
nlohmann::ordered_json qp_counters_json(const qp::QpCounters& c)
{
  nlohmann::ordered_json json = {{"iterations", c.iterations},
                                 {"hessian_multiplications", c.hessian_multiplications},
                                 {"cg_steps", c.cg_steps},
                                 {"expansion_steps", c.expansion_steps},
                                 {"proportioning_steps", c.proportioning_steps},
                                 {"expansion_fallbacks", c.expansion_fallbacks}};
  if (c.outer_iterations > 0)
  {
    json["smalbe_outer_iterations"] = c.outer_iterations;
    json["rho_updates"] = c.rho_updates;
    json["feasibility_corrections"] = c.feasibility_corrections;
  }
  if (c.operator_applications > 0)
    json["operator_applications"] = c.operator_applications;
  if (c.preconditioner_applications > 0)
    json["preconditioner_applications"] = c.preconditioner_applications;
  // Only when some CG run measured it: no null in the output.
  if (c.ritz.cg_steps > 0)
    json["face_spectrum"] = {{"ritz_min", c.ritz.min},
                             {"ritz_max", c.ritz.max},
                             {"condition_estimate", c.ritz.max / c.ritz.min},
                             {"cg_steps", c.ritz.cg_steps}};
  if (c.solution_face.cg_steps > 0)
    json["solution_face_spectrum"] = {{"ritz_min", c.solution_face.min},
                                      {"ritz_max", c.solution_face.max},
                                      {"condition_estimate", c.solution_face.max / c.solution_face.min},
                                      {"cg_steps", c.solution_face.cg_steps},
                                      {"steps_to_qp_rtol", c.solution_face_steps_to_rtol},
                                      {"ritz_values", c.solution_face.distinct}};
  return json;
}

qp::QpCounters qp_totals(const nonlinear::ContactSolution& solution)
{
  qp::QpCounters sum;
  for (const auto& it : solution.history)
    sum += it.qp;
  return sum;
}

nlohmann::ordered_json qp_json(const nonlinear::ContactSolution& solution)
{
  nlohmann::ordered_json json = qp_counters_json(qp_totals(solution));
  json["final_rho"] = solution.history.empty() ? 0.0 : solution.history.back().final_rho;
  json["outer_iterations"] = solution.history.size();
  return json;
}
} // namespace feticon::app
