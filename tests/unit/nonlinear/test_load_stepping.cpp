/// Tests of the load-stepping driver (load_stepping.hpp) with scripted phases: what it
/// records, when it stops and what it reports. References: the scripts themselves.

#include "nonlinear/load_stepping.hpp"

#include <gtest/gtest.h>

#include <functional>
#include <vector>

namespace feticon::nonlinear
{
namespace
{
/// Phases whose outer iteration k of step s returns script(s, k); logs what was called.
class ScriptedPhases final : public LoadStepPhases
{
public:
  explicit ScriptedPhases(std::function<IterationOutcome(int, int)> script) : _script(std::move(script)) {}
  void begin_load_step(int step, double t) override
  {
    _step = step;
    calls.push_back("begin " + std::to_string(step) + " " + std::to_string(t).substr(0, 4));
  }
  IterationOutcome outer_iteration(int k, OuterIteration& it) override
  {
    it.qp.iterations = 10 * _step + k;
    it.displacement_change = 1.0 / k;
    return _script(_step, k);
  }
  void end_load_step(const LoadStep& record) override
  {
    calls.push_back("end " + std::to_string(_step) + (record.converged ? " converged" : ""));
  }
  std::string format(const OuterIteration& it) const override { return std::to_string(it.iteration); }
  std::vector<std::string> calls;

private:
  std::function<IterationOutcome(int, int)> _script;
  int _step = 0;
};

/// A one-stage history of n equal load steps (no loads: the scripts need none).
fem::LoadHistory equal_steps(int n) { return fem::LoadHistory({}, {{la::Vector(), la::Vector(), n}}); }

/// Phases of a solver whose outer loop converges in two iterations where the load increment
/// is at most `largest`, and otherwise goes on (or diverges, `diverge`) forever; they own the
/// history the driver runs, as the solvers do, and split it on a cutback.
class IncrementLimitedPhases final : public LoadStepPhases
{
public:
  IncrementLimitedPhases(fem::LoadHistory history, double largest, bool diverge)
      : history(std::move(history)), _largest(largest), _diverge(diverge)
  {
  }
  void begin_load_step(int step, double t) override
  {
    _increment = t - _converged_t;
    _t = t;
    _step = step;
    calls.push_back("begin " + std::to_string(step) + " " + std::to_string(t).substr(0, 5));
  }
  IterationOutcome outer_iteration(int k, OuterIteration&) override
  {
    if (_increment > _largest + 1e-12)
      return _diverge && k == 2 // worded as the solvers word it
          ? IterationOutcome::diverged("load step " + std::to_string(_step) + ", outer iteration 2: diverged")
          : IterationOutcome::next();
    return k == 2 ? IterationOutcome::step_converged() : IterationOutcome::next();
  }
  void end_load_step(const LoadStep& record) override
  {
    if (record.converged)
      _converged_t = _t;
  }
  std::string format(const OuterIteration& it) const override { return std::to_string(it.iteration); }
  bool cut_back(int step) override
  {
    calls.push_back("cut back " + std::to_string(step));
    history.split(step);
    return true;
  }
  fem::LoadHistory history;
  std::vector<std::string> calls;

private:
  double _largest;
  bool _diverge;
  double _t = 0, _converged_t = 0, _increment = 0;
  int _step = 0;
};
} // namespace

TEST(LoadStepping, RecordsEveryIterationAndCallsBackAfterConvergedSteps)
{
  ScriptedPhases phases(
      [](int step, int k) { return k == step + 1 ? IterationOutcome::step_converged() : IterationOutcome::next(); });
  ContactSolution out;
  std::vector<int> called_back;
  fem::LoadHistory history = equal_steps(2);
  run_load_steps(phases, history, 1, 10, 0, out,
                 [&](int step, const ContactSolution&) { called_back.push_back(step); });
  EXPECT_TRUE(out.converged);
  EXPECT_TRUE(out.reason.empty());
  ASSERT_EQ(out.steps.size(), 2u);
  EXPECT_EQ(out.steps[0].outer_iterations, 2);
  EXPECT_EQ(out.steps[1].outer_iterations, 3);
  EXPECT_EQ(out.steps[1].inner_iterations, (std::vector<int>{21, 22, 23}));
  EXPECT_DOUBLE_EQ(out.steps[1].load_factor, 1.0);
  EXPECT_DOUBLE_EQ(out.steps[1].displacement_change, 1.0 / 3);
  ASSERT_EQ(out.history.size(), 5u);
  EXPECT_EQ(out.history[4].load_step, 2);
  EXPECT_EQ(out.history[4].iteration, 3);
  EXPECT_EQ(called_back, (std::vector<int>{1, 2}));
  EXPECT_EQ(phases.calls,
            (std::vector<std::string>{"begin 1 0.50", "end 1 converged", "begin 2 1.00", "end 2 converged"}));
}

TEST(LoadStepping, UnrecordedConvergenceKeepsTheLastRecordedIteration)
{
  // The primal penalty's small-displacement loop: iteration 3 finds the active set of
  // iteration 2 consistent without solving.
  ScriptedPhases phases(
      [](int, int k) { return k == 3 ? IterationOutcome::step_converged(false) : IterationOutcome::next(); });
  ContactSolution out;
  fem::LoadHistory history = equal_steps(1);
  run_load_steps(phases, history, 1, 10, 0, out);
  EXPECT_TRUE(out.converged);
  EXPECT_EQ(out.history.size(), 2u);
  EXPECT_EQ(out.steps[0].outer_iterations, 2);
}

TEST(LoadStepping, StopsWithTheReasonOfAFailedIteration)
{
  ScriptedPhases phases([](int step, int k) {
    return step == 2 && k == 2 ? IterationOutcome::stop("QP failed", false) : IterationOutcome::next();
  });
  ContactSolution out;
  int called_back = 0;
  fem::LoadHistory history = equal_steps(3);
  run_load_steps(phases, history, 2, 10, 5, out, [&](int, const ContactSolution&) { ++called_back; });
  EXPECT_FALSE(out.converged);
  EXPECT_EQ(out.reason, "QP failed");
  EXPECT_EQ(out.history.size(), 1u); // the failed iteration is no result
  EXPECT_EQ(called_back, 0);
  EXPECT_EQ(phases.calls.back(), "end 2"); // end_load_step runs for the failed step too
}

TEST(LoadStepping, ReportsAStepThatDoesNotConverge)
{
  ScriptedPhases phases([](int, int) { return IterationOutcome::next(); });
  ContactSolution out;
  fem::LoadHistory history = equal_steps(2);
  run_load_steps(phases, history, 1, 4, 0, out);
  EXPECT_FALSE(out.converged);
  EXPECT_EQ(out.history.size(), 4u);
  EXPECT_EQ(out.steps.size(), 1u);
  EXPECT_NE(out.reason.find("load step 1 did not converge in 4 outer iterations"), std::string::npos) << out.reason;
}
// Reference: the history's load factors (fem/load_history.hpp): stage 1 in 2 steps (0.5, 1),
// stage 2 in 3 (4/3, 5/3, 2), passed to the phases and recorded per step.
TEST(LoadStepping, StepsThroughTheStagesOfAHistory)
{
  ScriptedPhases phases([](int, int) { return IterationOutcome::step_converged(); });
  ContactSolution out;
  fem::LoadHistory history({}, {{la::Vector(), la::Vector(), 2}, {la::Vector(), la::Vector(), 3}});
  run_load_steps(phases, history, 1, 10, 0, out);
  EXPECT_TRUE(out.converged);
  ASSERT_EQ(out.steps.size(), 5u);
  const std::vector<double> t = {0.5, 1.0, 4.0 / 3, 5.0 / 3, 2.0};
  for (size_t i = 0; i < t.size(); ++i)
    EXPECT_DOUBLE_EQ(out.steps[i].load_factor, t[i]) << "step " << i + 1;
  EXPECT_EQ(phases.calls[4], "begin 3 1.33");
  EXPECT_EQ(out.history.back().load_step, 5);
}

// Reference: the halving rule (LoadHistory::split): a whole-load step that converges only for
// increments <= 0.3 is cut to 0.5, then 0.25; the step from 0.5 to 1 that follows is cut
// again, to 0.75. Each converged attempt takes two iterations, each failed one three.
TEST(LoadStepping, CutsAFailingStepBackUntilItConverges)
{
  IncrementLimitedPhases phases(equal_steps(1), 0.3, false);
  ContactSolution out;
  std::vector<int> called_back;
  run_load_steps(phases, phases.history, 1, 3, 5, out,
                 [&](int step, const ContactSolution&) { called_back.push_back(step); });
  EXPECT_TRUE(out.converged) << out.reason;
  const std::vector<double> t = {0.25, 0.5, 0.75, 1.0};
  ASSERT_EQ(out.steps.size(), t.size());
  for (size_t i = 0; i < t.size(); ++i)
    EXPECT_DOUBLE_EQ(out.steps[i].load_factor, t[i]) << "step " << i + 1;
  EXPECT_EQ(out.history.size(), 3u * 3 + 4 * 2);
  ASSERT_EQ(out.warnings.size(), 3u);
  EXPECT_NE(out.warnings[0].find("load step 1 at load factor 1 cut back to 0.5: not converged in 3 outer iterations"),
            std::string::npos)
      << out.warnings[0];
  EXPECT_NE(out.warnings[1].find("load step 1 at load factor 0.5 cut back to 0.25"), std::string::npos)
      << out.warnings[1];
  EXPECT_NE(out.warnings[2].find("load step 3 at load factor 1 cut back to 0.75"), std::string::npos)
      << out.warnings[2];
  EXPECT_EQ(called_back, (std::vector<int>{1, 2, 3, 4}));
  EXPECT_EQ(
      phases.calls,
      (std::vector<std::string>{"begin 1 1.000", "cut back 1", "begin 1 0.500", "cut back 1", "begin 1 0.250",
                                "begin 2 0.500", "begin 3 1.000", "cut back 3", "begin 3 0.750", "begin 4 1.000"}));
}

TEST(LoadStepping, CutsADivergedStepBackButStopsForOtherFailures)
{
  IncrementLimitedPhases diverging(equal_steps(2), 0.5, true);
  ContactSolution out;
  run_load_steps(diverging, diverging.history, 1, 10, 5, out);
  EXPECT_TRUE(out.converged) << out.reason; // increments of 0.5 converge: no cutback
  EXPECT_TRUE(out.warnings.empty());

  IncrementLimitedPhases diverging_whole(equal_steps(1), 0.5, true);
  ContactSolution cut;
  run_load_steps(diverging_whole, diverging_whole.history, 1, 10, 5, cut);
  EXPECT_TRUE(cut.converged) << cut.reason;
  ASSERT_EQ(cut.warnings.size(), 1u);
  // The failure's own "load step 1, " is not repeated after the warning's "load step 1 at ...".
  EXPECT_NE(cut.warnings[0].find("load step 1 at load factor 1 cut back to 0.5: outer iteration 2: diverged"),
            std::string::npos)
      << cut.warnings[0];
  EXPECT_EQ(cut.history.size(), 1u + 2 + 2); // the diverged iteration is no result

  // A QP that fails is no matter of the increment: the run stops.
  ScriptedPhases failing(
      [](int, int k) { return k == 2 ? IterationOutcome::stop("QP failed") : IterationOutcome::next(); });
  ContactSolution stopped;
  fem::LoadHistory history = equal_steps(1);
  run_load_steps(failing, history, 1, 10, 5, stopped);
  EXPECT_EQ(stopped.reason, "QP failed");
}

TEST(LoadStepping, StopsWhenTheCutbacksAreUsedUp)
{
  IncrementLimitedPhases phases(equal_steps(1), 0.1, false);
  ContactSolution out;
  run_load_steps(phases, phases.history, 1, 3, 2, out);
  EXPECT_FALSE(out.completed);
  EXPECT_EQ(out.warnings.size(), 2u);                  // 1 -> 0.5 -> 0.25
  EXPECT_EQ(out.history.size(), 9u);                   // three attempts of three iterations
  EXPECT_DOUBLE_EQ(out.steps.at(0).load_factor, 0.25); // the last attempt is the step's record
  EXPECT_NE(out.reason.find("load step 1 did not converge in 3 outer iterations"), std::string::npos) << out.reason;
}
} // namespace feticon::nonlinear
