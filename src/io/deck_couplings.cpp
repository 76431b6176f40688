#include "io/deck_couplings.hpp"

#include "common/error.hpp"

#include <algorithm>
#include <charconv>

namespace feticon::io
{
namespace
{
/// The nodes of a *DISTRIBUTING COUPLING line: a node label or a node set.
std::vector<int32_t> weighted_nodes(const DeckData& data, const DeckCoupling& c, const DeckCoupling::Weighted& w)
{
  int64_t label = 0;
  const char* const end = w.nodes.data() + w.nodes.size();
  if (const auto [stop, ec] = std::from_chars(w.nodes.data(), end, label); ec == std::errc() && stop == end)
  {
    const int32_t n = data.node_index.find(label);
    FETICON_CHECK(n >= 0, w.where.str() << ": " << c.name << ": node " << label << " is not defined");
    return {n};
  }
  const auto it = data.node_sets.find(w.nodes);
  FETICON_CHECK(it != data.node_sets.end(),
                w.where.str() << ": " << c.name << ": no node set '" << w.nodes << "' is defined");
  return it->second.expand();
}

/// The mesh nodes of what a kinematic or distributing coupling names: a node surface's own
/// nodes (CalculiX couples those, not the faces they span; one of no element's node is refused
/// with its faces, deck_model.cpp), an element surface's faces' nodes.
std::vector<int32_t> coupled_nodes(const DeckData& data, const DeckCoupling& c, const mesh::Mesh& mesh,
                                   const std::map<std::string, std::vector<int32_t>>& element_sets,
                                   const std::function<int32_t(int32_t)>& mesh_of)
{
  if (!c.node_set.empty())
  {
    const auto it = mesh.node_sets.find(c.node_set);
    FETICON_CHECK(it != mesh.node_sets.end(), c.name << ": NSET=" << c.node_set << " names no node set");
    return it->second;
  }
  if (!c.element_set.empty())
  {
    const auto it = element_sets.find(c.element_set);
    FETICON_CHECK(it != element_sets.end(), c.name << ": ELSET=" << c.element_set << " names no element set");
    std::vector<int32_t> out;
    for (const int32_t cell : it->second)
      for (const int32_t n : mesh.cells[cell])
        out.push_back(n);
    std::ranges::sort(out);
    out.erase(std::unique(out.begin(), out.end()), out.end());
    return out;
  }
  if (const auto surface = data.surfaces.find(c.surface); surface != data.surfaces.end() && surface->second.node_based)
  {
    std::vector<int32_t> out;
    for (const int32_t node : surface->second.nodes)
      if (mesh_of(node) >= 0)
        out.push_back(mesh_of(node));
    std::ranges::sort(out);
    out.erase(std::unique(out.begin(), out.end()), out.end());
    return out;
  }
  FETICON_CHECK(mesh.face_sets.count(c.surface), c.name << ": SURFACE=" << c.surface << " names no *SURFACE");
  return mesh.face_set_nodes(c.surface);
}
} // namespace

DeckReferenceNodes deck_reference_nodes(const DeckData& data, const std::function<int64_t(int32_t)>& label_of)
{
  DeckReferenceNodes out;
  for (size_t j = 0; j < data.couplings.size(); ++j)
  {
    const DeckCoupling& c = data.couplings[j];
    out.positions.push_back(c.ref_node >= 0 ? Eigen::Vector3d(data.coordinates.row(c.ref_node).transpose())
                                            : Eigen::Vector3d::Zero());
    for (const auto& [node, first] : {std::pair{c.ref_node, 0}, std::pair{c.rot_node, 3}})
    {
      if (node < 0)
        continue;
      const auto [it, inserted] = out.of_node.emplace(node, std::pair{static_cast<int32_t>(j), first});
      FETICON_CHECK(inserted,
                    c.name << ": node " << label_of(node) << " is a reference node of "
                           << data.couplings[static_cast<size_t>(it->second.first)].name << " already");
    }
    std::vector<std::pair<int32_t, double>>& weighted = out.weighted.emplace_back();
    for (const DeckCoupling::Weighted& w : c.weighted)
      for (const int32_t n : weighted_nodes(data, c, w))
        weighted.emplace_back(n, w.weight);
  }
  return out;
}

std::vector<fem::Coupling> deck_couplings(const DeckData& data, const DeckReferenceNodes& reference, mesh::Mesh& mesh,
                                          const std::map<std::string, std::vector<int32_t>>& element_sets,
                                          const std::function<int32_t(int32_t)>& mesh_of,
                                          const std::function<int64_t(int32_t)>& label_of)
{
  std::vector<fem::Coupling> out;
  for (size_t j = 0; j < data.couplings.size(); ++j)
  {
    const DeckCoupling& c = data.couplings[j];
    FETICON_CHECK(c.rot_node < 0 || mesh_of(c.rot_node) < 0,
                  c.name << ": ROT NODE " << label_of(c.rot_node)
                         << " belongs to an element; its DOFs are the rigid body's rotations and must be its own");
    fem::Coupling& coupling = out.emplace_back();
    coupling.name = c.name;
    coupling.kind = c.kind;
    coupling.reference = reference.positions[j];
    coupling.nodes = "coupling_" + std::to_string(j + 1) + "_nodes";
    coupling.components = c.components;
    coupling.moments = c.moments;
    if (c.kind == fem::CouplingKind::pretension)
    {
      // The model builder doubled the section's nodes and named the pairs' sets.
      coupling.partners = "coupling_" + std::to_string(j + 1) + "_partners";
      coupling.faces = c.surface;
      coupling.normal = c.normal;
      continue;
    }
    std::vector<int32_t>& nodes = mesh.node_sets[coupling.nodes];
    if (c.kind != fem::CouplingKind::mean)
    {
      nodes = coupled_nodes(data, c, mesh, element_sets, mesh_of);
      if (c.kind == fem::CouplingKind::distributing)
        coupling.faces = c.surface;
      continue;
    }
    std::map<int32_t, double> weight; // a node given twice takes both weights
    for (const auto& [read_node, w] : reference.weighted[j])
    {
      const int32_t m = mesh_of(read_node);
      FETICON_CHECK(m >= 0, c.name << ": node " << label_of(read_node) << " belongs to no element");
      weight[m] += w;
    }
    for (const auto& [m, w] : weight)
    {
      nodes.push_back(m);
      coupling.weights.push_back(w);
    }
  }
  return out;
}

std::vector<fem::ReferenceValue> reference_values(DeckData& data, const DeckReferenceNodes& reference,
                                                  const std::map<int64_t, DeckValue>& translations,
                                                  const std::map<int64_t, DeckValue>& rotations, bool supports,
                                                  const std::function<int32_t(int32_t)>& mesh_of,
                                                  const std::function<int64_t(int32_t)>& label_of)
{
  std::vector<fem::ReferenceValue> out;
  for (const auto& [dof, value] : translations)
  {
    const int32_t node = static_cast<int32_t>(dof / 3);
    const auto it = reference.of_node.find(node);
    // A reference node an element uses keeps its DOFs 1-3 (file comment).
    if (it != reference.of_node.end() && !(it->second.second == 0 && mesh_of(node) >= 0))
      out.push_back({it->second.first, it->second.second + static_cast<int>(dof % 3), value.value, value.amplitude});
  }
  for (const auto& [dof, value] : rotations)
  {
    const int32_t node = static_cast<int32_t>(dof / 3);
    const auto it = reference.of_node.find(node);
    if (it == reference.of_node.end() || it->second.second != 0)
    {
      FETICON_CHECK(supports,
                    "*CLOAD: a moment (degree of freedom " << dof % 3 + 4 << ") on node " << label_of(node)
                                                           << ", which is no reference node (solid nodes "
                                                              "have no rotations)");
      data.warn("*BOUNDARY on degrees of freedom 4 to 6 (rotations) of nodes that are no reference node: solid "
                "elements have none, so they are not used");
      continue;
    }
    out.push_back({it->second.first, 3 + static_cast<int>(dof % 3), value.value, value.amplitude});
  }
  return out;
}
} // namespace feticon::io
