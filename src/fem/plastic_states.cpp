#include "fem/plastic_states.hpp"

#include "common/error.hpp"
#include "fem/reference_element.hpp"

#include <algorithm>

namespace feticon::fem
{
size_t plastic_points(const mesh::Mesh& mesh, const std::vector<Material>& body_materials, int32_t c)
{
  if (!body_materials[mesh.cell_body[c]].is_plastic())
    return 0;
  return quadrature(mesh.cells.kind(c), mesh.reduced(c) ? Integration::reduced : Integration::full).points.size();
}

MeshPlasticStates MeshPlasticStates::zero(const mesh::Mesh& mesh, const std::vector<Material>& body_materials)
{
  MeshPlasticStates out;
  if (std::none_of(body_materials.begin(), body_materials.end(), [](const Material& m) { return m.is_plastic(); }))
    return out;
  out.offset.assign(1, 0);
  for (int32_t c = 0; c < mesh.n_cells(); ++c)
    out.offset.push_back(out.offset.back() + static_cast<int64_t>(plastic_points(mesh, body_materials, c)));
  out.points.resize(static_cast<size_t>(out.offset.back()));
  return out;
}

std::span<const PlasticPointState> MeshPlasticStates::of(int32_t c) const
{
  if (points.empty())
    return {};
  return std::span<const PlasticPointState>(points).subspan(static_cast<size_t>(offset[c]),
                                                            static_cast<size_t>(offset[c + 1] - offset[c]));
}

std::span<PlasticPointState> MeshPlasticStates::of(int32_t c)
{
  if (points.empty())
    return {};
  return std::span<PlasticPointState>(points).subspan(static_cast<size_t>(offset[c]),
                                                      static_cast<size_t>(offset[c + 1] - offset[c]));
}

double MeshPlasticStates::mean_equivalent_plastic_strain(int32_t c) const
{
  const std::span<const PlasticPointState> states = of(c);
  double sum = 0;
  for (const PlasticPointState& s : states)
    sum += s.equivalent_plastic_strain;
  return states.empty() ? 0.0 : sum / static_cast<double>(states.size());
}

MeshPlasticStates MeshPlasticStates::subset(const std::vector<int32_t>& cells) const
{
  MeshPlasticStates out;
  if (points.empty())
    return out;
  out.offset.assign(1, 0);
  for (const int32_t c : cells)
  {
    const std::span<const PlasticPointState> states = of(c);
    out.points.insert(out.points.end(), states.begin(), states.end());
    out.offset.push_back(static_cast<int64_t>(out.points.size()));
  }
  return out;
}

std::vector<double> MeshPlasticStates::pack(const std::vector<int32_t>& cells) const
{
  std::vector<double> out;
  for (const int32_t c : cells)
  {
    if (of(c).empty())
      continue;
    // -(c + 1): the layout with back stresses; an older one (7 doubles a point) wrote c >= 0.
    out.push_back(-(c + 1.0));
    for (const PlasticPointState& s : of(c))
    {
      out.insert(out.end(), s.plastic_strain.data(), s.plastic_strain.data() + 6);
      out.push_back(s.equivalent_plastic_strain);
      out.insert(out.end(), s.back_stress.data(), s.back_stress.data() + 6);
    }
  }
  return out;
}

void MeshPlasticStates::unpack(const std::vector<double>& packed)
{
  for (size_t i = 0; i < packed.size();)
  {
    FETICON_CHECK(packed[i] < 0,
                  "plastic states written by an older feticon (without back stresses): run the "
                  "problem again from its start");
    const auto c = static_cast<int32_t>(-packed[i++] - 1);
    FETICON_CHECK(c >= 0 && static_cast<size_t>(c) + 1 < offset.size() &&
                      i + packed_point_size * of(c).size() <= packed.size(),
                  "plastic states: cell " << c << " is not a plastic cell of this mesh, or its states are cut short");
    for (PlasticPointState& s : of(c))
    {
      s.plastic_strain = Eigen::Map<const Voigt>(&packed[i]);
      s.equivalent_plastic_strain = packed[i + 6];
      s.back_stress = Eigen::Map<const Voigt>(&packed[i + 7]);
      i += packed_point_size;
    }
  }
}
} // namespace feticon::fem
