/// Tests of the VTU and PVD writers. Reference: the values written, read back by an independent
/// reader (tests/tools/read_vtu.py: Debian's python3 with xml.etree, base64 and numpy).

#include "io/vtu.hpp"

#include "mesh/box.hpp"

#include "common/error.hpp"

#include "io_test_files.hpp"

#include <gtest/gtest.h>
#include <nlohmann/json.hpp>

#include <array>
#include <cmath>
#include <cstdio>
#include <filesystem>
#include <fstream>
#include <numeric>
#include <sstream>

namespace feticon::io
{
namespace
{
namespace fs = std::filesystem;

using test::fresh_directory;

/// Runs tests/tools/read_vtu.py on `path` and parses its JSON output.
nlohmann::json read_back(const fs::path& path)
{
  const std::string command =
      "/usr/bin/python3 '" + std::string(FETICON_SOURCE_DIR) + "/tests/tools/read_vtu.py' '" + path.string() + "'";
  FILE* pipe = popen(command.c_str(), "r");
  if (!pipe)
    throw std::runtime_error("cannot run " + command);
  std::string output;
  std::array<char, 4096> buffer;
  while (const std::size_t n = std::fread(buffer.data(), 1, buffer.size(), pipe))
    output.append(buffer.data(), n);
  const int status = pclose(pipe);
  if (status != 0)
    throw std::runtime_error(command + " failed with status " + std::to_string(status));
  return nlohmann::json::parse(output);
}

double sum(const std::vector<double>& values) { return std::accumulate(values.begin(), values.end(), 0.0); }

/// Relative difference; all sums below are of positive values, so there is no cancellation and
/// the summation orders of C++ and numpy differ by a few ulps only.
double relative_difference(double a, double b) { return std::abs(a - b) / std::max(std::abs(b), 1e-300); }

mesh::Mesh small_box()
{
  mesh::BoxParameters p;
  p.lengths = Eigen::Vector3d(1.0, 0.5, 0.25);
  p.nx = 3;
  p.ny = 2;
  p.nz = 2;
  return mesh::generate_box(p);
}

std::vector<double> positive_values(std::size_t n, double scale)
{
  std::vector<double> values(n);
  for (std::size_t i = 0; i < n; ++i)
    values[i] = scale * (1.0 + 0.5 * std::sin(0.7 * static_cast<double>(i)));
  return values;
}

int count(const std::string& text, const std::string& pattern)
{
  int n = 0;
  for (std::size_t at = text.find(pattern); at != std::string::npos; at = text.find(pattern, at + 1))
    ++n;
  return n;
}

std::string read_vtu_file(const fs::path& path)
{
  std::ifstream in(path, std::ios::binary);
  std::ostringstream content;
  content << in.rdbuf();
  return content.str();
}
} // namespace

TEST(Vtu, RoundTripThroughAnIndependentReader)
{
  const fs::path directory = fresh_directory("vtu_round_trip");
  const mesh::Mesh mesh = small_box();
  const int32_t n_points = mesh.n_nodes(), n_cells = mesh.n_cells();
  const VtuField displacement{"displacement", 3, positive_values(3 * n_points, 1e-3)};
  const VtuField temperature{"temperature", 1, positive_values(n_points, 300.0)};
  const VtuField stress{"stress", 6, positive_values(6 * n_cells, 2.5e9)};
  const VtuField gradient{"deformation gradient", 9, positive_values(9 * n_cells, 1.0)};
  PointMatrix deformed = mesh.nodes;
  for (int32_t i = 0; i < n_points; ++i)
    for (int d = 0; d < 3; ++d)
      deformed(i, d) += displacement.values[3 * i + d];
  const Eigen::Ref<const PointMatrix> deformed_ref(deformed);

  const fs::path path = directory / "box.vtu";
  write_vtu(path, mesh, &deformed_ref, {displacement, temperature}, {stress, gradient});
  const nlohmann::json file = read_back(path);

  EXPECT_EQ(file["NumberOfPoints"], n_points);
  EXPECT_EQ(file["NumberOfCells"], n_cells);
  const double points_sum = std::accumulate(deformed.data(), deformed.data() + deformed.size(), 0.0);
  EXPECT_EQ(file["points"]["Points"]["components"], 3);
  EXPECT_LT(relative_difference(file["points"]["Points"]["sum"], points_sum), 1e-12);

  for (const VtuField& field : {displacement, temperature})
  {
    const auto& array = file["point_data"][field.name];
    EXPECT_EQ(array["components"], field.components) << field.name;
    EXPECT_EQ(array["n_values"], field.values.size()) << field.name;
    EXPECT_EQ(array["type"], "Float64");
    EXPECT_LT(relative_difference(array["sum"], sum(field.values)), 1e-12) << field.name;
  }
  for (const VtuField& field : {stress, gradient})
  {
    const auto& array = file["cell_data"][field.name];
    EXPECT_EQ(array["components"], field.components) << field.name;
    EXPECT_EQ(array["n_values"], field.values.size()) << field.name;
    EXPECT_LT(relative_difference(array["sum"], sum(field.values)), 1e-12) << field.name;
  }

  // Generated fields: body of each cell, 0/1 membership of every node set.
  EXPECT_EQ(file["cell_data"]["body"]["type"], "Int32");
  EXPECT_EQ(file["cell_data"]["body"]["n_values"], n_cells);
  EXPECT_EQ(file["cell_data"]["body"]["max"], 0);
  EXPECT_EQ(file["point_data"].size(), 2 + mesh.node_sets.size());
  for (const auto& [name, ids] : mesh.node_sets)
  {
    const auto& array = file["point_data"]["set_" + name];
    EXPECT_EQ(array["type"], "UInt8") << name;
    EXPECT_EQ(array["n_values"], n_points) << name;
    EXPECT_EQ(array["sum"], ids.size()) << name;
  }

  // Topology: hexahedra (12), offsets 8, 16, ..., and the connectivity of the mesh.
  const auto& cells = file["cells"];
  EXPECT_EQ(cells["types"]["min"], 12);
  EXPECT_EQ(cells["types"]["max"], 12);
  EXPECT_EQ(cells["offsets"]["max"], 8 * n_cells);
  EXPECT_EQ(cells["offsets"]["sum"], 8.0 * n_cells * (n_cells + 1) / 2);
  double connectivity_sum = 0;
  for (const auto cell : mesh.cells)
    connectivity_sum += std::accumulate(cell.begin(), cell.end(), 0.0);
  EXPECT_EQ(cells["connectivity"]["n_values"], 8 * n_cells);
  EXPECT_EQ(cells["connectivity"]["sum"], connectivity_sum);

  // Reference coordinates when no deformed points are given.
  write_vtu(path, mesh, nullptr, {}, {});
  const nlohmann::json reference = read_back(path);
  const double reference_sum = std::accumulate(mesh.nodes.data(), mesh.nodes.data() + mesh.nodes.size(), 0.0);
  EXPECT_LT(relative_difference(reference["points"]["Points"]["sum"], reference_sum), 1e-12);
}

TEST(Vtu, RejectsMismatchedFields)
{
  const fs::path directory = fresh_directory("vtu_errors");
  const mesh::Mesh mesh = small_box();
  const fs::path path = directory / "bad.vtu";
  const VtuField short_field{"short", 3, std::vector<double>(3 * mesh.n_nodes() - 1, 1.0)};
  EXPECT_THROW(write_vtu(path, mesh, nullptr, {short_field}, {}), Error);
  const VtuField cell_scalar{"pressure", 1, std::vector<double>(mesh.n_cells(), 1.0)};
  EXPECT_THROW(write_vtu(path, mesh, nullptr, {cell_scalar}, {}), Error); // sized for cells
  EXPECT_THROW(write_vtu(path, mesh, nullptr, {}, {cell_scalar, cell_scalar}), Error);
  const VtuField clash{"body", 1, std::vector<double>(mesh.n_cells(), 1.0)};
  EXPECT_THROW(write_vtu(path, mesh, nullptr, {}, {clash}), Error);
  const VtuField set_clash{"set_xmin", 1, std::vector<double>(mesh.n_nodes(), 1.0)};
  EXPECT_THROW(write_vtu(path, mesh, nullptr, {set_clash}, {}), Error);
  const PointMatrix too_few = mesh.nodes.topRows(mesh.n_nodes() - 1);
  const Eigen::Ref<const PointMatrix> too_few_ref(too_few);
  EXPECT_THROW(write_vtu(path, mesh, &too_few_ref, {}, {}), Error);
  EXPECT_FALSE(fs::exists(path));
  EXPECT_TRUE(fs::is_empty(directory));
}

TEST(Vtu, UnwritablePathThrows)
{
  const fs::path directory = fresh_directory("vtu_unwritable");
  std::ofstream(directory / "plain_file") << "x";
  EXPECT_THROW(write_vtu(directory / "plain_file" / "out.vtu", small_box(), nullptr, {}, {}), Error);
}

TEST(Pvd, ListsExactlyTheStepsAddedAndLeavesNoTemporary)
{
  const fs::path directory = fresh_directory("pvd");
  const mesh::Mesh mesh = small_box();
  PvdWriter series(directory / "series.pvd");
  EXPECT_EQ(count(read_vtu_file(directory / "series.pvd"), "<DataSet "), 0);
  const std::vector<double> times = {0.1, 0.5, 1.0};
  for (std::size_t step = 0; step < times.size(); ++step)
  {
    const std::string name = "step_" + std::to_string(step) + ".vtu";
    write_vtu(directory / name, mesh, nullptr, {}, {});
    series.add(times[step], name);
    const std::string pvd = read_vtu_file(directory / "series.pvd");
    EXPECT_EQ(count(pvd, "<DataSet "), static_cast<int>(step) + 1);
    EXPECT_NE(pvd.find("file=\"" + name + "\""), std::string::npos);
  }
  EXPECT_EQ(series.n_steps(), 3);
  // 17 significant digits: the times read back exactly.
  EXPECT_NE(read_vtu_file(directory / "series.pvd").find("timestep=\"0.10000000000000001\""), std::string::npos);

  std::vector<std::string> names;
  for (const auto& entry : fs::directory_iterator(directory))
    names.push_back(entry.path().filename().string());
  std::sort(names.begin(), names.end());
  EXPECT_EQ(names, (std::vector<std::string>{"series.pvd", "step_0.vtu", "step_1.vtu", "step_2.vtu"}));
  EXPECT_THROW(series.add(std::nan(""), "step_3.vtu"), Error);
  EXPECT_EQ(series.n_steps(), 3);
}
} // namespace feticon::io
