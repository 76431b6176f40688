#include "nonlinear/feti_contact_solver.hpp"

#include "common/error.hpp"
#include "common/log.hpp"
#include "decomposition/constraint_rows.hpp"
#include "decomposition/subdomain_operators.hpp"

#include <chrono>
#include <map>
#include <cstdio>

namespace feticon::nonlinear
{
namespace
{
decomposition::Partition make_partition(const fem::Problem& problem, const SolverSettings& s)
{
  if (s.metis)
    return decomposition::partition_metis(problem.mesh, std::max(s.subdomains, problem.mesh.n_bodies()));
  // Structured: split each body along x only (enough for studies; boxes via the API).
  return decomposition::partition_structured(problem.mesh,
                                             {std::max(1, s.subdomains / problem.mesh.n_bodies()), 1, 1});
}

std::string format_iteration(const OuterIteration& it)
{
  char line[256];
  std::snprintf(line, sizeof line,
                "step %2d  outer %2d  inner %5d  residual %9.2e  |du|/|u| %9.2e  active %5ld  %7.2f s",
                it.load_step, it.iteration, it.qp_iterations, it.residual_norm,
                it.displacement_change, static_cast<long>(it.active_contacts), it.seconds);
  return line;
}
} // namespace

ContactSolution solve_feti_contact(const fem::Problem& problem, const SolverSettings& settings,
                                   TimerTable& timers, const StepCallback& on_step,
                                   const ContactSolution* previous)
{
  problem.validate();
  FETICON_CHECK(problem.contacts.size() == 1, "the FETI contact solver handles exactly one contact "
                                              "pair; the problem has " << problem.contacts.size());
  const auto run_start = std::chrono::steady_clock::now();
  ContactSolution out;

  std::unique_ptr<decomposition::Decomposition> decomp;
  {
    ScopedTimer t(timers, "decomposition");
    decomp = std::make_unique<decomposition::Decomposition>(
        problem.mesh, make_partition(problem, settings), problem.eliminated);
  }
  out.n_subdomains = decomp->n_subdomains();
  decomposition::SubdomainSystem system(*decomp, problem.materials, settings.kinematics,
                                        settings.generalized_inverse);
  la::Vector u = la::Vector::Zero(decomp->n_primal());
  {
    ScopedTimer t(timers, "assembly + factorization");
    system.update(u); // K_0 and R(X), kept for the whole run (modified Newton)
  }
  const fem::ConstrainedDofs dirichlet = problem.all_constrained_dofs();
  const la::Vector f_ext = problem.external_force();
  const la::Vector f_ext_stacked = decomp->scatter_split(f_ext);
  const double f_norm = std::max(f_ext.norm(), 1e-300);
  const contact::ContactPair pair{problem.contacts[0].slave, problem.contacts[0].master};
  contact::ContactOptions contact_options;
  contact_options.search_distance = settings.search_distance;
  contact_options.formulation = settings.formulation;

  la::Vector lambda_previous;
  std::map<int32_t, double> previous_contact; ///< contact multiplier by slave node
  const bool linear = settings.kinematics == fem::Kinematics::linear;
  int first_step = 1;
  if (previous)
  {
    const RestartState& r = previous->restart;
    FETICON_CHECK(r.u_stacked.size() == decomp->n_primal(),
                  "restart: the checkpoint has " << r.u_stacked.size() << " unknowns, this problem "
                                                 << decomp->n_primal() << " (different mesh or subdomains?)");
    FETICON_CHECK(r.completed_steps < settings.load_steps,
                  "restart: all " << settings.load_steps << " load steps are already done");
    u = r.u_stacked;
    lambda_previous = r.lambda;
    for (size_t i = 0; i < r.contact_slave.size(); ++i)
      previous_contact[r.contact_slave[i]] = r.contact_lambda[i];
    out.history = previous->history;
    out.steps = previous->steps;
    // A refreshed K_M(u) is rebuilt at the first outer iteration of the step, as it would
    // have been in the uninterrupted run.
    first_step = r.completed_steps + 1;
  }
  // Internal force at the current u, kept up to date after every update.
  la::Vector f_int;
  {
    ScopedTimer t(timers, "internal forces");
    f_int = system.internal_force(u);
  }
  for (int step = first_step; step <= settings.load_steps; ++step)
  {
    const double t_n = static_cast<double>(step) / settings.load_steps;
    fem::ConstrainedDofs target = dirichlet;
    target.values *= t_n;
    const auto equality = decomposition::build_equality_rows(*decomp, target);
    const la::Vector c_target = equality.rows.c_vector();
    LoadStep record;
    record.load_factor = t_n;
    for (int k = 1; k <= settings.max_outer_iterations; ++k)
    {
      const auto iteration_start = std::chrono::steady_clock::now();
      const bool refresh = !linear && ((settings.stiffness == StiffnessUpdate::load_step && k == 1 && step > 1) ||
                                       (settings.stiffness == StiffnessUpdate::iteration && (step > 1 || k > 1)));
      if (refresh)
      {
        ScopedTimer t(timers, "assembly + factorization");
        system.update(u); // K_M(u) and R(X + u)
      }
      const la::Vector u_global = decomp->gather_mean(u);
      contact::ContactConstraints contact_rows;
      la::Vector residual;
      {
        ScopedTimer t(timers, "contact search");
        contact_rows = contact::build_contact_constraints(problem.mesh, u_global, pair, contact_options);
      }
      residual = t_n * f_ext_stacked - f_int;
      decomposition::ConstraintRows rows = equality.rows;
      rows.append(decomposition::rows_from_global(*decomp, contact_rows.B, contact_rows.c));
      const int64_t n_equality = equality.rows.n_rows();

      std::unique_ptr<dual::FetiOperators> feti;
      {
        ScopedTimer t(timers, "coarse problem");
        feti = std::make_unique<dual::FetiOperators>(system, rows);
      }
      // c_E = target - B_E u (gluing 0, Dirichlet t_n u_D); c_I = current gaps.
      la::Vector c = rows.c_vector();
      c.head(n_equality) = c_target - feti->apply_B(u).head(n_equality);
      // Warm start: equality rows keep their numbering; contact rows are matched by slave
      // node (rows are rebuilt every iteration), new rows start at 0.
      la::Vector warm;
      if (lambda_previous.size() > 0)
      {
        warm = la::Vector::Zero(rows.n_rows());
        warm.head(n_equality) = lambda_previous.head(n_equality);
        for (size_t i = 0; i < contact_rows.slave_node.size(); ++i)
        {
          const auto it = previous_contact.find(contact_rows.slave_node[i]);
          if (it != previous_contact.end())
            warm(n_equality + static_cast<la::Index>(i)) = it->second;
        }
      }
      dual::DualSolution solution;
      {
        ScopedTimer t(timers, "dual solve (MPRGP)");
        solution = dual::solve_contact_dual(*feti, c, residual, n_equality, settings.dual, warm);
      }
      u += solution.u;
      lambda_previous = solution.lambda;
      previous_contact.clear();
      for (size_t i = 0; i < contact_rows.slave_node.size(); ++i)
        previous_contact[contact_rows.slave_node[i]] = solution.lambda(n_equality + static_cast<la::Index>(i));

      OuterIteration it;
      it.load_step = step;
      it.iteration = k;
      it.qp_iterations = solution.report.iterations;
      it.cg_steps = solution.report.cg_steps;
      it.expansion_steps = solution.report.expansion_steps;
      it.proportioning_steps = solution.report.proportioning_steps;
      it.hessian_multiplications = solution.report.hessian_multiplications;
      it.smalbe_outer = solution.outer_iterations;
      it.active_contacts = solution.active_contacts;
      it.feasibility_error = solution.feasibility_error;
      it.displacement_change = solution.u.norm() / std::max(u.norm(), 1e-300);
      {
        ScopedTimer t(timers, "internal forces");
        f_int = system.internal_force(u); // also the next iteration's, at the same u
        const la::Vector r_new = t_n * f_ext_stacked - f_int - feti->apply_Bt(solution.lambda);
        it.residual_norm = decomp->gather_sum(r_new).norm() / f_norm;
      }
      it.seconds = seconds_since(iteration_start);
      out.history.push_back(it);
      record.inner_iterations.push_back(it.qp_iterations);
      log::info(format_iteration(it));

      out.constraints = std::move(contact_rows);
      out.contact_lambda = solution.lambda.tail(rows.n_rows() - n_equality);
      out.n_dual = feti->n_dual();
      out.n_kernel = feti->n_kernel();
      out.feasibility_error = solution.feasibility_error;
      if (!solution.report.converged)
      {
        out.u = decomp->gather_mean(u);
        out.reason = "load step " + std::to_string(step) + ", outer iteration " +
                     std::to_string(k) + ": " + solution.report.reason;
        out.steps.push_back(record);
        return out;
      }
      record.outer_iterations = k;
      record.displacement_change = it.displacement_change;
      record.residual_norm = it.residual_norm;
      if (linear || it.displacement_change <= settings.displacement_tolerance)
      {
        record.converged = true;
        break;
      }
    }
    out.steps.push_back(record);
    out.u = decomp->gather_mean(u);
    if (!record.converged)
    {
      out.reason = "load step " + std::to_string(step) + " did not converge in " +
                   std::to_string(settings.max_outer_iterations) + " outer iterations (|du|/|u| = " +
                   std::to_string(record.displacement_change) + ")";
      return out;
    }
    out.restart.completed_steps = step;
    out.restart.u_stacked = u;
    out.restart.lambda = lambda_previous;
    out.restart.contact_slave.clear();
    out.restart.contact_lambda.clear();
    for (const auto& [node, value] : previous_contact)
    {
      out.restart.contact_slave.push_back(node);
      out.restart.contact_lambda.push_back(value);
    }
    if (on_step)
      on_step(step, out);
  }
  out.converged = true;
  timers.add("total solve", seconds_since(run_start));
  return out;
}
} // namespace feticon::nonlinear
