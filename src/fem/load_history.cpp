#include "fem/load_history.hpp"

#include "common/error.hpp"

#include <algorithm>
#include <numeric>
#include <set>
#include <string>

namespace feticon::fem
{
namespace
{
/// The DOFs of `step`'s supports that follow an amplitude, sorted.
std::vector<int64_t> amplitude_dofs(const Problem& problem, const Step& step)
{
  std::set<int64_t> dofs;
  for (const DirichletCondition& d : step.dirichlet)
    if (!d.amplitude.empty())
      for (const int32_t n : problem.mesh.node_set(d.set))
        for (int i = 0; i < 3; ++i)
          if (d.value[i])
            dofs.insert(3 * static_cast<int64_t>(n) + i);
  for (const ReferenceValue& r : step.reference_supports)
    if (!r.amplitude.empty())
      dofs.insert(problem.reference_dof(r.coupling, r.dof));
  return {dofs.begin(), dofs.end()};
}

/// `held`'s values in the order of `all` (a superset), 0 at the DOFs it does not hold.
la::Vector values_over(const std::vector<int64_t>& all, const ConstrainedDofs& held)
{
  la::Vector out = la::Vector::Zero(static_cast<la::Index>(all.size()));
  for (size_t k = 0; k < held.dofs.size(); ++k)
  {
    const auto at = std::lower_bound(all.begin(), all.end(), held.dofs[k]);
    out(at - all.begin()) = held.values(static_cast<la::Index>(k));
  }
  return out;
}

/// Indices into `all` of `dofs` (both sorted; dofs a subset).
std::vector<la::Index> indices_in(const std::vector<int64_t>& all, const std::vector<int64_t>& dofs)
{
  std::vector<la::Index> out;
  out.reserve(dofs.size());
  for (const int64_t dof : dofs)
    out.push_back(std::lower_bound(all.begin(), all.end(), dof) - all.begin());
  return out;
}

/// sum_k c_k term(k) over the (term, coefficient) pairs `c`, term by term, so that t f and
/// (1 - t) f_0 + t f_1 round as one-stage and two-stage runs did before amplitudes (c f in one
/// product; each element a x + b y).
template <class Term>
la::Vector linear_combination(const std::vector<std::pair<int, double>>& c, Term term)
{
  la::Vector out = c.front().second * term(c.front().first);
  for (size_t k = 1; k < c.size(); ++k)
    out += c[k].second * term(c[k].first);
  return out;
}
} // namespace

std::set<std::string> amplitudes_of(const Step& step)
{
  std::set<std::string> names;
  const auto add = [&](const auto& loads) {
    for (const auto& load : loads)
      if (!load.amplitude.empty())
        names.insert(load.amplitude);
  };
  add(step.dirichlet);
  add(step.tractions);
  add(step.pressures);
  add(step.nodal_forces);
  add(step.body_loads);
  add(step.reference_supports);
  add(step.reference_loads);
  add(step.temperatures); // no force, but the stage keeps its increments (fem/temperature_history.hpp)
  return names;
}

LoadHistory::LoadHistory(const Problem& problem, const Rules& rules)
{
  FETICON_CHECK(rules.default_steps >= 1, "load steps: " << rules.default_steps << ", must be >= 1");
  problem.validate();
  std::vector<ConstrainedDofs> held;
  std::set<int64_t> every;
  for (size_t k = 0; k < problem.steps.size(); ++k)
  {
    held.push_back(problem.all_constrained_dofs(k));
    every.insert(held.back().dofs.begin(), held.back().dofs.end());
  }
  _dofs.assign(every.begin(), every.end());
  double start_time = 0;
  for (size_t k = 0; k < problem.steps.size(); ++k)
  {
    const Step& step = problem.steps[k];
    Stage stage;
    stage.period = step.time;
    stage.start_time = start_time;
    stage.ramp = step.ramp;
    stage.held = indices_in(_dofs, held[k].dofs);
    stage.ramp_start = k == 0 ? -1 : _stages.back().ramp_end;
    if (k > 0 && step.ramp)
      start_new_dofs(stage, held[k - 1].dofs, held[k].dofs, amplitude_dofs(problem, step));
    stage.ramp_end = static_cast<int>(_terms.size());
    _terms.push_back({problem.external_force(k), values_over(_dofs, held[k])});
    for (const std::string& name : amplitudes_of(step))
    {
      stage.amplitudes.emplace_back(static_cast<int>(_terms.size()), problem.amplitudes.at(name));
      _terms.push_back({problem.external_force(k, name), values_over(_dofs, problem.all_constrained_dofs(k, name))});
    }
    stage.grow = rules.grow;
    if (rules.one_step_per_stage && stage.amplitudes.empty())
    {
      if (step.increments.value_or(1) > 1 || (step.automatic && step.automatic->initial < step.time))
        _stages_in_one_step.push_back(static_cast<int>(k) + 1);
    }
    else if (step.increments)
      stage.steps = *step.increments;
    else if (step.automatic && !(k == 0 && rules.default_first))
      stage.automatic = IncrementControl{
          std::min(1.0, step.automatic->initial / step.time), std::min(1.0, step.automatic->minimum / step.time),
          std::min(1.0, step.automatic->maximum / step.time), step.automatic->max_increments};
    else
      stage.steps = rules.default_steps;
    add_stage(std::move(stage));
    start_time += step.time;
  }
}

LoadHistory::LoadHistory(std::vector<int64_t> dofs, const std::vector<StageEnd>& stages) : _dofs(std::move(dofs))
{
  FETICON_CHECK(!stages.empty(), "a load history needs at least one stage");
  for (size_t s = 0; s < stages.size(); ++s)
  {
    const StageEnd& end = stages[s];
    FETICON_CHECK(
        end.force.size() == stages[0].force.size() && end.values.size() == static_cast<la::Index>(_dofs.size()),
        "load stage " << s + 1 << ": " << end.force.size() << " forces and " << end.values.size()
                      << " prescribed values, expected " << stages[0].force.size() << " and " << _dofs.size());
    Stage stage;
    stage.start_time = static_cast<double>(s);
    stage.steps = end.steps;
    stage.ramp_start = s == 0 ? -1 : _stages.back().ramp_end;
    stage.held.resize(_dofs.size());
    std::iota(stage.held.begin(), stage.held.end(), la::Index{0});
    stage.ramp_end = static_cast<int>(_terms.size());
    _terms.push_back({end.force, end.values});
    add_stage(std::move(stage));
  }
}

void LoadHistory::start_new_dofs(Stage& stage, const std::vector<int64_t>& before, const std::vector<int64_t>& now,
                                 const std::vector<int64_t>& with_amplitude)
{
  std::vector<int64_t> added, started;
  std::set_difference(now.begin(), now.end(), before.begin(), before.end(), std::back_inserter(added));
  std::set_difference(added.begin(), added.end(), with_amplitude.begin(), with_amplitude.end(),
                      std::back_inserter(started));
  if (started.empty())
    return;
  stage.started = indices_in(_dofs, started);
  // The stage ramps from a term of its own: R_{s-1}, whose values at the started DOFs
  // start_stage() sets.
  LoadTerm start = _terms[stage.ramp_start];
  stage.ramp_start = static_cast<int>(_terms.size());
  _terms.push_back(std::move(start));
}

std::vector<int64_t> LoadHistory::dofs_at(const std::vector<la::Index>& indices) const
{
  std::vector<int64_t> out;
  out.reserve(indices.size());
  for (const la::Index k : indices)
    out.push_back(_dofs[k]);
  return out;
}

size_t LoadHistory::stage_index(int stage) const
{
  FETICON_CHECK(stage >= 1 && stage <= n_stages(), "load stage " << stage << " of " << n_stages());
  return static_cast<size_t>(stage - 1);
}

double LoadHistory::increment_of(int step) const
{
  const LoadPoint p = point(step);
  const int j = step - last_step(p.stage - 1);
  return p.fraction - (j == 1 ? 0.0 : _fractions[p.stage - 1][j - 2]);
}

la::Vector LoadHistory::values_of(const ConstrainedDofs& held) const { return values_over(_dofs, held); }

std::vector<int64_t> LoadHistory::held_dofs(int stage) const { return dofs_at(_stages[stage_index(stage)].held); }

std::vector<int64_t> LoadHistory::started_dofs(int stage) const { return dofs_at(_stages[stage_index(stage)].started); }

void LoadHistory::start_stage(int step, const la::Vector& u)
{
  const LoadPoint p = point(step);
  Stage& stage = _stages[p.stage - 1];
  if (stage.started.empty() || step != last_step(p.stage - 1) + 1)
    return;
  la::Vector values(static_cast<la::Index>(stage.started.size()));
  for (size_t k = 0; k < stage.started.size(); ++k)
  {
    const int64_t dof = _dofs[stage.started[k]];
    FETICON_CHECK(dof < u.size(), "start_stage: a displacement of " << u.size() << " DOFs, DOF " << dof << " held");
    values(static_cast<la::Index>(k)) = u(dof);
  }
  set_start_values(p.stage, values);
}

la::Vector LoadHistory::start_values(int stage) const
{
  const Stage& s = _stages[stage_index(stage)];
  if (!s.started_given)
    return {};
  la::Vector out(static_cast<la::Index>(s.started.size()));
  for (size_t k = 0; k < s.started.size(); ++k)
    out(static_cast<la::Index>(k)) = _terms[s.ramp_start].values(s.started[k]);
  return out;
}

void LoadHistory::set_start_values(int stage, const la::Vector& values)
{
  Stage& s = _stages[stage_index(stage)];
  FETICON_CHECK(values.size() == static_cast<la::Index>(s.started.size()) && values.allFinite(),
                "step " << stage << ": " << values.size() << " start values for the " << s.started.size()
                        << " DOFs it holds and the step before leaves free (another model?), or not finite");
  for (size_t k = 0; k < s.started.size(); ++k)
    _terms[s.ramp_start].values(s.started[k]) = values(static_cast<la::Index>(k));
  s.started_given = true;
}

void LoadHistory::add_stage(Stage stage)
{
  const int number = n_stages() + 1;
  FETICON_CHECK(stage.steps >= 1, "load stage " << number << " has " << stage.steps << " load steps, must be >= 1");
  FETICON_CHECK(stage.steps <= 100000,
                "load stage " << number << " has " << stage.steps << " load steps, at most " << 100000 << " are taken");
  _last_step.push_back((_last_step.empty() ? 0 : _last_step.back()) + stage.steps);
  // As a one-stage run's t = n / N, so that stage 1 reproduces its numbers exactly.
  std::vector<double>& fractions = _fractions.emplace_back();
  if (!stage.automatic)
    for (int j = 1; j <= stage.steps; ++j)
      fractions.push_back(static_cast<double>(j) / stage.steps);
  _stages.push_back(std::move(stage));
  if (const std::optional<IncrementControl>& a = _stages.back().automatic)
  {
    FETICON_CHECK(a->minimum > 0 && a->minimum <= a->initial && a->initial <= a->maximum,
                  "step " << number << ": automatic increments need 0 < minimum <= initial <= maximum, given "
                          << a->minimum << ", " << a->initial << ", " << a->maximum << " (fractions of its time)");
    plan(_stages.size() - 1, 0, a->initial);
  }
}

void LoadHistory::plan(size_t stage, size_t j, double increment)
{
  std::vector<double>& fractions = _fractions[stage];
  fractions.resize(j);
  const double at = j == 0 ? 0.0 : fractions.back();
  // The rest in equal increments no larger than `increment` (k / n from the start, as a fixed
  // stage's, so that an increment that never changes gives the fixed plan bit for bit).
  const double n = std::max(1.0, std::ceil((1 - at) / increment - 1e-9));
  // The step stops after max_increments (increment_limit): the plan goes no further in these
  // increments (a tiny initial one that never grew), its last load step stays the step's end.
  const double limit = static_cast<double>(_stages[stage].automatic->max_increments) - static_cast<double>(j) + 1;
  const double planned = std::min(n, std::max(1.0, limit));
  FETICON_CHECK(j + planned <= 100000,
                "step " << stage + 1 << ": " << j + planned << " load steps; feticon takes at most 100000 per step");
  for (int k = 1; k < static_cast<int>(planned); ++k)
    fractions.push_back(at + (1 - at) * k / n);
  fractions.push_back(1.0);
  for (size_t s = stage; s < _last_step.size(); ++s)
    _last_step[s] = (s == 0 ? 0 : _last_step[s - 1]) + static_cast<int>(_fractions[s].size());
}

bool LoadHistory::may_halve(int step) const
{
  const Stage& stage = _stages[point(step).stage - 1];
  return !stage.automatic || 0.5 * increment_of(step) >= stage.automatic->minimum * (1 - 1e-9);
}

std::string LoadHistory::increment_limit(int step) const
{
  const LoadPoint p = point(step);
  const std::optional<IncrementControl>& a = _stages[p.stage - 1].automatic;
  const int j = step - last_step(p.stage - 1);
  if (!a || j <= a->max_increments)
    return {};
  return "step " + std::to_string(p.stage) + " needs more than its " + std::to_string(a->max_increments) +
      " increments (*STEP, INC=; CalculiX's default 100) and stopped at load factor " +
      std::to_string(point(step - 1).load_factor) + ": its increments stayed small (cut back, or slow to converge)";
}

bool LoadHistory::has_automatic_increments() const
{
  return std::ranges::any_of(_stages, [](const Stage& stage) { return stage.automatic.has_value(); });
}

void LoadHistory::increment_done(int step, int iterations)
{
  const LoadPoint p = point(step);
  Stage& stage = _stages[p.stage - 1];
  if (!stage.automatic || p.fraction == 1.0)
    return;
  const int j = step - last_step(p.stage - 1);
  const double increment = increment_of(step);
  double factor = 1;
  if (iterations > slow_iterations)
    factor = 0.75;
  else if (iterations <= easy_iterations && stage.easy_before && stage.grow)
    factor = 1.5;
  stage.easy_before = iterations <= easy_iterations;
  const double next = std::clamp(factor * increment, stage.automatic->minimum, stage.automatic->maximum);
  // A plan whose next increment is this one stands (one that never changes is the fixed plan);
  // after a cutback its next is the other half, and the one after is planned at that size.
  const std::vector<double>& fractions = _fractions[p.stage - 1];
  if (std::abs(fractions[j] - p.fraction - next) > 1e-9 * next)
    plan(p.stage - 1, j, next);
}

bool LoadHistory::has_amplitudes() const
{
  return std::ranges::any_of(_stages, [](const Stage& s) { return !s.amplitudes.empty(); });
}

int LoadHistory::last_step(int stage) const
{
  FETICON_CHECK(stage >= 0 && stage <= n_stages(), "load stage " << stage << " of " << n_stages());
  return stage == 0 ? 0 : _last_step[stage - 1];
}

LoadPoint LoadHistory::point(int step) const
{
  FETICON_CHECK(step >= 1 && step <= n_steps(), "load step " << step << " of " << n_steps());
  const auto stage =
      static_cast<int>(std::lower_bound(_last_step.begin(), _last_step.end(), step) - _last_step.begin());
  const int j = step - (stage == 0 ? 0 : _last_step[stage - 1]);
  const double fraction = _fractions[stage][j - 1];
  const Stage& s = _stages[stage];
  return {stage + 1, fraction, stage == 0 ? fraction : stage + fraction, s.start_time + fraction * s.period};
}

void LoadHistory::follow(const std::vector<Done>& done)
{
  for (int i = 1; i <= static_cast<int>(done.size()) && i <= n_steps(); ++i)
  {
    for (int cuts = 0; cuts < 64 && i <= n_steps() && load_factor(i) > done[i - 1].load_factor + 1e-12 * i; ++cuts)
      split(i);
    if (i <= n_steps())
      increment_done(i, done[i - 1].iterations);
  }
}

void LoadHistory::split(int step)
{
  const LoadPoint p = point(step);
  std::vector<double>& fractions = _fractions[p.stage - 1];
  const int j = step - last_step(p.stage - 1) - 1;
  const double before = j == 0 ? 0.0 : fractions[j - 1];
  fractions.insert(fractions.begin() + j, 0.5 * (before + fractions[j]));
  _stages[p.stage - 1].easy_before = false; // CalculiX's istab = 0 after a cutback
  for (size_t s = p.stage - 1; s < _last_step.size(); ++s)
    ++_last_step[s];
}

std::vector<std::pair<int, double>> LoadHistory::coefficients(int step) const
{
  const LoadPoint p = point(step);
  const Stage& stage = _stages[p.stage - 1];
  std::vector<std::pair<int, double>> out;
  if (!stage.ramp)
    out.emplace_back(stage.ramp_end, 1.0);
  else
  {
    if (stage.ramp_start >= 0)
      out.emplace_back(stage.ramp_start, 1 - p.fraction);
    out.emplace_back(stage.ramp_end, p.fraction);
  }
  for (const auto& [term, amplitude] : stage.amplitudes)
    out.emplace_back(term, amplitude.value(amplitude.total_time ? p.time : p.fraction * stage.period));
  return out;
}

la::Vector LoadHistory::combine(int step, const std::vector<la::Vector>& terms) const
{
  FETICON_CHECK(terms.size() == _terms.size(),
                "a quantity of " << terms.size() << " terms for a history of " << _terms.size());
  return linear_combination(coefficients(step), [&](int k) -> const la::Vector& { return terms[k]; });
}

la::Vector LoadHistory::external_force(int step) const
{
  return linear_combination(coefficients(step), [&](int k) -> const la::Vector& { return _terms[k].force; });
}

double LoadHistory::external_force_norm(int step) const
{
  const LoadPoint p = point(step);
  const Stage& stage = _stages[p.stage - 1];
  if (p.stage == 1 && stage.amplitudes.empty())
    return (stage.ramp ? p.fraction : 1.0) * _terms[stage.ramp_end].force.norm(); // as a one-stage solver scales ||f||
  return external_force(step).norm();
}

la::Vector LoadHistory::prescribed_values(int step) const
{
  return linear_combination(coefficients(step), [&](int k) -> const la::Vector& { return _terms[k].values; });
}

ConstrainedDofs LoadHistory::prescribed(int step) const
{
  const Stage& stage = _stages[point(step).stage - 1];
  FETICON_CHECK(stage.started.empty() || stage.started_given,
                "load step " << step << ": its step holds DOFs the step before leaves free, whose values start "
                             << "from the displacement at the step's start, and the solver did not give it");
  la::Vector values = prescribed_values(step);
  if (stage.held.size() == _dofs.size())
    return {_dofs, std::move(values)};
  ConstrainedDofs out{dofs_at(stage.held), la::Vector(static_cast<la::Index>(stage.held.size()))};
  for (size_t k = 0; k < stage.held.size(); ++k)
    out.values(static_cast<la::Index>(k)) = values(stage.held[k]);
  return out;
}
} // namespace feticon::fem
