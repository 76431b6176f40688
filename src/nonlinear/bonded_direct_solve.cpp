#include "nonlinear/bonded_direct_solve.hpp"

#include "common/error.hpp"
#include "common/parallel.hpp"
#include "common/timer.hpp"
#include "fem/assembler.hpp"
#include "fem/constraint_elimination.hpp"
#include "la/cholmod.hpp"
#include "nonlinear/contact_penalty.hpp"

#include <algorithm>
#include <chrono>

namespace feticon::nonlinear
{
std::vector<int32_t> active_slave_nodes(const ContactSolution& solution)
{
  std::vector<int32_t> nodes;
  for (la::Index i = 0; i < solution.contact_lambda.size(); ++i)
    if (solution.contact_lambda(i) > 0)
      nodes.push_back(solution.constraints.slave_node[i]);
  return nodes;
}

namespace
{
/// K + B_A' E B_A and its right-hand side, reduced by the elimination, with what the solve
/// needs to expand and post-process.
struct ReducedBondedSystem
{
  BondedSystem system;
  fem::ConstraintElimination elimination;
  std::vector<char> bonded; ///< per contact row
  la::Vector eps;           ///< row penalties
};

ReducedBondedSystem reduce_bonded(const fem::Problem& problem, const SolverSettings& settings,
                                  const std::vector<int32_t>& bonded_nodes, BondedSolve& out)
{
  problem.validate();
  FETICON_CHECK(problem.contacts.size() == 1, "the bonded direct solve handles one contact pair");
  FETICON_CHECK(!problem.has_temperatures(), "the bonded direct solve has no thermal strain");
  FETICON_CHECK(!problem.has_plastic_body(), "the bonded direct solve has no plasticity");
  FETICON_CHECK(problem.frames.empty(), "the bonded direct solve has no supports along local axes (*TRANSFORM)");
  const int64_t n = 3 * static_cast<int64_t>(problem.mesh.n_nodes());
  const auto start = std::chrono::steady_clock::now();
  const fem::Assembler assembler(problem.mesh, fem::whole_mesh_domain(problem.mesh), problem.materials,
                                 fem::Kinematics::linear);
  const la::Vector zero = la::Vector::Zero(n);
  const la::SparseMatrix K = assembler.stiffness(zero, fem::StiffnessKind::tangent);
  out.penalty = settings.eps_n_factor * K.diagonal().maxCoeff();

  contact::ContactOptions options;
  options.search_distance = settings.search_distance;
  options.formulation = settings.interaction(problem.contacts[0]).formulation;
  out.constraints = contact::build_contact_constraints(
      problem.mesh, zero, {problem.contacts[0].slave, problem.contacts[0].master, problem.contacts[0].slave_nodes},
      options);
  const auto& rows = out.constraints;
  // Rows are sorted by slave node, one row per node.
  std::vector<char> bonded(rows.c.size(), 0);
  for (int32_t node : bonded_nodes)
  {
    const auto it = std::lower_bound(rows.slave_node.begin(), rows.slave_node.end(), node);
    FETICON_CHECK(it != rows.slave_node.end() && *it == node,
                  "bonded direct solve: slave node " << node << " has no contact row at u = 0 (not a "
                                                     << "slave node, or farther than the search distance)");
    bonded[it - rows.slave_node.begin()] = 1;
  }
  out.n_bonded = std::count(bonded.begin(), bonded.end(), 1);
  la::Vector eps = row_penalties(rows, out.penalty);
  la::SparseMatrix K_pen;
  la::Vector f_pen;
  penalty_terms(rows, bonded, eps, K_pen, f_pen);
  const la::SparseMatrix A = K + K_pen;
  fem::ConstraintElimination elimination(n, problem.all_constrained_dofs(), problem.all_equations(), &problem.mesh);
  BondedSystem system{elimination.reduce_matrix(A), elimination.reduce_rhs(A, problem.external_force() + f_pen), {}};
  out.assembly_seconds = seconds_since(start);
  return {std::move(system), std::move(elimination), std::move(bonded), std::move(eps)};
}

/// The six rigid-body modes of the mesh (translations, rotations about its centroid) as
/// forces on the free DOFs, T' R, without the ones the elimination removes entirely (plane
/// strain's out-of-plane modes), orthonormalized.
la::Matrix free_rigid_body_modes(const fem::Problem& problem, const fem::ConstraintElimination& elimination)
{
  const auto& x = problem.mesh.nodes;
  const Eigen::RowVector3d centre = x.colwise().mean();
  const la::Index n = 3 * x.rows();
  la::Matrix R = la::Matrix::Zero(n, 6);
  for (la::Index i = 0; i < x.rows(); ++i)
  {
    const Eigen::RowVector3d r = x.row(i) - centre;
    for (int d = 0; d < 3; ++d)
      R(3 * i + d, d) = 1;
    R(3 * i + 0, 3) = -r.y(), R(3 * i + 1, 3) = r.x();
    R(3 * i + 1, 4) = -r.z(), R(3 * i + 2, 4) = r.y();
    R(3 * i + 0, 5) = r.z(), R(3 * i + 2, 5) = -r.x();
  }
  std::vector<la::Vector> kept;
  // In axisymmetry only the axial translation strains nothing (rigid_body_modes.hpp); with an
  // axisymmetric body beside plane ones, the plane bodies' rotations are left out too.
  const bool axisymmetric = problem.mesh.any_axisymmetric();
  for (int k = 0; k < 6; ++k)
  {
    if (axisymmetric && k != 1)
      continue;
    la::Vector v = elimination.reduce_force(R.col(k));
    for (const la::Vector& q : kept) // Gram-Schmidt, twice for round-off
      v -= q.dot(v) * q;
    for (const la::Vector& q : kept)
      v -= q.dot(v) * q;
    if (v.norm() > 1e-8 * R.col(k).norm())
      kept.push_back(v / v.norm());
  }
  la::Matrix out(elimination.n_free(), static_cast<la::Index>(kept.size()));
  for (size_t k = 0; k < kept.size(); ++k)
    out.col(static_cast<la::Index>(k)) = kept[k];
  return out;
}
} // namespace

BondedSystem bonded_system(const fem::Problem& problem, const SolverSettings& settings,
                           const std::vector<int32_t>& bonded_nodes)
{
  BondedSolve unused;
  ReducedBondedSystem reduced = reduce_bonded(problem, settings, bonded_nodes, unused);
  reduced.system.near_kernel = free_rigid_body_modes(problem, reduced.elimination);
  return std::move(reduced.system);
}

BondedSolve bonded_direct_solve(const fem::Problem& problem, const SolverSettings& settings,
                                const std::vector<int32_t>& bonded_nodes)
{
  // One undecomposed factorization: BLAS is the parallelism (common/parallel.hpp).
  const ScopedBlasThreads blas(threads());
  BondedSolve out;
  const ReducedBondedSystem reduced = reduce_bonded(problem, settings, bonded_nodes, out);
  const la::SparseMatrix& A_free = reduced.system.A;
  const la::Vector& rhs_free = reduced.system.b;

  auto start = std::chrono::steady_clock::now();
  la::CholmodFactor factor;
  factor.factorize(A_free, "the bonded stiffness (is every body supported once the bonded nodes are tied?)");
  out.factorization_seconds = seconds_since(start);
  out.factor_nonzeros = factor.factor_nonzeros();

  start = std::chrono::steady_clock::now();
  const la::Vector u_free = factor.solve(rhs_free);
  out.u = reduced.elimination.expand(u_free);
  out.solve_seconds = seconds_since(start);
  // CHOLMOD factorizes a singular stiffness (a body held only by contact, none of its nodes
  // bonded) without complaint when round-off keeps the pivots positive; the residual shows it.
  const double residual = (A_free * u_free - rhs_free).norm() / std::max(rhs_free.norm(), 1e-300);
  FETICON_CHECK(out.u.allFinite() && residual <= 1e-8,
                "bonded direct solve: the bonded system is singular (relative residual "
                    << residual << "): bond at least one node of every body held only by contact");

  const auto& rows = out.constraints;
  out.contact_lambda = reduced.eps.cwiseProduct(rows.B * out.u - rows.c);
  for (la::Index i = 0; i < out.contact_lambda.size(); ++i)
    if (!reduced.bonded[i])
      out.contact_lambda(i) = 0;
  return out;
}
} // namespace feticon::nonlinear
