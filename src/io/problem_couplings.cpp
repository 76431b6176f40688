#include "io/problem_couplings.hpp"

#include "common/error.hpp"
#include "io/problem_steps.hpp"

#include <algorithm>
#include <array>

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

} // namespace

std::vector<fem::Coupling> read_couplings(const YAML::Node& list, const mesh::Mesh& mesh, const ProblemReader& r)
{
  FETICON_CHECK(list.IsSequence(), r.source << ": couplings must be a list of couplings");
  std::vector<fem::Coupling> out;
  for (size_t i = 0; i < list.size(); ++i)
  {
    const YAML::Node c = list[i];
    const std::string key = "couplings." + std::to_string(i);
    r.only_keys(c, key, {"name", "kind", "surface", "nodes", "reference", "components", "moments"});
    fem::Coupling coupling;
    coupling.name = "coupling " + r.text(c["name"], key + ".name");
    FETICON_CHECK(std::ranges::none_of(out, [&](const fem::Coupling& o) { return o.name == coupling.name; }),
                  r.source << ": " << key << ".name: a second " << coupling.name);
    const std::string kind = r.text(c["kind"], key + ".kind");
    FETICON_CHECK(kind == "kinematic" || kind == "distributing",
                  r.source << ": " << key << ".kind = '" << kind << "' must be kinematic or distributing");
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
    r.only_keys(s, key, {"coupling", "x", "y", "z", "rx", "ry", "rz", "amplitude"});
    const int32_t j = coupling_of(s, key, r, p);
    const std::string amplitude = amplitude_of(s, key, r, p);
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
    r.only_keys(l, key, {"coupling", "force", "moment", "amplitude"});
    FETICON_CHECK(l["force"] || l["moment"], r.source << ": " << key << " needs a force or a moment");
    const int32_t j = coupling_of(l, key, r, p);
    const std::string amplitude = amplitude_of(l, key, r, p);
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
