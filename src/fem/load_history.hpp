#pragma once
/// @file The load history of a problem: external forces and prescribed displacements at every
/// load step of a run over several stages (a CalculiX deck's *STEPs).
///
/// Stage 1 is the problem's own tractions, pressures, nodal forces and Dirichlet values
/// (Problem::external_force(), Problem::all_constrained_dofs()), reached at load factor 1 in
/// its load steps; stage k + 1 (Problem::later_stages[k - 1]) runs linearly from the end of
/// stage k to its own loads and prescribed values in its load steps, ending at load factor
/// k + 1 (CalculiX's total time). At load step n, in stage s at its j-th of N_s steps,
///   t_n = (s - 1) + j / N_s,
/// (a step cut back after a failed outer loop, split(), halves its increment: its stage then
/// has a step at the midpoint of the fractions before and at it),
///   f(t_n) = (j / N_s) f_1                              (s = 1: t f of a one-stage run),
///   f(t_n) = (1 - j / N_s) f_{s-1} + (j / N_s) f_s      (s > 1),
/// and likewise for the prescribed values u_D. For s = 1 the numbers are those of t * f and
/// t * u_D bit for bit, so a one-stage problem runs as it did before stages existed. The
/// prescribed DOF set is stage 1's for the whole history: a stage changes values only.
///
/// Usage:
///   const LoadHistory history(problem, settings.steps(), linear);
///   for (int n = 1; n <= history.n_steps(); ++n)
///     solve(history.load_factor(n), history.external_force(n), history.prescribed(n));

#include "fem/dirichlet.hpp"
#include "fem/problem.hpp"
#include "la/types.hpp"

#include <cstdint>
#include <vector>

namespace feticon::fem
{
/// Where a load step stands in the history.
struct LoadPoint
{
  int stage = 1;          ///< 1-based; 1 is the problem's own loads
  double fraction = 0;    ///< j / N_s in (0, 1]: how far into its stage
  double load_factor = 0; ///< t_n = (stage - 1) + fraction
};

/// What a stage reaches at its end, and in how many load steps.
struct StageEnd
{
  la::Vector force;  ///< external forces at the end of the stage (N), 3 per mesh node
  la::Vector values; ///< prescribed values at its end (m), in the order of LoadHistory::dofs()
  int steps = 1;     ///< load steps of the stage (>= 1)
};

class LoadHistory
{
public:
  /// @brief The history of `problem`.
  /// @param[in] problem           stage 1 and problem.later_stages
  /// @param[in] first_stage_steps load steps of stage 1 (the solver's load_steps; 1 with small
  ///                              displacements)
  /// @param[in] one_step_per_stage every later stage in one load step whatever its increments:
  ///                              small displacements, where frictionless contact makes the
  ///                              answer at a stage's end independent of the path
  /// @throws feticon::Error naming the stage and the set for a later stage that prescribes a
  ///         component stage 1 leaves free or leaves free one stage 1 prescribes, and for a
  ///         stage's unknown or empty set, non-finite value, out-of-range node or increments < 1
  LoadHistory(const Problem& problem, int first_stage_steps, bool one_step_per_stage = false);

  /// @brief A history from its stage ends (tests, the direct Newton reference).
  /// @param[in] dofs   the prescribed DOFs (sorted, as ConstrainedDofs::dofs)
  /// @param[in] stages the ends of stages 1, 2, ...: equal vector sizes, steps >= 1
  LoadHistory(std::vector<int64_t> dofs, std::vector<StageEnd> stages);

  int n_stages() const { return static_cast<int>(_stages.size()); }
  /// Load steps of the whole history.
  int n_steps() const { return _last_step.back(); }
  /// Last load step of `stage` (1-based); 0 for stage 0 (the unloaded start).
  int last_step(int stage) const;
  /// Stage, fraction and load factor of load step `step` (1 .. n_steps()).
  LoadPoint point(int step) const;
  double load_factor(int step) const { return point(step).load_factor; }

  /// The prescribed DOFs (Problem::all_constrained_dofs()'s, every stage).
  const std::vector<int64_t>& dofs() const { return _dofs; }
  /// The end of `stage` (1 .. n_stages()).
  const StageEnd& stage_end(int stage) const;

  /// f(t_n) of the file comment, 3 per mesh node.
  la::Vector external_force(int step) const;
  /// ||f(t_n)||: t ||f_1|| in stage 1 (as a one-stage run scales it), the norm of f(t_n) after.
  double external_force_norm(int step) const;
  /// u_D(t_n) in the order of dofs().
  la::Vector prescribed_values(int step) const;
  /// dofs() with u_D(t_n): what a one-stage solver built as `constrained.values *= t`.
  ConstrainedDofs prescribed(int step) const;

  /// @brief Halves load step `step`'s increment (a cutback after its outer loop failed): a
  /// step at the midpoint of t_{step-1} and t_step (in the fractions of its stage) comes in
  /// as load step `step`, the old one follows as step + 1, and n_steps() grows by one.
  void split(int step);

  /// @brief Splits steps as a run that cut back did (a restart of it): step i is halved while
  /// its load factor is above load_factors[i - 1], so that the midpoints give the same numbers.
  /// A factor that no halving reaches (another load_steps) is left for the caller's check.
  void follow(const std::vector<double>& load_factors);

  /// @brief The value at load step `step` of a quantity given at the stage ends, by the rule of
  /// the file comment (for the solvers' own layouts, e.g. forces split over subdomains).
  /// @param[in] ends the quantity at the end of stages 1 .. n_stages()
  la::Vector interpolate(int step, const std::vector<la::Vector>& ends) const;

private:
  std::vector<int64_t> _dofs;
  std::vector<StageEnd> _stages;
  std::vector<int> _last_step; ///< cumulative: last load step of stage s at s - 1
  /// j / N_s of each load step of stage s at s - 1, with the midpoints of split steps.
  std::vector<std::vector<double>> _fractions;
  std::vector<double> _force_norm; ///< ||f_s||
};
} // namespace feticon::fem
