#pragma once
/// @file The committed J2 states of a mesh's plastic cells, one per quadrature point: what the
/// outputs (stress, equivalent plastic strain) and a checkpoint read after a solve.

#include "fem/j2_plasticity.hpp"
#include "fem/material.hpp"
#include "mesh/mesh.hpp"

#include <span>
#include <vector>

namespace feticon::fem
{
/// Quadrature points of cell `c` that keep a J2 state: its rule's where its body is plastic, else 0.
size_t plastic_points(const mesh::Mesh& mesh, const std::vector<Material>& body_materials, int32_t c);

struct MeshPlasticStates
{
  /// The states of cell c are points[offset[c], offset[c + 1]); empty: no plastic cell.
  std::vector<int64_t> offset;
  std::vector<PlasticPointState> points;

  /// Zero states at every point of every plastic cell of `mesh`.
  static MeshPlasticStates zero(const mesh::Mesh& mesh, const std::vector<Material>& body_materials);
  bool empty() const { return points.empty(); }
  std::span<const PlasticPointState> of(int32_t c) const;
  std::span<PlasticPointState> of(int32_t c);
  /// The mean equivalent plastic strain over cell c's points (0 for an elastic cell).
  double mean_equivalent_plastic_strain(int32_t c) const;
  /// The states of `cells`, in that order, as a MeshPlasticStates of a piece of the mesh (its
  /// cell k is cells[k]: mesh::submesh's numbering).
  MeshPlasticStates subset(const std::vector<int32_t>& cells) const;
  /// Numbers per point in pack's layout: eps_p (6), eqps, back stress (6).
  static constexpr size_t packed_point_size = 13;
  /// The states of `cells` as numbers: per cell -(id + 1) (an older layout, without back
  /// stresses, wrote id), then packed_point_size per point.
  std::vector<double> pack(const std::vector<int32_t>& cells) const;
  /// Sets the states of the cells in `packed` (pack's output, possibly several concatenated).
  void unpack(const std::vector<double>& packed);
};
} // namespace feticon::fem
