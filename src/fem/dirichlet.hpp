#pragma once
/// @file Dirichlet conditions on named node sets, per component.

#include "fem/node_frames.hpp"
#include "la/types.hpp"
#include "mesh/mesh.hpp"

#include <array>
#include <map>
#include <optional>
#include <string>
#include <vector>

namespace feticon::fem
{
/// Prescribed displacement components (m) on the nodes of a named set; components left
/// empty are free (e.g. {nullopt, nullopt, 0.0} is u_z = 0).
struct DirichletCondition
{
  std::string set;
  std::array<std::optional<double>, 3> value;
  std::string amplitude = {}; ///< fem::Problem::amplitudes name; empty: the step's ramp
};

/// Constrained DOFs, sorted, with their prescribed values: global ones 3 node + component, then
/// local components of nodes with a frame (fem/node_frames.hpp: 3 N + 3 k + component).
struct ConstrainedDofs
{
  std::vector<int64_t> dofs;
  la::Vector values;
};

/// Sorted DOFs and values of a DOF -> value map.
ConstrainedDofs to_constrained_dofs(const std::map<int64_t, double>& prescribed);

/// The held DOF and value of component `component` = `value` of `node`: global, or along the
/// node's local axis if `frames` gives it one (fem/node_frames.hpp).
std::pair<int64_t, double> held_dof(const mesh::Mesh& mesh, const NodeFrames* frames, int32_t node, int component,
                                    double value);

/// Collects the DOFs of all conditions (components along the local axes of the nodes `frames`
/// gives frames); throws if two conditions prescribe different values on one DOF.
ConstrainedDofs collect_dirichlet(const mesh::Mesh& mesh, const std::vector<DirichletCondition>& conditions,
                                  double scale = 1.0, const NodeFrames* frames = nullptr);

/// Elimination of constrained DOFs for direct solves of undecomposed problems:
/// K_ff u_f = f_f - K_fc u_c.
class DirichletElimination
{
public:
  DirichletElimination(int64_t n_dofs, const ConstrainedDofs& constrained);
  int64_t n_free() const { return static_cast<int64_t>(_free.size()); }
  /// K_ff.
  la::SparseMatrix reduce_matrix(const la::SparseMatrix& K) const;
  /// f_f - K_fc u_c.
  la::Vector reduce_rhs(const la::SparseMatrix& K, const la::Vector& f) const;
  /// Full vector from free values and the prescribed values.
  la::Vector expand(const la::Vector& u_free) const;
  /// Free part of a full vector.
  la::Vector restrict(const la::Vector& full) const;
  /// Full vector with the free entries zeroed (the prescribed values in place).
  la::Vector prescribed() const;

private:
  int64_t _n_dofs;
  std::vector<int64_t> _free;
  std::vector<int32_t> _free_index; ///< DOF -> position in _free or -1
  ConstrainedDofs _constrained;
};
} // namespace feticon::fem
