#include "io/problem_file.hpp"

#include "common/error.hpp"
#include "io/problem_reader.hpp"
#include "io/problem_couplings.hpp"
#include "io/problem_steps.hpp"
#include "mesh/box.hpp"
#include "mesh/gmsh_precheck.hpp"
#include "mesh/gmsh_reader.hpp"

#include <cmath>
#include <map>
#include <optional>
#include <algorithm>
#include <array>
#include <set>
#include <sstream>
#include <yaml-cpp/depthguard.h>

namespace feticon::io
{
namespace
{
const std::set<std::string> structured_keys = {
    "mesh",  "materials",  "bodies",  "plane_strain", "supports", "loads", "temperatures", "initial_temperature",
    "steps", "amplitudes", "contact", "ties",         "couplings"};

/// A body's `plastic:` table [[von Mises stress, equivalent plastic strain], ...] (the rows of
/// CalculiX's *PLASTIC).
fem::YieldCurve yield_curve(const YAML::Node& table, const std::string& key, const ProblemReader& r)
{
  FETICON_CHECK(table.IsSequence() && table.size() > 0,
                r.source << ": " << key << " must be a list of [von Mises stress, equivalent plastic strain]");
  fem::YieldCurve curve;
  for (size_t i = 0; i < table.size(); ++i)
  {
    const std::string at = key + "[" + std::to_string(i) + "]";
    FETICON_CHECK(table[i].IsSequence() && table[i].size() == 2,
                  r.source << ": " << at << " must be [von Mises stress, equivalent plastic strain]");
    curve.stress.push_back(r.number(table[i][0], at + "[0]"));
    curve.plastic_strain.push_back(r.number(table[i][1], at + "[1]"));
  }
  curve.check(r.source + ": " + key);
  return curve;
}

/// A body's `hyperelastic: {c10, c01, d1}` (CalculiX's *HYPERELASTIC; c01 0 or absent: Neo-Hooke).
fem::Hyperelastic hyperelastic_law(const YAML::Node& node, const std::string& key, const ProblemReader& r)
{
  FETICON_CHECK(node.IsMap(), r.source << ": " << key << " must be a map {c10, c01, d1} (Pa, Pa, 1/Pa)");
  r.only_keys(node, key, {"c10", "c01", "d1"});
  fem::Hyperelastic law;
  law.c10 = r.number(node["c10"], key + ".c10");
  law.c01 = node["c01"] ? r.number(node["c01"], key + ".c01") : 0.0;
  law.d1 = r.number(node["d1"], key + ".d1");
  law.check(r.source + ": " + key);
  return law;
}

/// The material properties at `key` (materials.NAME, or a body's or section's own): young and
/// poisson, or a hyperelastic law, and the optional density, expansion and plastic table.
/// `other_keys` are the keys beside them (a section's cells).
fem::Material material_properties(const YAML::Node& entry, const std::string& key, const ProblemReader& r,
                                  std::set<std::string> other_keys = {})
{
  other_keys.insert({"young", "poisson", "density", "expansion", "plastic", "hardening", "hyperelastic"});
  r.only_keys(entry, key, other_keys);
  fem::Material m;
  if (entry["hyperelastic"])
  {
    FETICON_CHECK(!entry["young"] && !entry["poisson"],
                  r.source << ": " << key << " gives young / poisson and a hyperelastic law: one or the other");
    m.set_hyperelastic(hyperelastic_law(entry["hyperelastic"], key + ".hyperelastic", r));
  }
  else
  {
    m.young = r.number(entry["young"], key + ".young");
    m.poisson = r.number(entry["poisson"], key + ".poisson");
  }
  if (entry["density"])
    m.density = r.number(entry["density"], key + ".density");
  if (entry["expansion"])
    m.expansion = r.number(entry["expansion"], key + ".expansion");
  if (entry["plastic"])
    m.plastic = yield_curve(entry["plastic"], key + ".plastic", r);
  if (entry["hardening"])
  {
    // CalculiX's HARDENING=: the table grows the yield surface or moves it (fem/yield_curve.hpp).
    const std::string hardening = r.text(entry["hardening"], key + ".hardening");
    FETICON_CHECK(hardening == "isotropic" || hardening == "kinematic",
                  r.source << ": " << key << ".hardening: '" << hardening << "' is not isotropic or kinematic");
    FETICON_CHECK(entry["plastic"], r.source << ": " << key << ".hardening needs a plastic: table");
    m.plastic.kinematic = hardening == "kinematic";
  }
  m.check(r.source + ": " + key);
  return m;
}

/// The named materials of the top-level `materials:` map (none without one).
std::map<std::string, fem::Material> named_materials(const YAML::Node& node, const ProblemReader& r)
{
  std::map<std::string, fem::Material> materials;
  if (!node)
    return materials;
  FETICON_CHECK(node.IsMap() && node.size() > 0,
                r.source << ": materials must be a map of names to properties, e.g. {steel: {young: 2.1e11, "
                            "poisson: 0.3}}");
  for (const auto& kv : node)
  {
    const std::string name = kv.first.as<std::string>();
    materials.emplace(name, material_properties(kv.second, "materials." + name, r));
  }
  return materials;
}

/// The material at `key`: `material: NAME` of `materials`, or properties of its own.
fem::Material material_entry(const YAML::Node& entry, const std::string& key,
                             const std::map<std::string, fem::Material>& materials, const ProblemReader& r,
                             std::set<std::string> other_keys = {})
{
  FETICON_CHECK(entry.IsMap(),
                r.source << ": " << key
                         << " must be a map: young and poisson (or a hyperelastic law), or material: "
                            "a name of materials:");
  if (!entry["material"])
    return material_properties(entry, key, r, other_keys);
  other_keys.insert("material");
  r.only_keys(entry, key + " (a named material: its properties are under materials:)", other_keys);
  const std::string name = r.text(entry["material"], key + ".material");
  const auto material = materials.find(name);
  FETICON_CHECK(
      material != materials.end(),
      r.source << ": " << key << ".material: no material '" << name << "' under materials:"
               << (materials.empty() ? " (the file has no materials: section)" : "; it has: " + names_of(materials)));
  return material->second;
}

/// The material of every body of `p.mesh` from the problem file's `bodies:` (and `materials:`).
/// A body entry names a body of the mesh and gives its material, or gives `sections:`, each
/// naming a body of the mesh as its cells and its material: one connected mesh of several
/// materials (Gmsh volumes fragmented together), whose bodies share the nodes of their
/// interfaces and are glued there as subdomains are. Bodies that share nodes must be sections
/// of one body entry: two bodies meant to touch are separate meshes, and a shared node between
/// them is a meshing mistake that would glue them silently.
void body_materials(const YAML::Node& root, const ProblemReader& r, fem::Problem& p)
{
  const mesh::Mesh& mesh = p.mesh;
  const auto materials = named_materials(root["materials"], r);
  FETICON_CHECK(root["bodies"] && root["bodies"].IsMap(),
                r.source << ": 'bodies' must give the material of every body (young and poisson, or material: NAME)");
  std::map<std::string, int32_t> body_index;
  for (int32_t b = 0; b < mesh.n_bodies(); ++b)
    body_index.emplace(mesh.body_names[b], b);
  const auto mesh_body = [&](const std::string& name, const std::string& key) {
    const auto it = body_index.find(name);
    FETICON_CHECK(it != body_index.end(),
                  r.source << ": " << key << ": the mesh has no body '" << name
                           << "'; it has: " << names_of(body_index));
    return it->second;
  };
  std::vector<std::optional<fem::Material>> material(mesh.n_bodies());
  std::vector<std::string> entry_of(mesh.n_bodies()); // the bodies: entry that gives each its material
  const auto assign = [&](int32_t body, fem::Material m, const std::string& entry, const std::string& key) {
    FETICON_CHECK(!material[body],
                  r.source << ": " << key << ": body '" << mesh.body_names[body]
                           << "' already has its material from bodies." << entry_of[body]);
    material[body] = std::move(m);
    entry_of[body] = entry;
  };
  for (const auto& kv : root["bodies"])
  {
    const std::string name = kv.first.as<std::string>();
    const std::string key = "bodies." + name;
    const YAML::Node& entry = kv.second;
    if (!entry.IsMap() || !entry["sections"])
    {
      assign(mesh_body(name, key), material_entry(entry, key, materials, r), name, key);
      continue;
    }
    r.only_keys(entry, key, {"sections"});
    FETICON_CHECK(!body_index.count(name),
                  r.source << ": " << key << " has sections, so it names no body of the mesh, but the mesh has a body '"
                           << name << "': give it as the cells of a section and the entry another name");
    const YAML::Node& sections = entry["sections"];
    FETICON_CHECK(sections.IsSequence() && sections.size() > 0,
                  r.source << ": " << key << ".sections must be a list of {cells: BODY, material: NAME}");
    for (size_t i = 0; i < sections.size(); ++i)
    {
      const std::string at = key + ".sections[" + std::to_string(i) + "]";
      FETICON_CHECK(sections[i].IsMap() && sections[i]["cells"],
                    r.source << ": " << at << " needs cells: (a body of the mesh) and its material");
      const int32_t body = mesh_body(r.text(sections[i]["cells"], at + ".cells"), at + ".cells");
      assign(body, material_entry(sections[i], at, materials, r, {"cells"}), name, at);
    }
  }
  for (int32_t b = 0; b < mesh.n_bodies(); ++b)
    FETICON_CHECK(material[b],
                  r.source << ": bodies." << mesh.body_names[b]
                           << " is missing (young and poisson, material: NAME, or a section's cells)");
  for (const mesh::SharedBodies& shared : mesh::bodies_sharing_nodes(mesh))
  {
    const std::string& first = mesh.body_names[shared.first_body];
    const std::string& second = mesh.body_names[shared.second_body];
    // Two bodies of one entry are its sections (a plain entry gives one body).
    FETICON_CHECK(entry_of[shared.first_body] == entry_of[shared.second_body],
                  r.source << ": bodies '" << first << "' and '" << second << "' share the node at ("
                           << mesh.nodes(shared.node, 0) << ", " << mesh.nodes(shared.node, 1) << ", "
                           << mesh.nodes(shared.node, 2)
                           << "): bodies meant to touch must be separate meshes (do not fragment or "
                              "Coherence their volumes); one connected mesh of several materials is one "
                              "body of sections (bodies.NAME.sections)");
  }
  for (auto& m : material)
    p.materials.push_back(std::move(*m));
}

std::vector<std::string> split_path(const std::string& path)
{
  std::vector<std::string> parts;
  std::stringstream ss(path);
  std::string part;
  while (std::getline(ss, part, '.'))
    parts.push_back(part);
  return parts;
}

bool is_index(const std::string& s) { return !s.empty() && s.find_first_not_of("0123456789") == std::string::npos; }

/// Sets the node at `path` (creating maps on the way) to `value`.
void set_path(YAML::Node node, const std::vector<std::string>& path, size_t i, const YAML::Node& value,
              const std::string& full)
{
  const std::string& key = path[i];
  const bool last = i + 1 == path.size();
  if (node.IsSequence())
  {
    FETICON_CHECK(is_index(key) && std::stoul(key) < node.size(),
                  "--set " << full << ": '" << key << "' is not an index of a list of " << node.size() << " entries");
    if (last)
      node[std::stoul(key)] = value;
    else
      set_path(node[std::stoul(key)], path, i + 1, value, full);
    return;
  }
  FETICON_CHECK(node.IsMap() || node.IsNull(), "--set " << full << ": '" << key << "' is below a single value");
  if (last)
  {
    node[key] = value;
    return;
  }
  if (!node[key] || !(node[key].IsMap() || node[key].IsSequence()))
    node[key] = YAML::Node(YAML::NodeType::Map);
  set_path(node[key], path, i + 1, value, full);
}

/// Throws for a key given twice in one map: YAML forbids it, yaml-cpp keeps both entries and
/// a lookup would silently take one of them. Also requires every key to be a name (a scalar)
/// and bounds the nesting, before anything else walks the tree: an alias that contains itself
/// (`x: &r [*r]`) makes an endless tree, which would overflow the stack.
void reject_duplicate_keys(const YAML::Node& node, const std::string& path, const std::string& source, int depth = 0)
{
  constexpr int max_depth = 32; // a problem file nests a few levels (sections, lists of maps)
  FETICON_CHECK(depth <= max_depth,
                source << ": '" << path.substr(0, 80) << (path.size() > 80 ? "..." : "") << "' nests deeper than "
                       << max_depth << " levels (a YAML alias that contains itself?)");
  if (node.IsMap())
  {
    std::set<std::string> seen;
    for (const auto& kv : node)
    {
      // Every later lookup reads keys as names: a list or map as a key (a stray '!' or '?' in
      // a flow map) would end in yaml-cpp's "bad conversion" without file or key.
      FETICON_CHECK(kv.first.IsScalar(),
                    source << ": '" << path.substr(0, 80) << "' has a key that is not a name (line "
                           << kv.first.Mark().line + 1 << ")");
      const std::string key = kv.first.Scalar();
      const std::string full = path.empty() ? key : path + "." + key;
      FETICON_CHECK(seen.insert(key).second,
                    source << ": key '" << full << "' is given twice (line " << kv.first.Mark().line + 1 << ")");
      reject_duplicate_keys(kv.second, full, source, depth + 1);
    }
  }
  else if (node.IsSequence())
    for (size_t i = 0; i < node.size(); ++i)
      reject_duplicate_keys(node[i], path + "." + std::to_string(i), source, depth + 1);
}

/// Scalars of the non-structured part as dotted keys.
void flatten(const YAML::Node& node, const std::string& prefix, const Settings& settings,
             std::vector<std::pair<std::string, std::string>>& out, const std::string& source)
{
  if (node.IsMap())
  {
    // A map where a setting's value belongs, or an empty section, would otherwise be
    // dropped without a word (`displacements: {}` ran with the default).
    FETICON_CHECK(!settings.knows(prefix), source << ": '" << prefix << "' must be a single value, not a map");
    FETICON_CHECK(prefix.empty() || node.size() > 0, source << ": section '" << prefix << "' is empty");
    for (const auto& kv : node)
      flatten(kv.second, prefix.empty() ? kv.first.as<std::string>() : prefix + "." + kv.first.as<std::string>(),
              settings, out, source);
    return;
  }
  if (!node.IsScalar())
  {
    settings.spec(prefix, source); // an unknown key is named as such whatever its value
    FETICON_CHECK(false, source << ": '" << prefix << "' must be a single value");
  }
  out.emplace_back(prefix, node.as<std::string>());
}

/// A box's `cells`: three integers in 1..10000 (read before meshing by the memory guard too).
std::array<int, 3> box_cells(const YAML::Node& box, const std::string& key, const ProblemReader& r)
{
  const Eigen::Vector3d cells = r.vector3(box["cells"], key + ".cells");
  for (int d = 0; d < 3; ++d)
    FETICON_CHECK(cells(d) >= 1 && cells(d) == std::floor(cells(d)) && cells(d) <= 1e4,
                  r.source << ": " << key << ".cells must be three positive integers (at most 10000)");
  return {static_cast<int>(cells(0)), static_cast<int>(cells(1)), static_cast<int>(cells(2))};
}

mesh::Mesh boxes_mesh(const YAML::Node& boxes, const ProblemReader& r)
{
  FETICON_CHECK(boxes.IsSequence() && boxes.size() > 0, r.source << ": mesh.boxes must be a non-empty list of boxes");
  mesh::Mesh out;
  for (size_t i = 0; i < boxes.size(); ++i)
  {
    const std::string key = "mesh.boxes." + std::to_string(i);
    r.only_keys(boxes[i], key, {"name", "origin", "lengths", "cells"});
    mesh::BoxParameters p;
    p.body_name = r.text(boxes[i]["name"], key + ".name");
    p.origin = boxes[i]["origin"] ? r.vector3(boxes[i]["origin"], key + ".origin") : Eigen::Vector3d::Zero();
    p.lengths = r.vector3(boxes[i]["lengths"], key + ".lengths");
    const std::array<int, 3> cells = box_cells(boxes[i], key, r);
    p.nx = cells[0];
    p.ny = cells[1];
    p.nz = cells[2];
    mesh::Mesh box = mesh::generate_box(p); // validates lengths
    if (i == 0)
    {
      // Sets are always <body>_<face> so that every box reads alike.
      std::map<std::string, std::vector<int32_t>> nodes;
      std::map<std::string, std::vector<mesh::Face>> faces;
      for (auto& [name, set] : box.node_sets)
        nodes[p.body_name + "_" + name] = set;
      for (auto& [name, set] : box.face_sets)
        faces[p.body_name + "_" + name] = set;
      box.node_sets = nodes;
      box.face_sets = faces;
      out = std::move(box);
    }
    else
      mesh::append_mesh(out, box, p.body_name + "_");
  }
  return out;
}
} // namespace

bool is_structured_key(const std::string& key) { return structured_keys.count(key) > 0; }

bool is_deck_file(const std::filesystem::path& path)
{
  std::string extension = path.extension().string();
  for (char& c : extension)
    c = static_cast<char>(std::tolower(static_cast<unsigned char>(c)));
  return extension == ".inp";
}

namespace
{
/// The settings a deck implies, below the overrides: `feticon run model.inp`.
void settings_of_deck(ProblemFile& file, const std::filesystem::path& path)
{
  file.deck_outline = deck_outline(path);
  const DeckOutline& outline = file.deck_outline;
  file.deck = std::filesystem::absolute(path);
  // The model's whole description is the deck; the tree names it, so problem.yaml reruns it.
  file.root["problem"] = "custom";
  file.root["mesh"]["file"] = file.deck.string();
  const std::string source = path.string();
  file.settings.set("displacements", outline.nlgeom ? "large" : "small", source);
  if (outline.increments) // a first *STATIC, DIRECT; automatic increments are the deck's step 1's
    file.settings.set("load_steps", std::to_string(*outline.increments), source);
}

/// A body load of the `loads` list: {gravity: [gx, gy, gz]} or {centrifugal: {omega, point,
/// axis}}, on one body (`body: NAME`) or on all.
/// A pair's or tie's `formulation:` (node_to_segment or mortar).
fem::ContactFormulation formulation_of(const YAML::Node& node, const std::string& key, const ProblemReader& r)
{
  const std::string formulation = r.text(node, key);
  FETICON_CHECK(formulation == "mortar" || formulation == "node_to_segment",
                r.source << ": " << key << " = '" << formulation << "' must be one of: node_to_segment, mortar");
  return formulation == "mortar" ? fem::ContactFormulation::mortar : fem::ContactFormulation::node_to_segment;
}

/// A pair's `law:` (fem::NormalLaw): hard, {model: linear, slope: K}, {model: exponential, c0,
/// p0} or {model: tabular, table: [[overclosure, pressure], ...]}; solved where the setting
/// contact.law is deck.
fem::NormalLaw pair_law(const YAML::Node& node, const std::string& key, const ProblemReader& r)
{
  fem::NormalLaw law;
  if (node.IsScalar())
  {
    FETICON_CHECK(r.text(node, key) == "hard",
                  r.source << ": " << key << " = '" << r.text(node, key)
                           << "': give hard, or a map with model (linear, exponential, "
                              "tabular) and its constants");
    return law;
  }
  const std::string model = r.text(node["model"], key + ".model");
  const auto positive = [&](const char* name) {
    const double value = r.number(node[name], key + "." + name);
    FETICON_CHECK(std::isfinite(value) && value > 0,
                  r.source << ": " << key << "." << name << " = " << value << " must be positive");
    return value;
  };
  if (model == "hard")
    r.only_keys(node, key, {"model"});
  else if (model == "linear")
  {
    r.only_keys(node, key, {"model", "slope"});
    law = {fem::NormalLawKind::linear, positive("slope")};
  }
  else if (model == "exponential")
  {
    r.only_keys(node, key, {"model", "c0", "p0"});
    law.kind = fem::NormalLawKind::exponential;
    law.c0 = positive("c0");
    law.p0 = positive("p0");
  }
  else if (model == "tabular")
  {
    r.only_keys(node, key, {"model", "table"});
    law.kind = fem::NormalLawKind::tabular;
    const YAML::Node table = node["table"];
    FETICON_CHECK(table && table.IsSequence() && table.size() > 0,
                  r.source << ": " << key << ".table must be a list of [overclosure, pressure] pairs");
    for (size_t i = 0; i < table.size(); ++i)
    {
      const std::string at = key + ".table." + std::to_string(i);
      FETICON_CHECK(table[i].IsSequence() && table[i].size() == 2,
                    r.source << ": " << at << " must be [overclosure, pressure]");
      const double overclosure = r.number(table[i][0], at), pressure = r.number(table[i][1], at);
      FETICON_CHECK(
          std::isfinite(overclosure) && std::isfinite(pressure) && pressure >= 0 &&
              (law.table.empty() || (overclosure > law.table.back().first && pressure >= law.table.back().second)),
          r.source << ": " << at
                   << ": the table needs increasing overclosures with finite pressures >= 0 "
                      "that do not decrease");
      law.table.emplace_back(overclosure, pressure);
    }
  }
  else
    throw Error(r.source + ": " + key + ".model = '" + model + "' must be one of: hard, linear, exponential, tabular");
  return law;
}

/// Slave and master of list entry `key` are two face sets of the mesh.
void check_surfaces(const std::string& slave, const std::string& master, const std::string& key, const mesh::Mesh& mesh,
                    const ProblemReader& r)
{
  for (const std::string& s : {slave, master})
    FETICON_CHECK(mesh.face_sets.count(s),
                  r.source << ": " << key << ": no face set '" << s
                           << "' in the mesh; it has: " << names_of(mesh.face_sets));
  FETICON_CHECK(slave != master,
                r.source << ": " << key << ": slave and master are the same face set '" << slave << "'");
}

std::vector<fem::ContactPairNames> contact_pairs(const YAML::Node& contact, const mesh::Mesh& mesh,
                                                 const ProblemReader& r)
{
  FETICON_CHECK(contact.IsSequence(), r.source << ": contact must be a list of pairs");
  std::vector<fem::ContactPairNames> out;
  for (size_t i = 0; i < contact.size(); ++i)
  {
    const YAML::Node c = contact[i];
    const std::string key = "contact." + std::to_string(i);
    r.only_keys(c, key, {"slave", "master", "friction", "formulation", "adjust", "law"});
    fem::ContactPairNames pair{r.text(c["slave"], key + ".slave"), r.text(c["master"], key + ".master")};
    pair.interaction.friction = pair_friction(c, key + ".friction", r);
    if (c["adjust"])
    {
      pair.adjust = r.number(c["adjust"], key + ".adjust");
      FETICON_CHECK(std::isfinite(pair.adjust) && pair.adjust >= 0,
                    r.source << ": " << key << ".adjust = " << pair.adjust << " m must be >= 0");
    }
    if (c["formulation"])
      pair.interaction.formulation = formulation_of(c["formulation"], key + ".formulation", r);
    if (c["law"])
      pair.interaction.law = pair_law(c["law"], key + ".law", r);
    check_surfaces(pair.slave, pair.master, key, mesh, r);
    out.push_back(pair);
  }
  return out;
}

/// The `ties:` list: slave and master face sets, and optionally name, position_tolerance (m),
/// adjust (true / false) and formulation (fem::Tie).
std::vector<fem::Tie> ties(const YAML::Node& list, const mesh::Mesh& mesh, const ProblemReader& r)
{
  FETICON_CHECK(list.IsSequence(), r.source << ": ties must be a list of ties");
  std::vector<fem::Tie> out;
  for (size_t i = 0; i < list.size(); ++i)
  {
    const YAML::Node t = list[i];
    const std::string key = "ties." + std::to_string(i);
    r.only_keys(t, key, {"name", "slave", "master", "position_tolerance", "adjust", "formulation"});
    fem::Tie tie{t["name"] ? r.text(t["name"], key + ".name") : std::to_string(i), r.text(t["slave"], key + ".slave"),
                 r.text(t["master"], key + ".master")};
    if (t["position_tolerance"])
    {
      tie.position_tolerance = r.number(t["position_tolerance"], key + ".position_tolerance");
      FETICON_CHECK(std::isfinite(tie.position_tolerance) && tie.position_tolerance > 0,
                    r.source << ": " << key << ".position_tolerance = " << tie.position_tolerance << " m must be > 0");
    }
    if (t["adjust"])
    {
      const std::string adjust = r.text(t["adjust"], key + ".adjust");
      FETICON_CHECK(adjust == "true" || adjust == "false",
                    r.source << ": " << key << ".adjust = '" << adjust << "' must be true or false");
      tie.adjust = adjust == "true";
    }
    if (t["formulation"])
      tie.formulation = formulation_of(t["formulation"], key + ".formulation", r);
    check_surfaces(tie.slave, tie.master, key, mesh, r);
    out.push_back(tie);
  }
  return out;
}

/// The tree of a YAML problem file, checked: a regular file of settings size, valid YAML, a
/// map at the top, no key twice.
/// The tree `load` parses, checked: a map of keys without duplicates; `name` for messages.
template <typename Load>
void parse_problem_tree(ProblemFile& file, const std::string& name, const Load& load)
{
  try
  {
    file.root = load();
  }
  catch (const YAML::DeepRecursion& e)
  {
    FETICON_CHECK(false,
                  name << ": YAML nested deeper than the reader's limit at line " << e.mark.line + 1
                       << "; a problem file nests a few levels (sections, lists of maps)");
  }
  catch (const YAML::Exception& e)
  {
    FETICON_CHECK(false,
                  name << ": invalid YAML at line " << e.mark.line + 1 << ", column " << e.mark.column + 1 << ": "
                       << e.msg);
  }
  FETICON_CHECK(!file.root.IsNull(),
                name << ": the file holds no settings (empty or comments "
                        "only); write at least 'problem: hertz'");
  FETICON_CHECK(file.root.IsMap(), name << ": the top level must be a map of keys");
  reject_duplicate_keys(file.root, "", name);
}

void read_problem_tree(ProblemFile& file, const std::filesystem::path& path)
{
  FETICON_CHECK(std::filesystem::exists(path), "problem file " << path.string() << " does not exist");
  // Problem files hold settings and small lists; 16 MiB is far beyond any real one.
  constexpr std::uintmax_t max_problem_file_bytes = 16u << 20;
  // Not a folder, a device or a FIFO (/dev/zero would be read forever), and settings-sized:
  // meshes go in their own files (mesh.file).
  std::error_code ec;
  FETICON_CHECK(std::filesystem::is_regular_file(path, ec),
                "problem file " << path.string() << " is not a regular file (a folder or a device?)");
  const auto bytes = std::filesystem::file_size(path, ec);
  FETICON_CHECK(!ec && bytes <= max_problem_file_bytes,
                "problem file " << path.string() << " has " << bytes
                                << " bytes; a problem file holds settings "
                                   "(at most "
                                << max_problem_file_bytes << " bytes), a mesh goes in mesh.file");
  parse_problem_tree(file, path.string(), [&] { return YAML::LoadFile(path.string()); });
}

/// The --set KEY=VALUE overrides: into the tree (their keys into `overridden`), or, for the
/// settings under a structured section's name, into `section_settings`.
void apply_overrides(const std::vector<std::string>& overrides, ProblemFile& file, std::set<std::string>& overridden,
                     std::vector<std::pair<std::string, std::string>>& section_settings)
{
  for (const std::string& o : overrides)
  {
    const auto eq = o.find('=');
    FETICON_CHECK(eq != std::string::npos && eq > 0, "--set '" << o << "' must have the form KEY=VALUE");
    const std::string key = o.substr(0, eq);
    if (const auto dot = key.find('.');
        dot != std::string::npos && is_structured_key(key.substr(0, dot)) && file.settings.knows(key))
    {
      section_settings.emplace_back(key, o.substr(eq + 1));
      continue;
    }
    YAML::Node value;
    try
    {
      value = YAML::Load(o.substr(eq + 1));
    }
    catch (const YAML::Exception&)
    {
      value = YAML::Node(o.substr(eq + 1));
    }
    if (value.IsNull())
      value = YAML::Node(o.substr(eq + 1));
    set_path(file.root, split_path(key), 0, value, key);
    overridden.insert(key);
  }
}
/// `file` as read with the overrides applied and every key validated: the problem as run.
ProblemFile with_overrides(ProblemFile file, const std::vector<std::string>& overrides);
} // namespace

ProblemFile load_problem_file(const std::filesystem::path& path, const std::vector<std::string>& overrides,
                              const std::vector<SettingSpec>& declared)
{
  ProblemFile file;
  file.settings = Settings(declared);
  file.source = path.empty() ? std::string("defaults") : path.string();
  file.folder = path.empty() ? std::filesystem::current_path() : path.parent_path();
  file.root = YAML::Node(YAML::NodeType::Map);
  if (!path.empty() && is_deck_file(path))
    settings_of_deck(file, path);
  else if (!path.empty())
    read_problem_tree(file, path);
  return with_overrides(std::move(file), overrides);
}

ProblemFile load_problem_text(const std::string& text, const std::string& source, const std::filesystem::path& folder,
                              const std::vector<std::string>& overrides, const std::vector<SettingSpec>& declared)
{
  ProblemFile file;
  file.settings = Settings(declared);
  file.source = source;
  file.folder = folder;
  parse_problem_tree(file, source, [&] { return YAML::Load(text); });
  return with_overrides(std::move(file), overrides);
}

namespace
{
ProblemFile with_overrides(ProblemFile file, const std::vector<std::string>& overrides)
{
  // Overrides act on the tree; the settings below remember which keys came from --set.
  // Settings under the name of a structured section (contact.formulation beside a custom
  // problem's list of contact pairs) go straight to the settings: in the tree they would
  // turn the section into a map of settings, or collide with the list.
  std::set<std::string> overridden;
  std::vector<std::pair<std::string, std::string>> section_settings;
  apply_overrides(overrides, file, overridden, section_settings);
  for (const auto& kv : file.root)
  {
    const std::string key = kv.first.as<std::string>();
    if (is_structured_key(key))
      continue;
    std::vector<std::pair<std::string, std::string>> scalars;
    flatten(kv.second, key, file.settings, scalars, file.source);
    for (const auto& [k, v] : scalars)
      file.settings.set(k, v, overridden.count(k) ? std::string("--set") : file.source);
  }
  for (const auto& [k, v] : section_settings)
    file.settings.set(k, v, "--set");
  // mesh.file naming a deck: the deck gives the whole model.
  if (file.deck.empty() && file.root["mesh"] && file.root["mesh"].IsMap() && file.root["mesh"]["file"] &&
      file.root["mesh"]["file"].IsScalar() && is_deck_file(file.root["mesh"]["file"].Scalar()))
  {
    file.deck = std::filesystem::absolute(file.folder / file.root["mesh"]["file"].Scalar());
    file.deck_outline = deck_outline(file.deck);
    for (const std::string& section : structured_keys)
      FETICON_CHECK(section == "mesh" || !file.root[section],
                    file.source << ": section '" << section << "' is not read when mesh.file is "
                                << "an input deck: the deck gives the whole model");
  }
  // A deck run has no sections: a --set under one (contact.frction.model, a misspelt setting)
  // would be dropped silently.
  if (!file.deck.empty())
    for (const std::string& key : overridden)
      FETICON_CHECK(!is_structured_key(key.substr(0, key.find('.'))),
                    "--set " << key << ": no such setting (`feticon run --help` lists them); the input deck "
                             << file.deck.filename().string() << " gives the whole model");
  // The structured sections describe a custom problem; a built-in one would ignore them.
  if (file.settings.text("problem") != "custom")
    for (const auto& kv : file.root)
    {
      const std::string key = kv.first.as<std::string>();
      FETICON_CHECK(!is_structured_key(key),
                    file.source << ": section '" << key << "' is read only by custom problems, "
                                << "but problem is " << file.settings.text("problem")
                                << "; add 'problem: custom' or remove it");
    }
  return file;
}
} // namespace

/// A 2D mesh's formulation from mesh.formulation (plane_strain, plane_stress, axisymmetric)
/// and mesh.thickness (m, default 1; not in axisymmetry): needed by 2D cells, refused for 3D
/// ones. u_z is then eliminated on every node (mesh::Planar).
void set_planar_formulation(const YAML::Node& mesh_node, const ProblemReader& r, fem::Problem& p)
{
  const bool planar_cells = p.mesh.n_cells() > 0 && mesh::cell_type(p.mesh.cells.kind(0)).dimension == 2;
  if (!mesh_node["formulation"])
  {
    FETICON_CHECK(!planar_cells,
                  r.source << ": the mesh has 2D cells: give mesh.formulation (plane_strain, "
                              "plane_stress or axisymmetric) and, for the first two, mesh.thickness");
    FETICON_CHECK(!mesh_node["thickness"], r.source << ": mesh.thickness is for 2D meshes with mesh.formulation");
    return;
  }
  const std::string name = r.text(mesh_node["formulation"], "mesh.formulation");
  const std::optional<mesh::PlanarKind> kind = name == "plane_strain" ? mesh::PlanarKind::plane_strain
      : name == "plane_stress"                                        ? mesh::PlanarKind::plane_stress
      : name == "axisymmetric"                                        ? std::optional(mesh::PlanarKind::axisymmetric)
                                                                      : std::nullopt;
  FETICON_CHECK(kind,
                r.source << ": mesh.formulation '" << name << "' is none of plane_strain, plane_stress, axisymmetric");
  FETICON_CHECK(planar_cells,
                r.source << ": mesh.formulation " << name << " needs a mesh of 2D cells (a Gmsh file "
                         << "whose bodies are physical surfaces); this mesh has 3D cells");
  FETICON_CHECK(!(mesh_node["thickness"] && *kind == mesh::PlanarKind::axisymmetric),
                r.source << ": mesh.thickness is not for an axisymmetric model (its measure is 2 pi r)");
  const double thickness = mesh_node["thickness"] ? r.number(mesh_node["thickness"], "mesh.thickness") : 1.0;
  FETICON_CHECK(std::isfinite(thickness) && thickness > 0,
                r.source << ": mesh.thickness = " << thickness << " must be a positive length (m)");
  p.mesh.planar = {*kind, thickness};
  p.eliminated = {false, false, true};
}

CustomMeshSize custom_mesh_size(const ProblemFile& file)
{
  const ProblemReader r{file.source};
  const YAML::Node& root = file.root;
  FETICON_CHECK(root["mesh"], file.source << ": problem: custom needs a 'mesh' section (file: or boxes:)");
  r.only_keys(root["mesh"], "mesh", {"file", "boxes", "formulation", "thickness"});
  CustomMeshSize size;
  size.plane_strain =
      root["plane_strain"] && root["plane_strain"].IsScalar() && root["plane_strain"].Scalar() == "true";
  if (root["mesh"]["file"])
  {
    const std::filesystem::path path = file.folder / r.text(root["mesh"]["file"], "mesh.file");
    std::error_code ec;
    if (is_deck_file(path))
    {
      size.nodes = file.deck_outline.nodes;
      size.plane_strain = false; // known once read; the estimate takes three components
      return size;
    }
    // A missing or unreadable file is left to the reader's messages; 0 nodes passes the guard.
    if (std::filesystem::is_regular_file(path, ec))
      size.nodes = std::max<int64_t>(0, mesh::precheck_gmsh_file(path, "Gmsh file '" + path.string() + "'").nodes);
    return size;
  }
  const YAML::Node boxes = root["mesh"]["boxes"];
  if (!boxes.IsSequence())
    return size;
  for (size_t i = 0; i < boxes.size(); ++i)
  {
    const std::string key = "mesh.boxes." + std::to_string(i);
    if (!boxes[i].IsMap() || !boxes[i]["cells"])
      continue; // boxes_mesh says what is missing
    const std::array<int, 3> cells = box_cells(boxes[i], key, r);
    size.nodes += int64_t(cells[0] + 1) * (cells[1] + 1) * (cells[2] + 1);
  }
  return size;
}

fem::Problem build_custom_problem(const ProblemFile& file)
{
  const ProblemReader r{file.source};
  const YAML::Node& root = file.root;
  FETICON_CHECK(root["mesh"], file.source << ": problem: custom needs a 'mesh' section (file: or boxes:)");
  r.only_keys(root["mesh"], "mesh", {"file", "boxes", "formulation", "thickness"});
  if (!file.deck.empty())
    return read_deck(file.deck, file.deck_outline).problem;
  fem::Problem p;
  p.name = "custom";
  if (root["mesh"]["file"])
    p.mesh = mesh::read_gmsh(file.folder / r.text(root["mesh"]["file"], "mesh.file"), &p.mesh_from_cache);
  else
    p.mesh = boxes_mesh(root["mesh"]["boxes"], r);
  set_planar_formulation(root["mesh"], r, p);

  body_materials(root, r, p);
  if (root["plane_strain"])
  {
    const std::string v = r.text(root["plane_strain"], "plane_strain");
    FETICON_CHECK(v == "true" || v == "false", file.source << ": plane_strain must be true or false");
    p.eliminated = {false, false, v == "true"};
  }
  if (root["couplings"])
    p.couplings = read_couplings(root["couplings"], p.mesh, r);
  read_steps(root, r, p);
  if (root["contact"])
    p.contacts = contact_pairs(root["contact"], p.mesh, r);
  if (root["ties"])
    p.ties = ties(root["ties"], p.mesh, r);
  p.validate();
  return p;
}
} // namespace feticon::io
