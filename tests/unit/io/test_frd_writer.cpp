/// Tests of the .frd writer. References:
///  - the .frd ccx 2.20 wrote for tests/data/calculix_results/two_blocks_frd.inp (README.md
///    there): fed with the values it holds, the writer reproduces its records byte for byte;
///  - values set here, read back by the fixed-column parser below (to the printed digits);
///  - cgx (CalculiX GraphiX), when installed, reading the file.

#include "io/frd_writer.hpp"

#include "common/error.hpp"

#include "io_test_files.hpp"

#include <gtest/gtest.h>

#include <array>
#include <cmath>
#include <cstdio>
#include <cstdlib>
#include <filesystem>
#include <fstream>
#include <map>
#include <string>
#include <vector>

namespace feticon::io
{
namespace
{
namespace fs = std::filesystem;

using test::fresh_directory;

const fs::path frd_reference_dir = fs::path(FETICON_SOURCE_DIR) / "tests" / "data" / "calculix_results";

std::vector<std::string> read_lines(const fs::path& path)
{
  std::ifstream in(path);
  if (!in)
    throw std::runtime_error("cannot read " + path.string());
  std::vector<std::string> lines;
  std::string line;
  while (std::getline(in, line))
    lines.push_back(line);
  return lines;
}

/// One result block: 1PSTEP and 100CL records, name, and per node label and values.
struct Block
{
  int block_counter = 0, increment = 0, step = 0, kode = 0, n_nodes = 0;
  std::string time_field;
  std::string name;
  int n_components = 0;
  std::vector<int64_t> labels;
  std::vector<std::vector<double>> values;
};

/// An .frd file read by the fixed columns of frd.c / frdheader.c / frdselect.c.
struct Frd
{
  std::vector<int64_t> node_labels;
  std::vector<std::array<double, 3>> coordinates;
  std::vector<int64_t> element_labels;
  std::vector<std::array<int, 3>> element_type_group_material;
  std::vector<std::array<int64_t, 8>> element_nodes;
  std::vector<Block> blocks;
  bool closed = false; ///< ends with " 9999"
};

int64_t integer_at(const std::string& line, std::size_t column, std::size_t width)
{
  return std::stoll(line.substr(column, width));
}

/// Values of a " -1" data record: I10 label from column 3, then E12.5 fields from column 13.
std::vector<double> values_of(const std::string& line)
{
  std::vector<double> values;
  for (std::size_t column = 13; column + 12 <= line.size(); column += 12)
    values.push_back(std::stod(line.substr(column, 12)));
  EXPECT_EQ((line.size() - 13) % 12, 0u) << "not a whole number of E12.5 fields: '" << line << "'";
  return values;
}

Frd parse_frd(const std::vector<std::string>& lines)
{
  Frd frd;
  std::size_t i = 0;
  EXPECT_EQ(lines.at(i++), "    1C");
  while (lines.at(i).rfind("    1U", 0) == 0)
    ++i;
  EXPECT_EQ(lines.at(i).substr(0, 6), "    2C");
  EXPECT_EQ(lines.at(i).size(), 74u);
  const int64_t n_nodes = integer_at(lines.at(i), 24, 12);
  for (++i; lines.at(i) != " -3"; ++i)
  {
    EXPECT_EQ(lines[i].substr(0, 3), " -1");
    EXPECT_EQ(lines[i].size(), 49u);
    frd.node_labels.push_back(integer_at(lines[i], 3, 10));
    const std::vector<double> x = values_of(lines[i]);
    frd.coordinates.push_back({x.at(0), x.at(1), x.at(2)});
  }
  EXPECT_EQ(static_cast<int64_t>(frd.node_labels.size()), n_nodes);
  ++i;
  EXPECT_EQ(lines.at(i).substr(0, 6), "    3C");
  const int64_t n_elements = integer_at(lines.at(i), 24, 12);
  for (++i; lines.at(i) != " -3"; i += 2)
  {
    EXPECT_EQ(lines[i].size(), 28u);
    frd.element_labels.push_back(integer_at(lines[i], 3, 10));
    frd.element_type_group_material.push_back({static_cast<int>(integer_at(lines[i], 13, 5)),
                                               static_cast<int>(integer_at(lines[i], 18, 5)),
                                               static_cast<int>(integer_at(lines[i], 23, 5))});
    const std::string& nodes = lines.at(i + 1);
    EXPECT_EQ(nodes.substr(0, 3), " -2");
    EXPECT_EQ(nodes.size(), 83u);
    std::array<int64_t, 8> ids;
    for (int k = 0; k < 8; ++k)
      ids[k] = integer_at(nodes, 3 + 10 * k, 10);
    frd.element_nodes.push_back(ids);
  }
  EXPECT_EQ(static_cast<int64_t>(frd.element_labels.size()), n_elements);
  for (++i; i < lines.size(); ++i)
  {
    if (lines[i] == " 9999")
    {
      frd.closed = true;
      EXPECT_EQ(i + 1, lines.size()) << "records after 9999";
      break;
    }
    Block block;
    const std::string& pstep = lines[i];
    EXPECT_EQ(pstep.substr(0, 10), "    1PSTEP");
    EXPECT_EQ(pstep.size(), 70u);
    block.block_counter = static_cast<int>(integer_at(pstep, 24, 12));
    block.increment = static_cast<int>(integer_at(pstep, 36, 12));
    block.step = static_cast<int>(integer_at(pstep, 48, 12));
    const std::string& cl = lines.at(++i);
    EXPECT_EQ(cl.substr(0, 7), "  100CL");
    EXPECT_EQ(cl.size(), 75u);
    block.kode = static_cast<int>(integer_at(cl, 58, 5));
    EXPECT_EQ(integer_at(cl, 7, 5), 100 + block.kode);
    block.time_field = cl.substr(12, 12);
    block.n_nodes = static_cast<int>(integer_at(cl, 24, 12));
    const std::string& name = lines.at(++i);
    EXPECT_EQ(name.substr(0, 5), " -4  ");
    block.name = name.substr(5, 8);
    while (!block.name.empty() && block.name.back() == ' ')
      block.name.pop_back();
    block.n_components = static_cast<int>(integer_at(name, 13, 5));
    for (++i; lines.at(i).rfind(" -5", 0) == 0; ++i)
      ;
    for (; lines.at(i) != " -3"; ++i)
    {
      EXPECT_EQ(lines[i].substr(0, 3), " -1");
      block.labels.push_back(integer_at(lines[i], 3, 10));
      block.values.push_back(values_of(lines[i]));
    }
    EXPECT_EQ(static_cast<int>(block.labels.size()), block.n_nodes);
    frd.blocks.push_back(block);
  }
  return frd;
}

/// Reference: ccx 2.20's .frd for two_blocks_frd.inp. The writer gets the mesh and every
/// value from that file and must write the same records: node and element blocks, 1PSTEP with
/// increment and step, 100CL with output number and time, field and component records, values.
/// Differences allowed: the 1U records (date, program), the ERROR blocks (ccx's error
/// estimator, not written by feticon) and hence the block counter of 1PSTEP.
TEST(FrdWriter, ReproducesWhatCcxWrites)
{
  const std::vector<std::string> reference_lines = read_lines(frd_reference_dir / "two_blocks_frd.frd");
  const Frd reference = parse_frd(reference_lines);
  ASSERT_TRUE(reference.closed);

  mesh::Mesh mesh;
  std::map<int64_t, int32_t> index_of_label;
  mesh.nodes.resize(static_cast<Eigen::Index>(reference.node_labels.size()), 3);
  for (std::size_t i = 0; i < reference.node_labels.size(); ++i)
  {
    index_of_label[reference.node_labels[i]] = static_cast<int32_t>(i);
    for (int k = 0; k < 3; ++k)
      mesh.nodes(static_cast<Eigen::Index>(i), k) = reference.coordinates[i][k];
  }
  for (const auto& nodes : reference.element_nodes)
  {
    feticon::mesh::Hex8Nodes cell;
    for (int k = 0; k < 8; ++k)
      cell[k] = index_of_label.at(nodes[k]);
    mesh.cells.add(feticon::mesh::CellKind::hex8, cell);
    mesh.cell_body.push_back(0);
  }
  mesh.body_names = {"EL"}; // ccx's material 1 of the deck

  const fs::path path = fresh_directory("frd_reproduces_ccx") / "two_blocks.frd";
  const io::Labels node_labels(reference.node_labels.begin(), reference.node_labels.end());
  const io::Labels element_labels(reference.element_labels.begin(), reference.element_labels.end());
  FrdWriter writer(path, mesh, node_labels, element_labels);
  const int n = mesh.n_nodes();
  int kode = 0;
  for (std::size_t b = 0; b < reference.blocks.size();)
  {
    // The blocks of one output time (same kode) into node-major arrays by mesh index.
    std::map<std::string, std::vector<double>> fields;
    const Block& first = reference.blocks[b];
    for (; b < reference.blocks.size() && reference.blocks[b].kode == first.kode; ++b)
    {
      const Block& block = reference.blocks[b];
      if (block.name == "ERROR")
        continue;
      const std::size_t width = block.values.at(0).size();
      std::vector<double>& values = fields[block.name];
      values.assign(n * width, 0.0);
      for (std::size_t r = 0; r < block.labels.size(); ++r)
        for (std::size_t k = 0; k < width; ++k)
          values[index_of_label.at(block.labels[r]) * width + k] = block.values[r][k];
    }
    ASSERT_EQ(fields.size(), 5u) << "DISP, STRESS, TOSTRAIN, FORC, CONTACT at kode " << first.kode;
    std::vector<double> pressure(n), gap(n);
    for (int i = 0; i < n; ++i)
    {
      gap[i] = fields["CONTACT"][6 * i + 0];
      pressure[i] = fields["CONTACT"][6 * i + 3];
      for (const int k : {1, 2, 4, 5}) // slip and shear: 0 in frictionless contact
        ASSERT_EQ(fields["CONTACT"][6 * i + k], 0.0);
    }
    FrdStep step;
    step.time = std::stod(first.time_field);
    step.step = first.step;
    step.increment = first.increment;
    step.displacement = fields["DISP"];
    step.stress = fields["STRESS"];
    step.strain = fields["TOSTRAIN"];
    step.reaction_force = fields["FORC"];
    step.contact_pressure = pressure;
    step.contact_gap = gap;
    writer.add_step(step);
    EXPECT_EQ(writer.n_steps(), ++kode);
  }
  EXPECT_EQ(kode, 3); // two increments of step 1, one of step 2
  writer.close();

  // Compare record by record.
  auto comparable = [](const std::vector<std::string>& lines) {
    std::vector<std::string> out;
    for (std::size_t i = 0; i < lines.size(); ++i)
    {
      if (lines[i].rfind("    1U", 0) == 0)
        continue;
      if (lines[i].rfind("    1PSTEP", 0) == 0 && lines.at(i + 2).rfind(" -4  ERROR", 0) == 0)
      {
        while (lines[i] != " -3")
          ++i;
        continue;
      }
      std::string line = lines[i];
      if (line.rfind("    1PSTEP", 0) == 0)
        line.replace(24, 12, 12, '#'); // block counter
      out.push_back(line);
    }
    return out;
  };
  const std::vector<std::string> expected = comparable(reference_lines);
  const std::vector<std::string> written_lines = read_lines(path);
  const std::vector<std::string> written = comparable(written_lines);
  ASSERT_EQ(written.size(), expected.size());
  for (std::size_t i = 0; i < expected.size(); ++i)
    ASSERT_EQ(written[i], expected[i]) << "record " << i;
  // The material record of body 0 is ccx's of material 1.
  EXPECT_EQ(written_lines.at(5), reference_lines.at(10));
  // Blocks are counted without gaps (ccx counts its ERROR blocks too).
  const Frd written_frd = parse_frd(written_lines);
  for (std::size_t b = 0; b < written_frd.blocks.size(); ++b)
    EXPECT_EQ(written_frd.blocks[b].block_counter, static_cast<int>(b + 1));
}

/// Two hex8 cells side by side. Each is its own body only to give two material numbers; the
/// writer does not look at Mesh's rule that bodies share no nodes.
mesh::Mesh two_cells()
{
  mesh::Mesh mesh;
  mesh.nodes.resize(12, 3);
  for (int i = 0; i < 12; ++i)
  {
    const int x = i % 3, y = (i / 3) % 2, z = i / 6;
    mesh.nodes.row(i) << 0.5 * x, 0.25 * y, -0.125 * z;
  }
  mesh.cells.add(mesh::CellKind::hex8, mesh::Hex8Nodes{0, 1, 4, 3, 6, 7, 10, 9});
  mesh.cells.add(mesh::CellKind::hex8, mesh::Hex8Nodes{1, 2, 5, 4, 7, 8, 11, 10});
  mesh.cell_body = {0, 1};
  mesh.body_names = {"slab", "punch"};
  return mesh;
}

/// A value of node i, component k, step s that needs all printed digits.
double known_value(int i, int k, int s) { return (i + 1) * 1.234567e-4 * std::pow(-10.0, k) * (s + 1); }

TEST(FrdWriter, WritesKnownValuesStepByStep)
{
  // Reference: the values set here; the parser reads them back by fixed columns. %12.5E of a
  // float-rounded value keeps 6 significant digits: relative error <= 5e-6 + 6e-8.
  const mesh::Mesh mesh = two_cells();
  io::Labels node_labels(12), element_labels = {70, 9};
  for (int i = 0; i < 12; ++i)
    node_labels[i] = 1000 + 10 * i;
  const std::vector<int64_t> node_labels_read(node_labels.begin(), node_labels.end());
  const std::vector<int64_t> element_labels_read(element_labels.begin(), element_labels.end());
  const fs::path path = fresh_directory("frd_known_values") / "out" / "known.frd";
  FrdWriter writer(path, mesh, node_labels, element_labels);

  const Frd empty = parse_frd(read_lines(path));
  EXPECT_TRUE(empty.closed);
  EXPECT_TRUE(empty.blocks.empty());
  EXPECT_EQ(empty.node_labels, node_labels_read);
  EXPECT_EQ(empty.element_labels, element_labels_read);
  EXPECT_EQ(empty.element_type_group_material[0], (std::array<int, 3>{1, 0, 1})); // C3D8, body 0
  EXPECT_EQ(empty.element_type_group_material[1], (std::array<int, 3>{1, 0, 2}));
  EXPECT_EQ(empty.element_nodes[1][0], 1010);
  EXPECT_EQ(empty.element_nodes[1][7], 1100);
  EXPECT_DOUBLE_EQ(empty.coordinates[11][0], 1.0);
  EXPECT_DOUBLE_EQ(empty.coordinates[11][2], -0.125);

  const std::array<double, 3> times = {0.5, 1.0, 12.25};
  const std::array<int, 3> deck_steps = {1, 1, 2};
  for (int s = 0; s < 3; ++s)
  {
    std::vector<double> u(36), stress(72), pressure(12, 0.0);
    for (int i = 0; i < 12; ++i)
    {
      for (int k = 0; k < 3; ++k)
        u[3 * i + k] = known_value(i, k, s);
      for (int k = 0; k < 6; ++k)
        stress[6 * i + k] = 1e6 * known_value(i, k, s);
    }
    pressure[4] = 3.5e7 * (s + 1);
    FrdStep step;
    step.time = times[s];
    step.step = deck_steps[s];
    step.displacement = u;
    step.stress = stress;
    step.contact_pressure = pressure;
    writer.add_step(step);

    // After every step the file is complete: a crash later leaves these steps readable.
    const Frd frd = parse_frd(read_lines(path));
    ASSERT_TRUE(frd.closed);
    ASSERT_EQ(frd.blocks.size(), 3u * (s + 1));
    for (int b = 0; b < 3; ++b)
    {
      const Block& block = frd.blocks[3 * s + b];
      EXPECT_EQ(block.name, (std::array<std::string, 3>{"DISP", "STRESS", "CONTACT"}[b]));
      EXPECT_EQ(block.kode, s + 1);
      EXPECT_EQ(block.step, deck_steps[s]);
      EXPECT_EQ(block.increment, s == 2 ? 1 : s + 1); // counted within each deck step
      EXPECT_EQ(block.n_nodes, 12);
      EXPECT_EQ(block.labels, node_labels_read);
    }
    // frdheader.c: fixed point with 10 significant digits for 1 <= t < 1e10, else %12.5E.
    EXPECT_EQ(frd.blocks[3 * s].time_field,
              (std::array<std::string, 3>{" 5.00000E-01", " 1.000000000", " 12.25000000"}[s]));
    const double tolerance = 5e-6 + 6e-8;
    for (int i = 0; i < 12; ++i)
    {
      for (int k = 0; k < 3; ++k)
        EXPECT_NEAR(frd.blocks[3 * s].values[i][k], u[3 * i + k], tolerance * std::abs(u[3 * i + k]));
      for (int k = 0; k < 6; ++k)
        EXPECT_NEAR(frd.blocks[3 * s + 1].values[i][k], stress[6 * i + k], tolerance * std::abs(stress[6 * i + k]));
      const std::vector<double>& contact = frd.blocks[3 * s + 2].values[i];
      ASSERT_EQ(contact.size(), 6u);
      EXPECT_EQ(contact[3], pressure[i]); // 3.5e7, 7e7, 1.05e8: exact in 6 digits
      for (const int k : {0, 1, 2, 4, 5})
        EXPECT_EQ(contact[k], 0.0) << "no gap given, frictionless";
    }
  }
  writer.close();
  EXPECT_THROW(writer.add_step(FrdStep{}), Error);
}

TEST(FrdWriter, RejectsWrongSizesAndLabels)
{
  // Reference: the sizes the header documents (n x 3, n x 6, n; positive labels).
  const mesh::Mesh mesh = two_cells();
  const fs::path directory = fresh_directory("frd_rejects");
  EXPECT_THROW(FrdWriter(directory / "a.frd", mesh, io::Labels(11, 1)), Error);
  EXPECT_THROW(FrdWriter(directory / "b.frd", mesh, {}, {1, 0}), Error);
  EXPECT_THROW(FrdWriter(directory / "c.frd", mesh, {}, {1, -3}), Error);
  FrdWriter writer(directory / "d.frd", mesh);
  const std::vector<double> short_field(35);
  FrdStep step;
  step.displacement = short_field;
  try
  {
    writer.add_step(step);
    FAIL() << "a displacement of 35 values for 12 nodes was accepted";
  }
  catch (const Error& error)
  {
    EXPECT_NE(std::string(error.what()).find("displacement has 35 values, expected 12 nodes x 3"), std::string::npos)
        << error.what();
  }
}

TEST(FrdWriter, FieldsOfTheDeckRequests)
{
  // Reference: the *_FILE keywords of the CalculiX manual and what the writer can write.
  using Kind = DeckOutputRequest::Kind;
  std::vector<DeckOutputRequest> outputs = {
      {Kind::node_file, "", {"U", "NT"}, DeckOutputRequest::Totals::no, "m.inp:10"},
      {Kind::el_file, "ETOP", {"S"}, DeckOutputRequest::Totals::no, "m.inp:12"},
      {Kind::contact_file, "", {"CDISP", "CSTRESS"}, DeckOutputRequest::Totals::no, "m.inp:14"},
      {Kind::node_print, "", {"RF"}, DeckOutputRequest::Totals::no, "m.inp:16"},
  };
  std::vector<std::string> warnings;
  const FrdFields fields = frd_fields(outputs, warnings);
  EXPECT_TRUE(fields.displacement);
  EXPECT_FALSE(fields.reaction_force); // RF only printed, not filed
  EXPECT_TRUE(fields.stress);
  EXPECT_FALSE(fields.strain);
  EXPECT_TRUE(fields.contact);
  ASSERT_EQ(warnings.size(), 2u);
  EXPECT_EQ(warnings[0], "m.inp:10: *NODE FILE: NT not available in feticon, not written to the .frd file");
  EXPECT_EQ(warnings[1], "m.inp:12: *EL FILE: set ETOP ignored, the .frd file holds all nodes");
}

/// Whether `program` is on PATH.
bool on_path(const std::string& program)
{
  return std::system(("command -v " + program + " > /dev/null 2>&1").c_str()) == 0;
}

TEST(FrdWriter, CgxReadsTheFile)
{
  // Reference: CalculiX GraphiX reading the file in batch mode without graphics (-bg; -b
  // needs a display) and reporting the extremes of D3 and of SXX with their node labels.
  if (!on_path("cgx"))
    GTEST_SKIP() << "cgx is not installed (Debian: calculix-cgx)";
  const mesh::Mesh mesh = two_cells();
  io::Labels node_labels(12);
  for (int i = 0; i < 12; ++i)
    node_labels[i] = 1000 + 10 * i;
  const fs::path directory = fresh_directory("frd_cgx");
  {
    FrdWriter writer(directory / "known.frd", mesh, node_labels, {70, 9});
    std::vector<double> u(36, 0.0), stress(72, 0.0);
    u[3 * 5 + 2] = -2.5e-3; // D3 minimum at node 1050
    u[3 * 8 + 2] = 1.25e-3; // D3 maximum at node 1080
    stress[6 * 11] = 7.5e6; // SXX maximum at node 1110
    FrdStep step;
    step.time = 1.0;
    step.displacement = u;
    step.stress = stress;
    writer.add_step(step);
  }
  std::ofstream(directory / "read.fbd") << "read known.frd\nds 1 e 3\nds 2 e 1\nquit\n";
  const std::string command =
      "cd '" + directory.string() + "' && timeout 60 cgx -bg read.fbd > cgx.log 2>&1 < /dev/null";
  ASSERT_EQ(std::system(command.c_str()), 0) << "see " << (directory / "cgx.log").string();
  std::ifstream log(directory / "cgx.log");
  const std::string text((std::istreambuf_iterator<char>(log)), std::istreambuf_iterator<char>());
  EXPECT_NE(text.find("reading Dataset No:2"), std::string::npos) << text;
  EXPECT_NE(text.find("max:1.250000e-03 at node:1080"), std::string::npos) << text;
  EXPECT_NE(text.find("min:-2.500000e-03 at node:1050"), std::string::npos) << text;
  EXPECT_NE(text.find("max:7.500000e+06 at node:1110"), std::string::npos) << text;
  EXPECT_EQ(text.find("ERROR"), std::string::npos) << text;
}
} // namespace
} // namespace feticon::io
