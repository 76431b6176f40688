#include "nonlinear/primal_penalty_solver.hpp"

#include "common/error.hpp"
#include "common/parallel.hpp"
#include "common/log.hpp"
#include "fem/assembler.hpp"
#include "la/cholmod.hpp"
#include "nonlinear/contact_penalty.hpp"

#include <algorithm>
#include <chrono>
#include <cstdio>

namespace feticon::nonlinear
{
namespace
{
void log_iteration(const OuterIteration& it)
{
  char line[200];
  std::snprintf(line, sizeof line,
                "step %2d  penalty iteration %2d  active %5ld  |du|/|u| %9.2e  %7.2f s", it.load_step,
                it.iteration, static_cast<long>(it.active_contacts), it.displacement_change, it.seconds);
  log::info(line);
}
} // namespace

ContactSolution solve_primal_penalty(const fem::Problem& problem, const SolverSettings& settings,
                                     TimerTable& timers)
{
  // One undecomposed factorization: BLAS is the parallelism (common/parallel.hpp).
  const ScopedBlasThreads blas(threads());
  problem.validate();
  FETICON_CHECK(problem.contacts.size() == 1, "the primal penalty solver handles one contact pair");
  const auto run_start = std::chrono::steady_clock::now();
  const int64_t n = 3 * static_cast<int64_t>(problem.mesh.n_nodes());
  fem::Assembler assembler(problem.mesh, fem::whole_mesh_domain(problem.mesh), problem.materials,
                           settings.kinematics);
  const fem::ConstrainedDofs all = problem.all_constrained_dofs();
  const la::Vector f_ext = problem.external_force();
  const contact::ContactPair pair{problem.contacts[0].slave, problem.contacts[0].master};
  contact::ContactOptions contact_options;
  contact_options.search_distance = settings.search_distance;
  contact_options.formulation = settings.formulation;
  const bool linear = settings.kinematics == fem::Kinematics::linear;

  ContactSolution out;
  out.n_subdomains = 1;
  la::Vector u = la::Vector::Zero(n);
  la::SparseMatrix K;
  if (linear)
  {
    ScopedTimer t(timers, "assembly");
    K = assembler.stiffness(u, fem::StiffnessKind::tangent);
    out.penalty = settings.eps_n_factor * K.diagonal().maxCoeff();
  }
  for (int step = 1; step <= settings.steps(); ++step)
  {
    const double t_n = static_cast<double>(step) / settings.steps();
    fem::ConstrainedDofs target = all;
    target.values *= t_n;
    LoadStep record;
    record.load_factor = t_n;
    std::vector<char> active;
    for (int k = 1; k <= settings.max_outer_iterations; ++k)
    {
      const auto iteration_start = std::chrono::steady_clock::now();
      contact::ContactConstraints rows;
      {
        ScopedTimer t(timers, "contact search");
        // Small displacements: contact in the reference configuration, total u unknown.
        // Large: rows in the current configuration, c = current gap, du unknown.
        rows = contact::build_contact_constraints(problem.mesh, linear ? la::Vector::Zero(n) : u,
                                                  pair, contact_options);
      }
      // Active set: violated rows (linear: v = B u - c at the current u; TL: current gap < 0).
      // The very first solve also takes touching rows (g = 0), or a body held only by
      // contact would have no spring at all.
      const la::Vector violation = linear ? la::Vector(rows.B * u - rows.c) : la::Vector(-rows.c);
      std::vector<char> new_active(rows.c.size());
      for (la::Index i = 0; i < rows.c.size(); ++i)
        new_active[i] = (step == 1 && k == 1) ? violation(i) >= 0 : violation(i) > 0;
      if (linear && k > 1 && new_active == active)
      {
        record.converged = true;
        break;
      }
      active = new_active;

      la::SparseMatrix K_pen;
      la::Vector f_pen, rhs;
      la::Vector f_int;
      if (!linear)
      {
        ScopedTimer t(timers, "assembly");
        assembler.assemble(u, fem::StiffnessKind::tangent, &K, &f_int);
        if (out.penalty == 0)
          out.penalty = settings.eps_n_factor * K.diagonal().maxCoeff();
      }
      const la::Vector eps = row_penalties(rows, out.penalty);
      penalty_terms(rows, active, eps, K_pen, f_pen);
      OuterIteration it;
      {
        ScopedTimer t(timers, "factorization + solve");
        la::CholmodFactor factor;
        const la::SparseMatrix A = K + K_pen;
        if (linear)
        {
          const fem::DirichletElimination elim(n, target);
          factor.factorize(elim.reduce_matrix(A), "the penalized stiffness");
          const la::Vector u_new = elim.expand(factor.solve(elim.reduce_rhs(A, t_n * f_ext + f_pen)));
          it.displacement_change = (u_new - u).norm() / std::max(u_new.norm(), 1e-300);
          u = u_new;
          out.contact_lambda = eps.cwiseProduct(rows.B * u - rows.c).cwiseMax(0.0);
        }
        else
        {
          for (size_t j = 0; j < target.dofs.size(); ++j)
            u(target.dofs[j]) = target.values(static_cast<la::Index>(j));
          fem::ConstrainedDofs homogeneous = target;
          homogeneous.values.setZero();
          const fem::DirichletElimination elim(n, homogeneous);
          // Active set of the linearized step made consistent first (rows violated after the
          // step, B du - c > 0), as in the linear case: taking it from the current gaps alone
          // lets nodes at the contact edge flip at every Newton iteration.
          la::Vector du;
          for (int inner = 0; inner < 30; ++inner)
          {
            factor.factorize(elim.reduce_matrix(K + K_pen), "the penalized tangent stiffness");
            du = elim.expand(factor.solve(elim.restrict(t_n * f_ext - f_int + f_pen)));
            const la::Vector predicted = rows.B * du - rows.c;
            std::vector<char> consistent(rows.c.size());
            for (la::Index i = 0; i < predicted.size(); ++i)
              consistent[i] = predicted(i) > 0;
            if (consistent == active || std::count(consistent.begin(), consistent.end(), 1) == 0)
              break;
            active = consistent;
            penalty_terms(rows, active, eps, K_pen, f_pen);
          }
          u += du;
          it.displacement_change = du.norm() / std::max(u.norm(), 1e-300);
          out.contact_lambda = eps.cwiseProduct(rows.B * du - rows.c).cwiseMax(0.0);
        }
      }
      FETICON_CHECK(u.allFinite(), "primal penalty: the solution is not finite");
      out.constraints = std::move(rows);
      it.load_step = step;
      it.iteration = k;
      it.qp.iterations = 1;
      it.active_contacts = std::count(active.begin(), active.end(), 1);
      it.seconds = seconds_since(iteration_start);
      out.history.push_back(it);
      log_iteration(it);
      record.outer_iterations = k;
      record.displacement_change = it.displacement_change;
      record.inner_iterations.push_back(1);
      if (!linear && it.displacement_change <= settings.displacement_tolerance)
      {
        record.converged = true;
        break;
      }
    }
    out.steps.push_back(record);
    if (!record.converged)
    {
      out.u = u;
      out.reason = "primal penalty: load step " + std::to_string(step) +
                   " did not converge in " + std::to_string(settings.max_outer_iterations) +
                   " iterations";
      return out;
    }
  }
  out.u = u;
  out.converged = true;
  timers.add("total solve", seconds_since(run_start));
  return out;
}
} // namespace feticon::nonlinear
