#include "fem/problem.hpp"

#include <algorithm>

#include "common/error.hpp"
#include "fem/loads.hpp"

#include <cmath>
#include <map>

namespace feticon::fem
{
namespace
{
/// Runs `check`, prefixing the message of a feticon::Error it throws with the step.
template <class F>
void in_step(size_t step, size_t n_steps, F&& check)
{
  try
  {
    check();
  }
  catch (const Error& e)
  {
    if (n_steps == 1)
      throw;
    throw Error("step " + std::to_string(step + 1) + ": " + e.what());
  }
}
} // namespace

void check_temperature(double value, const std::string& what)
{
  FETICON_CHECK(std::isfinite(value) && value >= absolute_zero_celsius,
                what << " is " << value << ": not finite or below absolute zero (" << absolute_zero_celsius
                     << " degrees Celsius)");
}

la::Vector Problem::external_force(size_t step, const std::string& amplitude, bool reference_loads) const
{
  FETICON_CHECK(step < steps.size(), "step " << step + 1 << " of " << steps.size());
  const Step& s = steps[step];
  la::Vector f = la::Vector::Zero(3 * mesh.n_nodes());
  for (const FaceTraction& t : s.tractions)
    if (t.amplitude == amplitude)
      add_face_traction(mesh, mesh.face_set(t.set), t.traction, f);
  for (const FacePressure& p : s.pressures)
    if (p.amplitude == amplitude)
      add_face_pressure(mesh, mesh.face_set(p.set), p.pressure, f);
  for (const NodalForce& n : s.nodal_forces)
    if (n.amplitude == amplitude)
      f(3 * static_cast<la::Index>(n.node) + n.component) += n.value;
  for (const BodyLoad& b : s.body_loads)
    if (b.amplitude == amplitude)
      add_body_load(mesh, materials, b, f);
  if (reference_loads && !s.reference_loads.empty())
  {
    const std::vector<ReferenceDofs> reference = reference_dofs();
    for (const ReferenceValue& load : s.reference_loads)
      if (load.amplitude == amplitude)
      {
        const DofCombination& unit = reference[static_cast<size_t>(load.coupling)].unit_load[load.dof];
        for (size_t k = 0; k < unit.dofs.size(); ++k)
          f(unit.dofs[k]) += load.value * unit.coefficients[k];
      }
  }
  for (int i = 0; i < 3; ++i)
    if (eliminated[i])
      for (int32_t n = 0; n < mesh.n_nodes(); ++n)
        f(3 * n + i) = 0;
  return f;
}

ConstrainedDofs Problem::all_constrained_dofs(size_t step, const std::string& amplitude) const
{
  FETICON_CHECK(step < steps.size(), "step " << step + 1 << " of " << steps.size());
  const ConstrainedDofs prescribed = collect_dirichlet(mesh, steps[step].dirichlet, 1.0, &frames);
  std::map<int64_t, double> merged;
  for (size_t k = 0; k < prescribed.dofs.size(); ++k)
    merged[prescribed.dofs[k]] = prescribed.values(static_cast<la::Index>(k));
  for (int i = 0; i < 3; ++i)
    if (eliminated[i])
      for (int32_t n = 0; n < mesh.n_nodes(); ++n)
      {
        auto [it, inserted] = merged.emplace(3 * static_cast<int64_t>(n) + i, 0.0);
        FETICON_CHECK(it->second == 0.0,
                      "node " << n << " prescribes " << it->second << " for component " << i
                              << ", which plane strain fixes to zero");
      }
  // The values of the supports of other amplitudes are 0 here (the DOFs stay held).
  for (const DirichletCondition& d : steps[step].dirichlet)
    if (d.amplitude != amplitude)
      for (const int32_t n : mesh.node_set(d.set))
        for (int i = 0; i < 3; ++i)
          if (d.value[i])
            merged[held_dof(mesh, &frames, n, i, 0.0).first] = 0.0;
  // A support on a reference DOF the coupling does not drive holds nothing (validate_couplings).
  if (!steps[step].reference_supports.empty())
  {
    const std::vector<ReferenceDofs> reference = reference_dofs();
    for (const ReferenceValue& r : steps[step].reference_supports)
      if (!reference[static_cast<size_t>(r.coupling)].value[r.dof].empty())
        merged[reference_dof(r.coupling, r.dof)] = r.amplitude == amplitude ? r.value : 0.0;
  }
  return to_constrained_dofs(merged);
}

std::vector<LinearEquation> Problem::tie_equations_in_force(size_t step) const
{
  const std::vector<int32_t>& removed = steps.at(step).removed_ties;
  if (removed.empty())
    return tie_equations;
  std::vector<LinearEquation> out;
  for (size_t k = 0; k < tie_equations.size(); ++k)
    if (std::ranges::find(removed, tie_of_equation.at(k)) == removed.end())
      out.push_back(tie_equations[k]);
  return out;
}

bool Problem::has_finite_couplings() const
{
  return std::ranges::any_of(couplings, [&](const Coupling& c) { return has_finite_kinematics(mesh, c, eliminated); });
}

bool Problem::has_plastic_body() const
{
  return std::ranges::any_of(materials, [](const Material& m) { return m.is_plastic(); });
}

bool Problem::has_inelastic_or_hyperelastic_body() const
{
  return std::ranges::any_of(materials, [](const Material& m) { return !m.is_st_venant_kirchhoff(); });
}

int64_t Problem::reference_dof(int32_t coupling, int dof) const
{
  return 3 * (int64_t{mesh.n_nodes()} + std::ssize(frames.nodes)) + 6 * int64_t{coupling} + dof;
}

std::vector<ReferenceDofs> Problem::reference_dofs() const
{
  std::vector<ReferenceDofs> out;
  for (const Coupling& c : couplings)
    out.push_back(fem::reference_dofs(mesh, c, eliminated));
  return out;
}

std::vector<DofCombination> Problem::held_combinations() const
{
  std::vector<DofCombination> out;
  for (size_t k = 0; k < frames.nodes.size(); ++k)
    for (int c = 0; c < 3; ++c)
    {
      DofCombination& axis = out.emplace_back();
      for (int g = 0; g < 3; ++g)
        if (!eliminated[g] && frames.axes[k](c, g) != 0)
        {
          axis.dofs.push_back(3 * int64_t{frames.nodes[k]} + g);
          axis.coefficients.push_back(frames.axes[k](c, g));
        }
    }
  for (const ReferenceDofs& r : reference_dofs())
    out.insert(out.end(), r.value.begin(), r.value.end());
  return out;
}

la::Vector Problem::extended(const la::Vector& u) const
{
  if (couplings.empty())
    return frames.extended(u);
  const std::vector<DofCombination> held = held_combinations();
  la::Vector out(u.size() + std::ssize(held));
  out.head(u.size()) = u;
  for (size_t k = 0; k < held.size(); ++k)
    out(u.size() + static_cast<la::Index>(k)) = held[k].of(u);
  return out;
}

std::vector<LinearEquation> Problem::all_equations() const
{
  std::vector<LinearEquation> out = equations;
  out.insert(out.end(), tie_equations.begin(), tie_equations.end());
  return out;
}

bool Problem::has_temperatures() const
{
  return std::ranges::any_of(steps, [](const Step& s) { return !s.temperatures.empty(); });
}

void Problem::validate_planar() const
{
  const bool planar = mesh.planar.kind != mesh::PlanarKind::none;
  for (int32_t c = 0; c < mesh.n_cells(); ++c)
    FETICON_CHECK(mesh::is_planar(mesh.cells.kind(c)) == planar,
                  "problem '" << name << "': cell " << c << " is " << mesh::cell_type(mesh.cells.kind(c)).name
                              << " in a " << mesh::planar_name(mesh.planar.kind)
                              << " model: 2D and 3D cells do not mix");
  if (!planar)
    return;
  FETICON_CHECK(eliminated == (std::array<bool, 3>{false, false, true}),
                "problem '" << name << "': a " << mesh::planar_name(mesh.planar.kind)
                            << " model has u_z eliminated, and only u_z");
  FETICON_CHECK(
      mesh.body_planar.empty() ||
          (std::ssize(mesh.body_planar) == mesh.n_bodies() && std::ssize(mesh.planar_body_of_node) == mesh.n_nodes()),
      "problem '" << name << "': formulations for " << mesh.body_planar.size() << " bodies and "
                  << mesh.planar_body_of_node.size() << " nodes, the mesh has " << mesh.n_bodies() << " and "
                  << mesh.n_nodes());
  for (int32_t b = 0; b < mesh.n_bodies(); ++b)
  {
    const mesh::Planar& planar = mesh.planar_of_body(b);
    FETICON_CHECK(planar.kind != mesh::PlanarKind::none,
                  "problem '" << name << "': body '" << mesh.body_names[b] << "' has no 2D formulation in a 2D model");
    FETICON_CHECK(std::isfinite(planar.thickness) && planar.thickness > 0,
                  "problem '" << name << "': body '" << mesh.body_names[b] << "': thickness " << planar.thickness
                              << " m is not positive");
    FETICON_CHECK(planar.kind != mesh::PlanarKind::plane_stress || b >= std::ssize(materials) ||
                      materials[b].is_st_venant_kirchhoff(),
                  "problem '" << name << "': body '" << mesh.body_names[b] << "' is "
                              << (materials[b].is_plastic() ? "plastic: plasticity" : "hyperelastic: hyperelasticity")
                              << " in plane stress is not implemented (plane strain and axisymmetry are)");
  }
  std::vector<char> axisymmetric_node(static_cast<size_t>(mesh.n_nodes()), 0);
  for (int32_t c = 0; c < mesh.n_cells(); ++c)
    if (mesh.planar_of_cell(c).kind == mesh::PlanarKind::axisymmetric)
      for (const int32_t n : mesh.cells[c])
        axisymmetric_node[n] = 1;
  for (int32_t n = 0; n < mesh.n_nodes(); ++n)
  {
    FETICON_CHECK(mesh.nodes(n, 2) == 0,
                  "problem '" << name << "': node " << n << " of a 2D model lies at z = " << mesh.nodes(n, 2)
                              << ", not in the x-y plane");
    FETICON_CHECK(!axisymmetric_node[n] || mesh.nodes(n, 0) >= 0,
                  "problem '" << name << "': node " << n
                              << " of an axisymmetric cell lies at r = x = " << mesh.nodes(n, 0) << " < 0");
  }
}

void Problem::validate_couplings() const
{
  if (couplings.empty())
    return;
  for (const Coupling& c : couplings)
    FETICON_CHECK(!mesh.any_axisymmetric() || c.kind == CouplingKind::pretension,
                  "problem '" << name << "': " << c.name
                              << ": couplings in an axisymmetric model are not implemented (pretension sections are)");
  const std::vector<ReferenceDofs> reference = reference_dofs(); // checks the sets and weights
  for (size_t k = 0; k < steps.size(); ++k)
  {
    for (const ReferenceValue& r : steps[k].reference_supports)
      FETICON_CHECK(r.coupling >= 0 && r.coupling < std::ssize(couplings) && r.dof >= 0 && r.dof < 6 &&
                        std::isfinite(r.value),
                    "step " << k + 1 << ": a reference support names coupling " << r.coupling << ", DOF " << r.dof
                            << ", value " << r.value << " (of " << couplings.size() << " couplings, DOFs 0 to 5)");
    for (const ReferenceValue& r : steps[k].reference_loads)
    {
      FETICON_CHECK(r.coupling >= 0 && r.coupling < std::ssize(couplings) && r.dof >= 0 && r.dof < 6 &&
                        std::isfinite(r.value),
                    "step " << k + 1 << ": a reference load names coupling " << r.coupling << ", DOF " << r.dof
                            << ", value " << r.value << " (of " << couplings.size() << " couplings, DOFs 0 to 5)");
      FETICON_CHECK(r.value == 0 || !reference[static_cast<size_t>(r.coupling)].unit_load[r.dof].empty(),
                    "step " << k + 1 << ": a load on " << describe_reference_dof(r.dof) << " of the reference node of "
                            << couplings[static_cast<size_t>(r.coupling)].name
                            << ", which the coupling does not carry (a *KINEMATIC without that direction, a "
                               "*DISTRIBUTING without that moment)");
    }
  }
}

void Problem::validate_frames() const
{
  FETICON_CHECK(frames.axes.size() == frames.nodes.size() && std::ranges::is_sorted(frames.nodes) &&
                    std::ranges::adjacent_find(frames.nodes) == frames.nodes.end(),
                "problem '" << name << "': node frames are not one per node, in node order");
  for (size_t k = 0; k < frames.nodes.size(); ++k)
  {
    const int32_t n = frames.nodes[k];
    FETICON_CHECK(n >= 0 && n < mesh.n_nodes(),
                  "problem '" << name << "': a frame names node " << n << ", out of range");
    const Eigen::Matrix3d& e = frames.axes[k];
    FETICON_CHECK(e.allFinite() && (e * e.transpose() - Eigen::Matrix3d::Identity()).norm() < 1e-12 &&
                      e.determinant() > 0,
                  "problem '" << name << "': the frame of node " << n << " is not a right-handed orthonormal system");
    // CalculiX: in a 2D model a local system keeps z (supports act in the plane).
    FETICON_CHECK(mesh.planar.kind == mesh::PlanarKind::none || std::abs(e(2, 2) - 1) < 1e-12,
                  "problem '" << name << "': the local system of node " << n
                              << " turns the z axis; a 2D model takes rectangular systems about z only (as CalculiX)");
  }
}

void Problem::validate() const
{
  FETICON_CHECK(mesh.n_cells() > 0, "problem '" << name << "': the mesh has no cells");
  FETICON_CHECK(mesh.reduced_integration.empty() ||
                    static_cast<int32_t>(mesh.reduced_integration.size()) == mesh.n_cells(),
                "problem '" << name << "': reduced-integration flags for " << mesh.reduced_integration.size()
                            << " cells, the mesh has " << mesh.n_cells());
  for (int32_t c = 0; c < static_cast<int32_t>(mesh.reduced_integration.size()); ++c)
    FETICON_CHECK(!mesh.reduced(c) || mesh.cells.kind(c) == mesh::CellKind::hex20 ||
                      mesh.cells.kind(c) == mesh::CellKind::quad8,
                  "problem '" << name << "': cell " << c << " (" << mesh::cell_type(mesh.cells.kind(c)).name
                              << ") is marked for reduced integration, which only hex20 and quad8 offer");
  validate_planar();
  validate_frames();
  validate_couplings();
  FETICON_CHECK(static_cast<int32_t>(materials.size()) == mesh.n_bodies(),
                "problem '" << name << "': " << mesh.n_bodies() << " bodies but " << materials.size() << " materials");
  for (size_t b = 0; b < materials.size(); ++b)
    materials[b].check("body '" + mesh.body_names[b] + "'");
  // Beyond 1e15 the softer body's stiffness is below the round-off of the stiffer one's in
  // double precision: no solver can resolve the contact between them (a deck fuzz mutant with a
  // modulus times 1e30 ran MPRGP to its 20 000-step limit, 7 s, instead).
  const auto [softest, stiffest] = std::ranges::minmax_element(materials, {}, &Material::young);
  if (!materials.empty())
    FETICON_CHECK(stiffest->young <= 1e15 * softest->young,
                  "problem '" << name << "': Young's moduli of body '" << mesh.body_names[stiffest - materials.begin()]
                              << "' (" << stiffest->young << " Pa) and body '"
                              << mesh.body_names[softest - materials.begin()] << "' (" << softest->young
                              << " Pa) differ by more than 1e15, beyond double precision");
  FETICON_CHECK(!steps.empty(), "problem '" << name << "' has no step");
  FETICON_CHECK(initial_temperatures.empty() || std::ssize(initial_temperatures) == mesh.n_nodes(),
                "problem '" << name << "': initial temperatures of " << initial_temperatures.size()
                            << " nodes, the mesh has " << mesh.n_nodes());
  for (size_t n = 0; n < initial_temperatures.size(); ++n)
    check_temperature(initial_temperatures[n], "the initial temperature of node " + std::to_string(n));
  for (const auto& [amplitude_name, amplitude] : amplitudes)
    amplitude.check();
  for (size_t k = 0; k < steps.size(); ++k)
    validate_step(k);
  for (const auto& e : equations)
  {
    FETICON_CHECK(!e.terms.empty(), "a linear equation has no terms");
    for (const auto& t : e.terms)
      FETICON_CHECK(t.node >= 0 && t.node < mesh.n_nodes() && t.component >= 0 && t.component < 3 &&
                        std::isfinite(t.coefficient),
                    "a linear equation names node " << t.node << ", component " << t.component
                                                    << " out of range or a coefficient that is not finite");
  }
  for (const Tie& t : ties)
  {
    FETICON_CHECK(!mesh.face_set(t.slave).empty(), "tie " << t.name << ": slave surface '" << t.slave << "' is empty");
    FETICON_CHECK(!mesh.face_set(t.master).empty(),
                  "tie " << t.name << ": master surface '" << t.master << "' is empty");
    FETICON_CHECK(t.slave != t.master,
                  "tie " << t.name << ": slave and master are the same surface '" << t.slave << "'");
    if (!t.slave_nodes.empty())
      FETICON_CHECK(!mesh.node_set(t.slave_nodes).empty(),
                    "tie " << t.name << ": slave node set '" << t.slave_nodes << "' is empty");
    FETICON_CHECK(std::isfinite(t.position_tolerance) && t.position_tolerance >= 0,
                  "tie " << t.name << ": position tolerance " << t.position_tolerance << " m must be >= 0");
  }
  for (size_t k = 0; k < contacts.size(); ++k)
    for (size_t j = 0; j < k; ++j)
      FETICON_CHECK(contacts[j].slave != contacts[k].slave || contacts[j].master != contacts[k].master,
                    "contact pairs " << j << " and " << k << " both have slave '" << contacts[k].slave
                                     << "' and master '" << contacts[k].master
                                     << "': their rows would be the same constraints twice");
  for (const auto& c : contacts)
  {
    if (!c.slave_nodes.empty())
      FETICON_CHECK(!mesh.node_set(c.slave_nodes).empty(), "contact slave node set '" << c.slave_nodes << "' is empty");
    FETICON_CHECK(!mesh.face_set(c.slave).empty(), "contact slave surface '" << c.slave << "' is empty");
    FETICON_CHECK(!mesh.face_set(c.master).empty(), "contact master surface '" << c.master << "' is empty");
    FETICON_CHECK(std::isfinite(c.adjust) && c.adjust >= 0,
                  "contact pair " << c.slave << " / " << c.master << ": adjust = " << c.adjust << " m must be >= 0");
    if (!c.adjust_nodes.empty())
      FETICON_CHECK(mesh.node_sets.count(c.adjust_nodes),
                    "contact pair " << c.slave << " / " << c.master << ": adjust node set '" << c.adjust_nodes
                                    << "' is not defined");
    const Friction& f = c.interaction.friction;
    FETICON_CHECK(std::isfinite(f.coefficient) && f.coefficient >= 0 && std::isfinite(f.slip_bound) &&
                      f.slip_bound >= 0,
                  "contact pair " << c.slave << " / " << c.master << ": friction coefficient " << f.coefficient
                                  << " and slip bound " << f.slip_bound << " must be finite and >= 0");
  }
}

void Problem::validate_step(size_t step) const
{
  const Step& s = steps[step];
  in_step(step, steps.size(), [&] {
    FETICON_CHECK(!s.increments || *s.increments >= 1, "the step has " << *s.increments << " increments, must be >= 1");
    FETICON_CHECK(std::isfinite(s.time) && s.time > 0, "the step's time " << s.time << " must be positive");
    const auto amplitude_known = [&](const std::string& a, const std::string& what) {
      FETICON_CHECK(a.empty() || amplitudes.count(a), what << " names amplitude '" << a << "', which is not defined");
    };
    for (const auto& d : s.dirichlet)
    {
      FETICON_CHECK(!mesh.node_set(d.set).empty(), "Dirichlet set '" << d.set << "' is empty");
      for (const std::optional<double>& v : d.value)
        FETICON_CHECK(!v || std::isfinite(*v), "a prescribed value on '" << d.set << "' is not finite");
      amplitude_known(d.amplitude, "the support on '" + d.set + "'");
    }
    for (const auto& t : s.tractions)
    {
      FETICON_CHECK(!mesh.face_set(t.set).empty(), "traction face set '" << t.set << "' is empty");
      FETICON_CHECK(t.traction.allFinite(), "traction on '" << t.set << "' is not finite");
      amplitude_known(t.amplitude, "the traction on '" + t.set + "'");
    }
    for (const auto& p : s.pressures)
    {
      FETICON_CHECK(!mesh.face_set(p.set).empty(), "pressure face set '" << p.set << "' is empty");
      FETICON_CHECK(std::isfinite(p.pressure), "pressure on '" << p.set << "' is not finite");
      amplitude_known(p.amplitude, "the pressure on '" + p.set + "'");
    }
    for (const auto& n : s.nodal_forces)
    {
      FETICON_CHECK(
          n.node >= 0 && n.node < mesh.n_nodes() && n.component >= 0 && n.component < 3 && std::isfinite(n.value),
          "nodal force on node " << n.node << ", component " << n.component << " is out of range or not finite");
      amplitude_known(n.amplitude, "the nodal force on node " + std::to_string(n.node));
    }
    for (const auto& b : s.body_loads)
      amplitude_known(b.amplitude, b.where);
    for (const auto* reference : {&s.reference_supports, &s.reference_loads})
      for (const ReferenceValue& r : *reference)
        amplitude_known(r.amplitude, "a load or support on a reference node");
    for (const int32_t tie : s.removed_ties)
      FETICON_CHECK(tie >= 0 && tie < std::ssize(ties),
                    "the step removes tie " << tie << ", the problem has " << ties.size());
    for (const int32_t pair : s.removed_contacts)
      FETICON_CHECK(pair >= 0 && pair < std::ssize(contacts),
                    "the step removes contact pair " << pair << ", the problem has " << contacts.size());
    for (const auto& [pair, f] : s.changed_friction)
      FETICON_CHECK(pair >= 0 && pair < std::ssize(contacts) && std::isfinite(f.coefficient) && f.coefficient >= 0 &&
                        std::isfinite(f.slip_bound) && f.slip_bound >= 0,
                    "the step changes the friction of contact pair "
                        << pair << " (of " << contacts.size() << ") to coefficient " << f.coefficient
                        << " and slip bound " << f.slip_bound << "; both must be finite and >= 0");
    for (const auto& t : s.temperatures)
    {
      FETICON_CHECK(t.node >= 0 && t.node < mesh.n_nodes(), "a temperature names node " << t.node << ", out of range");
      check_temperature(t.value, "the temperature of node " + std::to_string(t.node));
      amplitude_known(t.amplitude, "the temperature of node " + std::to_string(t.node));
    }
    (void)collect_dirichlet(mesh, s.dirichlet, 1.0, &frames); // two values for one DOF
  });
}
} // namespace feticon::fem
