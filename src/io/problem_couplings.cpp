#include "io/problem_couplings.hpp"

#include "common/error.hpp"
#include "io/problem_steps.hpp"

#include <algorithm>
#include <array>
#include <cmath>
#include <limits>

namespace feticon::io
{
namespace
{
/// Which of x, y, z a list like [x, z] names.
std::array<bool, 3> axes(const YAML::Node& list, const std::string& key, const ProblemReader& r)
{
  FETICON_CHECK(list.IsSequence(), r.source << ": " << key << " must be a list of x, y, z");
  std::array<bool, 3> out{false, false, false};
  for (size_t i = 0; i < list.size(); ++i)
  {
    const std::string axis = r.text(list[i], key + "." + std::to_string(i));
    FETICON_CHECK(axis == "x" || axis == "y" || axis == "z",
                  r.source << ": " << key << "." << i << " = '" << axis << "' must be x, y or z");
    out[static_cast<size_t>(axis[0] - 'x')] = true;
  }
  return out;
}

/// The index of the coupling entry `entry` names.
int32_t coupling_of(const YAML::Node& entry, const std::string& key, const ProblemReader& r, const fem::Problem& p)
{
  const std::string name = r.text(entry["coupling"], key + ".coupling");
  for (size_t j = 0; j < p.couplings.size(); ++j)
    if (p.couplings[j].name == "coupling " + name) // read_couplings' name
      return static_cast<int32_t>(j);
  FETICON_CHECK(false, r.source << ": " << key << ".coupling: no coupling '" << name << "' in couplings");
  return -1;
}

/// A face set of the mesh named by `entry[field]`.
std::string face_set_of(const YAML::Node& entry, const char* field, const std::string& key, const mesh::Mesh& mesh,
                        const ProblemReader& r)
{
  const std::string name = r.text(entry[field], key + "." + field);
  FETICON_CHECK(mesh.face_sets.count(name),
                r.source << ": " << key << "." << field << ": no face set '" << name
                         << "' in the mesh; it has: " << names_of(mesh.face_sets));
  return name;
}

/// A pretension section between the face sets `surface` and `partner` (problem_couplings.hpp):
/// each partner node paired with the surface node at its position (within 1e-6 of the shortest
/// distance between two surface nodes), as the node sets coupling_<number>_nodes and _partners.
fem::Coupling pretension(const YAML::Node& c, const std::string& key, size_t number, mesh::Mesh& mesh,
                         const ProblemReader& r)
{
  r.only_keys(c, key, {"name", "kind", "surface", "partner", "normal"});
  fem::Coupling coupling;
  coupling.kind = fem::CouplingKind::pretension;
  const std::string surface = face_set_of(c, "surface", key, mesh, r);
  coupling.faces = face_set_of(c, "partner", key, mesh, r);
  std::vector<int32_t> olds = mesh.face_set_nodes(surface);
  const std::vector<int32_t> news = mesh.face_set_nodes(coupling.faces);
  FETICON_CHECK(olds.size() == news.size(),
                r.source << ": " << key << ": surface " << surface << " has " << olds.size() << " nodes, partner "
                         << coupling.faces << " " << news.size()
                         << "; a pretension section joins two parts that meet with matching meshes");
  // The surface's nodes by x, so that each partner node looks at the few within the tolerance.
  const auto x = [&](int32_t n) { return mesh.nodes(n, 0); };
  std::ranges::sort(olds, {}, x);
  double spacing = std::numeric_limits<double>::infinity();
  for (size_t i = 0; i < olds.size(); ++i)
    for (size_t j = i + 1; j < olds.size() && x(olds[j]) - x(olds[i]) < spacing; ++j)
      spacing = std::min(spacing, (mesh.nodes.row(olds[j]) - mesh.nodes.row(olds[i])).norm());
  const double tolerance = 1e-6 * (std::isfinite(spacing) ? spacing : 1.0);
  std::vector<int32_t> paired;
  std::vector<char> taken(olds.size(), 0);
  for (const int32_t n : news)
  {
    int32_t match = -1;
    for (auto it = std::ranges::lower_bound(olds, x(n) - tolerance, {}, x);
         it != olds.end() && x(*it) <= x(n) + tolerance; ++it)
      if ((mesh.nodes.row(*it) - mesh.nodes.row(n)).norm() <= tolerance && !taken[it - olds.begin()])
      {
        match = *it;
        taken[it - olds.begin()] = 1;
        break;
      }
    FETICON_CHECK(match != n,
                  r.source << ": " << key << ": node " << n + 1 << " lies on both surface " << surface
                           << " and partner " << coupling.faces
                           << "; a pretension section joins two parts (two bodies) that meet there");
    FETICON_CHECK(match >= 0,
                  r.source << ": " << key << ": node " << n + 1 << " of partner " << coupling.faces << " at ("
                           << mesh.nodes(n, 0) << ", " << mesh.nodes(n, 1) << ", " << mesh.nodes(n, 2)
                           << ") has no node of surface " << surface
                           << " there; a pretension section joins two parts that meet with matching meshes");
    paired.push_back(match);
  }
  coupling.nodes = "coupling_" + std::to_string(number) + "_nodes";
  coupling.partners = "coupling_" + std::to_string(number) + "_partners";
  mesh.node_sets[coupling.nodes] = std::move(paired);
  mesh.node_sets[coupling.partners] = news;
  for (const int32_t n : news)
    coupling.reference += mesh.nodes.row(n).transpose() / static_cast<double>(news.size());
  if (c["normal"])
  {
    coupling.normal = r.vector3(c["normal"], key + ".normal");
    FETICON_CHECK(coupling.normal.norm() > 0 && coupling.normal.allFinite(),
                  r.source << ": " << key << ".normal must be a nonzero vector");
  }
  return coupling;
}
} // namespace

std::vector<fem::Coupling> read_couplings(const YAML::Node& list, mesh::Mesh& mesh, const ProblemReader& r)
{
  FETICON_CHECK(list.IsSequence(), r.source << ": couplings must be a list of couplings");
  std::vector<fem::Coupling> out;
  for (size_t i = 0; i < list.size(); ++i)
  {
    const YAML::Node c = list[i];
    const std::string key = "couplings." + std::to_string(i);
    FETICON_CHECK(c.IsMap(), r.source << ": " << key << " must be a map of keys (name, kind, ...)");
    const std::string name = "coupling " + r.text(c["name"], key + ".name");
    FETICON_CHECK(std::ranges::none_of(out, [&](const fem::Coupling& o) { return o.name == name; }),
                  r.source << ": " << key << ".name: a second " << name);
    const std::string kind = r.text(c["kind"], key + ".kind");
    FETICON_CHECK(kind == "kinematic" || kind == "distributing" || kind == "pretension",
                  r.source << ": " << key << ".kind = '" << kind << "' must be kinematic, distributing or pretension");
    if (kind == "pretension")
    {
      out.push_back(pretension(c, key, i + 1, mesh, r));
      out.back().name = name;
      continue;
    }
    r.only_keys(c, key, {"name", "kind", "surface", "nodes", "reference", "components", "moments"});
    fem::Coupling coupling;
    coupling.name = name;
    coupling.kind = kind == "kinematic" ? fem::CouplingKind::kinematic : fem::CouplingKind::distributing;
    coupling.reference = r.vector3(c["reference"], key + ".reference");
    FETICON_CHECK(c["surface"] ? !c["nodes"] : c["nodes"] && kind == "kinematic",
                  r.source << ": " << key << " needs one of surface (a face set) and nodes (a node set; kinematic)");
    if (c["surface"])
    {
      coupling.faces = r.text(c["surface"], key + ".surface");
      FETICON_CHECK(mesh.face_sets.count(coupling.faces),
                    r.source << ": " << key << ".surface: no face set '" << coupling.faces
                             << "' in the mesh; it has: " << names_of(mesh.face_sets));
    }
    else
    {
      coupling.nodes = r.text(c["nodes"], key + ".nodes");
      FETICON_CHECK(mesh.node_sets.count(coupling.nodes),
                    r.source << ": " << key << ".nodes: no node set '" << coupling.nodes
                             << "' in the mesh; it has: " << names_of(mesh.node_sets));
    }
    FETICON_CHECK(!c["components"] || kind == "kinematic",
                  r.source << ": " << key << ".components belongs to a kinematic coupling");
    FETICON_CHECK(!c["moments"] || kind == "distributing",
                  r.source << ": " << key << ".moments belongs to a distributing coupling");
    if (c["components"])
      coupling.components = axes(c["components"], key + ".components", r);
    if (c["moments"])
      coupling.moments = axes(c["moments"], key + ".moments", r);
    out.push_back(std::move(coupling));
  }
  return out;
}

std::vector<fem::ReferenceValue> coupling_supports(const YAML::Node& list, const std::string& where,
                                                   const ProblemReader& r, fem::Problem& p)
{
  std::vector<fem::ReferenceValue> out;
  static constexpr const char* names[6] = {"x", "y", "z", "rx", "ry", "rz"};
  for (size_t i = 0; list.IsSequence() && i < list.size(); ++i)
  {
    const YAML::Node s = list[i];
    if (!s.IsMap() || !s["coupling"])
      continue;
    const std::string key = where + "." + std::to_string(i);
    r.only_keys(s, key, {"coupling", "x", "y", "z", "rx", "ry", "rz", "gap", "amplitude"});
    const int32_t j = coupling_of(s, key, r, p);
    const std::string amplitude = amplitude_of(s, key, r, p);
    // A pretension section's one reference DOF is its gap.
    const bool section = p.couplings[j].kind == fem::CouplingKind::pretension;
    FETICON_CHECK(section == static_cast<bool>(s["gap"]) &&
                      (!section || std::ranges::none_of(names, [&](const char* d) { return s[d].IsDefined(); })),
                  r.source << ": " << key
                           << (section ? " holds a pretension section's gap alone (gap: m)"
                                       : ".gap belongs to a pretension coupling (x, y, z, rx, ry, rz here)"));
    if (section)
    {
      out.push_back({j, 0, r.number(s["gap"], key + ".gap"), amplitude});
      continue;
    }
    const size_t before = out.size();
    for (int d = 0; d < 6; ++d)
      if (s[names[d]])
        out.push_back({j, d, r.number(s[names[d]], key + "." + names[d]), amplitude});
    FETICON_CHECK(out.size() > before, r.source << ": " << key << " holds no DOF (x, y, z, rx, ry or rz)");
  }
  return out;
}

std::vector<fem::ReferenceValue> coupling_loads(const YAML::Node& list, const std::string& where,
                                                const ProblemReader& r, fem::Problem& p)
{
  std::vector<fem::ReferenceValue> out;
  for (size_t i = 0; list.IsSequence() && i < list.size(); ++i)
  {
    const YAML::Node l = list[i];
    if (!l.IsMap() || !l["coupling"])
      continue;
    const std::string key = where + "." + std::to_string(i);
    r.only_keys(l, key, {"coupling", "force", "moment", "tension", "amplitude"});
    const int32_t j = coupling_of(l, key, r, p);
    const std::string amplitude = amplitude_of(l, key, r, p);
    // A pretension section's one reference DOF carries its tension.
    const bool section = p.couplings[j].kind == fem::CouplingKind::pretension;
    FETICON_CHECK(section ? l["tension"] && !l["force"] && !l["moment"] : !l["tension"],
                  r.source << ": " << key
                           << (section ? " holds a pretension section's tension alone (tension: N)"
                                       : ".tension belongs to a pretension coupling (force and moment here)"));
    if (section)
    {
      out.push_back({j, 0, r.number(l["tension"], key + ".tension"), amplitude});
      continue;
    }
    FETICON_CHECK(l["force"] || l["moment"], r.source << ": " << key << " needs a force or a moment");
    for (const auto& [name, first] : {std::pair{"force", 0}, std::pair{"moment", 3}})
      if (l[name])
      {
        const Eigen::Vector3d v = r.vector3(l[name], key + "." + name);
        for (int c = 0; c < 3; ++c)
          if (v(c) != 0)
            out.push_back({j, first + c, v(c), amplitude});
      }
  }
  return out;
}
} // namespace feticon::io
