#pragma once
/// @file The load history of a problem: external forces and prescribed displacements at every
/// load step of a run over its steps (fem::Problem::steps, a CalculiX deck's *STEPs).
///
/// Step s (1-based here, a "stage" of the history) runs in N_s load steps; at its j-th,
///   fraction = j / N_s,  load factor t_n = (s - 1) + fraction,
///   time = T_1 + ... + T_{s-1} + fraction T_s   (the total time, T_s the step's period)
/// (a step cut back after a failed outer loop, split(), halves its increment: its stage then
/// has a step at the midpoint of the fractions before and at it). The forces are
///   f(t_n) = (1 - fraction) R_{s-1} + fraction R_s + sum_a a(time_a) V_{s,a},
/// R_s the loads of step s without amplitude (R_0 = 0; with `ramp = false` the first two terms
/// are R_s alone), V_{s,a} its loads with amplitude a, evaluated at the step time
/// (fraction T_s) or the total time (TIME=TOTAL TIME). The prescribed values u_D follow the
/// same rule. Each (R_s, V_{s,a}) is a term: a force vector and a vector of prescribed values,
/// and f(t_n) a linear combination of terms, so that a solver may combine its own layouts of
/// them (combine()). For a step 1 without amplitudes the numbers are those of t * f and
/// t * u_D bit for bit, so a one-step problem runs as it did before steps existed.
///
/// A step with automatic increments (Step::automatic) starts with its initial increment; after
/// every increment the run finishes (increment_done) the next is 1.5 times the last where it
/// and the one before converged in at most easy_iterations outer iterations, 0.75 times where
/// it took more than slow_iterations (CalculiX's I_G = 4, D_D = 1.5, I_L = 10, D_B = 0.75,
/// checkconvergence.c), else the same, within the step's minimum and maximum; the rest of the
/// step is planned in equal increments no larger (CalculiX instead shortens the last). A
/// cutback halves an increment (split), not below the minimum, and the increments after it
/// keep the halved size until they grow. A fixed step (Step::increments, or the default) keeps
/// its plan.
///
/// A load without amplitude starts a step from the value of the loads without amplitude at the
/// end of the step before: CalculiX's rule, as long as no load trades a ramp for an amplitude
/// between steps (the deck reader refuses that). Each step holds the DOFs its supports name (a
/// deck's *BOUNDARY, OP=NEW may hold others than the step before, or free some): dofs() is the
/// union over the steps, the values live in its order, and prescribed(n) gives the DOFs load
/// step n's stage holds. A DOF that a step holds and the step before left free ramps from the
/// displacement it has when the step starts (CalculiX's spcmatch.f), which the solver gives
/// (start_stage); one with an amplitude follows its amplitude. A freed DOF's reaction is gone
/// from the step's first increment on.
///
/// Usage:
///   const LoadHistory history(problem, settings.steps(), linear);
///   for (int n = 1; n <= history.n_steps(); ++n)
///     solve(history.load_factor(n), history.external_force(n), history.prescribed(n));

#include "fem/amplitude.hpp"
#include "fem/dirichlet.hpp"
#include "fem/problem.hpp"
#include "la/types.hpp"

#include <cstdint>
#include <optional>
#include <set>
#include <string>
#include <vector>

namespace feticon::fem
{
/// The amplitude names the loads, supports and temperatures of `step` give, each once, sorted.
std::set<std::string> amplitudes_of(const Step& step);

/// Where a load step stands in the history.
struct LoadPoint
{
  int stage = 1;          ///< 1-based: the problem's step
  double fraction = 0;    ///< j / N_s in (0, 1]: how far into its stage
  double load_factor = 0; ///< t_n = (stage - 1) + fraction
  double time = 0;        ///< the total time
};

/// What a stage without amplitudes reaches at its end, and in how many load steps.
struct StageEnd
{
  la::Vector force;  ///< external forces at the end of the stage (N), 3 per mesh node
  la::Vector values; ///< prescribed values at its end (m), in the order of LoadHistory::dofs()
  int steps = 1;     ///< load steps of the stage (>= 1)
};

/// One term of the history: a force vector and prescribed values, scaled together.
struct LoadTerm
{
  la::Vector force;  ///< 3 per mesh node
  la::Vector values; ///< in the order of LoadHistory::dofs()
};

class LoadHistory
{
public:
  /// How a problem's steps become load steps.
  struct Rules
  {
    /// Load steps of a step that does not give its increments (the solver's load_steps; 1 with
    /// small displacements).
    int default_steps = 1;
    /// Every stage without amplitudes in one load step whatever its increments: small
    /// displacements, where frictionless contact makes the answer at a stage's end independent
    /// of the path (a stage with amplitudes keeps its increments: their values in between are
    /// asked for).
    bool one_step_per_stage = false;
    /// Step 1 in default_steps equal increments even where it has automatic ones (an explicit
    /// load_steps setting).
    bool default_first = false;
    /// Automatic increments grow after easy ones; false keeps them at their initial size (cut
    /// back where one fails): friction on slave nodes tied by equations, whose slip reversals
    /// the QP does not pass from every state (fricloop, nonlinear::SolverSettings::
    /// tied_friction_slaves).
    bool grow = true;
  };
  /// @brief The history of `problem` by `rules`.
  /// @throws feticon::Error naming the step and the set for a step's unknown or empty set,
  ///         non-finite value, out-of-range node or increments < 1
  LoadHistory(const Problem& problem, const Rules& rules);

  /// @brief A history from its stage ends, all ramped (tests, the direct Newton reference).
  /// @param[in] dofs   the prescribed DOFs (sorted, as ConstrainedDofs::dofs)
  /// @param[in] stages the ends of stages 1, 2, ...: equal vector sizes, steps >= 1
  LoadHistory(std::vector<int64_t> dofs, const std::vector<StageEnd>& stages);

  int n_stages() const { return static_cast<int>(_stages.size()); }
  /// Load steps of the whole history.
  int n_steps() const { return _last_step.back(); }
  /// Last load step of `stage` (1-based); 0 for stage 0 (the unloaded start).
  int last_step(int stage) const;
  /// Stage, fraction, load factor and time of load step `step` (1 .. n_steps()).
  LoadPoint point(int step) const;
  double load_factor(int step) const { return point(step).load_factor; }

  /// The prescribed DOFs (the union of every stage's).
  const std::vector<int64_t>& dofs() const { return _dofs; }
  /// `held`'s values (a subset of dofs(), e.g. Problem::all_constrained_dofs of one amplitude)
  /// in the order of dofs(), 0 at the DOFs it does not hold.
  la::Vector values_of(const ConstrainedDofs& held) const;
  /// The DOFs stage `stage` (1-based) holds, sorted.
  std::vector<int64_t> held_dofs(int stage) const;
  /// The DOFs whose values ramp from the displacement at stage `stage`'s start (held there,
  /// free in the stage before, without amplitude), sorted; empty for most stages.
  std::vector<int64_t> started_dofs(int stage) const;

  /// @brief Gives the start values of load step `step`'s stage if it is the stage's first step
  /// and the stage has started_dofs(): the displacement `u` (3 per mesh node) there.
  void start_stage(int step, const la::Vector& u);
  /// The start values of stage `stage`'s started_dofs() (for a checkpoint); empty: none given.
  la::Vector start_values(int stage) const;
  /// @brief Gives them from a checkpoint (start_values() of the run that wrote it).
  /// @throws feticon::Error if their number is not that of started_dofs(stage)
  void set_start_values(int stage, const la::Vector& values);
  /// The terms f(t_n) and u_D(t_n) combine (the file comment).
  const std::vector<LoadTerm>& terms() const { return _terms; }
  /// True if some stage has a load or support with an amplitude.
  bool has_amplitudes() const;

  /// f(t_n) of the file comment, 3 per mesh node.
  la::Vector external_force(int step) const;
  /// ||f(t_n)||: t ||f_1|| in a stage 1 without amplitudes (as a one-stage run scales it),
  /// the norm of f(t_n) otherwise.
  double external_force_norm(int step) const;
  /// u_D(t_n) in the order of dofs() (0 where the stage does not hold the DOF).
  la::Vector prescribed_values(int step) const;
  /// The stage's held DOFs with u_D(t_n): what a one-stage solver built as
  /// `constrained.values *= t`.
  /// @throws feticon::Error if the stage has started_dofs() and start_stage() was not called
  ConstrainedDofs prescribed(int step) const;

  /// @brief Halves load step `step`'s increment (a cutback after its outer loop failed): a
  /// step at the midpoint of t_{step-1} and t_step (in the fractions of its stage) comes in
  /// as load step `step`, the old one follows as step + 1, and n_steps() grows by one.
  void split(int step);

  /// Whether some stage has automatic increments (a deck's *STATIC without DIRECT).
  bool has_automatic_increments() const;

  /// @brief Whether load step `step` may be halved: always in a fixed stage, in an automatic one
  /// while half its increment is not below the step's minimum.
  bool may_halve(int step) const;

  /// @brief Empty while load step `step` is within its automatic stage's max_increments; else
  /// the one line that ends the run (CalculiX's rule).
  std::string increment_limit(int step) const;

  /// @brief Load step `step` was finished in `iterations` outer iterations (a large number for
  /// one accepted without converging): an automatic stage plans the rest of its steps at the
  /// next increment (the file comment); a fixed one keeps its plan.
  void increment_done(int step, int iterations);

  /// One load step of a run, as follow() replays it.
  struct Done
  {
    double load_factor;
    int iterations; ///< as increment_done() had them
  };
  /// @brief Splits and plans steps as a run did (a restart of it): step i is halved while its
  /// load factor is above done[i - 1]'s, so that the midpoints give the same numbers, then
  /// finished as done[i - 1] was. A factor that no halving reaches (another load_steps) is
  /// left for the caller's check.
  void follow(const std::vector<Done>& done);

  /// Outer iterations of an easy increment, and of a slow one (the file comment).
  static constexpr int easy_iterations = 4, slow_iterations = 10;
  /// The stages taken in one load step although they ask for more (one_step_per_stage), 1-based.
  const std::vector<int>& stages_in_one_step() const { return _stages_in_one_step; }

  /// @brief The value at load step `step` of a quantity given per term, by the rule of the file
  /// comment (for the solvers' own layouts, e.g. forces split over subdomains).
  /// @param[in] terms the quantity of each of terms(), in its order
  la::Vector combine(int step, const std::vector<la::Vector>& terms) const;

private:
  /// How a stage's terms are scaled: the ramp from the last stage's ramp term to its own, and
  /// its amplitude terms.
  struct Stage
  {
    int steps = 1;
    double period = 1, start_time = 0;
    bool ramp = true;
    int ramp_start = -1; ///< the term of R_{s-1}; -1 in stage 1
    int ramp_end = 0;    ///< the term of R_s
    std::vector<std::pair<int, Amplitude>> amplitudes;
    /// Automatic increments, as fractions of the period; unset: a fixed plan.
    std::optional<IncrementControl> automatic = {};
    bool easy_before = false; ///< the last increment was easy (automatic stages)
    bool grow = true;         ///< Rules::grow
    /// Indices into _dofs of the DOFs the stage holds, and of its started_dofs(); the values of
    /// the latter at the stage's start are those of term ramp_start (a term of its own).
    std::vector<la::Index> held, started;
    bool started_given = false; ///< start_stage() or set_start_values() gave them
  };
  /// Plans the steps of stage `stage` (0-based) after its j-th at `increment` (a fraction)
  /// until its end, and moves the later stages' step numbers.
  void plan(size_t stage, size_t j, double increment);
  /// Sets `stage`'s started DOFs (held `now`, free `before`, not `with_amplitude`; all sorted)
  /// and the term of its own its ramp starts from.
  void start_new_dofs(Stage& stage, const std::vector<int64_t>& before, const std::vector<int64_t>& now,
                      const std::vector<int64_t>& with_amplitude);
  std::vector<int64_t> dofs_at(const std::vector<la::Index>& indices) const;
  /// The index into _stages of stage `stage` (1-based), checked.
  size_t stage_index(int stage) const;
  /// The increment of load step `step` (a fraction of its stage).
  double increment_of(int step) const;
  /// (term, coefficient) of load step `step`, in a fixed order.
  std::vector<std::pair<int, double>> coefficients(int step) const;
  void add_stage(Stage stage);

  std::vector<int64_t> _dofs;
  std::vector<LoadTerm> _terms;
  std::vector<Stage> _stages;
  std::vector<int> _last_step; ///< cumulative: last load step of stage s at s - 1
  /// j / N_s of each load step of stage s at s - 1, with the midpoints of split steps.
  std::vector<std::vector<double>> _fractions;
  std::vector<int> _stages_in_one_step;
};
} // namespace feticon::fem
