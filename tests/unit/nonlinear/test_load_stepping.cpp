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
} // namespace

TEST(LoadStepping, RecordsEveryIterationAndCallsBackAfterConvergedSteps)
{
  ScriptedPhases phases(
      [](int step, int k) { return k == step + 1 ? IterationOutcome::step_converged() : IterationOutcome::next(); });
  ContactSolution out;
  std::vector<int> called_back;
  run_load_steps(phases, equal_steps(2), 1, 10, out,
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
  run_load_steps(phases, equal_steps(1), 1, 10, out);
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
  run_load_steps(phases, equal_steps(3), 2, 10, out, [&](int, const ContactSolution&) { ++called_back; });
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
  run_load_steps(phases, equal_steps(2), 1, 4, out);
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
  run_load_steps(phases, fem::LoadHistory({}, {{la::Vector(), la::Vector(), 2}, {la::Vector(), la::Vector(), 3}}), 1,
                 10, out);
  EXPECT_TRUE(out.converged);
  ASSERT_EQ(out.steps.size(), 5u);
  const std::vector<double> t = {0.5, 1.0, 4.0 / 3, 5.0 / 3, 2.0};
  for (size_t i = 0; i < t.size(); ++i)
    EXPECT_DOUBLE_EQ(out.steps[i].load_factor, t[i]) << "step " << i + 1;
  EXPECT_EQ(phases.calls[4], "begin 3 1.33");
  EXPECT_EQ(out.history.back().load_step, 5);
}
} // namespace feticon::nonlinear
