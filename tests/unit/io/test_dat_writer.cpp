/// Tests of the .dat writer. References:
///  - the .dat ccx 2.20 wrote for tests/data/calculix_results/two_blocks_dat.inp (README.md
///    there): fed with the values it holds, the writer reproduces it byte for byte;
///  - CalculiX's integration point order (gauss3d2 in ccx's gauss.f, written out below) against
///    fem::hex8_gauss_points();
///  - values set here, read back by column (to the printed digits), and their sums.

#include "io/dat_writer.hpp"

#include "common/error.hpp"
#include "fem/hex8.hpp"

#include "io_test_files.hpp"

#include <gtest/gtest.h>

#include <array>
#include <cmath>
#include <filesystem>
#include <fstream>
#include <map>
#include <numeric>
#include <sstream>
#include <string>
#include <vector>

namespace feticon::io
{
namespace
{
namespace fs = std::filesystem;
using Kind = DeckOutputRequest::Kind;
using Totals = DeckOutputRequest::Totals;

using test::fresh_directory;

const fs::path reference_dir = fs::path(FETICON_SOURCE_DIR) / "tests" / "data" / "calculix_results";

std::string read_text(const fs::path& path)
{
  std::ifstream in(path, std::ios::binary);
  if (!in)
    throw std::runtime_error("cannot read " + path.string());
  return {std::istreambuf_iterator<char>(in), std::istreambuf_iterator<char>()};
}

/// One block of a .dat file: its header line and the numbers of its rows.
struct DatBlock
{
  std::string header;
  std::vector<std::vector<double>> rows;
};

/// Blocks of a .dat text: blank, header, blank, rows up to the next blank line.
std::vector<DatBlock> parse_dat(const std::string& text)
{
  std::vector<DatBlock> blocks;
  std::istringstream in(text);
  std::string line;
  while (std::getline(in, line))
  {
    if (line.empty())
      continue;
    if (line.find(" and time") != std::string::npos)
    {
      blocks.push_back({line, {}});
      continue;
    }
    std::istringstream fields(line);
    std::vector<double> row;
    std::string field;
    while (fields >> field)
      row.push_back(std::stod(field));
    blocks.at(blocks.size() - 1).rows.push_back(row);
  }
  return blocks;
}

/// The model of two_blocks_dat.inp: 16 nodes 101..116, elements 11 (top block) and 12.
DatModel two_blocks_model()
{
  DatModel model;
  model.n_nodes = 16;
  model.n_cells = 2;
  for (int i = 0; i < 16; ++i)
    model.node_labels.push_back(101 + i);
  model.element_labels = {11, 12};
  model.node_sets["NSLAV"] = {5, 4, 1, 0}; // any order: printed by label
  model.node_sets["NBIGCUBE"] = {8, 9, 10, 11, 12, 13, 14, 15};
  model.element_sets["ETOP"] = {0};
  model.contact_slave_nodes = {0, 1, 4, 5};
  return model;
}

/// The print requests of a step of two_blocks_dat.inp, in its order; the step's first one is on
/// line `line` (60 in step 1, 74 in step 2).
std::vector<DeckOutputRequest> two_blocks_requests(int line)
{
  auto where = [](int l) { return "two_blocks_dat.inp:" + std::to_string(l); };
  return {{Kind::node_print, "NBIGCUBE", {"U", "RF"}, Totals::yes, where(line)},
          {Kind::contact_print, "", {"CDIS", "CSTR"}, Totals::no, where(line + 2)},
          {Kind::node_print, "NSLAV", {"U", "RF"}, Totals::only, where(line + 4)},
          {Kind::el_print, "ETOP", {"S", "E"}, Totals::no, where(line + 6)}};
}

/// Reference: ccx 2.20's .dat for two_blocks_dat.inp. The writer gets the model of the deck and
/// the values ccx printed and must write the same text, byte for byte: blank lines, headers
/// with set names and times (E14.7), label columns (I10, I3), values (1PE13.6), the total line
/// of TOTALS=YES and TOTALS=ONLY, the order of requests and variables.
TEST(DatWriter, ReproducesWhatCcxWrites)
{
  const std::string reference = read_text(reference_dir / "two_blocks_dat.dat");
  const std::vector<DatBlock> blocks = parse_dat(reference);
  // Per output time: U, RF, total RF of NBIGCUBE; CDIS; CSTR; U, total RF of NSLAV; S; E.
  constexpr int per_time = 9;
  ASSERT_EQ(blocks.size(), 3u * per_time);

  const fs::path path = fresh_directory("dat_reproduces_ccx") / "two_blocks.dat";
  DatWriter writer(path, two_blocks_model());
  auto node = [](double label) { return static_cast<std::size_t>(label) - 101; };
  const std::array<double, 3> times = {0.5, 1.0, 2.0};
  for (int s = 0; s < 3; ++s)
  {
    const DatBlock* b = &blocks[per_time * s];
    ASSERT_NE(b[7].header.find("stresses"), std::string::npos);
    ASSERT_NE(b[8].header.find("strains"), std::string::npos);
    std::vector<double> u(48, 0.0), rf(48, 0.0), gap(16, 0.0), pressure(16, 0.0);
    std::vector<double> stress(2 * 48, 0.0), strain(2 * 48, 0.0);
    for (const DatBlock* block : {&b[0], &b[5]})
      for (const auto& row : block->rows)
        for (int k = 0; k < 3; ++k)
          u[3 * node(row[0]) + k] = row[1 + k];
    for (const auto& row : b[1].rows)
      for (int k = 0; k < 3; ++k)
        rf[3 * node(row[0]) + k] = row[1 + k];
    // NSLAV has TOTALS=ONLY: ccx prints no node values, so node 101 carries the whole total.
    for (int k = 0; k < 3; ++k)
      rf[k] = b[6].rows.at(0).at(k);
    for (const auto& row : b[3].rows)
      gap[node(row[0])] = row[1];
    for (const auto& row : b[4].rows)
      pressure[node(row[0])] = row[1];
    // Element 11 (cell 0): CalculiX's point j (stored in its order) and order xx yy zz xy xz yz
    // into feticon's order xx yy zz xy yz zx.
    const std::array<int, 6> component = {0, 1, 2, 3, 5, 4};
    for (const auto& [block, values] : {std::pair{&b[7], &stress}, std::pair{&b[8], &strain}})
    {
      ASSERT_EQ(block->rows.size(), 8u);
      for (const auto& row : block->rows)
      {
        ASSERT_EQ(row[0], 11.0);
        const int p = static_cast<int>(row[1]) - 1;
        for (int k = 0; k < 6; ++k)
          (*values)[6 * p + component[k]] = row[2 + k];
      }
    }
    const std::vector<int64_t> offsets = {0, 8, 16};
    DatStep step;
    step.time = times[s];
    step.displacement = u;
    step.reaction_force = rf;
    step.point_offsets = offsets;
    step.stress = stress;
    step.strain = strain;
    step.contact_pressure = pressure;
    step.contact_gap = gap;
    const int line = s < 2 ? 60 : 74; // times 0.5 and 1 in step 1, 2 in step 2
    const std::vector<std::string> warnings = writer.add_step(step, two_blocks_requests(line));
    // CDIS tang1, tang2 are printed as 0 with a note, once per request.
    ASSERT_EQ(warnings.size(), s == 1 ? 0u : 1u);
    if (s != 1)
    {
      EXPECT_EQ(warnings[0],
                "two_blocks_dat.inp:" + std::to_string(line + 2) +
                    ": *CONTACT PRINT: CDIS: tang1, tang2 (tangential relative "
                    "displacements) are not computed by feticon, printed as 0");
    }
  }
  writer.close();
  const std::string written = read_text(path);
  if (written != reference)
  {
    // Name the first differing line.
    std::istringstream a(written), b(reference);
    std::string line_a, line_b;
    for (int line = 1; std::getline(b, line_b); ++line)
    {
      std::getline(a, line_a);
      ASSERT_EQ(line_a, line_b) << "line " << line;
    }
    FAIL() << "the written file is longer than ccx's";
  }
}

TEST(DatWriter, IntegrationPointsPerCellInStoredOrder)
{
  // Reference: printout.f format 106 for the component order sxx syy szz sxy sxz syz; the
  // points are printed as stored (app/calculix_results.cpp puts them in CalculiX's order),
  // numbered from 1 in each cell, as many as the offsets give it (a C3D10's 4, a C3D20R's 8).
  // Point j of cell c carries 100 c + j, 10 + j, 20 + j as xx, yy, zz and 4, 5, 6 as xy, yz, zx.
  DatModel model;
  model.n_nodes = 8;
  model.n_cells = 2;
  model.element_labels = {42, 43};
  const std::vector<int64_t> offsets = {0, 4, 12};
  std::vector<double> stress;
  for (int c = 0; c < 2; ++c)
    for (int64_t j = 0; j < offsets[c + 1] - offsets[c]; ++j)
      for (const double v : {100.0 * c + static_cast<double>(j), 10.0 + static_cast<double>(j),
                             20.0 + static_cast<double>(j), 4.0, 5.0, 6.0})
        stress.push_back(v);
  const fs::path path = fresh_directory("dat_points") / "points.dat";
  DatWriter writer(path, model);
  DatStep step;
  step.time = 1.0;
  step.point_offsets = offsets;
  step.stress = stress;
  EXPECT_TRUE(writer.add_step(step, {{Kind::el_print, "", {"S"}, Totals::no, "m.inp:3"}}).empty());
  writer.close();
  const std::vector<DatBlock> blocks = parse_dat(read_text(path));
  ASSERT_EQ(blocks.size(), 1u);
  EXPECT_EQ(blocks[0].header,
            " stresses (elem, integ.pnt.,sxx,syy,szz,sxy,sxz,syz) for set EALL "
            "and time  0.1000000E+01");
  ASSERT_EQ(blocks[0].rows.size(), 12u);
  for (size_t r = 0; r < 12; ++r)
  {
    const std::vector<double>& row = blocks[0].rows[r];
    const int c = r < 4 ? 0 : 1;
    const auto j = static_cast<double>(r < 4 ? r : r - 4);
    EXPECT_EQ(row[0], 42 + c);
    EXPECT_EQ(row[1], j + 1);
    EXPECT_EQ(row[2], 100.0 * c + j);
    EXPECT_EQ(row[3], 10 + j);
    EXPECT_EQ(row[4], 20 + j);
    EXPECT_EQ(row[5], 4);
    EXPECT_EQ(row[6], 6);
    EXPECT_EQ(row[7], 5);
  }
}

TEST(DatWriter, TotalsLineIsTheSum)
{
  // Reference: the values set here (printed to 7 significant digits, 1PE13.6: relative error
  // <= 5e-7) and their sum over the set, computed here in double.
  DatModel model;
  model.n_nodes = 12;
  model.node_labels.resize(12);
  std::iota(model.node_labels.begin(), model.node_labels.end(), 500);
  model.node_sets["FIX"] = {11, 3, 7, 0};
  std::vector<double> rf(36);
  for (int i = 0; i < 12; ++i)
    for (int k = 0; k < 3; ++k)
      rf[3 * i + k] = (i + 1) * 1.2345678e3 * std::pow(-3.0, k);
  const fs::path path = fresh_directory("dat_totals") / "totals.dat";
  DatWriter writer(path, model);
  DatStep step;
  step.time = 0.25;
  step.reaction_force = rf;
  writer.add_step(step,
                  {{Kind::node_print, "FIX", {"RF"}, Totals::yes, "m.inp:5"},
                   {Kind::node_print, "", {"RF"}, Totals::only, "m.inp:7"}});
  writer.close();
  const std::vector<DatBlock> blocks = parse_dat(read_text(path));
  ASSERT_EQ(blocks.size(), 3u);
  EXPECT_EQ(blocks[0].header, " forces (fx,fy,fz) for set FIX and time  0.2500000E+00");
  EXPECT_EQ(blocks[1].header, " total force (fx,fy,fz) for set FIX and time  0.2500000E+00");
  EXPECT_EQ(blocks[2].header, " total force (fx,fy,fz) for set NALL and time  0.2500000E+00");
  const std::vector<int> fix = {0, 3, 7, 11}; // by label 500, 503, 507, 511
  ASSERT_EQ(blocks[0].rows.size(), 4u);
  for (std::size_t r = 0; r < fix.size(); ++r)
  {
    EXPECT_EQ(blocks[0].rows[r][0], 500 + fix[r]);
    for (int k = 0; k < 3; ++k)
      EXPECT_NEAR(blocks[0].rows[r][1 + k], rf[3 * fix[r] + k], 5e-7 * std::abs(rf[3 * fix[r] + k]));
  }
  for (const auto& [block, members] :
       {std::pair{&blocks[1], fix}, std::pair{&blocks[2], std::vector<int>{0, 1, 2, 3, 4, 5, 6, 7, 8, 9, 10, 11}}})
  {
    ASSERT_EQ(block->rows.size(), 1u);
    ASSERT_EQ(block->rows[0].size(), 3u); // no label column
    for (int k = 0; k < 3; ++k)
    {
      double sum = 0;
      for (const int i : members)
        sum += rf[3 * i + k];
      EXPECT_NEAR(block->rows[0][k], sum, 5e-7 * std::abs(sum));
    }
  }
}

TEST(DatWriter, WarnsOnceAboutWhatIsNotAvailable)
{
  // Reference: the variables the writer documents (U, RF, S, E, CSTR, CDIS) and the arrays
  // given; nothing is printed for the others.
  DatModel model;
  model.n_nodes = 8;
  model.n_cells = 1;
  model.contact_slave_nodes = {2, 1};
  const fs::path path = fresh_directory("dat_warnings") / "warnings.dat";
  DatWriter writer(path, model);
  const std::vector<DeckOutputRequest> requests = {
      {Kind::node_print, "", {"U", "NT", "RF"}, Totals::no, "m.inp:20"},
      {Kind::el_print, "", {"S", "ENER"}, Totals::no, "m.inp:22"},
      {Kind::contact_print, "", {"CSTRESS", "CELS"}, Totals::no, "m.inp:24"},
      {Kind::node_file, "", {"PEEQ"}, Totals::no, "m.inp:26"}};
  const std::vector<double> u(24, 1.0), pressure(8, 2.0);
  DatStep step;
  step.displacement = u;
  step.contact_pressure = pressure;
  for (int s = 0; s < 2; ++s)
  {
    step.time = s + 1.0;
    const std::vector<std::string> warnings = writer.add_step(step, requests);
    if (s == 1)
    {
      EXPECT_TRUE(warnings.empty());
      continue;
    }
    ASSERT_EQ(warnings.size(), 3u);
    EXPECT_EQ(warnings[0], "m.inp:20: *NODE PRINT: NT, RF not available in feticon, not printed to the .dat file");
    EXPECT_EQ(warnings[1], "m.inp:22: *EL PRINT: S, ENER not available in feticon, not printed to the .dat file");
    EXPECT_EQ(warnings[2], "m.inp:24: *CONTACT PRINT: CELS not available in feticon, not printed to the .dat file");
  }
  writer.close();
  const std::vector<DatBlock> blocks = parse_dat(read_text(path));
  ASSERT_EQ(blocks.size(), 4u); // U and CSTR at two times
  EXPECT_EQ(blocks[0].header, " displacements (vx,vy,vz) for set NALL and time  0.1000000E+01");
  EXPECT_EQ(blocks[0].rows.size(), 8u);
  EXPECT_EQ(blocks[1].header,
            " contact stress (slave node,press,tang1,tang2) for all contact "
            "elements and time 0.1000000E+01");
  ASSERT_EQ(blocks[1].rows.size(), 2u);
  EXPECT_EQ(blocks[1].rows[0], (std::vector<double>{2, 2.0, 0.0, 0.0})); // node label 2 = index 1
  EXPECT_EQ(blocks[1].rows[1], (std::vector<double>{3, 2.0, 0.0, 0.0}));
}

TEST(DatWriter, RejectsUnknownSetsAndWrongSizes)
{
  // Reference: the deck's sets and the sizes the header documents.
  DatModel model = two_blocks_model();
  const fs::path directory = fresh_directory("dat_rejects");
  DatWriter writer(directory / "a.dat", model);
  const std::vector<double> u(48, 0.0);
  DatStep step;
  step.displacement = u;
  try
  {
    writer.add_step(step, {{Kind::node_print, "NTOP", {"U"}, Totals::no, "m.inp:9"}});
    FAIL() << "an unknown set was accepted";
  }
  catch (const Error& error)
  {
    EXPECT_NE(std::string(error.what()).find("m.inp:9: node set NTOP is not defined (defined: NBIGCUBE, NSLAV)"),
              std::string::npos)
        << error.what();
  }
  const std::vector<int64_t> offsets = {0, 8, 16};
  const std::vector<double> short_stress(95);
  step.point_offsets = offsets;
  step.stress = short_stress;
  EXPECT_THROW(writer.add_step(step, {}), Error);
  model.node_sets["BAD"] = {16};
  EXPECT_THROW(DatWriter(directory / "b.dat", model), Error);
  model = two_blocks_model();
  model.element_labels = {11};
  EXPECT_THROW(DatWriter(directory / "c.dat", model), Error);
}
} // namespace
} // namespace feticon::io
