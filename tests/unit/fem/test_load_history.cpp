/// Tests of the load history (fem/load_history.hpp) on a 2x2x2 box: load factors, the
/// piecewise-linear forces and prescribed values, stage boundaries, one-stage problems bit for
/// bit as t * f, and the errors of a stage that changes the prescribed DOF set.
/// References: the rule of the file comment of load_history.hpp, evaluated by hand, and the
/// total force of a uniform traction = traction * face area (the unit square: 1 m^2).

#include "common/error.hpp"
#include "fem/load_history.hpp"
#include "mesh/box.hpp"

#include <gtest/gtest.h>

#include <cstdio>
#include <string>

using namespace feticon;

namespace
{
/// A later stage with traction (p, 0, 0) on xmax and the supports of box_problem with u_z = d.
fem::Step box_stage(double p, double d, int increments)
{
  fem::Step stage;
  stage.tractions = {{"xmax", Eigen::Vector3d(p, 0, 0)}};
  stage.dirichlet = {{"xmin", {0.0, std::nullopt, std::nullopt}}, {"zmax", {std::nullopt, std::nullopt, d}}};
  stage.increments = increments;
  return stage;
}

/// The unit cube in 2x2x2 cells, u_x = 0 on xmin, u_z = d on zmax, traction (p, 0, 0) on xmax.
fem::Problem box_problem(double p, double d)
{
  fem::Problem problem;
  problem.name = "box";
  mesh::BoxParameters box;
  box.nx = box.ny = box.nz = 2;
  problem.mesh = mesh::generate_box(box);
  problem.materials = {fem::Material{2e11, 0.3}};
  problem.steps.front() = box_stage(p, d, 0);
  problem.steps.front().increments.reset(); // the history's default steps
  problem.validate();
  return problem;
}

/// The problem's first step followed by `later`.
void set_later(fem::Problem& problem, std::vector<fem::Step> later)
{
  problem.steps.resize(1);
  problem.steps.insert(problem.steps.end(), later.begin(), later.end());
}

double total_x(const la::Vector& f) { return f(Eigen::seq(0, Eigen::last, 3)).sum(); }

bool identical(const la::Vector& a, const la::Vector& b)
{
  return a.size() == b.size() && (a.array() == b.array()).all();
}

std::string error_of(const fem::Problem& problem)
{
  try
  {
    const fem::LoadHistory history(problem, {.default_steps = 1});
    (void)history;
  }
  catch (const Error& e)
  {
    return e.what();
  }
  return "";
}
} // namespace

// Reference: a one-stage solver's t = n / N, f = t * f_ext, u_D = t * u_D (feti_contact_solver,
// primal_penalty_solver, direct_newton before stages): equal bit for bit.
TEST(LoadHistory, OneStageIsTTimesTheLoadBitForBit)
{
  const fem::Problem problem = box_problem(3e6, 1e-3);
  const int N = 7;
  const fem::LoadHistory history(problem, {.default_steps = N});
  ASSERT_EQ(history.n_stages(), 1);
  ASSERT_EQ(history.n_steps(), N);
  const la::Vector f = problem.external_force();
  const fem::ConstrainedDofs constrained = problem.all_constrained_dofs();
  EXPECT_EQ(history.dofs(), constrained.dofs);
  for (int n = 1; n <= N; ++n)
  {
    const double t = static_cast<double>(n) / N;
    EXPECT_EQ(history.load_factor(n), t);
    EXPECT_EQ(history.point(n).stage, 1);
    EXPECT_TRUE(identical(history.external_force(n), t * f)) << "step " << n;
    EXPECT_EQ(history.external_force_norm(n), t * f.norm());
    fem::ConstrainedDofs target = constrained;
    target.values *= t;
    EXPECT_TRUE(identical(history.prescribed_values(n), target.values)) << "step " << n;
    EXPECT_TRUE(identical(history.combine(n, {2 * f}), t * (2 * f)));
  }
  EXPECT_THROW(history.point(0), Error);
  EXPECT_THROW(history.point(N + 1), Error);
}

// Reference: the rule by hand. Stage 1: p = 1e6, d = 1e-3 in 2 steps; stage 2: p = 3e6,
// d = -1e-3 in 4 increments; stage 3: p = 0, d = 0 in 1. Load factors 0.5, 1, 1.25 ... 2, 3;
// the total x force is p(t) * 1 m^2 with p(t) piecewise linear through (0, 0), (1, 1e6),
// (2, 3e6), (3, 0); the stage ends are reached exactly.
TEST(LoadHistory, PiecewiseLinearThroughTheStageEnds)
{
  fem::Problem problem = box_problem(1e6, 1e-3);
  set_later(problem, {box_stage(3e6, -1e-3, 4), box_stage(0, 0, 1)});
  const fem::LoadHistory history(problem, {.default_steps = 2});
  ASSERT_EQ(history.n_stages(), 3);
  ASSERT_EQ(history.n_steps(), 7);
  EXPECT_EQ(history.last_step(0), 0);
  EXPECT_EQ(history.last_step(1), 2);
  EXPECT_EQ(history.last_step(2), 6);
  EXPECT_EQ(history.last_step(3), 7);
  const std::vector<double> t = {0.5, 1, 1.25, 1.5, 1.75, 2, 3};
  const std::vector<int> stage = {1, 1, 2, 2, 2, 2, 3};
  const std::vector<double> p = {0.5e6, 1e6, 1.5e6, 2e6, 2.5e6, 3e6, 0};
  const std::vector<double> d = {0.5e-3, 1e-3, 0.5e-3, 0, -0.5e-3, -1e-3, 0};
  for (int n = 1; n <= 7; ++n)
  {
    SCOPED_TRACE("load step " + std::to_string(n));
    const fem::LoadPoint point = history.point(n);
    EXPECT_EQ(point.stage, stage[n - 1]);
    EXPECT_DOUBLE_EQ(point.load_factor, t[n - 1]);
    EXPECT_NEAR(total_x(history.external_force(n)), p[n - 1], 1e-9 * 3e6);
    EXPECT_NEAR(history.external_force_norm(n), history.external_force(n).norm(), 1e-15 * 3e6);
    const la::Vector values = history.prescribed_values(n);
    for (size_t k = 0; k < history.dofs().size(); ++k)
    {
      const double expected = history.dofs()[k] % 3 == 2 ? d[n - 1] : 0.0;
      EXPECT_NEAR(values(static_cast<la::Index>(k)), expected, 1e-18) << "DOF " << history.dofs()[k];
    }
  }
  // Exactly the stage ends at the last step of each stage.
  for (int s = 1; s <= 3; ++s)
  {
    EXPECT_TRUE(identical(history.external_force(history.last_step(s)), problem.external_force(s - 1)));
    EXPECT_TRUE(identical(history.prescribed_values(history.last_step(s)), problem.all_constrained_dofs(s - 1).values));
  }
  EXPECT_NEAR(total_x(problem.external_force(1)), 3e6, 1e-9 * 3e6);
}

// Reference: SolverSettings::load_history with small displacements: one load step per stage,
// at the stage ends t = 1, 2, 3, whatever the increments.
TEST(LoadHistory, OneStepPerStage)
{
  fem::Problem problem = box_problem(1e6, 1e-3);
  set_later(problem, {box_stage(3e6, -1e-3, 4), box_stage(0, 0, 5)});
  const fem::LoadHistory history(problem, {.default_steps = 1, .one_step_per_stage = true});
  ASSERT_EQ(history.n_steps(), 3);
  for (int n = 1; n <= 3; ++n)
  {
    EXPECT_EQ(history.load_factor(n), n);
    EXPECT_TRUE(identical(history.external_force(n), problem.external_force(n - 1)));
  }
}

// Reference: Problem::eliminated adds its components to every stage's DOF set (plane strain:
// u_z = 0 on every node), so a later stage need not list them.
TEST(LoadHistory, EliminatedComponentsBelongToEveryStage)
{
  fem::Problem problem = box_problem(1e6, 0.0);
  problem.steps.front().dirichlet = {{"xmin", {0.0, std::nullopt, std::nullopt}}};
  problem.eliminated = {false, false, true};
  fem::Step stage = box_stage(2e6, 0, 1);
  stage.dirichlet = {{"xmin", {-1e-3, std::nullopt, std::nullopt}}};
  set_later(problem, {stage});
  const fem::LoadHistory history(problem, {.default_steps = 1});
  EXPECT_EQ(history.dofs(), problem.all_constrained_dofs().dofs);
  const la::Vector values = history.prescribed_values(2);
  for (size_t k = 0; k < history.dofs().size(); ++k)
    EXPECT_EQ(values(static_cast<la::Index>(k)), history.dofs()[k] % 3 == 0 ? -1e-3 : 0.0);
  EXPECT_EQ(history.external_force(2)(3 * 26 + 2), 0.0); // eliminated components carry no force
}

// Reference: input checks (STYLE.md, Errors): every message names the stage.
TEST(LoadHistory, BadStagesAreErrorsNamingTheStage)
{
  fem::Problem problem = box_problem(1e6, 1e-3);
  fem::Step stage = box_stage(1e6, 1e-3, 0);
  set_later(problem, {stage});
  EXPECT_NE(error_of(problem).find("step 2: the step has 0 increments"), std::string::npos) << error_of(problem);

  stage = box_stage(1e6, 1e-3, 1);
  stage.tractions[0].set = "no_such_set";
  set_later(problem, {stage});
  EXPECT_NE(error_of(problem).find("step 2: "), std::string::npos) << error_of(problem);
  EXPECT_NE(error_of(problem).find("no_such_set"), std::string::npos) << error_of(problem);

  stage = box_stage(1e6, 1e-3, 1);
  stage.nodal_forces = {{1000, 0, 1.0}};
  set_later(problem, {stage});
  EXPECT_NE(error_of(problem).find("step 2: nodal force on node 1000"), std::string::npos) << error_of(problem);

  stage = box_stage(1e6, 1e-3, 1);
  stage.dirichlet.push_back({"zmax", {std::nullopt, std::nullopt, 2e-3}}); // two values for one DOF
  set_later(problem, {stage});
  EXPECT_NE(error_of(problem).find("step 2: "), std::string::npos) << error_of(problem);

  EXPECT_THROW(fem::LoadHistory(problem.all_constrained_dofs().dofs, {}), Error);
  EXPECT_THROW(fem::LoadHistory({}, {{la::Vector::Zero(3), la::Vector::Zero(1), 1}}), Error);
}

// Reference: a quantity in another layout (here scaled by 2) follows the same rule.
TEST(LoadHistory, CombinesAnyQuantityGivenPerTerm)
{
  fem::Problem problem = box_problem(1e6, 1e-3);
  set_later(problem, {box_stage(3e6, -1e-3, 4)});
  const fem::LoadHistory history(problem, {.default_steps = 2});
  const std::vector<la::Vector> terms = {2 * history.terms()[0].force, 2 * history.terms()[1].force};
  for (int n = 1; n <= history.n_steps(); ++n)
    EXPECT_LE((history.combine(n, terms) - 2 * history.external_force(n)).norm(), 1e-15 * terms[1].norm());
  EXPECT_THROW(history.combine(1, {terms[0]}), Error);
}

// Reference: the rule of the file comment with a step split at the midpoint of the fractions
// before and at it: stage 1 in 2 steps (0.5, 1), step 2 split gives 0.75; stage 2 in 4
// (1.25, ...), its first step split gives 1.125; the forces follow the same rule (t f_1 in
// stage 1, the blend of the stage ends in stage 2), and a split steps the later steps on.
TEST(LoadHistory, SplitHalvesAStepsIncrement)
{
  fem::Problem problem = box_problem(1e6, 1e-3);
  set_later(problem, {box_stage(3e6, -1e-3, 4)});
  fem::LoadHistory history(problem, {.default_steps = 2});
  const fem::LoadHistory unsplit = history;
  history.split(2);
  history.split(4);
  ASSERT_EQ(history.n_steps(), 8);
  EXPECT_EQ(history.last_step(1), 3);
  const std::vector<double> t = {0.5, 0.75, 1.0, 1.125, 1.25, 1.5, 1.75, 2.0};
  for (int n = 1; n <= history.n_steps(); ++n)
    EXPECT_DOUBLE_EQ(history.load_factor(n), t[n - 1]) << "step " << n;
  const la::Vector f1 = problem.external_force(0);
  const la::Vector f2 = problem.external_force(1);
  EXPECT_TRUE(identical(history.external_force(2), 0.75 * f1));
  EXPECT_LE((history.external_force(4) - (0.875 * f1 + 0.125 * f2)).norm(), 1e-15 * f2.norm());
  EXPECT_DOUBLE_EQ(history.prescribed(4).values.maxCoeff(), 0.875e-3 - 0.125e-3);
  // The steps not split keep their numbers, bit for bit.
  EXPECT_TRUE(identical(history.external_force(1), unsplit.external_force(1)));
  EXPECT_TRUE(identical(history.external_force(8), unsplit.external_force(6)));
}

// Reference: the halving rule again. A run of one increment cut back to 0.25, whose next
// step went to 0.5 and was cut to 0.375: its load factors 0.25, 0.375, 0.5 are reproduced by
// halving the fresh history's steps while they lie above them; 1/3 (another load_steps) is
// not, and is left for the restart's check.
TEST(LoadHistory, FollowReproducesTheSplitsOfACutBackRun)
{
  fem::Problem problem = box_problem(1e6, 1e-3);
  fem::LoadHistory history(problem, {.default_steps = 1});
  history.follow({{0.25, 2}, {0.375, 2}, {0.5, 2}}); // iterations: a fixed plan ignores them
  const std::vector<double> t = {0.25, 0.375, 0.5, 1.0};
  ASSERT_EQ(history.n_steps(), 4);
  for (int n = 1; n <= 4; ++n)
    EXPECT_EQ(history.load_factor(n), t[n - 1]) << "step " << n;
  fem::LoadHistory other(problem, {.default_steps = 1});
  other.follow({{1.0 / 3, 2}});
  EXPECT_NE(other.load_factor(1), 1.0 / 3);
}

// Reference: the rule of the file comment by hand. Step 1 (time 2, 4 increments): the traction
// follows amplitude A at the step time, a = (0, 0), (1, 1), (2, -1) at 0.5, 1, 1.5, 2 gives
// 0.5, 1, 0, -1 (unloading and reversal); u_z on zmax ramps to 1e-3. Step 2 (time 1, 2
// increments): amplitude B at the total time, (2, 0), (3, 3) at 2.5 and 3 gives 1.5 and 3;
// u_z ramps from 1e-3 to -1e-3. Step 3 (AMPLITUDE=STEP, 2 increments): 2e6 Pa and u_z = 5e-4
// from its first increment on.
TEST(LoadHistory, AmplitudesAndStepLoadsByHand)
{
  fem::Problem problem = box_problem(1e6, 1e-3);
  problem.amplitudes["A"] = {{{0.0, 0.0}, {1.0, 1.0}, {2.0, -1.0}}};
  problem.amplitudes["B"] = {{{2.0, 0.0}, {3.0, 3.0}}, true};
  problem.steps.front().tractions[0].amplitude = "A";
  problem.steps.front().time = 2;
  problem.steps.front().increments = 4;
  fem::Step second = box_stage(1e6, -1e-3, 2);
  second.tractions[0].amplitude = "B";
  fem::Step third = box_stage(2e6, 5e-4, 2);
  third.ramp = false;
  set_later(problem, {second, third});
  const fem::LoadHistory history(problem,
                                 {.default_steps = 1, .one_step_per_stage = true}); // amplitudes keep their increments
  ASSERT_EQ(history.n_steps(), 4 + 2 + 1);                                          // step 3 has none: one load step
  EXPECT_TRUE(history.has_amplitudes());
  const std::vector<double> time = {0.5, 1, 1.5, 2, 2.5, 3, 4};
  const std::vector<double> p = {0.5e6, 1e6, 0, -1e6, 1.5e6, 3e6, 2e6};
  const std::vector<double> d = {0.25e-3, 0.5e-3, 0.75e-3, 1e-3, 0, -1e-3, 5e-4};
  for (int n = 1; n <= history.n_steps(); ++n)
  {
    SCOPED_TRACE("load step " + std::to_string(n));
    EXPECT_DOUBLE_EQ(history.point(n).time, time[n - 1]);
    EXPECT_NEAR(total_x(history.external_force(n)), p[n - 1], 1e-9 * 3e6);
    EXPECT_NEAR(history.external_force_norm(n), history.external_force(n).norm(), 1e-15 * 3e6);
    const la::Vector values = history.prescribed_values(n);
    for (size_t k = 0; k < history.dofs().size(); ++k)
      EXPECT_NEAR(values(static_cast<la::Index>(k)), history.dofs()[k] % 3 == 2 ? d[n - 1] : 0.0, 1e-18);
  }
  // Without one_step_per_stage the STEP stage takes its 2 increments, both at its values.
  const fem::LoadHistory every(problem, {.default_steps = 1});
  ASSERT_EQ(every.n_steps(), 8);
  EXPECT_NEAR(total_x(every.external_force(7)), 2e6, 1e-9 * 2e6);
  EXPECT_TRUE(identical(every.external_force(7), every.external_force(8)));
}

// Reference: an amplitude table by hand (CalculiX: linear between points, the end values
// beyond them; SHIFTX moves the table in time, SHIFTY adds to the values), and the bad
// tables of issue 65 item 8.
TEST(LoadHistory, AmplitudeTableAndItsErrors)
{
  fem::Amplitude a{{{1.0, 2.0}, {3.0, 6.0}, {3.0, 0.0}, {4.0, 1.0}}};
  EXPECT_EQ(a.value(0.0), 2.0);
  EXPECT_EQ(a.value(2.0), 4.0);
  EXPECT_EQ(a.value(3.5), 0.5); // after the jump at t = 3
  EXPECT_EQ(a.value(9.0), 1.0);
  a.shift_x = 1;
  a.shift_y = 10;
  EXPECT_EQ(a.value(3.0), 14.0);
  EXPECT_NO_THROW(a.check());
  a.where = "deck.inp:7: *AMPLITUDE R";
  fem::Amplitude one = a;
  one.points.resize(1);
  EXPECT_THROW(one.check(), Error);
  fem::Amplitude decreasing = a;
  decreasing.points[2].first = 2.0;
  try
  {
    decreasing.check();
    ADD_FAILURE() << "decreasing times accepted";
  }
  catch (const Error& e)
  {
    EXPECT_NE(std::string(e.what()).find("deck.inp:7: *AMPLITUDE R: the amplitude's times decrease at point 3"),
              std::string::npos)
        << e.what();
  }
  fem::Problem problem = box_problem(1e6, 1e-3);
  problem.steps.front().tractions[0].amplitude = "NONE";
  EXPECT_NE(error_of(problem).find("names amplitude 'NONE', which is not defined"), std::string::npos)
      << error_of(problem);
}

namespace
{
/// box_problem whose step 1 has automatic increments {initial, minimum, maximum}.
fem::Problem automatic_problem(double initial, double minimum, double maximum)
{
  fem::Problem problem = box_problem(1e6, 1e-3);
  problem.steps.front().automatic = fem::IncrementControl{initial, minimum, maximum};
  return problem;
}

std::vector<double> load_factors(const fem::LoadHistory& history)
{
  std::vector<double> t;
  for (int n = 1; n <= history.n_steps(); ++n)
    t.push_back(history.load_factor(n));
  return t;
}
} // namespace

// Reference: the rule of load_history.hpp's file comment by hand. Initial 0.1: ten steps,
// bit for bit the fixed plan of 10. Two easy increments (<= 4 outer iterations) grow the next
// to 0.15: the remaining 0.8 in ceil(0.8 / 0.15) = 6 equal ones; a slow one (> 10) shrinks it
// to 0.75 * 0.8 / 6 = 0.1: the remaining 2/3 in 7; easy ones then grow it to the maximum 0.4.
TEST(LoadHistory, AutomaticIncrementsGrowAndShrinkByHand)
{
  fem::Problem problem = automatic_problem(0.1, 0.01, 0.4);
  fem::LoadHistory history(problem, {});
  fem::Problem fixed = box_problem(1e6, 1e-3);
  fixed.steps.front().increments = 10;
  EXPECT_EQ(load_factors(history), load_factors(fem::LoadHistory(fixed, {})));
  history.increment_done(1, 3); // easy, but the first: the same size
  EXPECT_EQ(history.n_steps(), 10);
  history.increment_done(2, 4); // the second easy one in a row
  ASSERT_EQ(history.n_steps(), 2 + 6);
  EXPECT_DOUBLE_EQ(history.load_factor(3), 0.2 + 0.8 / 6);
  history.increment_done(3, 11);
  ASSERT_EQ(history.n_steps(), 3 + 7);
  EXPECT_DOUBLE_EQ(history.load_factor(4) - history.load_factor(3), (1 - history.load_factor(3)) / 7);
  for (int n = 4; n < history.n_steps(); ++n)
  {
    history.increment_done(n, 2);
    EXPECT_LE(history.load_factor(n + 1) - history.load_factor(n), 0.4 * (1 + 1e-12)) << "step " << n;
  }
  EXPECT_EQ(history.load_factor(history.n_steps()), 1.0);
  EXPECT_LT(history.n_steps(), 10);
}

// Reference: the halving rule with minimum 0.01: 0.1 halves to 0.05, 0.025, 0.0125, and
// stops there (half of it, 0.00625, is below the minimum). A step with maximum = initial and
// one with growth off (friction, Rules::grow) keep the fixed plan after easy increments.
TEST(LoadHistory, AutomaticIncrementsHalveDownToTheMinimumAndGrowOnlyWhereAllowed)
{
  fem::LoadHistory history(automatic_problem(0.1, 0.01, 1), {});
  for (const double t : {0.05, 0.025, 0.0125})
  {
    ASSERT_TRUE(history.may_halve(1));
    history.split(1);
    EXPECT_DOUBLE_EQ(history.load_factor(1), t);
  }
  EXPECT_FALSE(history.may_halve(1));
  const fem::Problem problem = automatic_problem(0.1, 0.01, 1);
  fem::LoadHistory capped(automatic_problem(0.1, 0.01, 0.1), {});
  fem::LoadHistory frozen(problem, {.grow = false});
  const std::vector<double> fixed = load_factors(capped);
  for (int n = 1; n < 10; ++n)
  {
    capped.increment_done(n, 1);
    frozen.increment_done(n, 1);
  }
  EXPECT_EQ(load_factors(capped), fixed);
  EXPECT_EQ(load_factors(frozen), fixed);
}

// Reference: a run's own history. A history that grew, shrank and was cut back is rebuilt by
// follow() from its (load factor, iterations) list with the same load factors bit for bit (a
// restart continues on the same plan).
TEST(LoadHistory, FollowReplaysAnAutomaticRunBitForBit)
{
  const fem::Problem problem = automatic_problem(0.1, 1e-3, 0.5);
  fem::LoadHistory run(problem, {});
  std::vector<fem::LoadHistory::Done> done;
  const std::vector<int> iterations = {2, 3, 2, 15, 12, 3, 3, 2};
  for (int n = 1; n <= static_cast<int>(iterations.size()) && n < run.n_steps(); ++n)
  {
    if (iterations[n - 1] == 15) // did not converge: cut back and redone
      run.split(n);
    done.push_back({run.load_factor(n), iterations[n - 1] == 15 ? 5 : iterations[n - 1]});
    run.increment_done(n, done.back().iterations);
  }
  fem::LoadHistory restarted(problem, {});
  restarted.follow(done);
  EXPECT_EQ(load_factors(restarted), load_factors(run));
}

// Reference: CalculiX's *STEP, INC= (nonlingeo.c): an automatic step's increments beyond
// max_increments end the run with one line; a fixed step is bounded by its own plan.
TEST(LoadHistory, AutomaticIncrementsStopAtTheirMaximumCount)
{
  fem::Problem problem = automatic_problem(0.1, 0.01, 1);
  problem.steps.front().automatic->max_increments = 3;
  const fem::LoadHistory history(problem, {});
  EXPECT_EQ(history.increment_limit(3), "");
  EXPECT_NE(history.increment_limit(4).find("step 1 needs more than its 3 increments (*STEP, INC="), std::string::npos)
      << history.increment_limit(4);
  fem::Problem fixed = box_problem(1e6, 1e-3);
  fixed.steps.front().increments = 10;
  EXPECT_EQ(fem::LoadHistory(fixed, {}).increment_limit(10), "");
  // An initial increment of 1e-7 of the step, which only growth could carry through: the plan
  // holds the 100 increments the step may take, then its end, which the limit never reaches.
  fem::Problem tiny = automatic_problem(1e-7, 1e-7, 1);
  const fem::LoadHistory small(tiny, {});
  ASSERT_EQ(small.n_steps(), 101);
  EXPECT_DOUBLE_EQ(small.load_factor(100), 1e-5);
  EXPECT_EQ(small.load_factor(101), 1.0);
  EXPECT_NE(small.increment_limit(101), "");
}

// Reference: the check of add_stage: 0 < minimum <= initial <= maximum, named by step.
TEST(LoadHistory, AutomaticIncrementsOutOfOrderAreRefused)
{
  EXPECT_NE(error_of(automatic_problem(0.1, 0.2, 1)).find("automatic increments need 0 < minimum <= initial"),
            std::string::npos)
      << error_of(automatic_problem(0.1, 0.2, 1));
}

// Reference: the rule of the file comment by hand. Step 1 holds u_x on xmin and u_z = 1e-3 on
// zmax; step 2 (2 increments) frees zmax and holds u_x = 2e-3 on xmax, which ramps from the
// displacement the solver gives at the step's start (here 1e-3 at every such DOF): 1.5e-3 at
// its first increment, 2e-3 at its second; xmin's u_x stays held at 0. dofs() is the union.
TEST(LoadHistory, AStepMayHoldAndFreeOtherDofs)
{
  fem::Problem problem = box_problem(1e6, 1e-3);
  fem::Step second = box_stage(1e6, 0, 2);
  second.dirichlet = {{"xmin", {0.0, std::nullopt, std::nullopt}}, {"xmax", {2e-3, std::nullopt, std::nullopt}}};
  set_later(problem, {second});
  fem::LoadHistory history(problem, {.default_steps = 1});
  const std::vector<int64_t> first = history.held_dofs(1), later = history.held_dofs(2);
  EXPECT_EQ(first.size(), 9u + 9u); // 9 nodes of xmin (u_x), 9 of zmax (u_z)
  EXPECT_EQ(later.size(), 9u + 9u); // xmin and xmax, u_x
  EXPECT_EQ(history.dofs().size(), 27u);
  const std::vector<int64_t> started = history.started_dofs(2);
  ASSERT_EQ(started.size(), 9u);
  for (const int64_t dof : started)
    EXPECT_EQ(dof % 3, 0);
  EXPECT_THROW(history.prescribed(2), Error); // the start values are not given yet
  la::Vector u = la::Vector::Zero(3 * problem.mesh.n_nodes());
  for (const int64_t dof : started)
    u(dof) = 1e-3;
  history.start_stage(1, u); // not step 2's first load step: nothing
  EXPECT_THROW(history.prescribed(2), Error);
  history.start_stage(2, u);
  for (const int step : {2, 3})
  {
    const fem::ConstrainedDofs held = history.prescribed(step);
    EXPECT_EQ(held.dofs, later);
    for (size_t k = 0; k < held.dofs.size(); ++k)
    {
      const bool on_xmax = std::binary_search(started.begin(), started.end(), held.dofs[k]);
      EXPECT_DOUBLE_EQ(held.values(static_cast<la::Index>(k)), on_xmax ? (step == 2 ? 1.5e-3 : 2e-3) : 0.0);
    }
  }
  EXPECT_EQ(history.prescribed(1).dofs, first);
  EXPECT_EQ(history.start_values(2).size(), 9);
  fem::LoadHistory restarted(problem, {.default_steps = 1});
  restarted.set_start_values(2, history.start_values(2));
  EXPECT_TRUE(identical(restarted.prescribed(3).values, history.prescribed(3).values));
  EXPECT_THROW(restarted.set_start_values(2, la::Vector::Zero(3)), Error);
}
