#include "decomposition/subdomain_operators.hpp"

#include "common/error.hpp"
#include "common/log.hpp"
#include "common/parallel.hpp"
#include "common/timer.hpp"
#include "decomposition/rigid_body_modes.hpp"
#include "la/submatrix.hpp"

#include <algorithm>
#include <numeric>

namespace feticon::decomposition
{
SubdomainSystem::SubdomainSystem(const Decomposition& decomposition, std::vector<fem::Material> materials,
                                 fem::Kinematics kinematics, GeneralizedInverseMethod method,
                                 la::FactorPrecision precision)
    : _decomposition(decomposition), _method(method), _precision(precision), _assemblers(decomposition.n_subdomains()),
      _operators(decomposition.n_subdomains())
{
  parallel_for(decomposition.first_owned(), decomposition.end_owned(), setup_work, [&](int32_t s) {
    _assemblers[s] = std::make_unique<fem::Assembler>(decomposition.mesh(), decomposition.subdomain(s).domain,
                                                      materials, kinematics);
  });
}

la::Vector SubdomainSystem::full_local(int32_t s, const la::Vector& u_stacked) const
{
  const Subdomain& sub = _decomposition.subdomain(s);
  la::Vector full = la::Vector::Zero(sub.domain.n_dofs());
  const auto seg = _decomposition.segment(u_stacked, s);
  for (int32_t k = 0; k < sub.n_dofs(); ++k)
    full(sub.full_of_active[k]) = seg(k);
  return full;
}

void SubdomainSystem::update(const la::Vector& u_stacked, TimerTable* timers)
{
  FETICON_CHECK(u_stacked.size() == _decomposition.n_primal(), "stacked displacement size");
  const int32_t first = _decomposition.first_owned();
  std::vector<std::vector<int32_t>> fixing_candidates(_decomposition.end_owned() - first);
  auto start = std::chrono::steady_clock::now();
  parallel_for(first, _decomposition.end_owned(), setup_work, [&](int32_t s) {
    const Subdomain& sub = _decomposition.subdomain(s);
    const fem::Assembler& assembler = *_assemblers[sub.id];
    const la::Vector u_full = full_local(sub.id, u_stacked);
    const la::SparseMatrix K_full = assembler.stiffness(u_full, fem::StiffnessKind::material);
    // Restrict to active DOFs (plane strain eliminates z); keep the lower triangle.
    SubdomainOperators& op = _operators[sub.id];
    // Swapped in: Eigen 3.4's SparseMatrix has no move assignment, and a copy of K costs
    // page faults on fresh memory.
    la::SparseMatrix K_active =
        la::principal_submatrix(K_full, sub.active_of_full, sub.n_dofs(), la::Entries::lower_triangle);
    op.K.swap(K_active);

    // Kernel from the current coordinates x = X + u (the kernel of K_M(u)); with small
    // displacements K(u) (a plastic body's tangent) keeps the kernel of X.
    Eigen::Matrix<double, Eigen::Dynamic, 3, Eigen::RowMajor> x = assembler.local_coordinates();
    if (assembler.kinematics() == fem::Kinematics::total_lagrangian)
      for (int32_t n = 0; n < sub.domain.n_nodes(); ++n)
        x.row(n) += u_full.segment<3>(3 * n).transpose();
    // A subdomain with an axisymmetric cell keeps the axial translation only (a plane body
    // glued to it moves with it).
    const mesh::Mesh& mesh = assembler.mesh();
    const bool axisymmetric = mesh.any_axisymmetric() && std::ranges::any_of(sub.domain.cells, [&](int32_t c) {
                                return mesh.planar_of_cell(c).kind == mesh::PlanarKind::axisymmetric;
                              });
    op.R = rigid_body_modes(x, sub.full_of_active, axisymmetric);
    for (int32_t node : choose_fixing_nodes(x))
      for (int i = 0; i < 3; ++i)
        if (sub.active_of_full[3 * node + i] >= 0)
          fixing_candidates[s - first].push_back(sub.active_of_full[3 * node + i]);
  });
  if (timers)
    timers->add("assembly", seconds_since(start));

  start = std::chrono::steady_clock::now();
  std::vector<int64_t> owned_kernel_dims(_decomposition.end_owned() - first);
  parallel_for(first, _decomposition.end_owned(), setup_work, [&](int32_t s) {
    SubdomainOperators& op = _operators[s];
    const std::string what = "subdomain " + std::to_string(s);
    try
    {
      op.K_plus.setup(op.K, op.R, fixing_candidates[s - first], _method, what, _precision);
    }
    catch (const Error&)
    {
      if (auto modes = zero_energy_modes(op.K, op.R))
        factor_with_zero_energy_modes(op, std::move(*modes), what);
      else
        factor_definite_part(s, u_stacked, fixing_candidates[s - first], what);
    }
    owned_kernel_dims[s - first] = op.R.cols();
  });
  // Kernel blocks of all subdomains, in subdomain order (the coarse space is replicated).
  const std::vector<int64_t> dims = _decomposition.comm().all_gather(owned_kernel_dims);
  _kernel_offsets.assign(1, 0);
  for (const int64_t k : dims)
    _kernel_offsets.push_back(_kernel_offsets.back() + k);
  if (timers)
    timers->add("factorization", seconds_since(start));
}

void SubdomainSystem::factor_with_zero_energy_modes(SubdomainOperators& op, la::Matrix modes, const std::string& what)
{
  const auto extra = modes.cols() - op.R.cols();
  op.R = std::move(modes);
  // The fixing DOFs among all of them: the zero-energy modes need not move the fixing nodes.
  std::vector<int32_t> every_dof(static_cast<size_t>(op.K.rows()));
  std::iota(every_dof.begin(), every_dof.end(), 0);
  op.K_plus.setup(op.K, op.R, every_dof, _method, what, _precision);
  log::warning("a subdomain's stiffness has " + std::to_string(extra) +
               " zero-energy mode(s) besides its rigid-body motions (a cell with reduced integration alone in "
               "its subdomain, or in its body: hourglass modes): its kernel is taken from the matrix, and the "
               "model's constraints must hold those modes");
}

void SubdomainSystem::factor_definite_part(int32_t s, const la::Vector& u_stacked,
                                           const std::vector<int32_t>& fixing_candidates, const std::string& what)
{
  // A hyperelastic law beyond its convexity in E can make K_M indefinite, and so can finite-
  // strain plasticity (dS/dE of a yielded point loses the shear stiffness that the stress's
  // own terms then exceed): K_M again from the positive definite part of each point's
  // tangent (fem/cell_element.cpp).
  const fem::Assembler& assembler = *_assemblers[s];
  const bool finite_plastic =
      assembler.has_plastic_cells() && assembler.kinematics() == fem::Kinematics::total_lagrangian;
  if (!assembler.has_hyperelastic_cells() && !finite_plastic)
    throw;
  SubdomainOperators& op = _operators[s];
  la::SparseMatrix K_active = la::principal_submatrix(
      assembler.stiffness(full_local(s, u_stacked), fem::StiffnessKind::material_definite),
      _decomposition.subdomain(s).active_of_full, _decomposition.subdomain(s).n_dofs(), la::Entries::lower_triangle);
  op.K.swap(K_active);
  op.K_plus.setup(op.K, op.R, fixing_candidates, _method, what, _precision);
  log::warning("a hyperelastic or finite-strain plastic subdomain's K_M was indefinite (dS/dE is not positive "
               "there): factored from each point's nearest positive definite tangent, a quasi-Newton step "
               "(docs/materials.md)");
}

void SubdomainSystem::set_temperature_change(const la::Vector& mesh_temperature_change)
{
  parallel_for(_decomposition.first_owned(), _decomposition.end_owned(), setup_work, [&](int32_t s) {
    const std::vector<int32_t>& nodes = _decomposition.subdomain(s).domain.local_to_global;
    la::Vector local;
    if (mesh_temperature_change.size() > 0)
    {
      local.resize(static_cast<la::Index>(nodes.size()));
      for (size_t a = 0; a < nodes.size(); ++a)
        local(static_cast<la::Index>(a)) = mesh_temperature_change(nodes[a]);
    }
    _assemblers[s]->set_temperature_change(std::move(local));
  });
}

la::Vector SubdomainSystem::internal_force(const la::Vector& u_stacked) const
{
  la::Vector f(_decomposition.n_primal());
  parallel_for(_decomposition.first_owned(), _decomposition.end_owned(), setup_work, [&](int32_t s) {
    const Subdomain& sub = _decomposition.subdomain(s);
    const la::Vector f_full = _assemblers[sub.id]->internal_force(full_local(sub.id, u_stacked));
    auto seg = _decomposition.segment(f, sub.id);
    for (int32_t k = 0; k < sub.n_dofs(); ++k)
      seg(k) = f_full(sub.full_of_active[k]);
  });
  return f;
}

void SubdomainSystem::commit_plastic_state(const la::Vector& u_stacked)
{
  parallel_for(_decomposition.first_owned(), _decomposition.end_owned(), setup_work, [&](int32_t s) {
    if (_assemblers[s]->has_plastic_cells())
      _assemblers[s]->commit_plastic_state(full_local(s, u_stacked));
  });
}

void SubdomainSystem::plastic_states(fem::MeshPlasticStates& states) const
{
  for (int32_t s = _decomposition.first_owned(); s < _decomposition.end_owned(); ++s)
  {
    const std::vector<int32_t>& cells = _decomposition.subdomain(s).domain.cells;
    for (size_t k = 0; k < cells.size(); ++k)
    {
      const std::span<const fem::PlasticPointState> committed = _assemblers[s]->plastic_state(k);
      std::copy(committed.begin(), committed.end(), states.of(cells[k]).begin());
    }
  }
}

void SubdomainSystem::set_plastic_states(const fem::MeshPlasticStates& states)
{
  for (int32_t s = _decomposition.first_owned(); s < _decomposition.end_owned(); ++s)
  {
    if (!_assemblers[s]->has_plastic_cells())
      continue;
    std::vector<fem::PlasticPointState> local;
    for (const int32_t c : _decomposition.subdomain(s).domain.cells)
    {
      const std::span<const fem::PlasticPointState> cell = states.of(c);
      local.insert(local.end(), cell.begin(), cell.end());
    }
    _assemblers[s]->set_plastic_state(std::move(local));
  }
}

long SubdomainSystem::factor_nonzeros() const
{
  long total = 0;
  for (int32_t s = _decomposition.first_owned(); s < _decomposition.end_owned(); ++s)
    total += _operators[s].K_plus.factor_nonzeros();
  return total;
}
} // namespace feticon::decomposition
