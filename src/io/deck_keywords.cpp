/// The keyword handlers of an input deck: each reads its keyword line's parameters and its
/// data lines into DeckData (deck_data.hpp). Keywords and their data follow the CalculiX
/// CrunchiX user's manual, chapter "Input deck format".

#include "common/error.hpp"
#include "fem/node_frames.hpp"
#include "io/deck_data.hpp"
#include "io/deck_parts.hpp"

#include <algorithm>
#include <charconv>
#include <cmath>
#include <functional>
#include <limits>
#include <optional>
#include <sstream>

namespace feticon::io
{
namespace
{
/// Labels up to this beyond twice the count so far go into the dense table (4 bytes each).
constexpr int64_t dense_label_slack = int64_t{1} << 20;
/// Node and element numbers are 32-bit, as in CalculiX (io/result_labels.hpp).
constexpr int64_t largest_label = std::numeric_limits<int32_t>::max();

/// Keywords that change nothing a static elastic contact run computes: read, reported.
const std::map<std::string, std::string> inert_keywords = {
    {"CONDUCTIVITY", "the run is mechanical only"},
    {"SPECIFIC HEAT", "the run is mechanical only"},
    {"GAP CONDUCTANCE", "the run is mechanical only"},
    {"NODE OUTPUT", "use *NODE FILE / *NODE PRINT; feticon writes U and S to the .frd"},
    {"ELEMENT OUTPUT", "use *EL FILE / *EL PRINT; feticon writes U and S to the .frd"},
    {"CONTACT OUTPUT", "use *CONTACT FILE / *CONTACT PRINT"},
    {"OUTPUT", "feticon writes its results folder and the .frd / .dat of the print and file requests"},
    {"ENERGY PRINT", "not written"},
    {"SECTION PRINT", "not written"},
    {"RESTART", "feticon restarts from its own checkpoint (feticon run --restart)"},
    {"CONTROLS", "feticon's solver settings are its own (feticon run --help)"},
    {"ORIENTATION", "the materials are isotropic, so an orientation changes nothing"},
    {"PREPRINT", "not written"},
    {"SECTION CONTROLS", "feticon integrates C3D8R cells fully, without hourglass control"},
};

/// Keywords feticon does not implement, with what they are (for the one-line error).
const std::map<std::string, std::string> unsupported_keywords = {
    {"DYNAMIC", "dynamics"},
    {"MODAL DYNAMIC", "dynamics"},
    {"FREQUENCY", "eigenfrequencies"},
    {"BUCKLE", "buckling"},
    {"HEAT TRANSFER", "heat transfer"},
    {"COUPLED TEMPERATURE-DISPLACEMENT", "thermo-mechanics"},
    {"VISCO", "viscous materials"},
    {"CYCLIC HARDENING", "plasticity"},
    {"DEFORMATION PLASTICITY", "plasticity"},
    {"HYPERFOAM", "hyperelastic materials"},
    {"CREEP", "creep"},
    {"USER MATERIAL", "user materials"},
    {"SHELL SECTION", "shell elements"},
    {"BEAM SECTION", "beam elements"},
    {"MEMBRANE SECTION", "membrane elements"},
    {"MPC", "nonlinear multi-point constraints (linear ones: *EQUATION)"},
    {"SPRING", "spring elements"},
    {"DASHPOT", "dashpot elements"},
    {"MASS", "mass elements"},
    {"GAP", "gap elements"},
    {"CFLUX", "heat fluxes"},
    {"DFLUX", "heat fluxes"},
    {"FILM", "heat transfer"},
    {"RADIATE", "heat transfer"},
    {"SUBMODEL", "submodels"},
};

std::string text(std::string_view v) { return std::string(v); }

/// Upper-case name of a data field (set, surface and material names are case-insensitive).
std::string name_of(std::string_view v)
{
  std::string out(v);
  for (char& c : out)
    c = static_cast<char>(std::toupper(static_cast<unsigned char>(c)));
  return out;
}

bool is_integer(std::string_view v)
{
  if (v.empty())
    return false;
  size_t i = v.front() == '+' || v.front() == '-' ? 1 : 0;
  if (i == v.size())
    return false;
  for (; i < v.size(); ++i)
    if (v[i] < '0' || v[i] > '9')
      return false;
  return true;
}

/// The integer of a whole field (a leading '+' allowed), none if it is not one or exceeds int64_t.
std::optional<int64_t> parse_integer(std::string_view v)
{
  if (!v.empty() && v.front() == '+')
    v.remove_prefix(1);
  int64_t out = 0;
  const auto [end, ec] = std::from_chars(v.data(), v.data() + v.size(), out);
  if (v.empty() || ec != std::errc() || end != v.data() + v.size())
    return std::nullopt;
  return out;
}

class KeywordReader
{
public:
  KeywordReader(const std::filesystem::path& path, const DeckOutline& outline) : _tokens(path), _path(path.string())
  {
    _data.coordinates.resize(outline.nodes, 3);
    _data.node_labels.reserve(outline.nodes);
    _data.cells.reserve(outline.elements, 8 * static_cast<size_t>(outline.elements));
    _data.element_labels.reserve(outline.elements);
    _data.reduced_integration.reserve(outline.elements);
    _data.node_index.reserve(outline.nodes);
    _data.element_index.reserve(outline.elements);
  }

  DeckData run()
  {
    DeckKeyword keyword;
    bool have = _tokens.next_keyword(keyword);
    FETICON_CHECK(have, "input deck " << _path << " has no keyword line (*NODE, *ELEMENT, ...)");
    while (have)
    {
      _keyword = keyword;
      _keyword.name = canonical_name(_keyword.name);
      if (_recording)
        record();
      else
        handle();
      have = _tokens.next_keyword(keyword);
    }
    FETICON_CHECK(!_recording, _recording->where.str() << ": *PART has no *END PART");
    FETICON_CHECK(!_pending_coupling,
                  _pending_coupling->where.str() << ": *COUPLING needs its *KINEMATIC or *DISTRIBUTING next");
    FETICON_CHECK(_open_instance.empty(),
                  _instances.at(_open_instance).where.str() << ": *INSTANCE has no *END INSTANCE");
    FETICON_CHECK(!_in_assembly, _assembly_where.str() << ": *ASSEMBLY has no *END ASSEMBLY");
    FETICON_CHECK(!_in_step, _step_where.str() << ": *STEP has no *END STEP");
    FETICON_CHECK(!_data.steps.empty(), "input deck has no *STEP: feticon solves the loads of a *STEP with *STATIC");
    FETICON_CHECK(!_data.cells.empty(), "input deck has no *ELEMENT");
    _data.file_names = _tokens.take_file_names();
    return std::move(_data);
  }

private:
  // ---- access to the current keyword and its data -------------------------------------
  std::string where() const { return _keyword.where.str() + ": *" + _keyword.name; }

  [[noreturn]] void fail_at(const DeckPosition& at, const std::string& what) const
  {
    throw Error(at.str() + ": *" + _keyword.name + ": " + what);
  }

  const std::string& required(std::string_view key) const
  {
    const std::string* v = _keyword.value(key);
    if (!v || v->empty())
      throw Error(where() + " needs " + std::string(key) + "=");
    return *v;
  }

  /// Parameters this handler knows; any other is an error naming it.
  void known_parameters(std::initializer_list<std::string_view> keys) const
  {
    for (const auto& [k, v] : _keyword.parameters)
      if (std::find(keys.begin(), keys.end(), k) == keys.end())
        throw Error(where() + ": parameter " + k + " is not implemented by feticon");
  }

  double real(const DeckDataLine& line, size_t i, const char* what) const
  {
    if (i >= line.fields.size() || line.fields[i].empty())
      fail_at(line.at(i), std::string("missing ") + what);
    const std::optional<double> out = parse_deck_real(line.fields[i]);
    if (!out)
      fail_at(line.at(i), "'" + text(line.fields[i]) + "' is not a finite number (" + what + ")");
    return *out;
  }

  int64_t integer(const DeckDataLine& line, size_t i, const char* what) const
  {
    if (i >= line.fields.size() || line.fields[i].empty())
      fail_at(line.at(i), std::string("missing ") + what);
    const std::optional<int64_t> out = parse_integer(line.fields[i]);
    if (!out)
      fail_at(line.at(i), "'" + text(line.fields[i]) + "' is not an integer (" + what + ")");
    return *out;
  }

  /// The mesh index of the node or element labelled by field i.
  int32_t entity(const DeckDataLine& line, size_t i, bool is_node) const
  {
    const int64_t label = integer(line, i, is_node ? "node number" : "element number");
    return index_of(label, is_node, _scope, line.at(i));
  }
  int32_t node(const DeckDataLine& line, size_t i) const { return entity(line, i, true); }

  /// The mesh index of the node or element `label` of `scope` (deck_parts.hpp: an instance's
  /// labels are its part's, shifted).
  int32_t index_of(int64_t label, bool is_node, const DeckScope& scope, const DeckPosition& at) const
  {
    const char* kind = is_node ? "node " : "element ";
    if (!_instances.empty() && scope.prefix.empty())
      fail_at(at,
              kind + std::to_string(label) +
                  ": in a deck of parts and instances a node or element is named by its instance, "
                  "INSTANCE.NUMBER, or by a set");
    const int64_t model_label = label + (is_node ? scope.node_offset : scope.element_offset);
    const int32_t index = (is_node ? _data.node_index : _data.element_index).find(model_label);
    if (index < 0)
      fail_at(at,
              kind + std::to_string(label) + " is not defined (by " + (is_node ? "a *NODE" : "an *ELEMENT") +
                  " before this line" +
                  (scope.prefix.empty() ? std::string(")")
                                        : ", in instance " + scope.prefix.substr(0, scope.prefix.size() - 1) + ")"));
    return index;
  }

  /// The nodes (elements) of field i: a number, the name of a node (element) set, or a label of
  /// an instance, "INSTANCE.NUMBER".
  std::vector<int32_t> members(const DeckDataLine& line, size_t i, bool is_node) const
  {
    if (i < line.fields.size() && !line.fields[i].empty() && !is_integer(line.fields[i]))
    {
      const std::string name = _scope.prefix + name_of(line.fields[i]);
      const auto& sets = is_node ? _data.node_sets : _data.element_sets;
      if (const auto it = sets.find(name); it != sets.end())
        return it->second.expand();
      if (const size_t dot = name.rfind('.'); _scope.prefix.empty() && dot != std::string::npos)
      {
        int64_t label = 0;
        const char* const end = name.data() + name.size();
        const auto [stop, ec] = std::from_chars(name.data() + dot + 1, end, label);
        if (_instances.count(name.substr(0, dot)) && ec == std::errc() && stop == end)
          return {index_of(label, is_node, scope_of(name.substr(0, dot)), line.at(i))};
      }
      fail_at(line.at(i), std::string(is_node ? "no node set '" : "no element set '") + name + "' is defined");
    }
    return {entity(line, i, is_node)};
  }

  /// The scope of the lines of instance `name` (known).
  DeckScope scope_of(const std::string& name) const
  {
    const DeckInstance& instance = _instances.at(name);
    return {name + ".", instance.node_offset, instance.element_offset, nullptr};
  }
  std::vector<int32_t> nodes(const DeckDataLine& line, size_t i) const { return members(line, i, true); }
  std::vector<int32_t> elements(const DeckDataLine& line, size_t i) const { return members(line, i, false); }

  /// Data lines of a keyword that takes none must have none.
  void no_data()
  {
    DeckDataLine line;
    if (next_data(line))
      fail_at(line.where, "takes no data lines");
  }

  /// The next data line of the current keyword: from the deck, or from the part an instance
  /// reads again.
  bool next_data(DeckDataLine& line)
  {
    if (!_replay)
      return _tokens.next_data(line);
    if (_replayed == _replay->size())
      return false;
    line = (*_replay)[_replayed++].view();
    return true;
  }

  void skip_data()
  {
    DeckDataLine line;
    while (next_data(line))
    {
    }
  }

  // ---- dispatch -------------------------------------------------------------------------
  using Handler = void (KeywordReader::*)();
  /// The handler of every keyword feticon reads.
  static const std::map<std::string, Handler>& handlers()
  {
    static const std::map<std::string, Handler> table = {
        {"HEADING", &KeywordReader::heading},
        {"NODE", &KeywordReader::node_block},
        {"ELEMENT", &KeywordReader::element_block},
        {"NSET", &KeywordReader::set_block},
        {"ELSET", &KeywordReader::set_block},
        {"SURFACE", &KeywordReader::surface},
        {"MATERIAL", &KeywordReader::material},
        {"ELASTIC", &KeywordReader::elastic},
        {"DENSITY", &KeywordReader::density},
        {"EXPANSION", &KeywordReader::expansion},
        {"PLASTIC", &KeywordReader::plastic},
        {"HYPERELASTIC", &KeywordReader::hyperelastic},
        {"INITIAL CONDITIONS", &KeywordReader::initial_conditions},
        {"TEMPERATURE", &KeywordReader::temperature},
        {"MODEL CHANGE", &KeywordReader::model_change},
        {"CHANGE FRICTION", &KeywordReader::change_friction},
        {"CHANGE SURFACE BEHAVIOR", &KeywordReader::change_surface_behavior},
        {"SOLID SECTION", &KeywordReader::solid_section},
        {"BOUNDARY", &KeywordReader::boundary},
        {"CLOAD", &KeywordReader::cload},
        {"DLOAD", &KeywordReader::dload},
        {"DSLOAD", &KeywordReader::dsload},
        {"EQUATION", &KeywordReader::equation},
        {"TRANSFORM", &KeywordReader::transform},
        {"AMPLITUDE", &KeywordReader::amplitude},
        {"SURFACE INTERACTION", &KeywordReader::surface_interaction},
        {"SURFACE BEHAVIOR", &KeywordReader::surface_behavior},
        {"FRICTION", &KeywordReader::friction},
        {"CONTACT PAIR", &KeywordReader::contact_pair},
        {"TIE", &KeywordReader::tie},
        {"RIGID BODY", &KeywordReader::rigid_body},
        {"COUPLING", &KeywordReader::coupling},
        {"KINEMATIC", &KeywordReader::kinematic},
        {"DISTRIBUTING", &KeywordReader::distributing},
        {"DISTRIBUTING COUPLING", &KeywordReader::distributing_coupling},
        {"PRE-TENSION SECTION", &KeywordReader::pre_tension_section},
        {"CYCLIC SYMMETRY MODEL", &KeywordReader::cyclic_symmetry_model},
        {"PART", &KeywordReader::part},
        {"END PART", &KeywordReader::end_part},
        {"ASSEMBLY", &KeywordReader::assembly},
        {"END ASSEMBLY", &KeywordReader::end_assembly},
        {"INSTANCE", &KeywordReader::instance},
        {"END INSTANCE", &KeywordReader::end_instance},
        {"STEP", &KeywordReader::step},
        {"STATIC", &KeywordReader::static_procedure},
        {"END STEP", &KeywordReader::end_step},
        {"NODE PRINT", &KeywordReader::output_request},
        {"EL PRINT", &KeywordReader::output_request},
        {"CONTACT PRINT", &KeywordReader::output_request},
        {"NODE FILE", &KeywordReader::output_request},
        {"EL FILE", &KeywordReader::output_request},
        {"CONTACT FILE", &KeywordReader::output_request},
    };
    return table;
  }

  /// The name feticon knows for `name` written without its blanks, as CalculiX reads keywords
  /// (it removes every blank: "*ENDSTEP", "*NODEPRINT"); `name` itself if none.
  static std::string canonical_name(const std::string& name)
  {
    const auto blank_free = [](const std::string& n) {
      std::string out;
      for (const char c : n)
        if (c != ' ')
          out += c;
      return out;
    };
    static const std::map<std::string, std::string> known = [&] {
      std::map<std::string, std::string> out;
      for (const auto& entry : handlers())
        out.emplace(blank_free(entry.first), entry.first);
      for (const auto* table : {&inert_keywords, &unsupported_keywords})
        for (const auto& entry : *table)
          out.emplace(blank_free(entry.first), entry.first);
      return out;
    }();
    const auto it = known.find(blank_free(name));
    return it == known.end() ? name : it->second;
  }

  void handle()
  {
    if (!_open_instance.empty() && _keyword.name != "END INSTANCE")
      throw Error(where() + ": the *INSTANCE at " + _instances.at(_open_instance).where.str() +
                  " has no *END INSTANCE before it (feticon reads instances of parts: no data inside an instance)");
    _in_interaction = _in_interaction && (_keyword.name == "SURFACE BEHAVIOR" || _keyword.name == "FRICTION");
    if (!_changing_friction.empty() && _keyword.name != "FRICTION")
      throw Error(where() + ": the *CHANGE FRICTION before it (" + _changing_friction_where +
                  ") needs its *FRICTION next");
    if (_pending_coupling && _keyword.name != "KINEMATIC" && _keyword.name != "DISTRIBUTING")
      throw Error(where() + ": the *COUPLING before it (" + _pending_coupling->where.str() +
                  ") needs its *KINEMATIC or *DISTRIBUTING next");
    if (!_changing_behavior.empty() && _keyword.name != "SURFACE BEHAVIOR")
      throw Error(where() + ": the *CHANGE SURFACE BEHAVIOR before it (" + _changing_behavior_where +
                  ") needs its *SURFACE BEHAVIOR next");
    if (const auto it = handlers().find(_keyword.name); it != handlers().end())
    {
      (this->*(it->second))();
      return;
    }
    if (const auto it = inert_keywords.find(_keyword.name); it != inert_keywords.end())
    {
      _data.warn("*" + _keyword.name + " (first at " + _keyword.where.str() + ") is read and not used: " + it->second);
      skip_data();
      return;
    }
    if (const auto it = unsupported_keywords.find(_keyword.name); it != unsupported_keywords.end())
      throw Error(where() + " is not implemented by feticon (" + it->second + ")");
    throw Error(where() + " is not a keyword feticon implements");
  }

  // ---- model data ---------------------------------------------------------------------------
  void heading() { skip_data(); }

  // ---- parts and assemblies (deck_parts.hpp) -------------------------------------------------
  /// *PART, NAME=: its keywords are kept (record) until *END PART and read for each instance.
  void part()
  {
    known_parameters({"NAME"});
    if (_in_step || _in_assembly)
      throw Error(where() + " belongs to the model data, before the *ASSEMBLY and the first *STEP");
    if (!_data.node_labels.empty() || !_data.cells.empty())
      throw Error(where() +
                  ": nodes or elements come before it outside any part; a deck has its mesh in parts "
                  "or has no parts");
    const std::string& name = required("NAME");
    if (_parts.count(name))
      throw Error(where() + ": part " + name + " is defined twice (first at " + _parts.at(name).where.str() + ")");
    no_data();
    _recording = &_parts[name];
    _recording->where = _keyword.where;
  }

  /// A keyword inside a *PART, kept for its instances.
  void record()
  {
    if (_keyword.name == "END PART")
    {
      known_parameters({});
      no_data();
      _recording = nullptr;
      return;
    }
    if (const auto it = unsupported_keywords.find(_keyword.name); it != unsupported_keywords.end())
      throw Error(where() + " is not implemented by feticon (" + it->second + ")");
    if (_keyword.name == "PART")
      throw Error(where() + ": the *PART at " + _recording->where.str() + " has no *END PART before it");
    if (!allowed_in_part(_keyword.name))
      throw Error(where() + " inside the *PART at " + _recording->where.str() +
                  ": a part holds nodes, elements, sets, surfaces and sections; this keyword belongs to the "
                  "model, the assembly or a step");
    RecordedKeyword kept{_keyword, {}};
    for (DeckDataLine line; _tokens.next_data(line);)
      kept.lines.emplace_back(line);
    _recording->keywords.push_back(std::move(kept));
  }

  void end_part() { throw Error(where() + " without a *PART"); }

  void assembly()
  {
    known_parameters({"NAME"});
    if (_in_step || _in_assembly || _assembly_where.line > 0)
      throw Error(where() + ": a deck has one *ASSEMBLY, in the model data before the first *STEP");
    if (!_data.node_labels.empty() || !_data.cells.empty())
      throw Error(where() + ": nodes or elements come before it outside any part; an assembly places parts");
    _in_assembly = true;
    _assembly_where = _keyword.where;
    no_data();
  }

  void end_assembly()
  {
    known_parameters({});
    if (!_in_assembly)
      throw Error(where() + " without an *ASSEMBLY");
    _in_assembly = false;
    no_data();
  }

  /// *INSTANCE, NAME=, PART=: the part's keywords read again under the instance's names, labels
  /// and placement (data lines: a translation; an axis a, b and an angle in degrees).
  void instance()
  {
    known_parameters({"NAME", "PART"});
    if (!_in_assembly)
      throw Error(where() + " belongs inside an *ASSEMBLY");
    const std::string name = required("NAME"), part_name = required("PART"); // copies: _keyword changes below
    const auto part = _parts.find(part_name);
    if (part == _parts.end())
      throw Error(where() + ": no *PART '" + part_name + "' is defined before it");
    if (_instances.count(name))
      throw Error(where() + ": instance " + name + " is defined twice (first at " + _instances.at(name).where.str() +
                  ")");
    const InstancePlacement placement = instance_placement();
    _instances[name] = {part_name, _largest_node_label, _largest_element_label, _keyword.where};
    DeckScope scope = scope_of(name);
    scope.placement = &placement;
    const DeckKeyword instance_keyword = _keyword;
    _scope = scope;
    for (const RecordedKeyword& kept : part->second.keywords)
    {
      _keyword = scoped_keyword(kept.keyword, scope.prefix);
      _replay = &kept.lines;
      _replayed = 0;
      handle();
      _replay = nullptr;
    }
    _scope = {};
    _keyword = instance_keyword;
    _open_instance = name;
  }

  /// The data lines of an *INSTANCE: none, a translation, or a translation and a rotation.
  InstancePlacement instance_placement()
  {
    InstancePlacement placement;
    DeckDataLine line;
    if (!next_data(line))
      return placement;
    for (int k = 0; k < 3; ++k)
      placement.translation[k] = real(line, k, "translation");
    if (!next_data(line))
      return placement;
    Eigen::Vector3d a, b;
    for (int k = 0; k < 3; ++k)
    {
      a[k] = real(line, k, "point a of the rotation axis");
      b[k] = real(line, k + 3, "point b of the rotation axis");
    }
    try
    {
      placement.rotation = rotation_about_axis(a, b, real(line, 6, "rotation angle (degrees)"));
    }
    catch (const Error& e)
    {
      fail_at(line.where, e.what());
    }
    placement.axis_point = a;
    if (next_data(line))
      fail_at(line.where,
              "an *INSTANCE has at most two data lines: a translation, and a rotation axis (a, b) "
              "with its angle");
    return placement;
  }

  void end_instance()
  {
    known_parameters({});
    if (_open_instance.empty())
      throw Error(where() + " without an *INSTANCE");
    _open_instance.clear();
    no_data();
  }

  void node_block()
  {
    known_parameters({"NSET", "SYSTEM"});
    if (_keyword.has("SYSTEM"))
      throw Error(where() + ": SYSTEM= (local coordinates) is not implemented by feticon");
    outside_parts_check();
    IndexRuns* set = nullptr;
    if (_keyword.has("NSET"))
      set = &_data.node_sets[required("NSET")];
    DeckDataLine line;
    while (next_data(line))
    {
      const int64_t label = model_label(line, "node", _scope.node_offset);
      if (line.fields.size() > 4)
        fail_at(line.at(4), "a node line has at most a number and three coordinates");
      const int32_t index = static_cast<int32_t>(_data.node_labels.size());
      if (index == std::numeric_limits<int32_t>::max())
        fail_at(line.where, "more nodes than feticon's 32-bit node indices hold");
      if (!_data.node_index.insert(label, index))
        fail_at(line.at(0), "node " + std::to_string(label - _scope.node_offset) + " is defined twice");
      _data.node_labels.push_back(static_cast<int32_t>(label));
      if (index >= _data.coordinates.rows()) // more nodes than the outline counted
        _data.coordinates.conservativeResize(2 * static_cast<Eigen::Index>(index) + 1024, 3);
      Eigen::Vector3d x;
      for (int k = 1; k <= 3; ++k)
        x[k - 1] =
            static_cast<size_t>(k) < line.fields.size() && !line.fields[k].empty() ? real(line, k, "coordinate") : 0.0;
      _data.coordinates.row(index) = (_scope.placement ? _scope.placement->apply(x) : x).transpose();
      _largest_node_label = std::max(_largest_node_label, label);
      if (set)
        set->push_back(index);
    }
  }

  void element_block()
  {
    known_parameters({"TYPE", "ELSET"});
    const std::string& type = required("TYPE");
    if (type == "DCOUP3D")
      return coupling_element_block();
    const mesh::CellType* cell_type = mesh::cell_type_of_calculix_name(type);
    if (!cell_type)
      throw Error(where() + ": element type " + type +
                  " is not implemented by feticon (C3D8, C3D8R, C3D8I, C3D20, C3D20R, C3D4, C3D10, C3D6; "
                  "CPE3/4/6/8, CPS3/4/6/8, CAX3/4/6/8 and their R variants)");
    if (type == "C3D8R" || type == "C3D8I")
      _data.warn("element type " + type + " (" + _keyword.where.str() +
                 ") is solved as C3D8 (full 2x2x2 "
                 "integration" +
                 (type == "C3D8R" ? std::string(", not reduced with hourglass control)")
                                  : std::string(", without incompatible modes: stiffer in bending)")));
    if (type.size() == 5 && type.back() == 'R' && type[3] == '4')
      _data.warn("element type " + type + " (" + _keyword.where.str() + ") is solved as " + type.substr(0, 4) +
                 " (full 2x2 integration, not reduced with hourglass control)");
    outside_parts_check();
    const mesh::PlanarKind planar = planar_formulation(type, *cell_type);
    // 2x2x2 (C3D20R) or 2x2 (CPE8R, CPS8R, CAX8R) Gauss points, as CalculiX.
    const char reduced = type == "C3D20R" || (cell_type->kind == mesh::CellKind::quad8 && type.back() == 'R') ? 1 : 0;
    const size_t n_nodes = static_cast<size_t>(cell_type->n_nodes);
    const std::string count = std::to_string(n_nodes);
    IndexRuns* set = _keyword.has("ELSET") ? &_data.element_sets[required("ELSET")] : nullptr;
    DeckDataLine line;
    std::vector<int32_t> nodes_of_element;
    int64_t label = 0;
    DeckPosition start;
    while (next_data(line))
    {
      size_t first = 0;
      if (nodes_of_element.empty() && label == 0)
      {
        label = model_label(line, "element", _scope.element_offset);
        start = line.where;
        first = 1;
      }
      for (size_t k = first; k < line.fields.size(); ++k)
      {
        if (nodes_of_element.size() == n_nodes)
          fail_at(line.at(k),
                  "element " + std::to_string(label) + " of type " + type + " has more than " + count + " nodes");
        nodes_of_element.push_back(node(line, k));
      }
      if (nodes_of_element.size() < n_nodes)
      {
        if (line.continues)
          continue;
        fail_at(line.where,
                "element " + std::to_string(label) + " of type " + type + " has " +
                    std::to_string(nodes_of_element.size()) + " nodes, not " + count);
      }
      const int32_t index = static_cast<int32_t>(_data.cells.size());
      if (!_data.element_index.insert(label, index))
        fail_at(start, "element " + std::to_string(label - _scope.element_offset) + " is defined twice");
      _data.cells.add(cell_type->kind, nodes_of_element);
      _data.reduced_integration.push_back(reduced);
      _data.cell_planar.push_back(planar);
      _data.element_labels.push_back(static_cast<int32_t>(label));
      _largest_element_label = std::max(_largest_element_label, label);
      if (set)
        set->push_back(index);
      nodes_of_element.clear();
      label = 0;
    }
    if (label != 0)
      fail_at(start, "element " + std::to_string(label) + " of type " + type + " has fewer than " + count + " nodes");
  }

  /// The model's label of the node or element numbered by field 0 (an instance's numbers are
  /// shifted past the labels before it, deck_parts.hpp).
  int64_t model_label(const DeckDataLine& line, const std::string& kind, int64_t offset) const
  {
    const int64_t label = integer(line, 0, (kind + " number").c_str());
    if (label <= 0 || label > largest_label - offset)
      fail_at(line.at(0),
              kind + " number " + std::to_string(label) + " is outside 1.." + std::to_string(largest_label - offset) +
                  (offset > 0 ? " (the labels of the instances before it take the rest)" : ""));
    return label + offset;
  }

  /// Nodes and elements of a deck of parts belong to parts (the assembly's own nodes are
  /// reference points, which feticon does not implement).
  void outside_parts_check() const
  {
    if (_scope.prefix.empty() && (!_parts.empty() || _in_assembly))
      throw Error(where() +
                  ": nodes and elements outside the parts (the assembly's reference points) are not "
                  "implemented by feticon");
  }

  /// The 2D formulation an element type names (CPE: plane strain, CPS: plane stress, CAX:
  /// axisymmetric; none for 3D cells). 2D formulations mix in one deck (CalculiX expands each
  /// into 3D cells; mesh::Mesh::body_planar), 2D and 3D cells do not.
  mesh::PlanarKind planar_formulation(const std::string& type, const mesh::CellType& cell_type)
  {
    mesh::PlanarKind kind = mesh::PlanarKind::none;
    if (cell_type.dimension == 2)
      kind = type.starts_with("CPE") ? mesh::PlanarKind::plane_strain
          : type.starts_with("CPS")  ? mesh::PlanarKind::plane_stress
                                     : mesh::PlanarKind::axisymmetric;
    if (_data.cells.empty())
    {
      _data.planar = kind;
      _data.first_cells = _keyword.where;
    }
    else if ((kind == mesh::PlanarKind::none) != (_data.planar == mesh::PlanarKind::none))
      throw Error(where() + ": " + type + " elements (" + std::string(mesh::planar_name(kind)) + ") in a " +
                  std::string(mesh::planar_name(_data.planar)) + " model (its first elements at " +
                  _data.first_cells.str() + "): 2D and 3D cells do not mix");
    return kind;
  }

  /// *NSET and *ELSET: numbers, names of sets of the same kind, or GENERATE triples.
  void set_block()
  {
    const bool nodes_kind = _keyword.name == "NSET";
    // CalculiX ignores a parameter a set does not have (with a warning): the set is the same.
    // INSTANCE= (an assembly's set of an instance's nodes or elements) and INTERNAL (hidden in
    // Abaqus/CAE) are Abaqus's.
    const DeckScope outer = _scope;
    if (const std::string* instance = _keyword.value("INSTANCE"))
    {
      if (!_scope.prefix.empty() || !_instances.count(*instance))
        throw Error(where() + ": INSTANCE=" + *instance + " names no instance placed before it");
      _scope = scope_of(*instance);
    }
    for (const auto& [key, value] : _keyword.parameters)
      if (key != (nodes_kind ? "NSET" : "ELSET") && key != "GENERATE" && key != "INSTANCE" && key != "INTERNAL")
        _data.warn(where() + ": parameter " + key + " is not one of *" + _keyword.name +
                   "'s; ignored, as CalculiX ignores it");
    const std::string name = required(nodes_kind ? "NSET" : "ELSET");
    auto& sets = nodes_kind ? _data.node_sets : _data.element_sets;
    IndexRuns listed;
    const size_t n_entities = nodes_kind ? _data.node_labels.size() : _data.cells.size();
    DeckDataLine line;
    const bool generate = _keyword.has("GENERATE");
    while (next_data(line))
    {
      if (generate)
      {
        const int64_t first = integer(line, 0, "first number"), last = integer(line, 1, "last number");
        const int64_t step = line.fields.size() > 2 && !line.fields[2].empty() ? integer(line, 2, "increment") : 1;
        if (step <= 0 || last < first)
          fail_at(line.where, "GENERATE needs first <= last and a positive increment");
        for (int64_t label = first;; label += step)
        {
          listed.push_back(index_of(label, nodes_kind, _scope, line.where));
          if (last - label < step) // the next label would pass `last` (or overflow int64)
            break;
        }
        listed.compact(n_entities);
        continue;
      }
      for (size_t k = 0; k < line.fields.size(); ++k)
      {
        if (line.fields[k].empty())
          continue;
        listed.append(members(line, k, nodes_kind));
        listed.compact(n_entities);
      }
    }
    IndexRuns& set = sets[name];
    set.append(listed.expand());
    set.compact(n_entities);
    _scope = outer;
  }

  void surface()
  {
    known_parameters({"NAME", "TYPE", "INTERNAL"});
    const std::string name = required("NAME");
    const std::string* type = _keyword.value("TYPE");
    if (type && *type != "ELEMENT" && *type != "NODE")
      throw Error(where() + ": TYPE=" + *type + " is not implemented by feticon (ELEMENT or NODE)");
    // A node surface and an element surface may share a name (CalculiX's surfaces.f keeps them
    // apart): the node one moves to node_surface_key.
    const bool node_based = type && *type == "NODE";
    std::string key = name;
    if (const auto other = _data.surfaces.find(name);
        other != _data.surfaces.end() && other->second.node_based != node_based)
    {
      if (node_based)
        key = node_surface_key(name);
      else
      {
        _data.surfaces[node_surface_key(name)] = std::move(other->second);
        _data.surfaces.erase(other);
      }
    }
    DeckSurface& s = _data.surfaces[key];
    s.where = _keyword.where;
    s.node_based = node_based;
    DeckDataLine line;
    while (next_data(line))
    {
      if (s.node_based)
      {
        const std::vector<int32_t> more = nodes(line, 0);
        s.nodes.insert(s.nodes.end(), more.begin(), more.end());
        continue;
      }
      const std::vector<int32_t> cells = elements(line, 0);
      if (line.fields.size() < 2)
        fail_at(line.where, "an element face needs its face, S1 to S6");
      const std::string face = name_of(line.fields[1]);
      if (face.size() != 2 || face[0] != 'S' || face[1] < '1' || face[1] > '6')
        fail_at(line.at(1), "face '" + text(line.fields[1]) + "' of an element is not S1 to S6");
      for (int32_t c : cells)
        s.faces.push_back({c, face[1] - '0'});
    }
  }

  void material()
  {
    known_parameters({"NAME"});
    _material = required("NAME");
    _data.materials[_material] = fem::Material{0.0, 0.0};
    if (_data.first_material.empty())
      _data.first_material = _material;
    no_data();
  }

  void elastic()
  {
    known_parameters({"TYPE"});
    const std::string* type = _keyword.value("TYPE");
    if (type && *type != "ISO" && *type != "ISOTROPIC")
      throw Error(where() + ": TYPE=" + *type + " is not implemented by feticon (isotropic elasticity)");
    if (_material.empty())
      throw Error(where() + " comes before any *MATERIAL");
    DeckDataLine line;
    if (!next_data(line))
      throw Error(where() + " needs a data line: Young's modulus, Poisson's ratio");
    fem::Material& m = _data.materials[_material];
    if (m.is_hyperelastic())
      throw Error(where() + ": material " + _material + " is hyperelastic already (*HYPERELASTIC)");
    m.young = real(line, 0, "Young's modulus");
    m.poisson = real(line, 1, "Poisson's ratio");
    try
    {
      m.check("material " + _material);
    }
    catch (const Error& e)
    {
      fail_at(line.where, e.what());
    }
    if (next_data(line))
      fail_at(line.where, "temperature-dependent elastic constants are not implemented by feticon (one data line)");
  }

  /// NEO HOOKE (C10, D1), MOONEY-RIVLIN (C10, C01, D1), or their POLYNOMIAL / REDUCED
  /// POLYNOMIAL forms with N=1 (CalculiX's default: POLYNOMIAL, N=1), at one temperature. CalculiX
  /// turns on NLGEOM for the whole model where a material is hyperelastic (deck_outline does).
  void hyperelastic()
  {
    known_parameters({"NEO HOOKE", "MOONEY-RIVLIN", "POLYNOMIAL", "REDUCED POLYNOMIAL", "N"});
    if (_material.empty())
      throw Error(where() + " comes before any *MATERIAL");
    if (const std::string* n = _keyword.value("N"); n && *n != "1")
      throw Error(where() + ": N=" + *n + " is not implemented by feticon (N=1: Neo-Hooke, Mooney-Rivlin)");
    const bool neo_hooke = _keyword.has("NEO HOOKE") || _keyword.has("REDUCED POLYNOMIAL");
    if (neo_hooke && (_keyword.has("MOONEY-RIVLIN") || _keyword.has("POLYNOMIAL")))
      throw Error(where() + " names two hyperelastic models");
    fem::Material& m = _data.materials[_material];
    if (m.young > 0)
      throw Error(where() + ": material " + _material + " has *ELASTIC or *HYPERELASTIC already");
    DeckDataLine line;
    if (!next_data(line))
      throw Error(where() + (neo_hooke ? " needs a data line: C10, D1" : " needs a data line: C10, C01, D1"));
    fem::Hyperelastic law;
    law.c10 = real(line, 0, "C10");
    law.c01 = neo_hooke ? 0 : real(line, 1, "C01");
    law.d1 = real(line, neo_hooke ? 1 : 2, "D1");
    try
    {
      law.check("material " + _material);
    }
    catch (const Error& e)
    {
      fail_at(line.where, e.what());
    }
    m.set_hyperelastic(law);
    if (next_data(line))
      fail_at(line.where,
              "temperature-dependent hyperelastic constants are not implemented by feticon (one data line)");
  }

  /// rho (mass per volume, in the deck's units): used by *DLOAD GRAV and CENTRIF only.
  void density()
  {
    known_parameters({});
    if (_material.empty())
      throw Error(where() + " comes before any *MATERIAL");
    DeckDataLine line;
    if (!next_data(line))
      throw Error(where() + " needs a data line: the density");
    const double rho = real(line, 0, "density");
    if (!(rho > 0) || !std::isfinite(rho))
      fail_at(line.at(0), "the density must be positive and finite");
    _data.materials[_material].density = rho;
    if (next_data(line))
      fail_at(line.where, "temperature-dependent densities are not implemented by feticon (one data line)");
  }

  /// Isotropic alpha. ZERO= (CalculiX's reference temperature) does not change the thermal
  /// strain of a constant alpha (fem/temperature_history.hpp), so it is read and not kept.
  void expansion()
  {
    known_parameters({"TYPE", "ZERO", "USER"});
    if (_material.empty())
      throw Error(where() + " comes before any *MATERIAL");
    if (_keyword.has("USER"))
      throw Error(where() + ": USER (a user subroutine) is not implemented by feticon");
    if (const std::string* type = _keyword.value("TYPE"); type && *type != "ISO")
      throw Error(where() + ": TYPE=" + *type + " is not implemented by feticon (isotropic expansion, TYPE=ISO)");
    if (const std::string* zero = _keyword.value("ZERO"); zero && !parse_deck_real(*zero))
      throw Error(where() + ": ZERO=" + *zero + " is not a number");
    DeckDataLine line;
    if (!next_data(line))
      throw Error(where() + " needs a data line: the expansion coefficient");
    _data.materials[_material].expansion = real(line, 0, "expansion coefficient");
    if (next_data(line))
      fail_at(line.where,
              "temperature-dependent expansion coefficients are not implemented by feticon (one data line)");
  }

  /// J2 plasticity with isotropic or kinematic hardening (fem/yield_curve.hpp): lines of von
  /// Mises stress, equivalent plastic strain (and a temperature, which may be given if it is one
  /// for the whole table).
  void plastic()
  {
    known_parameters({"HARDENING"});
    if (_material.empty())
      throw Error(where() + " comes before any *MATERIAL");
    const std::string* hardening = _keyword.value("HARDENING");
    if (hardening && *hardening != "ISOTROPIC" && *hardening != "KINEMATIC")
      throw Error(where() + ": HARDENING=" + *hardening +
                  " is not implemented by feticon (HARDENING=ISOTROPIC or KINEMATIC)");
    fem::YieldCurve& curve = _data.materials[_material].plastic;
    curve = {};
    curve.kinematic = hardening && *hardening == "KINEMATIC";
    DeckDataLine line;
    std::optional<double> temperature;
    while (next_data(line))
    {
      curve.stress.push_back(real(line, 0, "von Mises stress"));
      curve.plastic_strain.push_back(real(line, 1, "equivalent plastic strain"));
      if (line.fields.size() > 2 && !line.fields[2].empty())
      {
        const double t = real(line, 2, "temperature");
        if (temperature && *temperature != t)
          fail_at(line.at(2), "temperature-dependent plastic tables are not implemented by feticon (one temperature)");
        temperature = t;
      }
      try
      {
        // Each line as it comes, so that the error names the line that breaks the table.
        curve.check("material " + _material + ", *PLASTIC");
      }
      catch (const Error& e)
      {
        fail_at(line.where, e.what());
      }
    }
    if (curve.empty())
      throw Error(where() + " needs data lines: von Mises stress, equivalent plastic strain");
  }

  /// TYPE=TEMPERATURE: node or node set, T_0 (model data).
  void initial_conditions()
  {
    known_parameters({"TYPE", "USER"});
    const std::string type = required("TYPE");
    if (type != "TEMPERATURE")
      throw Error(where() + ": TYPE=" + type + " is not implemented by feticon (TYPE=TEMPERATURE)");
    if (_keyword.has("USER"))
      throw Error(where() + ": USER (a user subroutine) is not implemented by feticon");
    if (_in_step)
      throw Error(where() + " belongs to the model data, before the first *STEP");
    DeckDataLine line;
    while (next_data(line))
    {
      const double value = temperature_value(line);
      for (const int32_t n : nodes(line, 0))
        _data.initial_temperatures[n] = value;
    }
  }

  /// Node or node set, T in the step (OP=NEW: the nodes not named go back to T_0).
  void temperature()
  {
    known_parameters({"OP", "AMPLITUDE", "USER", "FILE", "BSTART", "FSTART", "BNSTART", "FNSTART", "SUBMODEL", "STEP",
                      "TIME DELAY"});
    for (const char* p : {"USER", "FILE", "BSTART", "FSTART", "BNSTART", "FNSTART", "SUBMODEL", "STEP", "TIME DELAY"})
      if (_keyword.has(p))
        throw Error(where() + ": " + p + " is not implemented by feticon (temperatures on data lines)");
    if (!_in_step)
      throw Error(where() + " belongs inside a *STEP");
    const std::string amplitude = begin_load(_data.state.temperature);
    DeckDataLine line;
    while (next_data(line))
    {
      const double value = temperature_value(line);
      for (const int32_t n : nodes(line, 0))
        _data.state.temperature[n] = {value, amplitude};
    }
  }

  /// TYPE=CONTACT PAIR, ADD or REMOVE: data lines "slave surface, master surface" of pairs
  /// taken out of the step (and the next ones) or put back.
  void model_change()
  {
    known_parameters({"TYPE", "ADD", "REMOVE"});
    if (!_in_step)
      throw Error(where() + " belongs inside a *STEP");
    const std::string type = required("TYPE");
    if (type != "CONTACT PAIR")
      throw Error(where() + ": TYPE=" + type + " is not implemented by feticon (TYPE=CONTACT PAIR)");
    if (_keyword.has("ADD") == _keyword.has("REMOVE"))
      throw Error(where() + " needs one of ADD and REMOVE");
    const bool remove = _keyword.has("REMOVE");
    DeckDataLine line;
    while (next_data(line))
    {
      if (line.fields.size() < 2 || line.fields[0].empty() || line.fields[1].empty())
        fail_at(line.where, "a *MODEL CHANGE line names a pair: slave surface, master surface");
      const std::pair<std::string, std::string> pair{name_of(line.fields[0]), name_of(line.fields[1])};
      if (remove)
        _data.state.removed_pairs[pair] = line.where.str();
      else
        _data.state.removed_pairs.erase(pair);
    }
  }

  /// *CHANGE FRICTION and *CHANGE SURFACE BEHAVIOR, INTERACTION= (in a step): the *FRICTION or
  /// *SURFACE BEHAVIOR after it gives the interaction's friction or law from this step on.
  /// `interaction` and `at` remember it for that keyword.
  void change_interaction(std::string& interaction, std::string& at)
  {
    known_parameters({"INTERACTION"});
    if (!_in_step)
      throw Error(where() + " belongs inside a *STEP");
    interaction = required("INTERACTION");
    if (!_data.interactions.count(interaction))
      throw Error(where() + ": no *SURFACE INTERACTION '" + interaction + "' is defined before it");
    at = _keyword.where.str();
    no_data();
  }
  void change_friction() { change_interaction(_changing_friction, _changing_friction_where); }
  void change_surface_behavior() { change_interaction(_changing_behavior, _changing_behavior_where); }

  /// Field 1 of a temperature line: finite and not below absolute zero.
  double temperature_value(const DeckDataLine& line)
  {
    const double value = real(line, 1, "temperature");
    try
    {
      fem::check_temperature(value, "the temperature");
    }
    catch (const Error& e)
    {
      fail_at(line.at(1), e.what());
    }
    return value;
  }

  void solid_section()
  {
    known_parameters({"ELSET", "MATERIAL", "ORIENTATION", "OFFSET", "CONTROLS"});
    if (_keyword.has("OFFSET") && real_parameter("OFFSET", 0) != 0)
      throw Error(where() + ": OFFSET (of a shell's reference surface) is not implemented by feticon");
    if (_keyword.has("ORIENTATION"))
      _data.warn(where() + ": ORIENTATION= changes nothing for the isotropic material, and is not used");
    DeckSection section{required("ELSET"), required("MATERIAL"), _keyword.where};
    if (_data.coupling_elements.count(_scope.prefix + section.elset))
      return skip_data(); // a DCOUP3D element's section: no cell, no material
    // The data line: the thickness of plane strain and plane stress cells (meaningless for
    // 3D and axisymmetric ones).
    DeckDataLine line;
    while (next_data(line))
      if (section.thickness == 0 && !line.fields.empty() && !line.fields[0].empty())
      {
        section.thickness = real(line, 0, "thickness");
        if (!(section.thickness > 0) || !std::isfinite(section.thickness))
          fail_at(line.at(0), "the thickness " + std::string(line.fields[0]) + " is not positive");
      }
    _data.sections.push_back(std::move(section));
  }

  // ---- loads and supports ------------------------------------------------------------------
  /// OP=NEW clears the kind's values set in steps; MOD keeps them.
  bool op_new() const
  {
    const std::string* op = _keyword.value("OP");
    if (op && *op != "NEW" && *op != "MOD")
      throw Error(where() + ": OP=" + *op + " must be NEW or MOD");
    return op && *op == "NEW";
  }

  /// The AMPLITUDE= of a load keyword (empty: none), remembered for the check that an
  /// *AMPLITUDE defines it (which may come later in the deck, as CalculiX allows).
  std::string amplitude_of()
  {
    const std::string* name = _keyword.value("AMPLITUDE");
    if (!name)
      return {};
    if (name->empty())
      throw Error(where() + ": AMPLITUDE= needs the name of an *AMPLITUDE");
    _data.amplitude_uses.emplace(*name, where());
    return *name;
  }

  void boundary()
  {
    known_parameters({"OP", "AMPLITUDE", "TYPE", "FIXED", "USER", "LOAD CASE"});
    const std::string amplitude = amplitude_of();
    for (const char* p : {"FIXED", "USER", "LOAD CASE"})
      if (_keyword.has(p))
        throw Error(where() + ": " + p + " is not implemented by feticon");
    if (const std::string* t = _keyword.value("TYPE"); t && *t != "DISPLACEMENT")
      throw Error(where() + ": TYPE=" + *t + " is not implemented by feticon (displacements)");
    auto& target = _in_step ? _data.state.boundary : _data.model_boundary;
    auto& rotation_target = _in_step ? _data.state.boundary_rotation : _data.model_boundary_rotation;
    if (op_new())
    {
      // CalculiX removes every support, the model's included (boundarys.f), from this step on.
      _data.state.boundary.clear();
      _data.state.boundary_rotation.clear();
      if (_in_step)
        _data.model_boundary.clear(), _data.model_boundary_rotation.clear();
    }
    DeckDataLine line;
    while (next_data(line))
    {
      const std::vector<int32_t> targets = nodes(line, 0);
      int64_t first = 0, last = 0;
      double value = 0;
      if (line.fields.size() >= 2 && !is_integer(line.fields[1]))
      {
        // Abaqus's named conditions.
        const std::string kind = name_of(line.fields[1]);
        if (kind == "ENCASTRE" || kind == "PINNED")
          first = 1, last = 3;
        else if (kind == "XSYMM")
          first = last = 1;
        else if (kind == "YSYMM")
          first = last = 2;
        else if (kind == "ZSYMM")
          first = last = 3;
        else
          fail_at(line.at(1), "'" + text(line.fields[1]) + "' is no degree of freedom or known condition");
      }
      else
      {
        first = integer(line, 1, "first degree of freedom");
        last = line.fields.size() > 2 && !line.fields[2].empty() ? integer(line, 2, "last degree of freedom") : first;
        value = line.fields.size() > 3 && !line.fields[3].empty() ? real(line, 3, "prescribed value") : 0.0;
      }
      if (first < 1 || last < first || last > 6)
        fail_at(line.where,
                "degrees of freedom " + std::to_string(first) + " to " + std::to_string(last) +
                    " are not within 1 to 6");
      // DOFs 4 to 6 are rotations: a reference node's (fem/coupling.hpp); the model builder
      // drops them on solid nodes, which have none.
      for (int64_t dof = first; dof <= last; ++dof)
        for (int32_t n : targets)
          (dof <= 3 ? target : rotation_target)[3 * int64_t{n} + (dof - 1) % 3] = {value, amplitude};
    }
  }

  /// The parameters of a load keyword: OP=NEW clears the loads of its kind set so far; the
  /// AMPLITUDE= of the keyword's loads.
  template <class Loads>
  std::string begin_load(Loads& loads)
  {
    known_parameters({"OP", "AMPLITUDE"});
    if (op_new())
      loads.clear();
    return amplitude_of();
  }

  void cload()
  {
    const std::string amplitude = begin_load(_data.state.cload);
    if (op_new())
      _cload_defined.clear(), _data.state.cload_moment.clear(), _moment_defined.clear();
    DeckDataLine line;
    while (next_data(line))
    {
      const std::vector<int32_t> targets = nodes(line, 0);
      const int64_t dof = integer(line, 1, "degree of freedom");
      if (dof < 1 || dof > 6)
        fail_at(line.at(1),
                "degree of freedom " + std::to_string(dof) +
                    ": forces act on 1 to 3, moments on a reference node's 4 to 6");
      const double value = real(line, 2, "force");
      for (int32_t n : unique(targets))
        if (dof <= 3)
          add_load(_data.state.cload, _cload_defined, 3 * int64_t{n} + dof - 1, {value, amplitude}, line.where);
        else
          add_load(_data.state.cload_moment, _moment_defined, 3 * int64_t{n} + dof - 4, {value, amplitude}, line.where);
    }
  }

  /// Pressure `value` on face `face_field` (P1..P6) of the cells of field 0.
  void pressure_on(const DeckDataLine& line, const std::vector<int32_t>& cells, size_t face_field,
                   const DeckValue& value)
  {
    const std::string kind = name_of(line.fields[face_field]);
    if (kind.size() != 2 || kind[0] != 'P' || kind[1] < '1' || kind[1] > '6')
      fail_at(line.at(face_field),
              "load type '" + text(line.fields[face_field]) + "' is not implemented by feticon (pressure P1 to P6)");
    for (int32_t c : unique(cells))
      add_load(_data.state.dload, _dload_defined, std::pair{c, kind[1] - '0'}, value, line.where);
  }

  /// CalculiX's forcadd.f and loadadd.f: the first value a step gives a DOF or a face replaces
  /// the one before the step; more values in the same step add to it (with the same amplitude).
  template <class Key>
  void add_load(std::map<Key, DeckValue>& loads, std::set<Key>& defined, const Key& key, const DeckValue& value,
                const DeckPosition& at)
  {
    if (defined.insert(key).second)
    {
      loads[key] = value;
      return;
    }
    DeckValue& sum = loads[key];
    if (sum.amplitude != value.amplitude)
      fail_at(at,
              "a second load on one degree of freedom or face in one step with another amplitude (CalculiX "
              "adds loads given twice in a step, and refuses that)");
    sum.value += value.value;
  }

  static std::vector<int32_t> unique(std::vector<int32_t> v)
  {
    std::sort(v.begin(), v.end());
    v.erase(std::unique(v.begin(), v.end()), v.end());
    return v;
  }

  /// GRAV (magnitude, direction) or CENTRIF (omega^2, a point of the axis, its direction) on
  /// the cells of field 0, as CalculiX reads them.
  void body_load_on(const DeckDataLine& line, const std::vector<int32_t>& cells, int kind, const std::string& amplitude)
  {
    std::array<double, 7> values{};
    const size_t needed = kind == 0 ? 6 : 9;
    if (line.fields.size() < needed)
      fail_at(line.where,
              kind == 0 ? "a *DLOAD GRAV line is: element or set, GRAV, magnitude, direction x, y, z"
                        : "a *DLOAD CENTRIF line is: element or set, CENTRIF, omega^2, a point of the "
                          "axis x, y, z, the axis's direction x, y, z");
    for (size_t k = 2; k < needed; ++k)
      values[k - 2] = real(line, k, "value");
    const Eigen::Vector3d direction =
        kind == 0 ? Eigen::Vector3d(values[1], values[2], values[3]) : Eigen::Vector3d(values[4], values[5], values[6]);
    if (!(direction.norm() > 0))
      fail_at(line.at(kind == 0 ? 3 : 6), kind == 0 ? "the gravity direction is zero" : "the rotation axis is zero");
    if (kind == 1 && values[0] < 0)
      fail_at(line.at(2), "omega^2 must not be negative");
    if (kind == 0) // the acceleration vector: CalculiX scales the normalized direction
    {
      const Eigen::Vector3d g = values[0] * direction.normalized();
      values = {g.x(), g.y(), g.z(), 0, 0, 0, 0};
    }
    for (int32_t c : cells)
      _data.state.body[{c, kind}] = {values, line.where.str() + ": *DLOAD " + (kind == 0 ? "GRAV" : "CENTRIF"),
                                     amplitude};
  }

  void dload()
  {
    const std::string amplitude = begin_load(_data.state.dload);
    if (op_new())
      _dload_defined.clear();
    if (op_new())
      _data.state.body.clear();
    DeckDataLine line;
    while (next_data(line))
    {
      const std::vector<int32_t> cells = elements(line, 0);
      if (line.fields.size() < 3)
        fail_at(line.where, "a *DLOAD line is: element or set, P1 to P6, pressure (or GRAV, CENTRIF)");
      const std::string kind = name_of(line.fields[1]);
      if (kind == "GRAV" || kind == "CENTRIF")
        body_load_on(line, cells, kind == "GRAV" ? 0 : 1, amplitude);
      else
        pressure_on(line, cells, 1, {real(line, 2, "pressure"), amplitude});
    }
  }

  void dsload()
  {
    const std::string amplitude = begin_load(_data.state.dload);
    if (op_new())
      _dload_defined.clear();
    DeckDataLine line;
    while (next_data(line))
    {
      const std::string name = line.fields.empty() ? std::string() : name_of(line.fields[0]);
      const auto it = _data.surfaces.find(name);
      if (it == _data.surfaces.end() || it->second.node_based)
        fail_at(line.at(0), "no element surface '" + name + "' is defined");
      if (line.fields.size() < 3 || name_of(line.fields[1]) != "P")
        fail_at(line.where, "a *DSLOAD line is: surface, P, pressure");
      const double value = real(line, 2, "pressure");
      std::set<std::pair<int32_t, int>> faces; // a surface lists a face once
      for (const DeckFace& f : it->second.faces)
        if (faces.insert({f.cell, f.face}).second)
          add_load(_data.state.dload, _dload_defined, std::pair{f.cell, f.face}, DeckValue{value, amplitude},
                   line.where);
    }
  }

  /// A real parameter value (SHIFTX=...), or `otherwise` without it.
  double real_parameter(const char* key, double otherwise) const
  {
    const std::string* v = _keyword.value(key);
    if (!v)
      return otherwise;
    const std::optional<double> x = parse_deck_real(*v);
    if (!x)
      throw Error(where() + ": " + key + "=" + *v + " is not a number");
    return *x;
  }

  /// A tabular amplitude: (time, value) pairs, four to a line as CalculiX writes them.
  void amplitude()
  {
    known_parameters({"NAME", "TIME", "SHIFTX", "SHIFTY", "VALUE", "DEFINITION", "USER"});
    const std::string name = required("NAME");
    if (_keyword.has("USER"))
      throw Error(where() + ": USER amplitudes are not implemented by feticon (tabular ones are)");
    if (const std::string* d = _keyword.value("DEFINITION"); d && *d != "TABULAR")
      throw Error(where() + ": DEFINITION=" + *d + " is not implemented by feticon (TABULAR)");
    if (const std::string* v = _keyword.value("VALUE"); v && *v != "RELATIVE")
      throw Error(where() + ": VALUE=" + *v + " is not implemented by feticon (RELATIVE: a factor on the load)");
    fem::Amplitude a;
    if (const std::string* t = _keyword.value("TIME"))
    {
      if (*t != "TOTAL TIME" && *t != "STEP TIME")
        throw Error(where() + ": TIME=" + *t + " must be TOTAL TIME or STEP TIME");
      a.total_time = *t == "TOTAL TIME";
    }
    a.shift_x = real_parameter("SHIFTX", 0);
    a.shift_y = real_parameter("SHIFTY", 0);
    a.where = where() + " " + name;
    std::vector<double> numbers;
    DeckDataLine line;
    while (next_data(line))
    {
      size_t n = line.fields.size();
      while (n > 0 && line.fields[n - 1].empty())
        --n; // a line that ends with a comma
      for (size_t k = 0; k < n; ++k)
        numbers.push_back(real(line, k, k % 2 == 0 ? "time" : "amplitude value"));
      if (numbers.size() % 2 != 0 && !line.continues)
        fail_at(line.where, "an *AMPLITUDE line holds (time, value) pairs: an odd number of values");
    }
    for (size_t k = 0; k + 1 < numbers.size(); k += 2)
      a.points.emplace_back(numbers[k], numbers[k + 1]);
    a.check();
    if (!_data.amplitudes.emplace(name, std::move(a)).second)
      throw Error(where() + ": amplitude " + name + " is defined twice");
  }

  void equation()
  {
    known_parameters({});
    DeckDataLine line;
    while (next_data(line))
    {
      const int64_t n = integer(line, 0, "number of terms");
      if (n < 1 || n > 1000)
        fail_at(line.at(0), "an equation has 1 to 1000 terms, not " + std::to_string(n));
      fem::LinearEquation eq;
      const DeckPosition start = line.where;
      while (static_cast<int64_t>(eq.terms.size()) < n)
      {
        if (!next_data(line))
          fail_at(start, "the equation has fewer than its " + std::to_string(n) + " terms");
        if (line.fields.size() % 3 != 0)
          fail_at(line.where, "equation terms come in triples: node, degree of freedom, coefficient");
        for (size_t k = 0; k + 2 < line.fields.size(); k += 3)
        {
          const std::vector<int32_t> targets = nodes(line, k);
          if (targets.size() != 1)
            fail_at(line.at(k), "an equation term names one node; this set has " + std::to_string(targets.size()));
          const int64_t dof = integer(line, k + 1, "degree of freedom");
          if (dof < 1 || dof > 3)
            fail_at(line.at(k + 1), "degree of freedom " + std::to_string(dof) + " is not 1 to 3");
          eq.terms.push_back({targets[0], static_cast<int>(dof - 1), real(line, k + 2, "coefficient")});
        }
      }
      if (static_cast<int64_t>(eq.terms.size()) != n)
        fail_at(line.where, "the equation has more terms than its " + std::to_string(n));
      if (eq.terms[0].coefficient == 0)
        fail_at(start, "the first term of an equation (the dependent one) has coefficient zero");
      _data.equations.push_back(std::move(eq));
    }
  }

  /// *TRANSFORM, NSET=, TYPE=R|C (model data; CalculiX's "*TRANSFORM"): the supports and
  /// concentrated forces of the set's nodes act along the local axes from points a and b.
  void transform()
  {
    known_parameters({"NSET", "TYPE"});
    if (_in_step)
      throw Error(where() + " belongs to the model data, before the first *STEP");
    const std::string& set = required("NSET");
    const auto nodes = _data.node_sets.find(set);
    if (nodes == _data.node_sets.end())
      throw Error(where() + ": no node set '" + set + "' is defined");
    const std::string* type = _keyword.value("TYPE");
    if (type && *type != "R" && *type != "C")
      throw Error(where() + ": TYPE=" + *type + " is not implemented by feticon (R: rectangular, C: cylindrical)");
    DeckTransform t{type && *type == "C", {}, {}, _keyword.where};
    DeckDataLine line;
    if (!next_data(line))
      throw Error(where() + " needs a data line: points a and b (x, y, z each)");
    for (int k = 0; k < 3; ++k)
    {
      t.a[k] = real(line, k, "a coordinate of point a");
      t.b[k] = real(line, k + 3, "a coordinate of point b");
    }
    try
    {
      if (t.cylindrical)
        (void)fem::cylindrical_axes(t.a, t.b, t.a);
      else
        (void)fem::rectangular_axes(t.a, t.b);
    }
    catch (const Error& e)
    {
      fail_at(line.where, e.what());
    }
    if (next_data(line))
      fail_at(line.where, "takes one data line (points a and b)");
    const auto index = static_cast<int32_t>(_data.transforms.size());
    _data.transforms.push_back(t);
    nodes->second.for_each([&](int32_t n) { _data.node_transform[n] = index; });
  }

  // ---- contact --------------------------------------------------------------------------
  void surface_interaction()
  {
    known_parameters({"NAME"});
    _interaction = required("NAME");
    _data.interactions.insert(_interaction);
    _in_interaction = true;
    // Abaqus's optional data line: the out-of-plane thickness of 2D surfaces (Abaqus/CAE writes
    // "1.,"); feticon's 2D pressures are per the section's thickness already.
    DeckDataLine line;
    if (next_data(line))
    {
      if (!line.fields.empty() && !line.fields[0].empty() && real(line, 0, "out-of-plane thickness") != 1.0)
        _data.warn(where() + ": the out-of-plane thickness " + text(line.fields[0]) +
                   " is not used (2D contact pressures are per the *SOLID SECTION thickness)");
      if (next_data(line))
        fail_at(line.where, "takes at most one data line (the out-of-plane thickness)");
    }
  }

  void surface_behavior()
  {
    known_parameters({"PRESSURE-OVERCLOSURE"});
    // After a *CHANGE SURFACE BEHAVIOR the law of its interaction from the step on (TIED or not:
    // the pairs are ties or contact there, DeckLoadState::tied); else the law of the interaction
    // whose block this is.
    const std::string changed = std::exchange(_changing_behavior, std::string());
    if (changed.empty() && _interaction.empty())
      throw Error(where() + " comes before any *SURFACE INTERACTION");
    const std::string interaction = changed.empty() ? _interaction : changed;
    const std::string law = required("PRESSURE-OVERCLOSURE");
    if (law != "HARD" && law != "TIED" && law != "LINEAR" && law != "EXPONENTIAL" && law != "TABULAR")
      throw Error(where() + ": PRESSURE-OVERCLOSURE=" + law + " is not a law feticon knows");
    std::string parameters;
    const fem::NormalLaw normal_law = pressure_overclosure(law, parameters);
    if (!changed.empty())
    {
      _data.state.tied[interaction] = law == "TIED";
      if (law != "TIED")
        _data.state.laws[interaction] = normal_law;
    }
    else if (law == "TIED")
      _data.tied_interactions.insert(interaction);
    else
      _data.laws[interaction] = normal_law;
    if (law == "HARD")
      return; // what feticon enforces
    if (law == "TIED")
    {
      // CalculiX's tied contact is a penalty law across the surfaces (these lines: its
      // stiffness) whose tangential direction follows the *FRICTION stick slope (changesurfbeh:
      // its slave nodes slide 0.02 of 0.1 over the master); feticon ties the surfaces exactly in
      // every direction, as a *TIE.
      if (!parameters.empty())
        _data.warn("interaction " + interaction + ": PRESSURE-OVERCLOSURE=TIED (" + parameters + ", " +
                   _keyword.where.str() +
                   ") is a penalty tie across the surfaces, tangentially the *FRICTION stick slope's in CalculiX; "
                   "feticon ties the surfaces exactly in every direction");
      return;
    }
    _data.warn("interaction " + interaction + ": PRESSURE-OVERCLOSURE=" + law + " (" + parameters + ", " +
               _keyword.where.str() +
               ") is a penalty law: contact.law=deck solves it, contact.law=hard (the default) solves hard contact "
               "instead (exact non-penetration: the answer differs from CalculiX's by the penetration the law "
               "allows)");
  }

  /// The data lines of a *SURFACE BEHAVIOR with law `law` as a normal law (TIED and HARD: hard),
  /// their fields joined in `parameters` for the messages.
  fem::NormalLaw pressure_overclosure(const std::string& law, std::string& parameters)
  {
    fem::NormalLaw out;
    out.kind = law == "LINEAR" ? fem::NormalLawKind::linear
        : law == "EXPONENTIAL" ? fem::NormalLawKind::exponential
        : law == "TABULAR"     ? fem::NormalLawKind::tabular
                               : fem::NormalLawKind::hard;
    int64_t n_lines = 0;
    for (DeckDataLine line; next_data(line); ++n_lines)
    {
      for (size_t k = 0; k < line.fields.size(); ++k)
        parameters += (parameters.empty() ? "" : ", ") + text(line.fields[k]);
      if (out.kind == fem::NormalLawKind::tabular)
        tabular_line(line, out);
      else if (n_lines == 0)
        law_constants(line, out);
    }
    if (out.kind == fem::NormalLawKind::exponential && !(out.c0 > 0))
      throw Error(where() + ": PRESSURE-OVERCLOSURE=EXPONENTIAL needs a data line: c0, p0");
    if (out.kind == fem::NormalLawKind::tabular && out.table.empty())
      throw Error(where() + ": PRESSURE-OVERCLOSURE=TABULAR needs data lines: pressure, overclosure");
    return out;
  }

  /// The first data line of a linear (K, sigma_inf, c0) or exponential (c0, p0) law.
  void law_constants(const DeckDataLine& line, fem::NormalLaw& out)
  {
    const auto given = [&](size_t field) { return line.fields.size() > field && !line.fields[field].empty(); };
    if (out.kind == fem::NormalLawKind::linear)
    {
      // CalculiX: a slope K <= 0 or none takes 50 times the first material's E (deck_model).
      out.slope = given(0) ? real(line, 0, "slope K") : 0.0;
      out.sigma_inf = given(1) ? std::max(real(line, 1, "tension sigma_inf"), 0.0) : 0.0;
      if (given(0) && !(out.slope > 0))
        _data.warn(where() + ": the slope K " + text(line.fields[0]) +
                   " is not positive; CalculiX's default, 50 times the first material's E, is used");
      out.slope = std::max(out.slope, 0.0);
    }
    else if (out.kind == fem::NormalLawKind::exponential)
    {
      if (!given(0) || !given(1))
        fail_at(line.where, "PRESSURE-OVERCLOSURE=EXPONENTIAL needs c0, p0");
      out.c0 = real(line, 0, "clearance c0");
      out.p0 = real(line, 1, "pressure p0");
      if (!(out.c0 > 0))
        fail_at(line.at(0), "the clearance c0 " + text(line.fields[0]) + " must be positive");
      if (!(out.p0 >= 0))
        fail_at(line.at(1), "the pressure p0 " + text(line.fields[1]) + " must not be negative");
    }
  }

  /// A line "pressure, overclosure" (CalculiX's order) of a tabular law: increasing overclosure,
  /// a pressure that does not decrease.
  void tabular_line(const DeckDataLine& line, fem::NormalLaw& out)
  {
    if (line.fields.size() > 2 && !line.fields[2].empty())
      fail_at(line.at(2), "a table per temperature is not implemented by feticon (pressure, overclosure)");
    const double pressure = real(line, 0, "pressure");
    const double overclosure = real(line, 1, "overclosure");
    if (!out.table.empty() && !(overclosure > out.table.back().first && pressure >= out.table.back().second))
      fail_at(line.where, "the table needs increasing overclosures with pressures that do not decrease");
    out.table.emplace_back(overclosure, pressure);
  }

  /// *FRICTION (CalculiX: no parameters, one line "mu, stick slope"): Coulomb's law on the
  /// interaction whose block it is in. Abaqus's options that change the law are refused;
  /// those that only tune a penalty stick are reported (feticon's stick is exact).
  void friction()
  {
    static const std::map<std::string, std::string> other_laws = {
        {"EXPONENTIAL DECAY", "a coefficient that decays with the slip rate"},
        {"EXPONENTIAL", "a coefficient that decays with the slip rate"},
        {"ANISOTROPIC", "anisotropic friction"},
        {"ROUGH", "rough friction (no slip at any load)"},
        {"TAUMAX", "a shear stress limit beside Coulomb's law"},
        {"USER", "user friction subroutines"},
        {"DEPENDENCIES", "a coefficient that depends on field variables"},
        {"TEMPERATURE", "a coefficient that depends on temperature"},
    };
    for (const auto& [key, value] : _keyword.parameters)
      if (const auto it = other_laws.find(key); it != other_laws.end())
        throw Error(where() + ": " + key + " (" + it->second + ") is not implemented by feticon (Coulomb's law: mu)");
    known_parameters({"LAGRANGE", "SLIP TOLERANCE", "ELASTIC SLIP"});
    // After a *CHANGE FRICTION (in a step) the friction of its interaction from the step on;
    // else that of the interaction whose block this is.
    const std::string changed = std::exchange(_changing_friction, std::string());
    const std::string interaction = changed.empty() ? _interaction : changed;
    if (changed.empty() && !_in_interaction)
      throw Error(where() +
                  " belongs in the block of a *SURFACE INTERACTION (right after it or its *SURFACE BEHAVIOR)");
    if (changed.empty() && _data.frictions.count(interaction))
      throw Error(where() + ": interaction " + interaction + " has a *FRICTION already (at " +
                  _data.frictions.at(interaction).where.str() + ")");
    // A tied interaction sticks whatever its *FRICTION says (CalculiX decks write mu = 1e30).
    if (_data.tied_interactions.count(interaction))
    {
      for (DeckDataLine line; next_data(line);)
        ;
      return;
    }
    (changed.empty() ? _data.frictions : _data.state.frictions)[interaction] = friction_line(interaction);
  }

  /// The data line of a *FRICTION of `interaction` (mu, stick slope), checked.
  DeckFriction friction_line(const std::string& interaction)
  {
    DeckFriction friction;
    friction.where = _keyword.where;
    DeckDataLine line;
    if (!next_data(line))
      throw Error(where() + " needs a data line: friction coefficient mu [, stick slope]");
    friction.coefficient = real(line, 0, "friction coefficient mu");
    if (friction.coefficient < 0 || friction.coefficient > largest_friction_coefficient)
      fail_at(line.at(0), "friction coefficient " + text(line.fields[0]) + " is outside 0 to 100");
    if (line.fields.size() > 2)
      fail_at(line.at(2),
              "a coefficient that depends on slip rate, pressure or temperature is not implemented by "
              "feticon (the data line is: mu, stick slope)");
    std::string slope;
    if (line.fields.size() == 2 && !line.fields[1].empty())
    {
      friction.stick_slope = real(line, 1, "stick slope");
      slope = text(line.fields[1]);
      if (!(friction.stick_slope > 0))
        fail_at(line.at(1), "the stick slope " + slope + " must be positive");
    }
    if (next_data(line))
      fail_at(line.where, "takes one data line (a table of coefficients is not implemented by feticon)");
    for (const char* p : {"LAGRANGE", "SLIP TOLERANCE", "ELASTIC SLIP"})
      if (_keyword.has(p))
        _data.warn(where() + ": " + p + " is not used; feticon enforces the stick exactly");
    if (!slope.empty())
      _data.warn("interaction " + interaction + ": the stick slope " + slope + " of *FRICTION (" +
                 _keyword.where.str() + ") is not used; feticon enforces the stick exactly (no elastic slip)");
    return friction;
  }

  void contact_pair()
  {
    known_parameters({"INTERACTION", "TYPE", "SMALL SLIDING", "ADJUST", "NLGEOM"});
    DeckContactPair pair;
    pair.interaction = required("INTERACTION");
    pair.where = _keyword.where;
    if (const std::string* type = _keyword.value("TYPE"))
    {
      if (*type != "SURFACE TO SURFACE" && *type != "NODE TO SURFACE")
        throw Error(where() + ": TYPE=" + *type +
                    " is not implemented by feticon (SURFACE TO SURFACE, NODE TO SURFACE)");
      pair.node_to_surface = *type == "NODE TO SURFACE";
    }
    if (const std::string* adjust = _keyword.value("ADJUST"))
    {
      // A number is a distance (CalculiX: the slave nodes with a clearance up to it), anything
      // else the name of the node set to move.
      if (const std::optional<double> distance = parse_deck_real(*adjust))
      {
        if (!std::isfinite(*distance) || *distance < 0)
          throw Error(where() + ": ADJUST=" + *adjust + " must be a distance >= 0 or a node set");
        pair.adjust = *distance;
      }
      else
        pair.adjust_set = name_of(*adjust);
    }
    if (_keyword.has("SMALL SLIDING"))
      _data.warn(where() + ": SMALL SLIDING is not used; feticon searches the contact in every outer iteration");
    DeckDataLine line;
    bool any = false;
    while (next_data(line))
    {
      if (line.fields.size() != 2 || line.fields[0].empty() || line.fields[1].empty())
        fail_at(line.where, "a contact pair line is: slave surface, master surface");
      pair.slave = name_of(line.fields[0]);
      pair.master = name_of(line.fields[1]);
      _data.pairs.push_back(pair);
      any = true;
    }
    if (!any)
      throw Error(where() + " needs a data line: slave surface, master surface");
  }

  /// *TIE (model data): NAME, POSITION TOLERANCE, ADJUST=YES|NO and one line "slave, master";
  /// cyclic symmetry and multistage ties are other constraints, refused.
  void tie()
  {
    if (_keyword.has("MULTISTAGE"))
      throw Error(where() + ": MULTISTAGE ties are not implemented by feticon (cyclic symmetry across stages)");
    known_parameters({"NAME", "POSITION TOLERANCE", "ADJUST", "CYCLIC SYMMETRY"});
    if (_in_step)
      throw Error(where() + " belongs to the model data, before the first *STEP");
    DeckTie tie;
    tie.name = required("NAME");
    tie.where = _keyword.where;
    tie.cyclic = _keyword.has("CYCLIC SYMMETRY");
    if (const std::string* tolerance = _keyword.value("POSITION TOLERANCE"))
    {
      const std::optional<double> value = parse_deck_real(*tolerance);
      if (!value || !std::isfinite(*value) || *value < 0)
        throw Error(where() + ": POSITION TOLERANCE=" + *tolerance + " must be a distance >= 0");
      tie.position_tolerance = *value;
    }
    if (const std::string* adjust = _keyword.value("ADJUST"))
    {
      if (*adjust != "YES" && *adjust != "NO")
        throw Error(where() + ": ADJUST=" + *adjust + " must be YES or NO");
      tie.adjust = *adjust == "YES";
    }
    DeckDataLine line;
    if (!next_data(line))
      throw Error(where() + " needs a data line: slave surface, master surface");
    if (line.fields.size() != 2 || line.fields[0].empty() || line.fields[1].empty())
      fail_at(line.where, "a tie line is: slave surface, master surface");
    tie.slave = name_of(line.fields[0]);
    tie.master = name_of(line.fields[1]);
    if (next_data(line))
      fail_at(line.where, "a *TIE has one line (slave surface, master surface); write one *TIE per pair of surfaces");
    _data.ties.push_back(std::move(tie));
  }

  /// *CYCLIC SYMMETRY MODEL, N=, TIE= (model data): the number of sectors and the axis (points a
  /// and b) of a cyclic symmetry *TIE before it; a static run solves the datum sector with the
  /// same answer in every sector (fem::Tie::CyclicSymmetry). NGRAPH, NPHYS, ELSET and CHECK only
  /// shape CalculiX's plots and checks.
  // ---- reference nodes and couplings (fem/coupling.hpp) ---------------------------------
  /// The node of parameter `key` (a node number, or a node set of one node), or -1 if absent.
  int32_t reference_node(std::initializer_list<std::string_view> keys) const
  {
    for (const std::string_view key : keys)
      if (const std::string* v = _keyword.value(key); v && !v->empty())
      {
        if (!is_integer(*v))
        {
          const auto it = _data.node_sets.find(_scope.prefix + *v);
          if (it == _data.node_sets.end() || it->second.expand().size() != 1)
            throw Error(where() + ": " + std::string(key) + "=" + *v +
                        " is neither a node number nor a node set of one node");
          return it->second.expand().front();
        }
        const std::optional<int64_t> label = parse_integer(*v);
        if (!label)
          throw Error(where() + ": " + std::string(key) + "=" + *v + " is not a node number");
        return index_of(*label, true, _scope, _keyword.where);
      }
    return -1;
  }

  std::string coupling_name(const std::string& what) const
  {
    return "*" + _keyword.name + (what.empty() ? "" : " " + what) + " (" + _keyword.where.str() + ")";
  }

  void rigid_body()
  {
    known_parameters({"NSET", "ELSET", "REF NODE", "REFNODE", "ROT NODE", "ROTNODE"});
    if (_keyword.has("NSET") == _keyword.has("ELSET"))
      throw Error(where() + " needs one of NSET= and ELSET=");
    DeckCoupling c;
    c.name = coupling_name("");
    c.where = _keyword.where;
    if (_keyword.has("NSET"))
      c.node_set = _scope.prefix + required("NSET");
    else
      c.element_set = _scope.prefix + required("ELSET");
    c.ref_node = reference_node({"REF NODE", "REFNODE"});
    c.rot_node = reference_node({"ROT NODE", "ROTNODE"});
    if (c.ref_node >= 0 && c.ref_node == c.rot_node)
      throw Error(where() + ": REF NODE and ROT NODE are the same node");
    _data.couplings.push_back(std::move(c));
    no_data();
  }

  void coupling()
  {
    known_parameters({"REF NODE", "REFNODE", "SURFACE", "CONSTRAINT NAME", "ORIENTATION"});
    if (_keyword.has("ORIENTATION"))
      throw Error(where() + ": ORIENTATION= (a coupling in a local system) is not implemented by feticon");
    DeckCoupling c;
    const std::string* name = _keyword.value("CONSTRAINT NAME");
    c.name = coupling_name(name ? *name : "");
    c.where = _keyword.where;
    c.surface = _scope.prefix + required("SURFACE");
    c.ref_node = reference_node({"REF NODE", "REFNODE"});
    if (c.ref_node < 0)
      throw Error(where() + " needs REF NODE=");
    _pending_coupling = std::move(c);
    no_data();
  }

  /// *PRE-TENSION SECTION, SURFACE=, NODE= and an optional line with the normal (fem/coupling.hpp).
  void pre_tension_section()
  {
    known_parameters({"SURFACE", "NODE", "ELEMENT"});
    if (_keyword.has("ELEMENT"))
      throw Error(where() +
                  ": ELEMENT= (a pretension through a beam element) is not implemented by feticon, which "
                  "has no beam elements; give SURFACE=, a cut through the solid bolt");
    DeckCoupling c;
    c.kind = fem::CouplingKind::pretension;
    c.name = coupling_name("");
    c.where = _keyword.where;
    c.surface = _scope.prefix + required("SURFACE");
    c.ref_node = reference_node({"NODE"});
    if (c.ref_node < 0)
      throw Error(where() + " needs NODE=");
    DeckDataLine line;
    if (next_data(line))
    {
      for (int k = 0; k < 3; ++k)
        c.normal(k) = line.fields.size() > static_cast<size_t>(k) && !line.fields[k].empty()
            ? real(line, static_cast<size_t>(k), "normal component")
            : 0.0;
      if (!(c.normal.norm() > 0) || !c.normal.allFinite())
        fail_at(line.where, "the normal of a pretension section must be a nonzero vector");
      if (next_data(line))
        fail_at(line.where, "takes one data line (the normal)");
    }
    _data.couplings.push_back(std::move(c));
  }

  /// The DOF ranges of a *KINEMATIC or *DISTRIBUTING line, each within 1 to `largest`.
  std::vector<int> coupling_dofs(int largest)
  {
    std::vector<int> out;
    DeckDataLine line;
    while (next_data(line))
    {
      const int64_t first = integer(line, 0, "first degree of freedom");
      const int64_t last =
          line.fields.size() > 1 && !line.fields[1].empty() ? integer(line, 1, "last degree of freedom") : first;
      if (first < 1 || last < first || last > largest)
        fail_at(line.where,
                "degrees of freedom " + std::to_string(first) + " to " + std::to_string(last) +
                    " are not within 1 to " + std::to_string(largest));
      for (int64_t d = first; d <= last; ++d)
        out.push_back(static_cast<int>(d));
    }
    if (out.empty())
      throw Error(where() + " needs a line of degrees of freedom");
    return out;
  }

  void kinematic()
  {
    known_parameters({});
    if (!_pending_coupling)
      throw Error(where() + " must follow a *COUPLING");
    DeckCoupling c = *std::exchange(_pending_coupling, std::nullopt);
    c.components = {false, false, false};
    for (const int d : coupling_dofs(3))
      c.components[d - 1] = true;
    _data.couplings.push_back(std::move(c));
  }

  void distributing()
  {
    known_parameters({});
    if (!_pending_coupling)
      throw Error(where() + " must follow a *COUPLING");
    DeckCoupling c = *std::exchange(_pending_coupling, std::nullopt);
    c.kind = fem::CouplingKind::distributing;
    for (const int d : coupling_dofs(6))
      if (d > 3)
        c.moments[d - 4] = true;
    _data.couplings.push_back(std::move(c));
  }

  /// *DISTRIBUTING COUPLING, ELSET= (one DCOUP3D element, whose node is the reference node);
  /// lines of a node or node set and its weight, resolved by the model builder (the sets may
  /// come later).
  void distributing_coupling()
  {
    known_parameters({"ELSET"});
    const std::string set = _scope.prefix + required("ELSET");
    const auto it = _data.coupling_elements.find(set);
    if (it == _data.coupling_elements.end())
      throw Error(where() + ": ELSET=" + set + " is no set of one DCOUP3D element");
    DeckCoupling c;
    c.kind = fem::CouplingKind::mean;
    c.name = coupling_name(set);
    c.where = _keyword.where;
    c.ref_node = _data.node_index.find(it->second);
    if (c.ref_node < 0)
      throw Error(where() + ": node " + std::to_string(it->second - _scope.node_offset) + " of ELSET=" + set +
                  " is not defined (by a *NODE before this line)");
    DeckDataLine line;
    while (next_data(line))
    {
      if (line.fields.empty() || line.fields[0].empty())
        fail_at(line.where, "missing node or node set");
      const std::string nodes =
          is_integer(line.fields[0]) ? text(line.fields[0]) : _scope.prefix + name_of(line.fields[0]);
      c.weighted.push_back({nodes, real(line, 1, "weight"), line.at(0)});
    }
    if (c.weighted.empty())
      throw Error(where() + " needs lines of a node or node set and its weight");
    _data.couplings.push_back(std::move(c));
  }

  /// *ELEMENT, TYPE=DCOUP3D: one node per element, the reference node of a *DISTRIBUTING
  /// COUPLING naming the element set; no cell.
  void coupling_element_block()
  {
    const std::string set = _scope.prefix + required("ELSET");
    DeckDataLine line;
    int count = 0;
    while (next_data(line))
    {
      if (line.fields.size() != 2 || ++count > 1)
        fail_at(line.where, "a DCOUP3D element set holds one element of one node: 'element, node'");
      (void)model_label(line, "element", _scope.element_offset);
      // CalculiX takes the node's *NODE after the element too: the label is resolved by the
      // *DISTRIBUTING COUPLING.
      _data.coupling_elements[set] = integer(line, 1, "node number") + _scope.node_offset;
    }
    if (count == 0)
      throw Error(where() + ": a DCOUP3D element set needs its element line 'element, node'");
  }

  void cyclic_symmetry_model()
  {
    known_parameters({"N", "TIE", "NGRAPH", "NPHYS", "ELSET", "CHECK", "CONTACT", "MATRIX"});
    for (const char* p : {"CONTACT", "MATRIX"})
      if (_keyword.has(p))
        throw Error(where() + ": " + p + " is not implemented by feticon");
    if (_in_step)
      throw Error(where() + " belongs to the model data, before the first *STEP");
    const double sectors = real_parameter("N", 0);
    if (!(sectors >= 2) || !std::isfinite(sectors))
      throw Error(where() + " needs N=, the number of sectors (at least 2)");
    DeckTie* tie = nullptr;
    for (DeckTie& t : _data.ties)
      if (t.cyclic && (!_keyword.has("TIE") ? true : t.name == required("TIE")))
      {
        if (tie && !_keyword.has("TIE"))
          throw Error(where() + " needs TIE=: more than one cyclic symmetry *TIE is defined");
        tie = &t;
      }
    if (!tie)
      throw Error(where() + ": no cyclic symmetry *TIE" + (_keyword.has("TIE") ? " '" + required("TIE") + "'" : "") +
                  " is defined before it");
    DeckDataLine line;
    if (!next_data(line))
      throw Error(where() + " needs a data line: points a and b of the axis");
    fem::Tie::CyclicSymmetry symmetry;
    for (int k = 0; k < 3; ++k)
    {
      symmetry.axis_a[k] = real(line, k, "a coordinate of point a");
      symmetry.axis_b[k] = real(line, k + 3, "a coordinate of point b");
    }
    if (!((symmetry.axis_b - symmetry.axis_a).norm() > 0))
      fail_at(line.where, "the axis needs two different points a and b");
    symmetry.sectors = sectors;
    tie->symmetry = symmetry;
    if (const std::string* n = _keyword.value("NGRAPH"); n && *n != "1")
      _data.warn(where() + ": NGRAPH=" + *n + " is not used; feticon writes the datum sector");
    if (next_data(line))
      fail_at(line.where, "takes one data line (points a and b of the axis)");
  }

  // ---- steps ----------------------------------------------------------------------------
  void step()
  {
    known_parameters(
        {"NAME", "NLGEOM", "INC", "INCF", "AMPLITUDE", "PERTURBATION", "THERMAL NETWORK", "SHOCK SMOOTHING"});
    if (_in_step)
      throw Error(where() + ": the *STEP at " + _step_where.str() + " has no *END STEP before this one");
    if (_in_assembly)
      throw Error(where() + ": the *ASSEMBLY at " + _assembly_where.str() + " has no *END ASSEMBLY before it");
    for (const char* p : {"PERTURBATION", "THERMAL NETWORK"})
      if (_keyword.has(p))
        throw Error(where() + ": " + p + " is not implemented by feticon");
    _in_step = true;
    _step_where = _keyword.where;
    _cload_defined.clear();
    _moment_defined.clear();
    _dload_defined.clear();
    _step = DeckStep{};
    _step.where = _keyword.where.str();
    if (const std::string* a = _keyword.value("AMPLITUDE"))
    {
      if (*a != "RAMP" && *a != "STEP")
        throw Error(where() + ": AMPLITUDE=" + *a + " must be RAMP or STEP");
      _step.ramp = *a == "RAMP";
    }
    if (const std::string* inc = _keyword.value("INC"))
    {
      const std::optional<double> n = parse_deck_real(*inc);
      if (!n || *n < 1 || *n > 1e9 || *n != std::floor(*n))
        throw Error(where() + ": INC=" + *inc + " must be a whole number of increments >= 1");
      _step_max_increments = static_cast<int>(*n);
    }
    else
      _step_max_increments = 100; // CalculiX's default
    const std::string* nlgeom = _keyword.value("NLGEOM");
    // NLGEOM stays on once a step has set it (CalculiX: "it remains active in all steps").
    _step.nlgeom =
        (!_data.steps.empty() && _data.steps.back().nlgeom) || (nlgeom && (nlgeom->empty() || *nlgeom == "YES"));
    _have_procedure = false;
    no_data();
  }

  /// *STATIC's automatic increments: the initial one, the minimum (default: the initial or
  /// 1e-5 of the step time, whichever is smaller) and the maximum (default: the step time), as
  /// CalculiX defines them.
  fem::IncrementControl automatic_increments(const DeckDataLine& line, double initial, double total) const
  {
    fem::IncrementControl c{initial, std::min(initial, 1e-5 * total), total, _step_max_increments};
    if (line.fields.size() > 2 && !line.fields[2].empty())
      c.minimum = real(line, 2, "minimum increment");
    if (line.fields.size() > 3 && !line.fields[3].empty())
      c.maximum = std::min(real(line, 3, "maximum increment"), total);
    c.initial = std::min(initial, total);
    if (!(c.minimum > 0) || c.minimum > c.initial || c.initial > c.maximum)
    {
      std::ostringstream what;
      what << "the increments need 0 < minimum <= initial <= maximum, given " << c.minimum << ", " << c.initial << ", "
           << c.maximum;
      fail_at(line.where, what.str());
    }
    return c;
  }

  void static_procedure()
  {
    known_parameters({"DIRECT", "SOLVER", "TIME RESET", "TOTAL TIME"});
    if (!_in_step)
      throw Error(where() + " belongs inside a *STEP");
    if (const std::string* solver = _keyword.value("SOLVER"))
      _data.warn(where() + ": SOLVER=" + *solver + " is not used; feticon solves by FETI");
    _have_procedure = true;
    DeckDataLine line;
    if (!next_data(line))
      return; // one increment
    const double initial = line.fields.size() > 0 && !line.fields[0].empty() ? real(line, 0, "initial increment") : 1.0;
    const double total = line.fields.size() > 1 && !line.fields[1].empty() ? real(line, 1, "step time") : 1.0;
    if (!(initial > 0) || !(total > 0))
      fail_at(line.where, "the initial increment and the step time must be positive");
    _step.time = total;
    if (_keyword.has("DIRECT"))
    {
      const double increments = std::ceil(total / initial - 1e-9);
      if (increments > 100000)
        fail_at(line.where,
                "the step asks for " + std::to_string(static_cast<int64_t>(increments)) +
                    " fixed increments (DIRECT); feticon takes at most 100000 load steps per step");
      _step.increments = std::max(1, static_cast<int>(increments));
    }
    else
      _step.automatic = automatic_increments(line, initial, total);
    if (next_data(line))
      fail_at(line.where, "*STATIC takes one data line");
  }

  void end_step()
  {
    if (!_in_step)
      throw Error(where() + " without a *STEP");
    if (!_have_procedure)
      throw Error(_step_where.str() + ": *STEP has no *STATIC procedure (the only one feticon implements)");
    _in_step = false;
    _data.steps.push_back(_step);
    DeckLoadState state = _data.state;
    for (const auto& [dof, value] : _data.model_boundary)
      state.boundary.emplace(dof, value); // a step's own value of a model support wins
    for (const auto& [dof, value] : _data.model_boundary_rotation)
      state.boundary_rotation.emplace(dof, value);
    _data.step_states.push_back(std::move(state));
    no_data();
  }

  void output_request()
  {
    known_parameters({"NSET", "ELSET", "TOTALS", "FREQUENCY", "FREQUENCYF", "GLOBAL", "OUTPUT", "SLAVE", "MASTER",
                      "TIME POINTS", "LAST ITERATIONS", "CONTACT ELEMENTS", "SECTION FORCES", "OUTPUT ALL", "NSETF",
                      "POSITION", "SET"});
    if (!_in_step)
      throw Error(where() + " belongs inside a *STEP");
    if (_keyword.has("SET")) // thread.inp's *CONTACT PRINT
      _data.warn(where() + ": SET= is no parameter of *" + _keyword.name +
                 "; CalculiX ignores it with a warning, and so does feticon");
    using Kind = DeckOutputRequest::Kind;
    static const std::map<std::string, Kind> kinds = {
        {"NODE PRINT", Kind::node_print}, {"EL PRINT", Kind::el_print}, {"CONTACT PRINT", Kind::contact_print},
        {"NODE FILE", Kind::node_file},   {"EL FILE", Kind::el_file},   {"CONTACT FILE", Kind::contact_file}};
    DeckOutputRequest request;
    request.kind = kinds.at(_keyword.name);
    request.where = _keyword.where.str();
    if (const std::string* s = _keyword.value("NSET"))
      request.set = *s;
    if (const std::string* s = _keyword.value("ELSET"))
      request.set = *s;
    if (!request.set.empty())
    {
      const bool node_set = _keyword.has("NSET");
      const auto& sets = node_set ? _data.node_sets : _data.element_sets;
      if (!sets.count(request.set))
        throw Error(where() + ": no " + (node_set ? "node" : "element") + " set '" + request.set + "' is defined");
    }
    if (const std::string* t = _keyword.value("TOTALS"))
    {
      if (*t != "YES" && *t != "ONLY" && *t != "NO")
        throw Error(where() + ": TOTALS=" + *t + " must be YES, ONLY or NO");
      request.totals = *t == "YES" ? DeckOutputRequest::Totals::yes
          : *t == "ONLY"           ? DeckOutputRequest::Totals::only
                                   : DeckOutputRequest::Totals::no;
    }
    if (const std::string* g = _keyword.value("GLOBAL"))
    {
      if (*g != "YES" && *g != "NO")
        throw Error(where() + ": GLOBAL=" + *g + " must be YES or NO");
      request.global = *g == "YES";
      if (!*request.global && request.kind == Kind::node_file)
        _data.warn(where() + ": GLOBAL=NO is not honoured; feticon writes the .frd in global components");
    }
    for (const char* p : {"FREQUENCY", "FREQUENCYF", "TIME POINTS", "LAST ITERATIONS", "CONTACT ELEMENTS"})
      if (_keyword.has(p))
        _data.warn(where() + ": " + p + " is not honoured; feticon writes every converged increment");
    DeckDataLine line;
    while (next_data(line))
      for (const std::string_view v : line.fields)
        if (!v.empty())
          request.variables.push_back(name_of(v));
    if (request.variables.empty())
      request.variables = request.kind == Kind::node_print || request.kind == Kind::node_file
          ? std::vector<std::string>{"U"}
          : request.kind == Kind::el_print || request.kind == Kind::el_file ? std::vector<std::string>{"S"}
                                                                            : std::vector<std::string>{"CSTR"};
    _step.outputs.push_back(std::move(request));
  }

  DeckTokenizer _tokens;
  /// Parts and assemblies (deck_parts.hpp): the parts by name, the part whose keywords are being
  /// kept, the instances placed so far, the one whose *END INSTANCE is due.
  std::map<std::string, DeckPart> _parts;
  DeckPart* _recording = nullptr;
  std::map<std::string, DeckInstance> _instances;
  std::string _open_instance;
  bool _in_assembly = false;
  DeckPosition _assembly_where;
  /// The names and labels of the lines being read, and the kept lines an instance reads.
  DeckScope _scope;
  const std::vector<RecordedLine>* _replay = nullptr;
  size_t _replayed = 0;
  int64_t _largest_node_label = 0, _largest_element_label = 0;
  /// The DOFs and faces this step gave a load so far (add_load: more values add up).
  std::set<int64_t> _cload_defined, _moment_defined;
  std::set<std::pair<int32_t, int>> _dload_defined;
  std::string _path;
  DeckKeyword _keyword;
  DeckData _data;
  std::string _material, _interaction;
  /// True from a *SURFACE INTERACTION until a keyword other than its *SURFACE BEHAVIOR and
  /// *FRICTION (CalculiX: the interaction's block ends there, as a material's does).
  bool _in_interaction = false;
  /// The interaction of a *CHANGE FRICTION whose *FRICTION comes next, and where it was.
  std::string _changing_friction, _changing_friction_where;
  std::optional<DeckCoupling> _pending_coupling; ///< a *COUPLING waiting for *KINEMATIC or *DISTRIBUTING
  /// The interaction of a *CHANGE SURFACE BEHAVIOR whose *SURFACE BEHAVIOR comes next, and where.
  std::string _changing_behavior, _changing_behavior_where;
  int _step_max_increments = 100; ///< the current *STEP's INC= (automatic increments)
  bool _in_step = false, _have_procedure = false;
  DeckPosition _step_where;
  DeckStep _step;
};
} // namespace

std::optional<double> parse_deck_real(std::string_view v)
{
  if (!v.empty() && v.front() == '+')
    v.remove_prefix(1);
  if (v.empty())
    return std::nullopt;
  double out = 0;
  auto [end, ec] = std::from_chars(v.data(), v.data() + v.size(), out);
  if (ec == std::errc() && end != v.data() + v.size() && (*end == 'd' || *end == 'D'))
  {
    // Fortran's double-precision exponent: 1.5D3.
    std::string copy(v);
    copy[end - v.data()] = 'e';
    auto r = std::from_chars(copy.data(), copy.data() + copy.size(), out);
    ec = r.ec;
    end = r.ptr == copy.data() + copy.size() ? v.data() + v.size() : v.data();
  }
  if (ec != std::errc() || end != v.data() + v.size() || !std::isfinite(out))
    return std::nullopt;
  return out;
}

bool LabelIndex::insert(int64_t label, int32_t index)
{
  if (_identity >= 0 && label == _identity + 1 && index == _identity)
  {
    ++_identity;
    ++_count;
    return true;
  }
  if (find(label) >= 0)
    return false;
  if (_identity >= 0) // the first label off the rule: the labels so far go to the dense table
  {
    // Sized once for the outline's count where it fits, so that the usual numbering 1..n is
    // not regrown (a regrowth holds the old and the new table at once).
    if (_reserve > 0 && _reserve < largest_label)
      _dense.reserve(static_cast<size_t>(_reserve) + 1);
    _dense.resize(static_cast<size_t>(_identity) + 1, 0);
    for (int64_t l = 1; l <= _identity; ++l)
      _dense[l] = static_cast<int32_t>(l);
    _identity = -1;
  }
  ++_count;
  if (label >= 0 && label < 2 * _count + dense_label_slack)
  {
    if (static_cast<size_t>(label) >= _dense.size())
    {
      size_t size = std::max<size_t>(static_cast<size_t>(label) + 1, _dense.size() * 3 / 2);
      if (static_cast<size_t>(label) < _dense.capacity()) // within the reserved table: stay there
        size = std::min(size, _dense.capacity());
      _dense.resize(size, 0);
    }
    _dense[label] = index + 1;
    return true;
  }
  _sparse.emplace(label, index); // a label far beyond the count: a dense table would be mostly empty
  return true;
}

void LabelIndex::reserve(int64_t labels) { _reserve = labels; }

int32_t LabelIndex::find(int64_t label) const
{
  if (_identity >= 0)
    return label >= 1 && label <= _identity ? static_cast<int32_t>(label - 1) : -1;
  if (label >= 0 && static_cast<size_t>(label) < _dense.size() && _dense[label] != 0)
    return _dense[label] - 1;
  if (_sparse.empty())
    return -1;
  const auto it = _sparse.find(label);
  return it == _sparse.end() ? -1 : it->second;
}

DeckData read_deck_data(const std::filesystem::path& path, const DeckOutline& outline)
{
  return KeywordReader(path, outline).run();
}
} // namespace feticon::io
