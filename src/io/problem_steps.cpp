#include "io/problem_steps.hpp"

#include "io/problem_couplings.hpp"

#include <algorithm>
#include <cmath>
#include <map>

namespace feticon::io
{
namespace
{
/// An amplitude: a table [[t, a], ...] or {points: [[t, a], ...], time: step | total,
/// shift_x, shift_y}.
fem::Amplitude amplitude(const YAML::Node& node, const std::string& key, const ProblemReader& r)
{
  fem::Amplitude a;
  a.where = r.source + ": " + key;
  // Not `table = node["points"]` on a copy of `node`: yaml-cpp's assignment writes through to
  // the node it refers to, which then lost its time and shifts.
  const YAML::Node table = node.IsMap() ? node["points"] : node;
  if (node.IsMap())
  {
    r.only_keys(node, key, {"points", "time", "shift_x", "shift_y"});
    if (node["time"])
    {
      const std::string time = r.text(node["time"], key + ".time");
      FETICON_CHECK(time == "step" || time == "total", r.source << ": " << key << ".time must be step or total");
      a.total_time = time == "total";
    }
    if (node["shift_x"])
      a.shift_x = r.number(node["shift_x"], key + ".shift_x");
    if (node["shift_y"])
      a.shift_y = r.number(node["shift_y"], key + ".shift_y");
  }
  FETICON_CHECK(table && table.IsSequence(),
                r.source << ": " << key << " must be a list of [time, value] pairs, e.g. [[0, 0], [1, 1]]");
  for (size_t i = 0; i < table.size(); ++i)
  {
    const std::string at = key + "[" + std::to_string(i) + "]";
    FETICON_CHECK(table[i].IsSequence() && table[i].size() == 2, r.source << ": " << at << " must be [time, value]");
    a.points.emplace_back(r.number(table[i][0], at + "[0]"), r.number(table[i][1], at + "[1]"));
  }
  a.check();
  return a;
}

} // namespace

std::string amplitude_of(const YAML::Node& entry, const std::string& key, const ProblemReader& r, fem::Problem& p)
{
  const YAML::Node a = entry["amplitude"];
  if (!a)
    return {};
  if (a.IsScalar())
  {
    const std::string name = a.as<std::string>();
    FETICON_CHECK(p.amplitudes.count(name),
                  r.source << ": " << key << ".amplitude: no amplitude '" << name
                           << "' in amplitudes; it has: " << names_of(p.amplitudes));
    return name;
  }
  p.amplitudes[key] = amplitude(a, key + ".amplitude", r);
  return key;
}

namespace
{
/// The index of the body an entry's `body:` names.
int32_t body_of(const YAML::Node& entry, const std::string& key, const ProblemReader& r, const mesh::Mesh& mesh)
{
  const std::string body = r.text(entry["body"], key + ".body");
  const auto it = std::find(mesh.body_names.begin(), mesh.body_names.end(), body);
  FETICON_CHECK(it != mesh.body_names.end(), r.source << ": " << key << ".body: the mesh has no body '" << body << "'");
  return static_cast<int32_t>(it - mesh.body_names.begin());
}

fem::BodyLoad body_load(const YAML::Node& load, const std::string& key, const mesh::Mesh& mesh, const ProblemReader& r)
{
  r.only_keys(load, key, {"gravity", "centrifugal", "body"});
  FETICON_CHECK(!(load["gravity"] && load["centrifugal"]),
                r.source << ": " << key << ": gravity or centrifugal, not both");
  fem::BodyLoad out;
  out.where = r.source + ": " + key;
  if (load["gravity"])
    out.gravity = r.vector3(load["gravity"], key + ".gravity");
  else
  {
    const YAML::Node c = load["centrifugal"];
    r.only_keys(c, key + ".centrifugal", {"omega", "point", "axis"});
    out.kind = fem::BodyLoad::Kind::centrifugal;
    const double omega = r.number(c["omega"], key + ".centrifugal.omega");
    out.omega2 = omega * omega;
    out.point = r.vector3(c["point"], key + ".centrifugal.point");
    out.axis = r.vector3(c["axis"], key + ".centrifugal.axis");
  }
  if (load["body"])
  {
    const int32_t index = body_of(load, key, r, mesh);
    for (size_t c = 0; c < mesh.cells.size(); ++c)
      if (mesh.cell_body[c] == index)
        out.cells.push_back(static_cast<int32_t>(c));
  }
  return out;
}

/// The problem file's `contact` list: each pair's face sets, friction and formulation.
std::vector<fem::DirichletCondition> supports(const YAML::Node& list, const std::string& where, const ProblemReader& r,
                                              fem::Problem& p)
{
  FETICON_CHECK(list.IsSequence(), r.source << ": " << where << " must be a list");
  std::vector<fem::DirichletCondition> out;
  for (size_t i = 0; i < list.size(); ++i)
  {
    const YAML::Node s = list[i];
    if (s.IsMap() && s["coupling"])
      continue; // a reference node's (problem_couplings.hpp)
    const std::string key = where + "." + std::to_string(i);
    r.only_keys(s, key, {"set", "x", "y", "z", "amplitude"});
    fem::DirichletCondition c{r.text(s["set"], key + ".set"), {}};
    const char* names[3] = {"x", "y", "z"};
    for (int d = 0; d < 3; ++d)
      if (s[names[d]])
        c.value[d] = r.number(s[names[d]], key + "." + names[d]);
    FETICON_CHECK(c.value[0] || c.value[1] || c.value[2],
                  r.source << ": " << key << " prescribes no component (x, y or z)");
    FETICON_CHECK(p.mesh.node_sets.count(c.set),
                  r.source << ": " << key << ".set: no node set '" << c.set
                           << "' in the mesh; it has: " << names_of(p.mesh.node_sets));
    c.amplitude = amplitude_of(s, key, r, p);
    out.push_back(c);
  }
  return out;
}

/// The nodes a temperature entry names: its node `set`, the nodes of its `body`, or every node.
std::vector<int32_t> temperature_nodes(const YAML::Node& t, const std::string& key, const ProblemReader& r,
                                       const mesh::Mesh& mesh)
{
  FETICON_CHECK(!(t["set"] && t["body"]), r.source << ": " << key << ": set or body, not both");
  if (t["set"])
  {
    const std::string set = r.text(t["set"], key + ".set");
    FETICON_CHECK(mesh.node_sets.count(set),
                  r.source << ": " << key << ".set: no node set '" << set
                           << "' in the mesh; it has: " << names_of(mesh.node_sets));
    return mesh.node_sets.at(set);
  }
  std::vector<char> named(static_cast<size_t>(mesh.n_nodes()), t["body"] ? 0 : 1);
  if (t["body"])
  {
    const int32_t index = body_of(t, key, r, mesh);
    for (int32_t c = 0; c < mesh.n_cells(); ++c)
      if (mesh.cell_body[c] == index)
        for (const int32_t n : mesh.cells[c])
          named[n] = 1;
  }
  std::vector<int32_t> nodes;
  for (int32_t n = 0; n < mesh.n_nodes(); ++n)
    if (named[n])
      nodes.push_back(n);
  return nodes;
}

/// `temperatures:` [{set | body, value, amplitude}, ...] (neither set nor body: every node): the
/// nodes' temperatures in the step (a node named twice takes the later entry's).
std::vector<fem::NodalTemperature> temperatures(const YAML::Node& list, const std::string& where,
                                                const ProblemReader& r, fem::Problem& p)
{
  FETICON_CHECK(list.IsSequence(), r.source << ": " << where << " must be a list of {set or body, value}");
  std::map<int32_t, fem::NodalTemperature> by_node;
  for (size_t i = 0; i < list.size(); ++i)
  {
    const YAML::Node t = list[i];
    const std::string key = where + "." + std::to_string(i);
    r.only_keys(t, key, {"set", "body", "value", "amplitude"});
    const double value = r.number(t["value"], key + ".value");
    fem::check_temperature(value, r.source + ": " + key + ".value");
    const std::string amplitude = amplitude_of(t, key, r, p);
    for (const int32_t n : temperature_nodes(t, key, r, p.mesh))
      by_node[n] = {n, value, amplitude};
  }
  std::vector<fem::NodalTemperature> out;
  for (const auto& [node, t] : by_node)
    out.push_back(t);
  return out;
}

/// `initial_temperature:` one value for every node, or [{set or body, value}, ...] over 0 elsewhere.
void initial_temperatures(const YAML::Node& node, const ProblemReader& r, fem::Problem& p)
{
  if (node.IsScalar())
  {
    const double value = r.number(node, "initial_temperature");
    fem::check_temperature(value, r.source + ": initial_temperature");
    p.initial_temperatures.assign(p.mesh.n_nodes(), value);
    return;
  }
  FETICON_CHECK(node.IsSequence(), r.source << ": initial_temperature must be a number or a list of {set, value}");
  p.initial_temperatures.assign(p.mesh.n_nodes(), 0.0);
  for (const fem::NodalTemperature& t : temperatures(node, "initial_temperature", r, p))
  {
    FETICON_CHECK(t.amplitude.empty(), r.source << ": initial_temperature takes no amplitude");
    p.initial_temperatures[t.node] = t.value;
  }
}

/// A step's loads: tractions and body loads (its other load kinds are cleared).
void loads(const YAML::Node& list, const std::string& where, const ProblemReader& r, fem::Problem& p, fem::Step& step)
{
  FETICON_CHECK(list.IsSequence(), r.source << ": " << where << " must be a list");
  step.tractions.clear();
  step.pressures.clear();
  step.nodal_forces.clear();
  step.body_loads.clear();
  for (size_t i = 0; i < list.size(); ++i)
  {
    const YAML::Node l = list[i];
    const std::string key = where + "." + std::to_string(i);
    if (l.IsMap() && l["coupling"])
      continue; // a reference node's (problem_couplings.hpp)
    if (l.IsMap() && (l["gravity"] || l["centrifugal"]))
    {
      YAML::Node body = YAML::Clone(l);
      body.remove("amplitude");
      step.body_loads.push_back(body_load(body, key, p.mesh, r));
      step.body_loads.back().amplitude = amplitude_of(l, key, r, p);
      continue;
    }
    r.only_keys(l, key, {"set", "traction", "amplitude"});
    const std::string set = r.text(l["set"], key + ".set");
    FETICON_CHECK(p.mesh.face_sets.count(set),
                  r.source << ": " << key << ".set: no face set '" << set
                           << "' in the mesh; it has: " << names_of(p.mesh.face_sets));
    step.tractions.push_back({set, r.vector3(l["traction"], key + ".traction"), amplitude_of(l, key, r, p)});
  }
  step.reference_loads = coupling_loads(list, where, r, p);
}

/// A step's `increment: {initial, minimum, maximum}` (in its time; the minimum defaults to the
/// initial or 1e-5 of the step time, whichever is smaller, the maximum to the step time, as a
/// deck's *STATIC).
fem::IncrementControl increment_control(const YAML::Node& node, const std::string& key, const ProblemReader& r,
                                        double time)
{
  FETICON_CHECK(node.IsMap() && node["initial"],
                r.source << ": " << key << " must be a map {initial: DT, minimum: DT, maximum: DT, max_increments: N}");
  r.only_keys(node, key, {"initial", "minimum", "maximum", "max_increments"});
  fem::IncrementControl c;
  c.initial = r.number(node["initial"], key + ".initial");
  c.minimum = node["minimum"] ? r.number(node["minimum"], key + ".minimum") : std::min(c.initial, 1e-5 * time);
  c.maximum = node["maximum"] ? r.number(node["maximum"], key + ".maximum") : time;
  if (node["max_increments"])
  {
    const double n = r.number(node["max_increments"], key + ".max_increments");
    FETICON_CHECK(n >= 1 && n <= 1e9 && n == std::floor(n),
                  r.source << ": " << key << ".max_increments = " << n << " must be a whole number >= 1");
    c.max_increments = static_cast<int>(n);
  }
  FETICON_CHECK(c.minimum > 0 && c.minimum <= c.initial && c.initial <= c.maximum && c.initial <= time,
                r.source << ": " << key
                         << " needs 0 < minimum <= initial <= maximum and initial <= the step's time, given "
                         << c.minimum << ", " << c.initial << ", " << c.maximum << " (time " << time << ")");
  return c;
}

/// A step's `contact:` list, each entry {pair: I, friction: {...}, in_force: true|false} on pair
/// I of the top-level `contact:` list: its friction from this step on (a deck's *CHANGE
/// FRICTION), and whether it is in force (*MODEL CHANGE, REMOVE / ADD), over what `step` holds.
void contact_changes(const YAML::Node& list, const std::string& key, const ProblemReader& r, size_t n_pairs,
                     fem::Step& step)
{
  FETICON_CHECK(list.IsSequence(), r.source << ": " << key << " must be a list of {pair, friction, in_force}");
  for (size_t i = 0; i < list.size(); ++i)
  {
    const YAML::Node entry = list[i];
    const std::string at = key + "." + std::to_string(i);
    r.only_keys(entry, at, {"pair", "friction", "in_force"});
    FETICON_CHECK(entry["pair"], r.source << ": " << at << " needs pair (an index into the contact list)");
    const double number = r.number(entry["pair"], at + ".pair");
    FETICON_CHECK(number >= 0 && number < static_cast<double>(n_pairs) && number == std::floor(number),
                  r.source << ": " << at << ".pair = " << number << " is not an index into the contact list ("
                           << n_pairs << " pairs)");
    const auto pair = static_cast<int32_t>(number);
    if (entry["friction"])
    {
      std::erase_if(step.changed_friction, [&](const auto& change) { return change.first == pair; });
      step.changed_friction.emplace_back(pair, pair_friction(entry, at + ".friction", r));
      std::sort(step.changed_friction.begin(), step.changed_friction.end(),
                [](const auto& a, const auto& b) { return a.first < b.first; });
    }
    if (entry["in_force"])
    {
      const std::string in_force = r.text(entry["in_force"], at + ".in_force");
      FETICON_CHECK(in_force == "true" || in_force == "false",
                    r.source << ": " << at << ".in_force must be true or false");
      std::erase(step.removed_contacts, pair);
      if (in_force == "false")
        step.removed_contacts.insert(std::lower_bound(step.removed_contacts.begin(), step.removed_contacts.end(), pair),
                                     pair);
    }
  }
}

/// One entry of `steps:` over `step`, which holds the step before (what the entry does not give
/// carries over, as in CalculiX's steps).
void step_entry(const YAML::Node& entry, const std::string& key, const ProblemReader& r, fem::Problem& p,
                size_t n_pairs, fem::Step& step)
{
  r.only_keys(entry, key, {"supports", "loads", "temperatures", "increments", "increment", "time", "ramp", "contact"});
  if (entry["contact"])
    contact_changes(entry["contact"], key + ".contact", r, n_pairs, step);
  if (entry["supports"])
  {
    step.dirichlet = supports(entry["supports"], key + ".supports", r, p);
    step.reference_supports = coupling_supports(entry["supports"], key + ".supports", r, p);
  }
  if (entry["temperatures"])
    step.temperatures = temperatures(entry["temperatures"], key + ".temperatures", r, p);
  if (entry["loads"])
    loads(entry["loads"], key + ".loads", r, p, step);
  step.increments.reset();
  if (entry["increments"])
  {
    const double n = r.number(entry["increments"], key + ".increments");
    FETICON_CHECK(n >= 1 && n <= 100000 && n == std::floor(n),
                  r.source << ": " << key << ".increments = " << n << " must be an integer in 1 .. 100000");
    step.increments = static_cast<int>(n);
  }
  step.time = entry["time"] ? r.number(entry["time"], key + ".time") : 1.0;
  FETICON_CHECK(step.time > 0, r.source << ": " << key << ".time = " << step.time << " must be positive");
  step.automatic.reset();
  if (entry["increment"])
  {
    FETICON_CHECK(!step.increments,
                  r.source << ": " << key << " gives both increments (fixed) and increment (automatic)");
    step.automatic = increment_control(entry["increment"], key + ".increment", r, step.time);
  }
  step.ramp = true;
  if (entry["ramp"])
  {
    const std::string ramp = r.text(entry["ramp"], key + ".ramp");
    FETICON_CHECK(ramp == "true" || ramp == "false", r.source << ": " << key << ".ramp must be true or false");
    step.ramp = ramp == "true";
  }
}
} // namespace

/// The friction of a contact pair of the problem file, `friction: {model: coulomb, coefficient:
/// 0.3}` (or tresca with slip_bound, or none); none if it has none.
fem::Friction pair_friction(const YAML::Node& pair, const std::string& key, const ProblemReader& r)
{
  fem::Friction out;
  if (!pair.IsMap() || !pair["friction"])
    return out;
  const YAML::Node friction = pair["friction"];
  r.only_keys(friction, key, {"model", "coefficient", "slip_bound"});
  const std::string model = r.text(friction["model"], key + ".model");
  FETICON_CHECK(model == "none" || model == "coulomb" || model == "tresca",
                r.source << ": " << key << ".model = '" << model << "' must be one of: none, tresca, coulomb");
  const std::map<std::string, std::string> needs = {{"coulomb", "coefficient"}, {"tresca", "slip_bound"}};
  for (const char* number : {"coefficient", "slip_bound"})
  {
    const auto need = needs.find(model);
    const bool wanted = need != needs.end() && need->second == number;
    FETICON_CHECK(!friction[number] || wanted,
                  r.source << ": " << key << "." << number << " does not belong to model " << model
                           << " (coulomb takes coefficient, tresca slip_bound, none neither)");
    FETICON_CHECK(friction[number] || !wanted, r.source << ": " << key << " (model " << model << ") needs " << number);
  }
  out.model = model == "coulomb" ? fem::FrictionModel::coulomb
      : model == "tresca"        ? fem::FrictionModel::tresca
                                 : fem::FrictionModel::none;
  if (friction["coefficient"])
    out.coefficient = r.number(friction["coefficient"], key + ".coefficient");
  if (friction["slip_bound"])
    out.slip_bound = r.number(friction["slip_bound"], key + ".slip_bound");
  FETICON_CHECK(out.coefficient >= 0 && out.coefficient <= 100 && out.slip_bound >= 0 && std::isfinite(out.slip_bound),
                r.source << ": " << key << ": coefficient must be in [0, 100] and slip_bound a finite value >= 0");
  return out;
}

void read_steps(const YAML::Node& root, const ProblemReader& r, fem::Problem& p)
{
  if (const YAML::Node amplitudes = root["amplitudes"])
  {
    FETICON_CHECK(amplitudes.IsMap(), r.source << ": amplitudes must be a map of names to [[t, a], ...] tables");
    for (const auto& kv : amplitudes)
    {
      const std::string name = kv.first.as<std::string>();
      p.amplitudes[name] = amplitude(kv.second, "amplitudes." + name, r);
    }
  }
  if (root["initial_temperature"])
    initial_temperatures(root["initial_temperature"], r, p);
  fem::Step first;
  if (root["supports"])
  {
    first.dirichlet = supports(root["supports"], "supports", r, p);
    first.reference_supports = coupling_supports(root["supports"], "supports", r, p);
  }
  if (root["temperatures"])
    first.temperatures = temperatures(root["temperatures"], "temperatures", r, p);
  if (root["loads"])
    loads(root["loads"], "loads", r, p, first);
  p.steps = {first};
  const YAML::Node steps = root["steps"];
  if (!steps)
    return;
  FETICON_CHECK(steps.IsSequence() && steps.size() > 0, r.source << ": steps must be a non-empty list");
  FETICON_CHECK(steps.size() <= 10000, r.source << ": steps has " << steps.size() << " entries, at most 10000");
  p.steps.clear();
  const YAML::Node pairs = root["contact"];
  const size_t n_pairs = pairs && pairs.IsSequence() ? pairs.size() : 0;
  for (size_t i = 0; i < steps.size(); ++i)
  {
    fem::Step step = i == 0 ? first : p.steps.back();
    step_entry(steps[i], "steps." + std::to_string(i), r, p, n_pairs, step);
    p.steps.push_back(std::move(step));
  }
}
} // namespace feticon::io
