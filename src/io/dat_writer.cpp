#include "io/dat_writer.hpp"

#include "common/error.hpp"
#include "io/fixed_width.hpp"

#include <algorithm>
#include <array>
#include <numeric>

namespace feticon::io
{
namespace
{
using Kind = DeckOutputRequest::Kind;
using Totals = DeckOutputRequest::Totals;

/// The I10 field of node and element labels.

/// CalculiX prints tensors as xx yy zz xy xz yz; feticon's arrays hold xx yy zz xy yz zx.
constexpr std::array<int, 6> feticon_component_of_calculix = {0, 1, 2, 3, 5, 4};

void check_members(const std::vector<int32_t>& ids, int32_t n, const std::string& what,
                   const std::filesystem::path& path)
{
  for (const int32_t id : ids)
    FETICON_CHECK(id >= 0 && id < n,
                  "dat '" << path.string() << "': " << what << " holds index " << id << " outside [0, " << n << ")");
}

template <class T>
void check_size(std::span<const T> values, std::size_t expected, const char* name, const std::filesystem::path& path)
{
  FETICON_CHECK(values.empty() || values.size() == expected,
                "dat '" << path.string() << "': " << name << " has " << values.size() << " values, expected "
                        << expected);
}

/// Blank line, " <what> for set <set> and time <E14.7>", blank line (printout.f formats 100-107).
void append_set_header(std::string& out, const char* what, const std::string& set, double time,
                       const char* for_set = " for set ")
{
  out += "\n ";
  out += what;
  out += for_set;
  out += set;
  out += " and time ";
  append_fortran_e(out, time, 14, 7);
  out += "\n\n";
}

/// Rows I10, n x (1X, 1PE13.6).
void append_row(std::string& out, int64_t label, const double* values, int n)
{
  append_integer(out, label, 10);
  for (int k = 0; k < n; ++k)
  {
    out += ' ';
    append_fortran_1pe(out, values[k], 13, 6);
  }
  out += '\n';
}

void add_to_list(std::string& list, const std::string& item)
{
  if (!list.empty())
    list += ", ";
  list += item;
}

const char* keyword_of(Kind kind)
{
  return kind == Kind::node_print ? "*NODE PRINT" : kind == Kind::el_print ? "*EL PRINT" : "*CONTACT PRINT";
}
} // namespace

DatWriter::DatWriter(const std::filesystem::path& path, DatModel model) : _path(path), _model(std::move(model))
{
  FETICON_CHECK(_model.n_nodes >= 0 && _model.n_cells >= 0,
                "dat '" << path.string() << "': negative mesh size " << _model.n_nodes << " nodes, " << _model.n_cells
                        << " cells");
  check_labels(_model.node_labels, _model.n_nodes, "node", "dat", path);
  check_labels(_model.element_labels, _model.n_cells, "element", "dat", path);
  for (const auto& [name, ids] : _model.node_sets)
    check_members(ids, _model.n_nodes, "node set " + name, path);
  for (const auto& [name, ids] : _model.element_sets)
    check_members(ids, _model.n_cells, "element set " + name, path);
  check_members(_model.contact_slave_nodes, _model.n_nodes, "contact_slave_nodes", path);

  _sorted_slaves = _model.contact_slave_nodes;
  std::sort(_sorted_slaves.begin(), _sorted_slaves.end(),
            [&](int32_t a, int32_t b) { return label_of(_model.node_labels, a) < label_of(_model.node_labels, b); });
  _sorted_slaves.erase(std::unique(_sorted_slaves.begin(), _sorted_slaves.end()), _sorted_slaves.end());

  _file = create_file(path);
}

void DatWriter::close() { close_file(_file, _path); }

const std::vector<int32_t>& DatWriter::sorted_set(bool nodes, const std::string& name, const std::string& where)
{
  const auto key = std::make_pair(nodes, name);
  if (const auto found = _sorted_sets.find(key); found != _sorted_sets.end())
    return found->second;
  const std::map<std::string, std::vector<int32_t>>& sets = nodes ? _model.node_sets : _model.element_sets;
  std::vector<int32_t> members;
  if (name.empty())
  {
    members.resize(static_cast<std::size_t>(nodes ? _model.n_nodes : _model.n_cells));
    std::iota(members.begin(), members.end(), 0);
  }
  else
  {
    const auto found = sets.find(name);
    if (found == sets.end())
    {
      std::string known;
      for (const auto& entry : sets)
        add_to_list(known, entry.first);
      FETICON_CHECK(false,
                    where << ": " << (nodes ? "node" : "element") << " set " << name
                          << " is not defined (defined: " << (known.empty() ? "none" : known) << ")");
    }
    members = found->second;
  }
  const Labels& labels = nodes ? _model.node_labels : _model.element_labels;
  std::sort(members.begin(), members.end(),
            [&](int32_t a, int32_t b) { return label_of(labels, a) < label_of(labels, b); });
  members.erase(std::unique(members.begin(), members.end()), members.end());
  return _sorted_sets.emplace(key, std::move(members)).first->second;
}

void DatWriter::append_vector_row(std::string& out, int32_t node, const double* values, bool global) const
{
  const int32_t frame = global ? -1 : _model.frames.index_of(node);
  if (frame < 0)
  {
    append_row(out, label_of(_model.node_labels, node), values, 3);
    return;
  }
  const Eigen::Vector3d local = _model.frames.axes[static_cast<size_t>(frame)] * Eigen::Vector3d(values);
  append_row(out, label_of(_model.node_labels, node), local.data(), 3);
  out.insert(out.size() - 1, " L"); // printoutnode.f: (i10, 3(1x, e13.6), 1x, a1)
}

void DatWriter::print_nodal(TextFileBuffer& file, const DatStep& step, const DeckOutputRequest& request,
                            std::string& unavailable)
{
  std::string& out = file.buffer;
  const std::vector<int32_t>& nodes = sorted_set(true, request.set, request.where);
  const std::string set = request.set.empty() ? "NALL" : request.set;
  for (const std::string& variable : request.variables)
  {
    const bool global = request.global.value_or(false);
    if (variable == "U" && !step.displacement.empty())
    {
      append_set_header(out, "displacements (vx,vy,vz)", set, step.time);
      for (const int32_t node : nodes)
      {
        append_vector_row(out, node, &step.displacement[3 * std::size_t(node)], global);
        file.flush_if_full();
      }
    }
    else if (variable == "RF" && !step.reaction_force.empty())
    {
      if (request.totals != Totals::only)
      {
        append_set_header(out, "forces (fx,fy,fz)", set, step.time);
        for (const int32_t node : nodes)
        {
          append_vector_row(out, node, &step.reaction_force[3 * std::size_t(node)], global);
          file.flush_if_full();
        }
      }
      if (request.totals != Totals::no)
      {
        // printoutnode.f sums in set order, printout.f prints 6X, 3 x (1X, 1PE13.6).
        std::array<double, 3> total = {0.0, 0.0, 0.0};
        for (const int32_t node : nodes)
          for (int k = 0; k < 3; ++k)
            total[k] += step.reaction_force[3 * std::size_t(node) + k];
        append_set_header(out, "total force (fx,fy,fz)", set, step.time);
        out += "      ";
        for (const double value : total)
        {
          out += ' ';
          append_fortran_1pe(out, value, 13, 6);
        }
        out += '\n';
      }
    }
    else
      add_to_list(unavailable, variable);
  }
}

void DatWriter::print_integration_points(TextFileBuffer& file, const DatStep& step, const DeckOutputRequest& request,
                                         std::string& unavailable)
{
  std::string& out = file.buffer;
  const std::vector<int32_t>& cells = sorted_set(false, request.set, request.where);
  const std::string set = request.set.empty() ? "EALL" : request.set;
  for (const std::string& variable : request.variables)
  {
    std::span<const double> values;
    const char* header = nullptr;
    int components = 6;
    if (variable == "S")
    {
      values = step.stress;
      header = "stresses (elem, integ.pnt.,sxx,syy,szz,sxy,sxz,syz)";
    }
    else if (variable == "E")
    {
      values = step.strain;
      header = "strains (elem, integ.pnt.,exx,eyy,ezz,exy,exz,eyz)";
    }
    else if (variable == "PEEQ")
    {
      values = step.plastic_strain;
      // ccx's format 108 has no space before "for set" (append_set_header's for_set).
      header = "equivalent plastic strain (elem, integ.pnt.,pe)";
      components = 1;
    }
    if (values.empty())
    {
      add_to_list(unavailable, variable);
      continue;
    }
    append_set_header(out, header, set, step.time, components == 1 ? "for set " : " for set ");
    for (const int32_t cell : cells)
    {
      const int64_t label = label_of(_model.element_labels, cell);
      const auto first = static_cast<std::size_t>(step.point_offsets[static_cast<std::size_t>(cell)]);
      const auto count = static_cast<std::size_t>(step.point_offsets[static_cast<std::size_t>(cell) + 1]) - first;
      for (std::size_t j = 0; j < count; ++j)
      {
        // printoutint.f: I10, 1X, I3, 6 x (1X, 1PE13.6).
        const double* point = &values[(first + j) * components];
        append_integer(out, label, 10);
        out += ' ';
        append_integer(out, static_cast<int64_t>(j) + 1, 3);
        for (int k = 0; k < components; ++k)
        {
          out += ' ';
          append_fortran_1pe(out, components == 1 ? point[0] : point[feticon_component_of_calculix[k]], 13, 6);
        }
        out += '\n';
      }
      file.flush_if_full();
    }
  }
}

void DatWriter::print_contact(TextFileBuffer& file, const DatStep& step, const DeckOutputRequest& request,
                              std::string& unavailable)
{
  std::string& out = file.buffer;
  for (const std::string& variable : request.variables)
  {
    // ccx reads the first four characters of a label (CSTRESS = CSTR).
    const std::string head = variable.substr(0, 4);
    std::span<const double> values;
    const char* header = nullptr;
    if (head == "CSTR")
    {
      values = step.contact_pressure;
      header = " contact stress (slave node,press,tang1,tang2) for all contact elements and time";
    }
    else if (head == "CDIS")
    {
      values = step.contact_gap;
      header = " relative contact displacement (slave node,normal,tang1,tang2) for all contact "
               "elements and time";
    }
    if (values.empty())
    {
      add_to_list(unavailable, variable);
      continue;
    }
    // printout.f formats 122 and 123: the time follows "time" directly as E14.7.
    out += '\n';
    out += header;
    append_fortran_e(out, step.time, 14, 7);
    out += "\n\n";
    for (const int32_t node : _sorted_slaves)
    {
      const std::array<double, 3> row = {values[node], 0.0, 0.0};
      append_row(out, label_of(_model.node_labels, node), row.data(), 3);
      file.flush_if_full();
    }
  }
}

std::vector<std::string> DatWriter::add_step(const DatStep& step, const std::vector<DeckOutputRequest>& requests)
{
  FETICON_CHECK(_file != nullptr, "dat '" << _path.string() << "': add_step after close");
  const std::size_t n_nodes = static_cast<std::size_t>(_model.n_nodes);
  const std::size_t n_cells = static_cast<std::size_t>(_model.n_cells);
  check_size(step.displacement, 3 * n_nodes, "displacement", _path);
  check_size(step.reaction_force, 3 * n_nodes, "reaction_force", _path);
  check_size(step.point_offsets, n_cells + 1, "point_offsets (cells + 1)", _path);
  const std::size_t n_points = step.point_offsets.empty() ? 0 : static_cast<std::size_t>(step.point_offsets.back());
  FETICON_CHECK(
      step.point_offsets.empty() ||
          (step.point_offsets.front() == 0 && std::is_sorted(step.point_offsets.begin(), step.point_offsets.end())),
      "dat '" << _path.string() << "': point_offsets do not start at 0 and increase");
  check_size(step.stress, 6 * n_points, "stress (points x 6)", _path);
  check_size(step.strain, 6 * n_points, "strain (points x 6)", _path);
  check_size(step.plastic_strain, n_points, "plastic_strain (points)", _path);
  check_size(step.contact_pressure, n_nodes, "contact_pressure", _path);
  check_size(step.contact_gap, n_nodes, "contact_gap", _path);

  std::vector<std::string> warnings;
  auto warn = [&](const std::string& line) {
    if (_warned.insert(line).second)
      warnings.push_back(line);
  };
  TextFileBuffer out(_file.get(), _path.string());
  for (const DeckOutputRequest& request : requests)
  {
    std::string unavailable;
    if (request.kind == Kind::node_print)
      print_nodal(out, step, request, unavailable);
    else if (request.kind == Kind::el_print)
      print_integration_points(out, step, request, unavailable);
    else if (request.kind == Kind::contact_print)
    {
      print_contact(out, step, request, unavailable);
      for (const std::string& variable : request.variables)
        if (variable.substr(0, 4) == "CDIS" && !step.contact_gap.empty())
          warn(request.where + ": *CONTACT PRINT: " + variable +
               ": tang1, tang2 (tangential relative displacements) are not computed by feticon, "
               "printed as 0");
    }
    else
      continue;
    if (!unavailable.empty())
      warn(request.where + ": " + keyword_of(request.kind) + ": " + unavailable +
           " not available in feticon, not printed to the .dat file");
    out.flush_if_full();
  }
  out.write();
  FETICON_CHECK(std::fflush(_file.get()) == 0, "cannot write '" << _path.string() << "': is the disk full?");
  return warnings;
}
} // namespace feticon::io
