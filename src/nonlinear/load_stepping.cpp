#include "nonlinear/load_stepping.hpp"

#include "common/log.hpp"
#include "common/timer.hpp"

#include <algorithm>
#include <chrono>
#include <cstdio>
#include <limits>

namespace feticon::nonlinear
{
fem::LoadHistory::Done done_of(const LoadStep& record)
{
  return {record.load_factor, record.converged ? record.outer_iterations : std::numeric_limits<int>::max()};
}

void run_load_steps(LoadStepPhases& phases, fem::LoadHistory& history, int first_step, int max_outer_iterations,
                    int max_cutbacks, ContactSolution& out, const StepCallback& on_step)
{
  // Warnings after the loop (post-processing) are not the last iteration's.
  struct ContextReset
  {
    ~ContextReset() { log::set_context(""); }
  } reset_context;
  int cutbacks_in_a_row = 0;
  for (int step = first_step; step <= history.n_steps(); ++step)
  {
    if (std::string limit = history.increment_limit(step); !limit.empty())
    {
      out.reason = std::move(limit);
      return;
    }
    const double t = history.load_factor(step);
    phases.begin_load_step(step, t);
    LoadStep record;
    record.load_factor = t;
    std::string failure;
    bool retry = false;
    for (int k = 1; k <= max_outer_iterations && !record.converged && record.floor.empty() && failure.empty(); ++k)
    {
      const auto start = std::chrono::steady_clock::now();
      OuterIteration it;
      it.load_step = step;
      it.iteration = k;
      log::set_context("load step " + std::to_string(step) + ", outer iteration " + std::to_string(k));
      IterationOutcome outcome = phases.outer_iteration(k, it);
      if (outcome.recorded)
      {
        it.seconds = seconds_since(start);
        out.history.push_back(it);
        record.inner_iterations.push_back(it.qp.iterations);
        record.outer_iterations = k;
        record.displacement_change = it.displacement_change;
        record.residual_norm = it.residual_norm;
        log::info(phases.format(it));
      }
      record.converged = outcome.converged;
      record.floor = std::move(outcome.floor);
      failure = std::move(outcome.failure);
      retry = outcome.retry;
    }
    const bool unconverged = !record.converged && record.floor.empty() && failure.empty();
    const bool may_halve = history.may_halve(step);
    if ((unconverged || retry) && cutbacks_in_a_row < max_cutbacks && may_halve && phases.cut_back(step))
    {
      ++cutbacks_in_a_row;
      std::string why =
          unconverged ? "not converged in " + std::to_string(max_outer_iterations) + " outer iterations" : failure;
      // The solvers word a failure "load step N, outer iteration k: ..."; the warning names the step.
      const std::string own_step = "load step " + std::to_string(step) + ", ";
      if (why.rfind(own_step, 0) == 0)
        why.erase(0, own_step.size());
      char warning[400];
      std::snprintf(warning, sizeof warning,
                    "load step %d at load factor %g cut back to %g: %s (its outer iterations stay in history.csv)",
                    step, t, history.load_factor(step), why.c_str());
      log::warning(warning);
      out.warnings.emplace_back(warning);
      --step; // the same step number, now at the midpoint
      continue;
    }
    cutbacks_in_a_row = 0;
    out.steps.push_back(record);
    phases.end_load_step(record);
    if (!failure.empty())
    {
      out.reason = failure;
      return;
    }
    if (!record.floor.empty())
    {
      const std::string warning = floor_warning(step, record);
      log::warning(warning);
      out.warnings.push_back(warning);
    }
    else if (!record.converged)
    {
      char reason[220];
      std::snprintf(reason, sizeof reason, "load step %d did not converge in %d outer iterations (|du|/|u| = %g)%s",
                    step, max_outer_iterations, record.displacement_change,
                    may_halve ? "" : "; half its increment is below the step's minimum");
      out.reason = reason;
      return;
    }
    history.increment_done(step, done_of(record).iterations);
    if (on_step)
      on_step(step, out);
  }
  out.completed = true;
  out.converged = std::all_of(out.steps.begin(), out.steps.end(), [](const LoadStep& s) { return s.converged; });
  if (!out.converged)
    out.reason = "every load step ran, but not every one met the stopping test (warnings)";
}
} // namespace feticon::nonlinear
