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
/// the .frd's nodal values. The .dat's integration points are C3D8's: other cell types only get
/// the nodal values (the .dat reports S and E as unavailable).
struct PointResults
{
  std::vector<double> stress, strain; ///< cells x 8 points x 6, or empty
  std::vector<double> plastic_strain; ///< cells x 8 points (PEEQ), or empty (no plastic body)
  std::vector<Eigen::Matrix<double, 6, 1>> cell_stress, cell_strain;
};

/// The point of hex8's 2x2x2 rule (x fastest, then y, then z) that is hex8_gauss_points()[a]
/// (the corners' order, the .dat's).
size_t rule_point_of_gauss_point(int a)
{
  const Eigen::Vector3d& xi = fem::hex8_gauss_points()[a];
  return (xi(0) > 0 ? 1 : 0) + (xi(1) > 0 ? 2 : 0) + (xi(2) > 0 ? 4 : 0);
}

/// The results of cell c at the points of its solve's rule (a plastic cell from its J2 states,
/// or a hyperelastic one); hex8's in hex8_gauss_points() order, as hex8_point_results gives them.
fem::CellPointResults rule_point_results(const mesh::Mesh& mesh, int32_t c, const Eigen::MatrixX3d& X,
                                         const Eigen::MatrixX3d& u, const fem::Material& material,
                                         fem::Kinematics kinematics, const Eigen::VectorXd* temperature_change,
                                         std::span<const fem::PlasticPointState> states)
{
  const mesh::CellKind type = mesh.cells.kind(c);
  const fem::CellPointResults r = fem::cell_point_results(
      type, X, u, material, kinematics, mesh.reduced(c) ? fem::Integration::reduced : fem::Integration::full, c,
      temperature_change, states, mesh.planar);
  if (type != mesh::CellKind::hex8)
    return r;
  fem::CellPointResults out = r;
  for (int a = 0; a < 8; ++a)
  {
    const size_t q = rule_point_of_gauss_point(a);
    out.stress[a] = r.stress[q];
    out.strain[a] = r.strain[q];
    out.weight[a] = r.weight[q];
  }
  return out;
}

PointResults point_results(const fem::Problem& p, const la::Vector& u, const la::Vector& temperature_change,
                           fem::Kinematics kinematics, const fem::MeshPlasticStates& plastic)
{
  const bool thermal = temperature_change.size() > 0;
  const mesh::Mesh& mesh = p.mesh;
  PointResults out;
  const bool dat_points = mesh.cells.all_of_kind(mesh::CellKind::hex8);
  std::vector<double>& point_stress = out.stress;
  std::vector<double>& point_strain = out.strain;
  point_stress.assign(dat_points ? static_cast<size_t>(mesh.n_cells()) * 48 : 0, 0.0);
  point_strain.assign(point_stress.size(), 0.0);
  std::vector<Eigen::Matrix<double, 6, 1>>& cell_stress = out.cell_stress;
  std::vector<Eigen::Matrix<double, 6, 1>>& cell_strain = out.cell_strain;
  cell_stress.resize(mesh.n_cells());
  cell_strain.resize(mesh.n_cells());
  fem::NodeCoords X, ue;
  fem::NodeTemperatures dT = fem::NodeTemperatures::Zero();
  Eigen::MatrixX3d X_any, u_any;
  Eigen::VectorXd dT_any;
  for (int32_t c = 0; c < mesh.n_cells(); ++c)
  {
    const std::span<const int32_t> cell = mesh.cells[c];
    const fem::Material& material = p.materials[mesh.cell_body[c]];
    fem::CellPointResults r;
    if (mesh.cells.kind(c) == mesh::CellKind::hex8 && plastic.of(c).empty() && !material.is_hyperelastic())
    {
      for (int a = 0; a < 8; ++a)
      {
        X.row(a) = mesh.nodes.row(cell[a]);
        ue.row(a) = u.segment<3>(3 * cell[a]).transpose();
        if (thermal)
          dT(a) = temperature_change(cell[a]);
      }
      const fem::Hex8PointResults h = fem::hex8_point_results(X, ue, material, kinematics, c, thermal ? &dT : nullptr);
      r.stress.assign(h.stress.begin(), h.stress.end());
      r.strain.assign(h.strain.begin(), h.strain.end());
      r.weight.assign(h.weight.begin(), h.weight.end());
    }
    else
    {
      X_any.resize(static_cast<Eigen::Index>(cell.size()), 3);
      u_any.resize(X_any.rows(), 3);
      dT_any.setZero(X_any.rows());
      for (size_t a = 0; a < cell.size(); ++a)
      {
        X_any.row(a) = mesh.nodes.row(cell[a]);
        u_any.row(a) = u.segment<3>(3 * cell[a]).transpose();
        if (thermal)
          dT_any(a) = temperature_change(cell[a]);
      }
      r = material.is_st_venant_kirchhoff()
          ? fem::cell_point_results(mesh.cells.kind(c), X_any, u_any, material, kinematics, fem::Integration::full, c,
                                    thermal ? &dT_any : nullptr, {}, mesh.planar)
          : rule_point_results(mesh, c, X_any, u_any, material, kinematics, thermal ? &dT_any : nullptr, plastic.of(c));
    }
    Eigen::Matrix<double, 6, 1> s = Eigen::Matrix<double, 6, 1>::Zero(), e = s;
    double volume = 0;
    for (size_t g = 0; g < r.weight.size(); ++g)
    {
      Eigen::Matrix<double, 6, 1> strain = r.strain[g];
      strain.tail<3>() *= 0.5; // engineering to tensor shears
      if (dat_points)
        for (int j = 0; j < 6; ++j)
        {
          point_stress[48 * c + 6 * g + j] = r.stress[g](j);
          point_strain[48 * c + 6 * g + j] = strain(j);
        }
      s += r.weight[g] * r.stress[g];
      e += r.weight[g] * strain;
      volume += r.weight[g];
    }
    cell_stress[c] = s / volume;
    cell_strain[c] = e / volume;
  }
  if (dat_points && !plastic.empty())
  {
    out.plastic_strain.assign(static_cast<size_t>(mesh.n_cells()) * 8, 0.0);
    for (int32_t c = 0; c < mesh.n_cells(); ++c)
      for (size_t a = 0; a < plastic.of(c).size(); ++a)
        out.plastic_strain[8 * c + a] =
            plastic.of(c)[rule_point_of_gauss_point(static_cast<int>(a))].equivalent_plastic_strain;
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
