#include "fem/load_history.hpp"

#include "common/error.hpp"
#include "fem/loads.hpp"

#include <algorithm>
#include <cmath>
#include <map>
#include <string>

namespace feticon::fem
{
namespace
{
/// Runs `check`, prefixing the message of a feticon::Error it throws with the stage.
template <class F>
auto in_stage(int stage, F&& check)
{
  try
  {
    return check();
  }
  catch (const Error& e)
  {
    throw Error("load stage " + std::to_string(stage) + ": " + e.what());
  }
}

/// The consistent nodal forces of a later stage, as Problem::external_force() makes stage 1's.
la::Vector stage_force(const Problem& problem, const LoadStage& stage, int number)
{
  const mesh::Mesh& mesh = problem.mesh;
  la::Vector f = la::Vector::Zero(3 * static_cast<la::Index>(mesh.n_nodes()));
  in_stage(number, [&] {
    for (const FaceTraction& t : stage.tractions)
    {
      FETICON_CHECK(!mesh.face_set(t.set).empty() && t.traction.allFinite(),
                    "the traction on '" << t.set << "' is on an empty set or not finite");
      add_face_traction(mesh, mesh.face_set(t.set), t.traction, f);
    }
    for (const FacePressure& p : stage.pressures)
    {
      FETICON_CHECK(!mesh.face_set(p.set).empty() && std::isfinite(p.pressure),
                    "the pressure on '" << p.set << "' is on an empty set or not finite");
      add_face_pressure(mesh, mesh.face_set(p.set), p.pressure, f);
    }
    for (const NodalForce& n : stage.nodal_forces)
    {
      FETICON_CHECK(
          n.node >= 0 && n.node < mesh.n_nodes() && n.component >= 0 && n.component < 3 && std::isfinite(n.value),
          "the nodal force on node " << n.node << ", component " << n.component << " is out of range or not finite");
      f(3 * static_cast<la::Index>(n.node) + n.component) += n.value;
    }
    for (const BodyLoad& b : stage.body_loads)
      add_body_load(mesh, problem.materials, b, f);
  });
  for (int i = 0; i < 3; ++i)
    if (problem.eliminated[i])
      for (int32_t n = 0; n < mesh.n_nodes(); ++n)
        f(3 * static_cast<la::Index>(n) + i) = 0;
  return f;
}

/// A later stage's prescribed DOFs with the eliminated components, as
/// Problem::all_constrained_dofs() makes stage 1's.
ConstrainedDofs stage_dirichlet(const Problem& problem, const LoadStage& stage, int number)
{
  return in_stage(number, [&] {
    for (const DirichletCondition& d : stage.dirichlet)
      for (const std::optional<double>& v : d.value)
        FETICON_CHECK(!v || std::isfinite(*v), "a prescribed value on '" << d.set << "' is not finite");
    const ConstrainedDofs prescribed = collect_dirichlet(problem.mesh, stage.dirichlet);
    std::map<int64_t, double> merged;
    for (size_t k = 0; k < prescribed.dofs.size(); ++k)
      merged[prescribed.dofs[k]] = prescribed.values(static_cast<la::Index>(k));
    for (int i = 0; i < 3; ++i)
      if (problem.eliminated[i])
        for (int32_t n = 0; n < problem.mesh.n_nodes(); ++n)
        {
          auto [it, inserted] = merged.emplace(3 * static_cast<int64_t>(n) + i, 0.0);
          FETICON_CHECK(it->second == 0.0,
                        "node " << n << " prescribes " << it->second << " for component " << i
                                << ", which plane strain fixes to zero");
        }
    return to_constrained_dofs(merged);
  });
}

/// "u_y of node 17 (set 'FIX')": the first of `conditions` that prescribes `dof`.
std::string describe(const mesh::Mesh& mesh, const std::vector<DirichletCondition>& conditions, int64_t dof)
{
  const auto node = static_cast<int32_t>(dof / 3);
  const int component = static_cast<int>(dof % 3);
  std::string set = "?";
  for (const DirichletCondition& d : conditions)
  {
    const auto& nodes = mesh.node_set(d.set);
    if (d.value[component] && std::binary_search(nodes.begin(), nodes.end(), node))
    {
      set = d.set;
      break;
    }
  }
  return std::string("u_") + "xyz"[component] + " of node " + std::to_string(node) + " (set '" + set + "')";
}

/// Throws unless a later stage prescribes exactly stage 1's DOFs, naming the first that differs.
void check_same_dofs(const Problem& problem, const ConstrainedDofs& first, const ConstrainedDofs& later,
                     const LoadStage& stage, int number)
{
  std::vector<int64_t> added, omitted;
  std::set_difference(later.dofs.begin(), later.dofs.end(), first.dofs.begin(), first.dofs.end(),
                      std::back_inserter(added));
  std::set_difference(first.dofs.begin(), first.dofs.end(), later.dofs.begin(), later.dofs.end(),
                      std::back_inserter(omitted));
  FETICON_CHECK(added.empty(),
                "load stage " << number << " prescribes " << describe(problem.mesh, stage.dirichlet, added.front())
                              << ", which stage 1 leaves free: a later stage may change the "
                                 "values of stage 1's prescribed components only");
  FETICON_CHECK(omitted.empty(),
                "load stage " << number << " leaves " << describe(problem.mesh, problem.dirichlet, omitted.front())
                              << " free, which stage 1 prescribes: a later stage may change "
                                 "the values of stage 1's prescribed components only");
}

/// The rule of the file comment at `p`: start null in stage 1 (the unloaded start).
la::Vector blend(const LoadPoint& p, const la::Vector* start, const la::Vector& end)
{
  if (!start)
    return p.fraction * end; // t f, rounded as a one-stage solver rounds it
  // At fraction 1 this is the stage's end exactly (0 * start + 1 * end).
  return (1 - p.fraction) * *start + p.fraction * end;
}
} // namespace

LoadHistory::LoadHistory(const Problem& problem, int first_stage_steps, bool one_step_per_stage)
{
  FETICON_CHECK(first_stage_steps >= 1, "load steps of stage 1: " << first_stage_steps << ", must be >= 1");
  ConstrainedDofs first = problem.all_constrained_dofs();
  std::vector<StageEnd> stages;
  stages.push_back({problem.external_force(), first.values, first_stage_steps});
  for (size_t k = 0; k < problem.later_stages.size(); ++k)
  {
    const LoadStage& stage = problem.later_stages[k];
    const int number = static_cast<int>(k) + 2;
    FETICON_CHECK(stage.increments >= 1,
                  "load stage " << number << " has " << stage.increments << " increments, must be >= 1");
    const ConstrainedDofs later = stage_dirichlet(problem, stage, number);
    check_same_dofs(problem, first, later, stage, number);
    stages.push_back({stage_force(problem, stage, number), later.values, one_step_per_stage ? 1 : stage.increments});
  }
  *this = LoadHistory(std::move(first.dofs), std::move(stages));
}

LoadHistory::LoadHistory(std::vector<int64_t> dofs, std::vector<StageEnd> stages)
    : _dofs(std::move(dofs)), _stages(std::move(stages))
{
  FETICON_CHECK(!_stages.empty(), "a load history needs at least one stage");
  for (size_t s = 0; s < _stages.size(); ++s)
  {
    const StageEnd& end = _stages[s];
    FETICON_CHECK(end.steps >= 1, "load stage " << s + 1 << " has " << end.steps << " load steps, must be >= 1");
    FETICON_CHECK(
        end.force.size() == _stages[0].force.size() && end.values.size() == static_cast<la::Index>(_dofs.size()),
        "load stage " << s + 1 << ": " << end.force.size() << " forces and " << end.values.size()
                      << " prescribed values, expected " << _stages[0].force.size() << " and " << _dofs.size());
    _last_step.push_back((s == 0 ? 0 : _last_step.back()) + end.steps);
    _force_norm.push_back(end.force.norm());
    // As a one-stage run's t = n / N, so that stage 1 reproduces its numbers exactly.
    std::vector<double>& fractions = _fractions.emplace_back();
    for (int j = 1; j <= end.steps; ++j)
      fractions.push_back(static_cast<double>(j) / end.steps);
  }
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
  return {stage + 1, fraction, stage == 0 ? fraction : stage + fraction};
}

void LoadHistory::follow(const std::vector<double>& load_factors)
{
  for (int i = 1; i <= static_cast<int>(load_factors.size()); ++i)
    for (int cuts = 0; cuts < 64 && i <= n_steps() && load_factor(i) > load_factors[i - 1] + 1e-12 * i; ++cuts)
      split(i);
}

void LoadHistory::split(int step)
{
  const LoadPoint p = point(step);
  std::vector<double>& fractions = _fractions[p.stage - 1];
  const int j = step - last_step(p.stage - 1) - 1;
  const double before = j == 0 ? 0.0 : fractions[j - 1];
  fractions.insert(fractions.begin() + j, 0.5 * (before + fractions[j]));
  for (size_t s = p.stage - 1; s < _last_step.size(); ++s)
    ++_last_step[s];
}

const StageEnd& LoadHistory::stage_end(int stage) const
{
  FETICON_CHECK(stage >= 1 && stage <= n_stages(), "load stage " << stage << " of " << n_stages());
  return _stages[stage - 1];
}

la::Vector LoadHistory::interpolate(int step, const std::vector<la::Vector>& ends) const
{
  FETICON_CHECK(static_cast<int>(ends.size()) == n_stages(),
                "a quantity at " << ends.size() << " stage ends for a history of " << n_stages() << " stages");
  const LoadPoint p = point(step);
  return blend(p, p.stage == 1 ? nullptr : &ends[p.stage - 2], ends[p.stage - 1]);
}

la::Vector LoadHistory::external_force(int step) const
{
  const LoadPoint p = point(step);
  return blend(p, p.stage == 1 ? nullptr : &_stages[p.stage - 2].force, _stages[p.stage - 1].force);
}

double LoadHistory::external_force_norm(int step) const
{
  const LoadPoint p = point(step);
  if (p.stage == 1)
    return p.fraction * _force_norm[0]; // as a one-stage solver scales ||f||
  return external_force(step).norm();
}

la::Vector LoadHistory::prescribed_values(int step) const
{
  const LoadPoint p = point(step);
  return blend(p, p.stage == 1 ? nullptr : &_stages[p.stage - 2].values, _stages[p.stage - 1].values);
}

ConstrainedDofs LoadHistory::prescribed(int step) const { return {_dofs, prescribed_values(step)}; }
} // namespace feticon::fem
