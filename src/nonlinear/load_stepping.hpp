#pragma once
/// @file The load-stepping loop of the contact solvers (FETI and primal penalty): the load
/// steps of a fem::LoadHistory (t_n = n / N for a one-stage problem; stage s - 1 + j / N_s
/// over several stages), in each outer iterations until the solver reports the step
/// converged; the
/// records of both (LoadStep, OuterIteration), the progress lines and the reason of a run
/// that stops. A solver supplies its phases: begin a load step, one outer iteration, end a
/// load step.

#include "fem/load_history.hpp"
#include "nonlinear/contact_solution.hpp"

#include <functional>
#include <string>
#include <utility>

namespace feticon::nonlinear
{
/// Called after every accepted load step (converged, or at a floor) with the solution so far.
using StepCallback = std::function<void(int load_step, const ContactSolution&)>;

/// How one outer iteration ended.
struct IterationOutcome
{
  /// The iteration goes into the history. False for an iteration that is no result (a
  /// non-finite residual) or that found the step converged before solving anything.
  bool recorded = true;
  bool converged = false; ///< the load step has converged
  std::string failure;    ///< not empty: the run stops, and this is why
  /// Not empty: the load step ends short of the stopping test, at a floor the loop cannot go
  /// below (OuterVerdict::floor); this says which. The run goes on and reports it.
  std::string floor;
  /// With `failure`: a smaller load increment may succeed (the outer loop diverged), so the
  /// driver cuts the step back where it can instead of stopping.
  bool retry = false;

  /// The next iteration follows.
  static IterationOutcome next() { return {}; }
  /// The load step has converged (`recorded`: with this iteration in the history).
  static IterationOutcome step_converged(bool recorded = true) { return {recorded, true, {}, {}}; }
  /// The run stops, for `why`.
  static IterationOutcome stop(std::string why, bool recorded = true) { return {recorded, false, std::move(why), {}}; }
  /// The load step ends at a floor, for `why`.
  static IterationOutcome step_at_floor(std::string why) { return {true, false, {}, std::move(why)}; }
  /// The outer loop diverged for `why` (the iteration is no result): the step is cut back, or
  /// the run stops.
  static IterationOutcome diverged(std::string why) { return {false, false, std::move(why), {}, true}; }
};

class LoadStepPhases
{
public:
  virtual ~LoadStepPhases() = default;
  /// Prepares load step `step` at the load factor t (the history's t_n).
  virtual void begin_load_step(int step, double t) = 0;
  /// Outer iteration k of the current load step; fills `it` (its load_step and iteration are
  /// set, the driver times it).
  virtual IterationOutcome outer_iteration(int k, OuterIteration& it) = 0;
  /// After the load step, converged or not: its answer and state into the solution.
  virtual void end_load_step(const LoadStep& record) = 0;
  /// The progress line of an iteration.
  virtual std::string format(const OuterIteration& it) const = 0;
  /// Load step `step` failed (diverged, or not converged in its outer iterations): back to
  /// the state at its start, and its increment halved (fem::LoadHistory::split), so that
  /// `step` is next solved at the midpoint. False: this solver cannot, and the run stops.
  virtual bool cut_back(int step)
  {
    (void)step;
    return false;
  }
};

/// A finished load step as its history's increment control takes it (fem::LoadHistory::Done):
/// its outer iterations, or the largest int for one accepted without converging (at a floor).
fem::LoadHistory::Done done_of(const LoadStep& record);

/// Runs load steps first_step, ..., history.n_steps() of `phases` at the history's load
/// factors (LoadStep::load_factor) with at most max_outer_iterations outer iterations each,
/// appending to out.history and out.steps; `on_step` after every converged step (or one ended
/// at a floor, which goes into out.warnings). A step whose outer loop diverges or does not
/// converge is cut back (LoadStepPhases::cut_back, which splits it in the history that
/// `phases` owns: the same object as `history`) up to max_cutbacks times in a row and not below
/// an automatic step's minimum increment, as CalculiX and Abaqus cut an increment back; each
/// cutback goes into out.warnings, and the failed attempt's iterations stay in out.history
/// (work done). Every finished step goes to history.increment_done (automatic increments
/// grow after easy ones). Ends with out.completed (and out.converged if every step met the
/// stopping test), or out.reason saying where and why it stopped.
void run_load_steps(LoadStepPhases& phases, fem::LoadHistory& history, int first_step, int max_outer_iterations,
                    int max_cutbacks, ContactSolution& out, const StepCallback& on_step = {});
} // namespace feticon::nonlinear
