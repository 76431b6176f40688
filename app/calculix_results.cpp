#include "app/calculix_results.hpp"

#include "app/constraint_summary.hpp"

#include "fem/cell_element.hpp"

#include "contact/contact_constraints.hpp"
#include "fem/assembler.hpp"
#include "fem/cell_element.hpp"
#include "fem/hex8_element.hpp"
#include "fem/stress.hpp"
#include "nonlinear/contact_pressure.hpp"

#include <algorithm>
#include <cmath>
#include <set>

namespace feticon::app
{
namespace
{
bool prints_anything(const io::DeckInfo& deck)
{
  using Kind = io::DeckOutputRequest::Kind;
  for (const io::DeckStep& step : deck.steps)
    for (const io::DeckOutputRequest& r : step.outputs)
      if (r.kind == Kind::node_print || r.kind == Kind::el_print || r.kind == Kind::contact_print)
        return true;
  return false;
}

/// Deck step (0-based) and CalculiX's total time at the load factor t of the load history
/// (stage k runs over t in (k, k + 1], CalculiX's step k + 1 over its own step time).
std::pair<size_t, double> step_and_time(const io::DeckInfo& deck, double t)
{
  const size_t k = std::min(deck.steps.size() - 1, static_cast<size_t>(std::max(0.0, std::ceil(t - 1e-12) - 1)));
  double time = 0;
  for (size_t j = 0; j < k; ++j)
    time += deck.steps[j].time;
  return {k, time + (t - static_cast<double>(k)) * deck.steps[k].time};
}

/// Appends lines not seen before.
void add_warnings(std::vector<std::string>& to, const std::vector<std::string>& lines)
{
  for (const std::string& line : lines)
    if (std::find(to.begin(), to.end(), line) == to.end())
      to.push_back(line);
}
/// Gauss point stresses and strains (tensor shears) for the .dat, and their cell averages for
/// the .frd's nodal values.
struct PointResults
{
  /// The .dat's points: those of cell c are offsets[c] to offsets[c + 1] (dat_points); all
  /// empty where a cell has none that CalculiX's are (the .dat reports S and E unavailable).
  std::vector<int64_t> offsets;
  std::vector<double> stress, strain; ///< points x 6
  std::vector<double> plastic_strain; ///< per point (PEEQ), or empty (no plastic body)
  std::vector<Eigen::Matrix<double, 6, 1>> cell_stress, cell_strain;
};

/// The point of hex8's 2x2x2 rule (x fastest, then y, then z) that is hex8_gauss_points()[a]
/// (the corners' order, hex8_point_results').
size_t rule_point_of_gauss_point(int a)
{
  const Eigen::Vector3d& xi = fem::hex8_gauss_points()[a];
  return (xi(0) > 0 ? 1 : 0) + (xi(1) > 0 ? 2 : 0) + (xi(2) > 0 ? 4 : 0);
}

fem::Integration integration_of(const mesh::Mesh& mesh, int32_t c)
{
  return mesh.reduced(c) ? fem::Integration::reduced : fem::Integration::full;
}

/// The points at which CalculiX prints cell c's S, E and PEEQ, in its order, as indices into the
/// points of the cell's own rule (fem::quadrature). CalculiX's rules (gauss.f: gauss3d2, gauss3d3
/// for C3D8 and C3D20(R), x fastest; gauss3d4, gauss3d5 for C3D4 and C3D10) are feticon's, in the
/// same order. A 2D cell CalculiX expands into a 3D one through the thickness, its in-plane axes
/// kept: CPE4 into C3D8, CPE8R into C3D20R, CPE8 into C3D20, CPE6 into C3D15, so each in-plane
/// point is printed once per layer of that rule (2, 2, 3, 3), x fastest (feticon's squares run y
/// fastest). Empty where CalculiX's points are not feticon's: C3D6 (2 against 6), CPE3 (C3D6).
/// C3D8R and CPE4R cells, which feticon integrates fully (a warning says so when the deck is
/// read), print the 8 points of that rule where CalculiX prints its one reduced point.
std::vector<int> dat_points(const mesh::Mesh& mesh, int32_t c)
{
  const mesh::CellKind kind = mesh.cells.kind(c);
  const auto n = static_cast<int>(fem::quadrature(kind, integration_of(mesh, c)).points.size());
  std::vector<int> out;
  switch (kind)
  {
  case mesh::CellKind::hex8:
  case mesh::CellKind::hex20:
  case mesh::CellKind::tet4:
  case mesh::CellKind::tet10:
    for (int q = 0; q < n; ++q)
      out.push_back(q);
    break;
  case mesh::CellKind::quad4:
  case mesh::CellKind::quad8:
  {
    const int side = n == 4 ? 2 : 3;
    for (int layer = 0; layer < (n == 9 ? 3 : 2); ++layer)
      for (int j = 0; j < side; ++j)
        for (int i = 0; i < side; ++i)
          out.push_back(side * i + j);
    break;
  }
  case mesh::CellKind::tri6:
    for (int layer = 0; layer < 3; ++layer)
      for (int q = 0; q < n; ++q)
        out.push_back(q);
    break;
  case mesh::CellKind::tri3:
  case mesh::CellKind::wedge6:
    break;
  }
  return out;
}

/// The results of cell c at the points of its rule (a plastic cell from its J2 states, a
/// hyperelastic one from its law); hex8_point_results's corner order put into the rule's.
fem::CellPointResults rule_point_results(const mesh::Mesh& mesh, int32_t c, const Eigen::MatrixX3d& X,
                                         const Eigen::MatrixX3d& u, const fem::Material& material,
                                         fem::Kinematics kinematics, const Eigen::VectorXd* temperature_change,
                                         std::span<const fem::PlasticPointState> states)
{
  const mesh::CellKind type = mesh.cells.kind(c);
  if (type == mesh::CellKind::hex8 && states.empty() && !material.is_hyperelastic())
  {
    fem::NodeCoords X8 = X;
    fem::NodeCoords u8 = u;
    fem::NodeTemperatures dT = fem::NodeTemperatures::Zero();
    if (temperature_change)
      dT = *temperature_change;
    const fem::Hex8PointResults h =
        fem::hex8_point_results(X8, u8, material, kinematics, c, temperature_change ? &dT : nullptr);
    fem::CellPointResults out;
    out.stress.resize(8);
    out.strain.resize(8);
    out.weight.resize(8);
    for (int a = 0; a < 8; ++a)
    {
      const size_t q = rule_point_of_gauss_point(a);
      out.stress[q] = h.stress[a];
      out.strain[q] = h.strain[a];
      out.weight[q] = h.weight[a];
    }
    return out;
  }
  return fem::cell_point_results(type, X, u, material, kinematics, integration_of(mesh, c), c, temperature_change,
                                 states, mesh.planar_of_cell(c));
}

/// Whether every cell has the .dat's points (dat_points).
bool prints_points(const mesh::Mesh& mesh)
{
  for (int32_t c = 0; c < mesh.n_cells(); ++c)
    if (dat_points(mesh, c).empty())
      return false;
  return true;
}

PointResults point_results(const fem::Problem& p, const la::Vector& u, const la::Vector& temperature_change,
                           fem::Kinematics kinematics, const fem::MeshPlasticStates& plastic)
{
  const bool thermal = temperature_change.size() > 0;
  const mesh::Mesh& mesh = p.mesh;
  PointResults out;
  const bool print = prints_points(mesh);
  if (print)
    out.offsets.assign(1, 0);
  out.cell_stress.resize(mesh.n_cells());
  out.cell_strain.resize(mesh.n_cells());
  Eigen::MatrixX3d X, ue;
  Eigen::VectorXd dT;
  for (int32_t c = 0; c < mesh.n_cells(); ++c)
  {
    const fem::Material& material = p.materials[mesh.cell_body[c]];
    fem::gather_cell(mesh, c, u, temperature_change, X, ue, dT);
    const fem::CellPointResults r =
        rule_point_results(mesh, c, X, ue, material, kinematics, thermal ? &dT : nullptr, plastic.of(c));
    Eigen::Matrix<double, 6, 1> s = Eigen::Matrix<double, 6, 1>::Zero(), e = s;
    double volume = 0;
    for (size_t g = 0; g < r.weight.size(); ++g)
    {
      s += r.weight[g] * r.stress[g];
      e += r.weight[g] * r.strain[g];
      volume += r.weight[g];
    }
    out.cell_stress[c] = s / volume;
    out.cell_strain[c] = e / volume;
    out.cell_strain[c].tail<3>() *= 0.5; // engineering to tensor shears
    if (!print)
      continue;
    for (const int q : dat_points(mesh, c))
    {
      Eigen::Matrix<double, 6, 1> strain = r.strain[static_cast<size_t>(q)];
      strain.tail<3>() *= 0.5;
      for (int j = 0; j < 6; ++j)
      {
        out.stress.push_back(r.stress[static_cast<size_t>(q)](j));
        out.strain.push_back(strain(j));
      }
      if (!plastic.empty())
        out.plastic_strain.push_back(
            plastic.of(c).empty() ? 0.0 : plastic.of(c)[static_cast<size_t>(q)].equivalent_plastic_strain);
    }
    out.offsets.push_back(static_cast<int64_t>(out.stress.size() / 6));
  }
  return out;
}

/// The .frd's PE: at each node the mean over its cells of their points' mean equivalent plastic
/// strain (elastic cells count 0, as ccx's extrapolation of their zero points does).
std::vector<double> nodal_plastic_strain(const mesh::Mesh& mesh, const fem::MeshPlasticStates& plastic)
{
  std::vector<double> sum(mesh.n_nodes(), 0.0), count(mesh.n_nodes(), 0.0);
  for (int32_t c = 0; c < mesh.n_cells(); ++c)
    for (const int32_t node : mesh.cells[c])
    {
      sum[node] += plastic.mean_equivalent_plastic_strain(c);
      count[node] += 1;
    }
  for (int32_t n = 0; n < mesh.n_nodes(); ++n)
    sum[n] = count[n] > 0 ? sum[n] / count[n] : 0.0;
  return sum;
}
/// The deck's cell-less reference nodes as nodes n_nodes, n_nodes + 1, ... of the .dat model,
/// with their labels and in the node sets that name them (DeckInfo::reference_nodes).
void add_reference_nodes(const io::DeckInfo& deck, io::DatModel& model)
{
  if (deck.reference_nodes.empty())
    return;
  if (model.node_labels.empty())
    for (int32_t n = 0; n < model.n_nodes; ++n)
      model.node_labels.push_back(n + 1);
  for (const io::DeckInfo::ReferenceNode& r : deck.reference_nodes)
    model.node_labels.push_back(static_cast<int32_t>(r.label));
  for (const auto& [name, references] : deck.reference_node_sets)
    for (const int32_t r : references)
      model.node_sets[name].push_back(model.n_nodes + r);
  model.n_nodes += static_cast<int32_t>(deck.reference_nodes.size());
}
} // namespace

la::Vector calculix_reaction(const fem::Problem& problem, const nonlinear::ContactSolution& solution,
                             fem::Kinematics kinematics)
{
  const mesh::Mesh& mesh = problem.mesh;
  fem::Assembler assembler(mesh, fem::whole_mesh_domain(mesh), problem.materials, kinematics);
  if (!solution.plastic.empty())
    assembler.set_plastic_state(solution.plastic.points); // the whole mesh's cells in order
  // The thermal strain's stress is in the internal force too: without it a heated bar held at
  // both ends printed a reaction of the wrong sign (K u alone).
  assembler.set_temperature_change(solution.temperature_change);
  la::Vector reaction = assembler.internal_force(solution.u);
  if (solution.constraints.n_rows() > 0)
    reaction += solution.constraints.B.transpose() * solution.contact_lambda;
  return reaction;
}

CalculixResults::CalculixResults(const std::filesystem::path& out_dir, const fem::Problem& problem,
                                 const io::DeckInfo& deck, fem::Kinematics kinematics)
    : _problem(problem), _deck(deck), _kinematics(kinematics)
{
  const std::string stem = deck.path.stem().string();
  _frd =
      std::make_unique<io::FrdWriter>(out_dir / (stem + ".frd"), problem.mesh, deck.node_labels, deck.element_labels);
  if (!prints_anything(deck))
    return;
  io::DatModel model;
  model.n_nodes = problem.mesh.n_nodes();
  model.n_cells = problem.mesh.n_cells();
  model.node_labels = deck.node_labels;
  model.element_labels = deck.element_labels;
  model.node_sets = problem.mesh.node_sets;
  add_reference_nodes(deck, model);
  model.element_sets = deck.element_sets;
  std::set<int32_t> slaves; // of every pair, as CalculiX prints the slave nodes of all its pairs
  for (const fem::ContactPairNames& pair : problem.contacts)
    for (int32_t node : contact::slave_nodes(problem.mesh, {pair.slave, pair.master, pair.slave_nodes}))
      slaves.insert(node);
  model.contact_slave_nodes.assign(slaves.begin(), slaves.end());
  model.frames = problem.frames;
  _dat = std::make_unique<io::DatWriter>(out_dir / (stem + ".dat"), std::move(model));
}

void CalculixResults::add_step(const nonlinear::ContactSolution& solution)
{
  const fem::Problem& p = _problem;
  const mesh::Mesh& mesh = p.mesh;
  const int32_t n = mesh.n_nodes();
  const auto [k, time] = step_and_time(_deck, solution.steps.back().load_factor);
  const io::DeckStep& step = _deck.steps[k];

  // Contact: the nodal pressure (slave_nodal_pressures) per slave node, and the linearized gap.
  const auto& rows = solution.constraints;
  std::vector<double> pressure(n, 0.0), gap(n, 0.0);
  if (!p.contacts.empty() && rows.n_rows() > 0)
  {
    std::vector<la::Vector> nodal_pressure;
    for (int32_t pair = 0; pair < static_cast<int32_t>(p.contacts.size()); ++pair)
      nodal_pressure.push_back(nonlinear::slave_nodal_pressures(p, solution, _kinematics, pair));
    const la::Vector Bu = rows.B * solution.u;
    for (int64_t i = 0; i < rows.n_rows(); ++i)
    {
      const int32_t node = rows.slave_node[i];
      pressure[node] = nodal_pressure[rows.pair[i]](node);
      gap[node] = (rows.c(i) - Bu(i)) * rows.row_norm[i];
    }
  }
  const la::Vector reaction = calculix_reaction(p, solution, _kinematics);

  const PointResults points = point_results(p, solution.u, solution.temperature_change, _kinematics, solution.plastic);
  const std::vector<double>& point_stress = points.stress;
  const std::vector<double>& point_strain = points.strain;
  const auto& cell_stress = points.cell_stress;
  const auto& cell_strain = points.cell_strain;
  const auto nodal_stress = fem::nodal_average(mesh, cell_stress), nodal_strain = fem::nodal_average(mesh, cell_strain);
  std::vector<double> stress(6 * static_cast<size_t>(n)), strain(stress.size());
  for (int32_t i = 0; i < n; ++i)
    for (int j = 0; j < 6; ++j)
    {
      stress[6 * i + j] = nodal_stress[i](j);
      strain[6 * i + j] = nodal_strain[i](j);
    }

  const std::span<const double> u(solution.u.data(), static_cast<size_t>(solution.u.size()));
  const std::span<const double> rf(reaction.data(), static_cast<size_t>(reaction.size()));
  // The .dat's reference nodes follow the mesh nodes (add_reference_nodes).
  la::Vector u_dat = solution.u, rf_dat = reaction;
  if (!_deck.reference_nodes.empty())
  {
    const std::vector<fem::ReferenceResult> results = reference_results(p, solution.u, reaction, _kinematics);
    const auto n_mesh = u_dat.size();
    u_dat.conservativeResize(n_mesh + 3 * std::ssize(_deck.reference_nodes));
    rf_dat.conservativeResize(u_dat.size());
    for (size_t r = 0; r < _deck.reference_nodes.size(); ++r)
    {
      const io::DeckInfo::ReferenceNode& node = _deck.reference_nodes[r];
      const fem::ReferenceResult& result = results[static_cast<size_t>(node.coupling)];
      for (int c = 0; c < 3; ++c)
      {
        u_dat(n_mesh + 3 * static_cast<la::Index>(r) + c) = result.value[node.first_dof + c];
        rf_dat(n_mesh + 3 * static_cast<la::Index>(r) + c) = result.reaction[node.first_dof + c];
      }
    }
  }
  // CalculiX's .dat prints a model with CAX cells per 2-degree wedge, 1/180 of the full circle
  // (plane sections' thickness too, solidsections.f; its .frd, its *CLOAD and feticon's other
  // outputs are per full circle): the .dat's lines then compare with CalculiX's.
  if (mesh.any_axisymmetric())
    rf_dat /= 180.0;
  // The .frd always holds U, S and the contact (what feticon's VTU holds), RF if a request asks.
  std::vector<std::string> frd_warnings;
  const io::FrdFields fields = io::frd_fields(step.outputs, frd_warnings);
  add_warnings(_warnings, frd_warnings);
  io::FrdStep frd;
  frd.time = time;
  frd.step = static_cast<int32_t>(k + 1);
  frd.displacement = u;
  frd.stress = stress;
  if (fields.strain)
    frd.strain = strain;
  const std::vector<double> nodal_peeq = fields.plastic_strain && !solution.plastic.empty()
      ? nodal_plastic_strain(mesh, solution.plastic)
      : std::vector<double>{};
  frd.plastic_strain = nodal_peeq;
  if (fields.reaction_force)
    frd.reaction_force = rf;
  frd.contact_pressure = pressure;
  frd.contact_gap = gap;
  _frd->add_step(frd);

  if (!_dat)
    return;
  io::DatStep dat;
  dat.time = time;
  dat.displacement = std::span<const double>(u_dat.data(), static_cast<size_t>(u_dat.size()));
  dat.reaction_force = std::span<const double>(rf_dat.data(), static_cast<size_t>(rf_dat.size()));
  dat.point_offsets = points.offsets;
  dat.stress = point_stress;
  dat.strain = point_strain;
  dat.plastic_strain = points.plastic_strain;
  pressure.resize(u_dat.size() / 3, 0.0); // no contact at the reference nodes
  gap.resize(pressure.size(), 0.0);
  dat.contact_pressure = pressure;
  dat.contact_gap = gap;
  add_warnings(_warnings, _dat->add_step(dat, step.outputs));
}
} // namespace feticon::app
