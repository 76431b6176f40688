#include "io/frd_writer.hpp"

#include "common/error.hpp"
#include "io/fixed_width.hpp"

#include <array>
#include <cmath>
#include <ctime>
#include <limits>

namespace feticon::io
{
namespace
{
/// The I10 field of node and element labels.
/// frd element types (CalculiX's frd format: 1 he8, 2 pe6, 3 te4, 4 he20, 6 te10, 7 tr3, 8 tr6,
/// 9 qu4, 10 qu8), indexed by mesh::CellKind (hex8, tet4, tet10, hex20, wedge6, tri3, quad4,
/// tri6, quad8). 2D cells are written as themselves, as CalculiX's default OUTPUT=2D does.
constexpr std::array<int, 9> frd_type = {1, 3, 6, 4, 2, 7, 9, 8, 10};

/// The frd's node k of a cell is its local node frd_local(kind)[k]: CalculiX's order, except
/// that the frd lists a he20's vertical edges (CalculiX's nodes 17-20) before its top edges
/// (13-16), as CalculiX's own frd writer does.
int frd_local(mesh::CellKind kind, int k)
{
  if (kind != mesh::CellKind::hex20 || k < 12)
    return k;
  return k < 16 ? k + 4 : k - 4;
}

/// A "    1U" record: keyword from column 6, value from column 24, 72 characters.
void append_user_record(std::string& out, const std::string& keyword, const std::string& value)
{
  std::string line = "    1U" + keyword;
  line.resize(24, ' ');
  line += value;
  if (line.size() < 72)
    line.resize(72, ' ');
  out += line;
  out += '\n';
}

/// Date and time as ccx writes them: "25.november.2026", "21:40:18".
std::pair<std::string, std::string> date_and_clock()
{
  static const std::array<const char*, 12> months = {"january",   "february", "march",    "april",
                                                     "may",       "june",     "july",     "august",
                                                     "september", "october",  "november", "december"};
  const std::time_t now = std::time(nullptr);
  std::tm local{};
  localtime_r(&now, &local);
  char date[40];
  std::snprintf(date, sizeof date, "%02d.%s.%04d", local.tm_mday, months[local.tm_mon], local.tm_year + 1900);
  char clock[16];
  std::snprintf(clock, sizeof clock, "%02d:%02d:%02d", local.tm_hour, local.tm_min, local.tm_sec);
  return {date, clock};
}

/// The time field of the 100CL record (frdheader.c): fixed point with ten significant digits
/// for 1 <= t < 1e10, else %12.5E.
std::string time_field(double time)
{
  char text[64];
  if (time <= 0.0 || !std::isfinite(time) || std::log10(time) >= 10.0 || std::log10(time) < 0.0)
    std::snprintf(text, sizeof text, "%12.5E", time);
  else
  {
    const int decimals = 10 - static_cast<int>(std::floor(std::log10(time) + 1.0));
    std::snprintf(text, sizeof text, "%12.*f", decimals, time);
  }
  return text;
}

void check_field(std::span<const double> values, int32_t n_nodes, int components, const char* name,
                 const std::filesystem::path& path)
{
  if (values.empty())
    return;
  const std::size_t expected = static_cast<std::size_t>(n_nodes) * components;
  FETICON_CHECK(values.size() == expected,
                "frd '" << path.string() << "': " << name << " has " << values.size() << " values, expected " << n_nodes
                        << " nodes x " << components << " = " << expected);
}

/// The .frd holds single-precision numbers, as CalculiX writes them: a value beyond float's
/// range would be written as INF (a model far from SI magnitudes, e.g. lengths of 1e-30 m).
void check_single_precision(std::span<const double> values, int components, const char* name, const Labels& node_labels,
                            const std::filesystem::path& path)
{
  for (std::size_t j = 0; j < values.size(); ++j)
    FETICON_CHECK(std::isfinite(values[j]) && std::abs(values[j]) <= std::numeric_limits<float>::max(),
                  "frd '" << path.string() << "': " << name << " of node "
                          << label_of(node_labels, static_cast<int64_t>(j / components)) << " is " << values[j]
                          << ", beyond the single precision of the .frd (3.4e38): check the model's units");
}

/// value(i, k) of a field stored node after node, `components` values each.
auto row_major(std::span<const double> values, int components)
{
  return [values, components](int32_t i, int k) { return values[static_cast<std::size_t>(i) * components + k]; };
}

/// Whether `name` (a deck variable) is one of `known`.
bool is_one_of(const std::string& name, std::initializer_list<const char*> known)
{
  for (const char* k : known)
    if (name == k)
      return true;
  return false;
}
} // namespace

FrdFields frd_fields(const std::vector<DeckOutputRequest>& outputs, std::vector<std::string>& warnings)
{
  using Kind = DeckOutputRequest::Kind;
  FrdFields fields;
  for (const DeckOutputRequest& request : outputs)
  {
    if (request.kind != Kind::node_file && request.kind != Kind::el_file && request.kind != Kind::contact_file)
      continue;
    const char* keyword = request.kind == Kind::node_file ? "*NODE FILE"
        : request.kind == Kind::el_file                   ? "*EL FILE"
                                                          : "*CONTACT FILE";
    std::string unsupported;
    for (const std::string& variable : request.variables)
    {
      const std::string head = variable.substr(0, 4);
      if (request.kind == Kind::node_file && variable == "U")
        fields.displacement = true;
      else if (request.kind == Kind::node_file && variable == "RF")
        fields.reaction_force = true;
      else if (request.kind == Kind::el_file && variable == "S")
        fields.stress = true;
      else if (request.kind == Kind::el_file && variable == "E")
        fields.strain = true;
      else if (request.kind == Kind::el_file && variable == "PE")
        fields.plastic_strain = true;
      else if (request.kind == Kind::contact_file && is_one_of(head, {"CDIS", "CSTR"}))
        fields.contact = true;
      else
        unsupported += (unsupported.empty() ? "" : ", ") + variable;
    }
    if (!unsupported.empty())
      warnings.push_back(request.where + ": " + keyword + ": " + unsupported +
                         " not available in feticon, not written to the .frd file");
    if (!request.set.empty())
      warnings.push_back(request.where + ": " + keyword + ": set " + request.set +
                         " ignored, the .frd file holds all nodes");
  }
  return fields;
}

FrdWriter::FrdWriter(const std::filesystem::path& path, const mesh::Mesh& mesh, const Labels& node_labels,
                     const Labels& element_labels)
    : _path(path), _node_labels(node_labels), _n_nodes(mesh.n_nodes())
{
  check_labels(node_labels, mesh.n_nodes(), "node", "frd", path);
  check_labels(element_labels, mesh.n_cells(), "element", "frd", path);
  FETICON_CHECK(mesh.cell_body.empty() || mesh.cell_body.size() == mesh.cells.size(),
                "frd '" << path.string() << "': mesh has " << mesh.cells.size() << " cells but "
                        << mesh.cell_body.size() << " body indices");
  for (const std::span<const int32_t> cell : mesh.cells)
    for (const int32_t id : cell)
      FETICON_CHECK(id >= 0 && id < mesh.n_nodes(),
                    "frd '" << path.string() << "': cell node id " << id << " outside [0, " << mesh.n_nodes() << ")");
  check_single_precision({mesh.nodes.data(), static_cast<std::size_t>(mesh.nodes.size())}, 3, "coordinate", node_labels,
                         path);
  _file = create_file(path);

  TextFileBuffer out(_file.get(), path.string());
  std::string& text = out.buffer;
  text += "    1C\n";
  const auto [date, clock] = date_and_clock();
  append_user_record(text, "USER", "");
  append_user_record(text, "DATE", date);
  append_user_record(text, "TIME", clock);
  append_user_record(text, "PGM", "feticon");
  for (std::size_t b = 0; b < mesh.body_names.size(); ++b)
  {
    // 1UMAT: material number I5, name in 58 characters.
    std::string line = "    1UMAT";
    append_integer(line, static_cast<int64_t>(b + 1), 5);
    line += mesh.body_names[b].substr(0, 58);
    line.resize(72, ' ');
    text += line + '\n';
  }

  char line[128];
  std::snprintf(line, sizeof line, "%5s%1s                  %12d%38d\n", "2", "C", mesh.n_nodes(), 1);
  text += line;
  for (int32_t i = 0; i < mesh.n_nodes(); ++i)
  {
    text += " -1";
    append_integer(text, label_of(node_labels, i), 10);
    for (int k = 0; k < 3; ++k)
      append_c_exponential(text, static_cast<float>(mesh.nodes(i, k)), 12, 5);
    text += '\n';
    out.flush_if_full();
  }
  text += " -3\n";

  std::snprintf(line, sizeof line, "%5s%1s                  %12d%38d\n", "3", "C", mesh.n_cells(), 1);
  text += line;
  for (int32_t c = 0; c < mesh.n_cells(); ++c)
  {
    const int32_t material = mesh.cell_body.empty() ? 1 : mesh.cell_body[c] + 1;
    text += " -1";
    append_integer(text, label_of(element_labels, c), 10);
    append_integer(text, frd_type[static_cast<size_t>(mesh.cells.kind(c))], 5);
    append_integer(text, 0, 5);
    append_integer(text, material, 5);
    text += "\n -2";
    // At most 10 nodes a line (I10 fields), as CalculiX writes its 20-node elements.
    const std::span<const int32_t> cell = mesh.cells[c];
    for (size_t k = 0; k < cell.size(); ++k)
    {
      if (k > 0 && k % 10 == 0)
        text += "\n -2";
      append_integer(text, label_of(node_labels, cell[frd_local(mesh.cells.kind(c), static_cast<int>(k))]), 10);
    }
    text += '\n';
    out.flush_if_full();
  }
  text += " -3\n";
  out.write();
  _end_of_results = std::ftell(_file.get());
  text = " 9999\n";
  out.write();
  FETICON_CHECK(std::fflush(_file.get()) == 0, "cannot write '" << path.string() << "': is the disk full?");
}

void FrdWriter::close() { close_file(_file, _path); }

void FrdWriter::write_block_header(std::string& out, const FrdStep& step, int32_t increment)
{
  ++_n_blocks;
  char line[160];
  // frdheader.c: 1PSTEP with block counter, increment and step in I12 fields from column 24.
  std::snprintf(line, sizeof line, "    1PSTEP              %12d%12d%12d          \n", _n_blocks, increment, step.step);
  out += line;
  // 100CL: output number + 100 (I5 at column 7), time (12 characters at 12), nodes (I12 at 24),
  // analysis type 0 = static (column 57), output number (I5 at 58), 1 = ASCII (column 74).
  std::string record(75, ' ');
  record.replace(0, 7, "  100CL");
  char field[64];
  std::snprintf(field, sizeof field, "%5d", 100 + _n_steps);
  record.replace(7, 5, field);
  record.replace(12, 12, time_field(step.time));
  std::snprintf(field, sizeof field, "%12d", _n_nodes);
  record.replace(24, 12, field);
  record[57] = '0';
  std::snprintf(field, sizeof field, "%5d", _n_steps);
  record.replace(58, 5, field);
  record[74] = '1';
  out += record;
  out += '\n';
}

void FrdWriter::add_step(const FrdStep& step)
{
  check_step(step);
  if (step.step != _last_step)
  {
    _last_step = step.step;
    _increment = 0;
  }
  ++_increment;
  const int32_t increment = step.increment > 0 ? step.increment : _increment;
  ++_n_steps;

  FETICON_CHECK(std::fseek(_file.get(), _end_of_results, SEEK_SET) == 0, "cannot seek in '" << _path.string() << "'");
  TextFileBuffer out(_file.get(), _path.string());
  std::string& text = out.buffer;
  write_fields(out, step, increment);
  out.write();
  _end_of_results = std::ftell(_file.get());
  text = " 9999\n";
  out.write();
  FETICON_CHECK(std::fflush(_file.get()) == 0, "cannot write '" << _path.string() << "': is the disk full?");
}

void FrdWriter::check_step(const FrdStep& step) const
{
  FETICON_CHECK(_file != nullptr, "frd '" << _path.string() << "': add_step after close");
  check_field(step.displacement, _n_nodes, 3, "displacement", _path);
  check_field(step.stress, _n_nodes, 6, "stress", _path);
  check_field(step.strain, _n_nodes, 6, "strain", _path);
  check_field(step.reaction_force, _n_nodes, 3, "reaction_force", _path);
  check_field(step.plastic_strain, _n_nodes, 1, "plastic_strain", _path);
  check_field(step.contact_pressure, _n_nodes, 1, "contact_pressure", _path);
  check_field(step.contact_gap, _n_nodes, 1, "contact_gap", _path);
  check_single_precision(step.displacement, 3, "displacement", _node_labels, _path);
  check_single_precision(step.stress, 6, "stress", _node_labels, _path);
  check_single_precision(step.strain, 6, "strain", _node_labels, _path);
  check_single_precision(step.reaction_force, 3, "reaction force", _node_labels, _path);
  check_single_precision(step.plastic_strain, 1, "equivalent plastic strain", _node_labels, _path);
  check_single_precision(step.contact_pressure, 1, "contact pressure", _node_labels, _path);
  check_single_precision(step.contact_gap, 1, "contact gap", _node_labels, _path);
  FETICON_CHECK(step.step >= 1, "frd '" << _path.string() << "': step " << step.step << " must be >= 1");
  FETICON_CHECK(step.time >= 0.0 && step.time < 1e99,
                "frd '" << _path.string() << "': time " << step.time << " outside [0, 1e99)");
}

template <class Value>
void FrdWriter::write_block(TextFileBuffer& out, const FrdStep& step, int32_t increment, const char* records,
                            int components, Value value)
{
  std::string& text = out.buffer;
  write_block_header(text, step, increment);
  text += records;
  for (int32_t i = 0; i < _n_nodes; ++i)
  {
    text += " -1";
    append_integer(text, label_of(_node_labels, i), 10);
    for (int k = 0; k < components; ++k)
      append_c_exponential(text, static_cast<float>(value(i, k)), 12, 5);
    text += '\n';
    out.flush_if_full();
  }
  text += " -3\n";
}

void FrdWriter::write_fields(TextFileBuffer& out, const FrdStep& step, int32_t increment)
{
  auto block = [&](const char* records, int components, auto value) {
    write_block(out, step, increment, records, components, value);
  };
  if (!step.displacement.empty())
    block(" -4  DISP        4    1\n"
          " -5  D1          1    2    1    0\n"
          " -5  D2          1    2    2    0\n"
          " -5  D3          1    2    3    0\n"
          " -5  ALL         1    2    0    0    1ALL\n",
          3, row_major(step.displacement, 3));
  if (!step.stress.empty())
    block(" -4  STRESS      6    1\n"
          " -5  SXX         1    4    1    1\n"
          " -5  SYY         1    4    2    2\n"
          " -5  SZZ         1    4    3    3\n"
          " -5  SXY         1    4    1    2\n"
          " -5  SYZ         1    4    2    3\n"
          " -5  SZX         1    4    3    1\n",
          6, row_major(step.stress, 6));
  if (!step.strain.empty())
    block(" -4  TOSTRAIN    6    1\n"
          " -5  EXX         1    4    1    1\n"
          " -5  EYY         1    4    2    2\n"
          " -5  EZZ         1    4    3    3\n"
          " -5  EXY         1    4    1    2\n"
          " -5  EYZ         1    4    2    3\n"
          " -5  EZX         1    4    3    1\n",
          6, row_major(step.strain, 6));
  if (!step.plastic_strain.empty())
    block(" -4  PE          1    1\n"
          " -5  PE          1    1    0    0\n",
          1, row_major(step.plastic_strain, 1));
  if (!step.reaction_force.empty())
    block(" -4  FORC        4    1\n"
          " -5  F1          1    2    1    0\n"
          " -5  F2          1    2    2    0\n"
          " -5  F3          1    2    3    0\n"
          " -5  ALL         1    2    0    0    1ALL\n",
          3, row_major(step.reaction_force, 3));
  if (!step.contact_pressure.empty())
  {
    // COPEN, CSLIP1, CSLIP2, CPRESS, CSHEAR1, CSHEAR2; frictionless: no slip or shear recorded.
    const std::span<const double> pressure = step.contact_pressure;
    const std::span<const double> gap = step.contact_gap;
    block(" -4  CONTACT     6    1\n"
          " -5  COPEN       1    4    1    1\n"
          " -5  CSLIP1      1    4    2    2\n"
          " -5  CSLIP2      1    4    3    3\n"
          " -5  CPRESS      1    4    1    2\n"
          " -5  CSHEAR1     1    4    2    3\n"
          " -5  CSHEAR2     1    4    3    1\n",
          6, [&](int32_t i, int k) {
            if (k == 0)
              return gap.empty() ? 0.0 : gap[i];
            return k == 3 ? pressure[i] : 0.0;
          });
  }
}
} // namespace feticon::io
