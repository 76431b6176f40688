#include "app/problem_setup.hpp"

#include "problems/cantilever_obstacle.hpp"
#include "problems/hertz3d.hpp"

#include <algorithm>

namespace feticon::app
{
namespace
{
problems::CantileverObstacleParameters cantilever_parameters(const io::Settings& s)
{
  problems::CantileverObstacleParameters p;
  p.gap = s.number("cantilever.gap");
  p.linear_deflection_ratio = s.number("cantilever.load");
  p.cells_along = s.integer("cantilever.cells");
  p.material = {s.number("material.young"), s.number("material.poisson")};
  return p;
}
} // namespace

problems::HertzParameters hertz_parameters(const io::Settings& s)
{
  problems::HertzParameters p;
  p.line_load = s.number("hertz.line_load");
  p.mesh.kind = s.text("hertz.mesh") == "tensor" ? mesh::HertzMeshKind::tensor : mesh::HertzMeshKind::graded;
  p.mesh.refinement = s.number("hertz.refinement");
  p.mesh.element_size = s.number("hertz.element_size");
  p.mesh.master_ratio = s.number("hertz.master_ratio");
  p.mesh.block_width = s.number("hertz.block_width");
  p.mesh.block_depth = s.number("hertz.block_depth");
  p.mesh.growth_ratio = s.number("hertz.growth_ratio");
  p.mesh.cylinder_width = s.number("hertz.cylinder_width");
  p.material = {s.number("material.young"), s.number("material.poisson")};
  return p;
}

problems::Hertz3dParameters hertz3d_parameters(const io::Settings& s)
{
  problems::Hertz3dParameters p;
  p.radius = s.number("hertz3d.radius");
  p.load = s.number("hertz3d.load");
  p.material = {s.number("material.young"), s.number("material.poisson")};
  p.element_size = s.number("hertz3d.element_size");
  p.refinement = s.number("hertz3d.refinement");
  p.master_ratio = s.number("hertz3d.master_ratio");
  p.block_radius = s.number("hertz3d.block_radius");
  p.cap_radius = s.number("hertz3d.cap_radius");
  p.radial_aspect = s.number("hertz3d.radial_aspect");
  return p;
}

MeshPrediction predict_mesh(const io::ProblemFile& file)
{
  const std::string& kind = file.settings.text("problem");
  if (kind == "hertz")
    return {mesh::hertz_node_estimate(hertz_parameters(file.settings).mesh), true};
  if (kind == "hertz3d")
    return {problems::hertz3d_node_count(hertz3d_parameters(file.settings)), false};
  if (kind == "cantilever_obstacle")
    return {problems::cantilever_obstacle_node_count(cantilever_parameters(file.settings)), true};
  const io::CustomMeshSize size = io::custom_mesh_size(file);
  return {size.nodes, size.plane_strain};
}

fem::Problem build_problem(const io::ProblemFile& file)
{
  const std::string& kind = file.settings.text("problem");
  if (kind == "hertz")
    return problems::hertz_problem(hertz_parameters(file.settings));
  if (kind == "hertz3d")
    return problems::hertz3d_problem(hertz3d_parameters(file.settings));
  if (kind == "cantilever_obstacle")
    return problems::cantilever_obstacle_problem(cantilever_parameters(file.settings));
  return io::build_custom_problem(file);
}

nonlinear::SolverSettings solver_settings(const io::Settings& s, const fem::Problem& problem)
{
  nonlinear::SolverSettings out;
  const std::string& method = s.text("method");
  out.method = method == "smalbe"         ? nonlinear::ContactMethod::smalbe
               : method == "dual_penalty" ? nonlinear::ContactMethod::dual_penalty
                                          : nonlinear::ContactMethod::primal_penalty;
  out.dual.method = out.method == nonlinear::ContactMethod::dual_penalty ? dual::DualMethod::dual_penalty
                                                                        : dual::DualMethod::smalbe;
  out.dual.rho = s.number("rho");
  out.dual.smalbe_M0 = s.number("smalbe.M0");
  out.dual.smalbe_beta = s.number("smalbe.beta");
  out.dual.rtol = s.number("qp.rtol");
  out.dual.expansion = qp::expansion_from_name(s.text("qp.expansion"));
  const std::string& preconditioner = s.text("qp.preconditioner");
  out.dual.preconditioner = preconditioner == "lumped"      ? dual::DualPreconditioner::lumped
                            : preconditioner == "dirichlet" ? dual::DualPreconditioner::dirichlet
                                                            : dual::DualPreconditioner::none;
  out.dual.max_iterations = s.integer("qp.max_iterations");
  out.dual.constraint_scaling = s.flag("qp.constraint_scaling");
  out.eps_n_factor = s.number("eps_n");
  out.formulation = s.text("contact.formulation") == "mortar" ? contact::ContactFormulation::mortar
                                                               : contact::ContactFormulation::node_to_segment;
  const bool large = s.text("displacements") == "large";
  out.kinematics = large ? fem::Kinematics::total_lagrangian : fem::Kinematics::linear;
  out.load_steps = large ? s.integer("load_steps") : 1;
  out.subdomains = s.integer("subdomains");
  const int cells = s.integer("subdomain_cells");
  if (cells > 0)
    out.subdomains = std::max<int>(problem.mesh.n_bodies(),
                                   static_cast<int>((problem.mesh.n_cells() + cells - 1) / cells));
  const std::string& stiffness = s.text("newton.stiffness");
  out.stiffness = stiffness == "initial" ? nonlinear::StiffnessUpdate::initial
                  : stiffness == "step"  ? nonlinear::StiffnessUpdate::load_step
                                         : nonlinear::StiffnessUpdate::iteration;
  out.max_outer_iterations = s.integer("newton.max_iterations");
  out.displacement_tolerance = s.number("newton.tolerance");
  out.residual_tolerance = s.number("newton.residual_tolerance");
  out.forcing = s.number("newton.forcing");
  const std::string& dual_operator = s.text("dual.operator");
  out.dual_operator = dual_operator == "implicit"   ? nonlinear::DualOperatorMode::implicit
                      : dual_operator == "explicit" ? nonlinear::DualOperatorMode::explicit_
                                                    : nonlinear::DualOperatorMode::automatic;
  const std::string& partitioner = s.text("partitioner");
  out.partitioner = partitioner == "metis" ? nonlinear::Partitioner::metis
                    : partitioner == "rcb" ? nonlinear::Partitioner::rcb
                                           : nonlinear::Partitioner::structured;
  return out;
}

nonlinear::OuterIteration qp_totals(const nonlinear::ContactSolution& solution)
{
  nonlinear::OuterIteration sum;
  for (const auto& it : solution.history)
  {
    sum.qp_iterations += it.qp_iterations;
    sum.cg_steps += it.cg_steps;
    sum.expansion_steps += it.expansion_steps;
    sum.proportioning_steps += it.proportioning_steps;
    sum.hessian_multiplications += it.hessian_multiplications;
    sum.smalbe_outer += it.smalbe_outer;
    sum.rho_updates += it.rho_updates;
    sum.operator_applications += it.operator_applications;
    sum.operator_seconds += it.operator_seconds;
    sum.preconditioner_applications += it.preconditioner_applications;
    sum.preconditioner_seconds += it.preconditioner_seconds;
    sum.qp_seconds += it.qp_seconds;
  }
  return sum;
}

nlohmann::ordered_json qp_json(const nonlinear::ContactSolution& solution)
{
  const nonlinear::OuterIteration sum = qp_totals(solution);
  // The spectrum estimate of the longest CG run of the whole solve.
  qp::RitzValues longest;
  for (const auto& it : solution.history)
    if (it.ritz.cg_steps > longest.cg_steps)
      longest = it.ritz;
  nlohmann::ordered_json json = {
      {"iterations", sum.qp_iterations},
      {"hessian_multiplications", sum.hessian_multiplications},
      {"cg_steps", sum.cg_steps},
      {"expansion_steps", sum.expansion_steps},
      {"proportioning_steps", sum.proportioning_steps},
      {"smalbe_outer_iterations", sum.smalbe_outer},
      {"rho_updates", sum.rho_updates},
      {"final_rho", solution.history.empty() ? 0.0 : solution.history.back().final_rho},
      {"outer_iterations", solution.history.size()}};
  // Only when some CG run measured it: no null in summary.json.
  if (longest.cg_steps > 0)
    json["face_spectrum"] = {{"ritz_min", longest.min},
                             {"ritz_max", longest.max},
                             {"condition_estimate", longest.max / longest.min},
                             {"cg_steps", longest.cg_steps}};
  return json;
}
} // namespace feticon::app
