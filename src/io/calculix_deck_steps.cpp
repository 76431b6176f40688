#include "io/calculix_deck_writer.hpp"

#include "fem/load_history.hpp"

#include <algorithm>
#include <cmath>
#include <map>
#include <tuple>

namespace feticon::io::deck_writer
{
namespace
{
/// The AMPLITUDE= parameter of loads that follow amplitude `name` (none for "": the step's ramp).
std::string amplitude_parameter(const std::string& name)
{
  return name.empty() ? std::string() : ", AMPLITUDE=" + deck_name("A_", name);
}

/// The groups of a step's loads and supports: "" (those without amplitude) first, then each
/// amplitude the step names.
std::vector<std::string> amplitude_groups(const fem::Step& step)
{
  std::vector<std::string> groups{""};
  for (const std::string& name : fem::amplitudes_of(step))
    groups.push_back(name);
  return groups;
}

/// *STEP (AMPLITUDE=STEP where the step's loads take their values at once) and *STATIC of
/// `step` in its time (the amplitudes run on it): its automatic increments, or its fixed ones
/// (the step's own, else `options`') as automatic ones whose maximum is the initial (CalculiX
/// may cut them back, as feticon does, but not grow them).
void write_step_start(std::ostream& out, const fem::Step& step, const CalculixOptions& options)
{
  // INC=: the step's own count for automatic increments; for fixed ones room for cutbacks (twice
  // the count, at least CalculiX's default 100), not so much that a failing model creeps on.
  const bool automatic = step.automatic && !step.increments;
  const int fixed = step.increments.value_or(options.increments);
  out << "*STEP" << (options.nlgeom ? ", NLGEOM" : "") << (step.ramp ? "" : ", AMPLITUDE=STEP")
      << ", INC=" << (automatic ? step.automatic->max_increments : std::max(100, 2 * fixed)) << "\n*STATIC\n";
  if (automatic)
  {
    const fem::IncrementControl& a = *step.automatic;
    out << number(a.initial) << ", " << number(step.time) << ", " << number(a.minimum) << ", " << number(a.maximum)
        << '\n';
    return;
  }
  const double increment = step.time / fixed;
  out << number(increment) << ", " << number(step.time) << ", " << number(increment * 1e-5) << ", " << number(increment)
      << '\n';
}

/// The nodal forces of step `step`'s (0-based) loads, one vector per amplitude group
/// (amplitude_groups), the loads on reference nodes left out (write_cloads writes them).
/// @throws feticon::Error for a node direction loaded in two groups in one step, which a deck
///         cannot say (CalculiX's forcadd.f: one amplitude per node and direction in a step), or
///         loaded with an amplitude in one step and without in the next (or the reverse), whose
///         ramp CalculiX starts from the old value and feticon from the loads without amplitude
///         (the deck reader refuses it too)
std::vector<la::Vector> group_forces(const fem::Problem& problem, size_t step)
{
  const auto forces_of = [&](size_t k) {
    std::vector<la::Vector> out;
    for (const std::string& group : amplitude_groups(problem.steps[k]))
      out.push_back(problem.external_force(k, group, false));
    return out;
  };
  const std::vector<la::Vector> now = forces_of(step);
  const auto group_at = [](const std::vector<la::Vector>& forces, la::Index i, size_t k) {
    int found = -1;
    for (size_t g = 0; g < forces.size(); ++g)
      if (forces[g](i) != 0)
      {
        FETICON_CHECK(found < 0,
                      "calculix export: step "
                          << k + 1 << ": node " << i / 3 + 1 << ", direction " << i % 3 + 1
                          << " is loaded by loads of two amplitudes (or with and without one), which a deck's *CLOAD "
                             "cannot say (CalculiX: one amplitude per node and direction in a step)");
        found = static_cast<int>(g);
      }
    return found;
  };
  const std::vector<la::Vector> before = step > 0 ? forces_of(step - 1) : std::vector<la::Vector>{};
  for (la::Index i = 0; i < now.front().size(); ++i)
  {
    const int g = group_at(now, i, step);
    const int g_before = before.empty() ? -1 : group_at(before, i, step - 1);
    FETICON_CHECK(g < 0 || g_before < 0 || (g == 0) == (g_before == 0),
                  "calculix export: step " << step + 1 << ": node " << i / 3 + 1 << ", direction " << i % 3 + 1
                                           << " is loaded " << (g == 0 ? "without" : "with") << " amplitude, in step "
                                           << step << " " << (g_before == 0 ? "without" : "with")
                                           << ": CalculiX ramps it from its last value there, feticon from the loads "
                                              "without amplitude");
  }
  return now;
}

/// The *CLOAD blocks of step `step` (0-based): its loads without amplitude (OP=NEW after the
/// first step: the whole external force, reached linearly in the step's increments), then a
/// block per amplitude; the loads on reference nodes on them (write_couplings), the others as
/// their nodal forces (3 per node, global components; a node with a frame in its local ones,
/// write_frames); their totals counted in `summary`.
void write_cloads(std::ostream& out, const fem::Problem& problem, size_t step, const DeckNodes& nodes,
                  CalculixDeckSummary& summary)
{
  const fem::Step& s = problem.steps[step];
  const std::vector<std::string> groups = amplitude_groups(s);
  const std::vector<la::Vector> forces = group_forces(problem, step);
  for (size_t g = 0; g < groups.size(); ++g)
  {
    const bool on_reference = std::ranges::any_of(
        s.reference_loads, [&](const fem::ReferenceValue& load) { return load.amplitude == groups[g]; });
    if (g > 0 && !on_reference && forces[g].isZero(0))
      continue;
    out << "*CLOAD" << (g == 0 ? (step == 0 ? "" : ", OP=NEW") : amplitude_parameter(groups[g])) << '\n';
    for (const fem::ReferenceValue& load : s.reference_loads)
    {
      if (load.amplitude != groups[g])
        continue;
      out << problem.mesh.n_nodes() + load.coupling + 1 << ", " << load.dof + 1 << ", " << number(load.value) << '\n';
      if (load.dof < 3)
        summary.total_load[load.dof] += load.value;
      ++summary.n_cloads;
    }
    for (int32_t n = 0; n < problem.mesh.n_nodes(); ++n)
    {
      const Eigen::Vector3d global = forces[g].segment<3>(3 * la::Index{n});
      const int32_t k = problem.frames.index_of(n);
      const Eigen::Vector3d given =
          k < 0 ? global : Eigen::Vector3d(problem.frames.axes[static_cast<size_t>(k)] * global);
      for (int i = 0; i < 3; ++i)
      {
        summary.total_load[i] += global(i);
        if (given(i) == 0)
          continue;
        out << nodes.label(n, "a load") << ", " << i + 1 << ", " << number(given(i)) << '\n';
        ++summary.n_cloads;
      }
    }
  }
}

/// The changes of step `step` (0-based) to the contact pairs: *MODEL CHANGE, TYPE=CONTACT PAIR,
/// REMOVE or ADD where a pair leaves or comes back into force (fem::Step::removed_contacts),
/// *CHANGE SURFACE BEHAVIOR where its law changes or it turns from tied to contact or back, and
/// *CHANGE FRICTION with its *FRICTION where a pair's mu changes (CalculixOptions::friction).
void write_model_changes(std::ostream& out, const fem::Problem& problem, const CalculixOptions& options,
                         const std::vector<ContactPairFaces>& pairs, size_t step)
{
  // A pair out of force where it is tied is the same pair in the deck (its surface behavior
  // TIED, below).
  const auto in_force = [&](size_t k, int32_t p) {
    return std::ranges::find(problem.steps[k].removed_contacts, p) == problem.steps[k].removed_contacts.end() ||
        tied_in_step(problem, p, k);
  };
  for (const bool add : {false, true})
  {
    std::vector<int32_t> changed;
    for (int32_t p = 0; p < std::ssize(problem.contacts); ++p)
      if (in_force(step, p) == add && (step == 0 ? !add : in_force(step - 1, p) != add))
        changed.push_back(p);
    if (changed.empty())
      continue;
    out << "*MODEL CHANGE, TYPE=CONTACT PAIR, " << (add ? "ADD" : "REMOVE") << '\n';
    for (const int32_t p : changed)
      out << deck_name("S_", problem.contacts[p].slave) << ", " << deck_name("S_", problem.contacts[p].master) << '\n';
  }
  if (step == 0)
    return;
  for (int32_t p = 0; p < std::ssize(problem.contacts); ++p)
  {
    const bool tied = tied_in_step(problem, p, step);
    const fem::NormalLaw law = law_in_step(problem, p, step);
    if (tied == tied_in_step(problem, p, step - 1) && (tied || law == law_in_step(problem, p, step - 1)))
      continue;
    out << "*CHANGE SURFACE BEHAVIOR, INTERACTION=SI_" << p + 1 << '\n';
    write_surface_behavior(out, law, tied, pairs[p],
                           static_cast<size_t>(p) < options.node_to_segment.size() && options.node_to_segment[p]);
  }
  for (size_t p = 0; p < problem.contacts.size(); ++p)
  {
    const double mu = friction_of(options, step, p);
    if (mu == friction_of(options, step - 1, p))
      continue;
    FETICON_CHECK(mu > 0,
                  "calculix export: step " << step + 1 << " takes the friction of contact pair "
                                           << problem.contacts[p].slave << " / " << problem.contacts[p].master
                                           << " away, which CalculiX cannot say (its *FRICTION asks mu > 0)");
    out << "*CHANGE FRICTION, INTERACTION=SI_" << p + 1 << "\n*FRICTION\n"
        << number(mu) << ", "
        << number(normal_slope(problem.contacts[p].interaction.law, pairs[p]) / options.stick_slope_ratio) << '\n';
  }
}

/// The deck's node, component and value of held DOF `dof` = `value`: a node with a frame is
/// held in its local components (write_frames), whether the history numbers the DOF as local or,
/// along an axis that is a global one, as global (fem::NodeFrames::held); a coupling's reference
/// DOF is its reference node's (write_couplings), component 0-5.
std::tuple<int32_t, int, double> deck_dof(const fem::Problem& problem, int64_t dof, double value)
{
  const int32_t n_nodes = problem.mesh.n_nodes();
  if (!problem.couplings.empty() && dof >= problem.reference_dof(0, 0)) // a reference node's DOF 1-6
  {
    const int64_t k = dof - problem.reference_dof(0, 0);
    return {n_nodes + static_cast<int32_t>(k / 6), static_cast<int>(k % 6), value};
  }
  if (fem::NodeFrames::is_local(n_nodes, dof))
    return {problem.frames.node_of(n_nodes, dof), static_cast<int>(dof % 3), value};
  const auto node = static_cast<int32_t>(dof / 3);
  const int g = static_cast<int>(dof % 3);
  if (const int32_t k = problem.frames.index_of(node); k >= 0)
    for (int c = 0; c < 3; ++c)
      if (const double e = problem.frames.axes[static_cast<size_t>(k)](c, g); std::abs(std::abs(e) - 1) < 1e-14)
        return {node, c, e > 0 ? value : -value};
  return {node, g, value};
}
} // namespace

/// A step's *TEMPERATURE, OP=NEW (the nodes it does not name go back to T_0, as in
/// fem::TemperatureHistory), then a *TEMPERATURE, AMPLITUDE= per amplitude; nothing for a
/// problem without temperatures.
void write_temperatures(std::ostream& out, const fem::Problem& problem, const fem::Step& step, const DeckNodes& nodes)
{
  if (!problem.has_temperatures())
    return;
  // A doubled node takes its original's temperature when CalculiX doubles it again.
  std::map<int32_t, std::pair<double, std::string>> given;
  for (const fem::NodalTemperature& t : step.temperatures)
    given[t.node] = {t.value, t.amplitude};
  const auto as_original = [&](const fem::NodalTemperature& t) {
    const auto original = given.find(nodes.original(t.node));
    return nodes.doubled(t.node) && original != given.end() && original->second == given[t.node];
  };
  for (const std::string& group : amplitude_groups(step))
  {
    const bool any =
        std::ranges::any_of(step.temperatures, [&](const fem::NodalTemperature& t) { return t.amplitude == group; });
    if (!group.empty() && !any)
      continue;
    out << "*TEMPERATURE" << (group.empty() ? ", OP=NEW" : amplitude_parameter(group)) << '\n';
    for (const fem::NodalTemperature& t : step.temperatures)
      if (t.amplitude == group && !as_original(t))
        out << nodes.label(t.node, "a temperature") << ", " << number(t.value) << '\n';
  }
}

/// The first *STEP with its increments (write_step_start), *BOUNDARY (supports, plane strain;
/// a block per amplitude) and *CLOAD (write_cloads).
void write_step(std::ostream& out, const fem::Problem& problem, const CalculixOptions& options,
                const std::vector<ContactPairFaces>& pairs, const DeckNodes& nodes, CalculixDeckSummary& summary)
{
  const mesh::Mesh& mesh = problem.mesh;
  const fem::Step& step = problem.steps.front();
  write_step_start(out, step, options);
  write_model_changes(out, problem, options, pairs, 0);
  for (const std::string& group : amplitude_groups(step))
  {
    const bool any =
        std::ranges::any_of(step.dirichlet, [&](const fem::DirichletCondition& d) { return d.amplitude == group; }) ||
        std::ranges::any_of(step.reference_supports,
                            [&](const fem::ReferenceValue& r) { return r.amplitude == group; });
    if (!group.empty() && !any)
      continue;
    out << "*BOUNDARY" << amplitude_parameter(group) << '\n';
    for (const fem::DirichletCondition& d : step.dirichlet)
      for (int i = 0; i < 3; ++i)
        if (d.value[i] && d.amplitude == group)
          out << deck_name("N_", d.set) << ", " << i + 1 << ", " << i + 1 << ", " << number(*d.value[i]) << '\n';
    // A hex layer's eliminated u_z is a support in the deck (2D cells have no u_z).
    for (int i = 0; i < 3; ++i)
      if (group.empty() && problem.eliminated[i] && mesh.planar.kind == mesh::PlanarKind::none)
        out << "NALL, " << i + 1 << ", " << i + 1 << ", 0.0\n";
    for (const fem::ReferenceValue& r : step.reference_supports)
      if (r.amplitude == group)
        out << mesh.n_nodes() + r.coupling + 1 << ", " << r.dof + 1 << ", " << r.dof + 1 << ", " << number(r.value)
            << '\n';
  }
  write_cloads(out, problem, 0, nodes, summary);
}

/// A later load stage as the next *STEP: its supports (write_later_supports) and the stage's
/// whole external force (write_cloads; *CLOAD, OP=NEW drops the last step's loads), reached
/// linearly in its increments, as feticon's load history runs from one stage's end to the next.
void write_later_step(std::ostream& out, const fem::Problem& problem, const fem::LoadHistory& history, int stage,
                      const CalculixOptions& options, const std::vector<ContactPairFaces>& pairs,
                      const DeckNodes& nodes, CalculixDeckSummary& summary)
{
  const auto k = static_cast<size_t>(stage - 1);
  write_step_start(out, problem.steps[k], options);
  write_model_changes(out, problem, options, pairs, k);
  // The same held DOFs and no amplitude in this step or the one before: the values that
  // changed (*BOUNDARY keeps the others). Otherwise all of them anew, a block per amplitude (a
  // DOF held from here on without amplitude ramps from its displacement in both codes).
  const std::vector<int64_t> held = history.held_dofs(stage);
  const std::vector<std::string> groups = amplitude_groups(problem.steps[k]);
  const bool same =
      held == history.held_dofs(stage - 1) && groups.size() == 1 && amplitude_groups(problem.steps[k - 1]).size() == 1;
  std::vector<la::Vector> values;
  for (const std::string& group : groups)
    values.push_back(history.values_of(problem.all_constrained_dofs(k, group)));
  const la::Vector values_before = history.prescribed_values(history.last_step(stage - 1));
  // The group of each DOF: the amplitude whose value it has (a DOF at 0 goes without one).
  std::vector<size_t> group_of(history.dofs().size(), 0);
  for (size_t g = 1; g < groups.size(); ++g)
    for (size_t i = 0; i < group_of.size(); ++i)
      if (values[g](static_cast<la::Index>(i)) != 0)
        group_of[i] = g;
  for (size_t g = 0; g < groups.size(); ++g)
  {
    if (g > 0 && std::ranges::find(group_of, g) == group_of.end())
      continue;
    out << "*BOUNDARY" << (g == 0 && !same ? ", OP=NEW" : amplitude_parameter(groups[g])) << '\n';
    for (size_t i = 0; i < history.dofs().size(); ++i)
    {
      const int64_t dof = history.dofs()[i];
      const double value = values[g](static_cast<la::Index>(i));
      const bool write = same ? value != values_before(static_cast<la::Index>(i))
                              : group_of[i] == g && std::binary_search(held.begin(), held.end(), dof);
      if (!write)
        continue;
      const auto [node, component, deck_value] = deck_dof(problem, dof, value);
      out << (node < problem.mesh.n_nodes() ? nodes.label(node, "a support") : node + int64_t{1}) << ", "
          << component + 1 << ", " << component + 1 << ", " << number(deck_value) << '\n';
    }
  }
  std::fill(std::begin(summary.total_load), std::end(summary.total_load), 0.0);
  write_cloads(out, problem, k, nodes, summary);
}
} // namespace feticon::io::deck_writer
