#pragma once
/// @file Per-subdomain FETI data: stiffness K_s, kernel R_s and generalized inverse K_s^+.

#include "common/timer.hpp"
#include "decomposition/decomposition.hpp"
#include "decomposition/generalized_inverse.hpp"
#include "fem/assembler.hpp"
#include "fem/plastic_states.hpp"

#include <memory>
#include <vector>

namespace feticon::decomposition
{
struct SubdomainOperators
{
  /// Stiffness on active DOFs, lower triangle only: CHOLMOD reads no more, the products
  /// use K.selfadjointView<Eigen::Lower>(), and the upper half would double K's memory.
  la::SparseMatrix K;
  la::Matrix R; ///< orthonormal kernel basis (n_dofs x k)
  GeneralizedInverse K_plus;
};

/// Assembles and factorizes the subdomains this rank owns (all of them on one rank);
/// operators(s) of another rank's subdomain is empty.
class SubdomainSystem
{
public:
  /// @param kinematics linear: K_0; total_lagrangian: see update()
  /// @param precision what the Cholesky factors (K+, and SchurComplements' K_ii) are kept in
  SubdomainSystem(const Decomposition& decomposition, std::vector<fem::Material> materials, fem::Kinematics kinematics,
                  GeneralizedInverseMethod method,
                  la::FactorPrecision precision = la::FactorPrecision::double_precision);

  /// Assembles K_s at the stacked displacement `u` (material part K_M(u) in TL, K_0 when
  /// u = 0 or linear), computes R_s from the coordinates X + u and factorizes (a subdomain of
  /// hyperelastic cells whose K_M is indefinite: StiffnessKind::material_definite); with
  /// `timers`, adds the wall time of the two to its "assembly" and "factorization".
  void update(const la::Vector& u_stacked, TimerTable* timers = nullptr);

  /// @brief The temperature change T - T_0 (K) of every mesh node for the internal forces and
  /// stiffnesses that follow (fem::Assembler::set_temperature_change); empty: none.
  void set_temperature_change(const la::Vector& mesh_temperature_change);

  /// Makes the J2 states at stacked displacement `u` the committed ones in every owned
  /// subdomain (fem::Assembler::commit_plastic_state): the end of a converged increment.
  void commit_plastic_state(const la::Vector& u_stacked);
  /// The committed J2 states of the owned subdomains' cells, written into `states` (indexed by
  /// mesh cell, fem::MeshPlasticStates::zero of the mesh).
  void plastic_states(fem::MeshPlasticStates& states) const;
  /// Sets the owned subdomains' committed states from `states` (a restart).
  void set_plastic_states(const fem::MeshPlasticStates& states);

  /// Internal force of every subdomain at stacked displacement `u` (stacked).
  la::Vector internal_force(const la::Vector& u_stacked) const;

  const Decomposition& decomposition() const { return _decomposition; }
  const SubdomainOperators& operators(int32_t s) const { return _operators[s]; }
  int32_t n_subdomains() const { return static_cast<int32_t>(_operators.size()); }
  /// Kernel dimension of subdomain s and the start of its block in the kernel vector.
  int32_t kernel_dim(int32_t s) const { return static_cast<int32_t>(_kernel_offsets[s + 1] - _kernel_offsets[s]); }
  int64_t kernel_offset(int32_t s) const { return _kernel_offsets[s]; }
  int64_t n_kernel() const { return _kernel_offsets.back(); }
  /// Sum of the nonzeros of the owned Cholesky factors.
  long factor_nonzeros() const;
  la::FactorPrecision factor_precision() const { return _precision; }

private:
  la::Vector full_local(int32_t s, const la::Vector& u_stacked) const;
  /// K+ of a subdomain whose kernel is larger than its rigid-body modes (zero_energy_modes).
  void factor_with_zero_energy_modes(SubdomainOperators& op, la::Matrix modes, const std::string& what);
  /// Where K_M's factorization failed: K_M from each point's nearest positive definite tangent
  /// (hyperelastic and finite-strain plastic subdomains), or the error rethrown (call only in a
  /// handler).
  void factor_definite_part(int32_t s, const la::Vector& u_stacked, const std::vector<int32_t>& fixing_candidates,
                            const std::string& what);

  const Decomposition& _decomposition;
  GeneralizedInverseMethod _method;
  la::FactorPrecision _precision;
  std::vector<std::unique_ptr<fem::Assembler>> _assemblers;
  std::vector<SubdomainOperators> _operators;
  std::vector<int64_t> _kernel_offsets;
};
} // namespace feticon::decomposition
