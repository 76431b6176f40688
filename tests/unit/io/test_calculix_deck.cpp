/// Tests of the CalculiX deck writer. Reference: the model itself (mesh, sets, consistent loads
/// of fem::Problem::external_force) compared with what an independent reading of the deck text
/// finds, CalculiX's C3D8 face numbering written out again here from its manual.

#include "io/calculix_deck.hpp"

#include "common/error.hpp"
#include "mesh/box.hpp"

#include <gtest/gtest.h>

#include <algorithm>
#include <map>
#include <set>
#include <sstream>

namespace feticon::io
{
namespace
{
/// Base 1 x 0.5 below y = 0 and a punch 0.5 x 0.5 on it, one cell layer, plane strain.
fem::Problem punch_problem(bool punch_supported_in_y)
{
  mesh::BoxParameters base;
  base.origin = {0, -0.5, 0};
  base.lengths = {1, 0.5, 0.1};
  base.nx = 4;
  base.ny = 2;
  base.body_name = "base";
  mesh::BoxParameters punch;
  punch.origin = {0, 0, 0};
  punch.lengths = {0.5, 0.5, 0.1};
  punch.nx = 3;
  punch.ny = 3;
  punch.body_name = "punch";
  fem::Problem p;
  p.name = "punch";
  mesh::append_mesh(p.mesh, mesh::generate_box(base), "base_");
  mesh::append_mesh(p.mesh, mesh::generate_box(punch), "punch_");
  p.materials = {{2e11, 0.3}, {1e11, 0.25}};
  p.eliminated = {false, false, true};
  p.steps.front().dirichlet = {{"base_ymin", {0.0, 0.0, std::nullopt}},
                               {"punch_xmin", {0.0, std::nullopt, std::nullopt}}};
  if (punch_supported_in_y)
    p.steps.front().dirichlet.push_back({"punch_ymax", {std::nullopt, -1e-4, std::nullopt}});
  else
    p.steps.front().tractions = {{"punch_ymax", Eigen::Vector3d(0, -1e8, 0)}};
  p.contacts = {{"punch_ymin", "base_ymax"}};
  p.validate();
  return p;
}

/// The deck split into keyword blocks: keyword line -> data lines (comments dropped).
std::vector<std::pair<std::string, std::vector<std::vector<std::string>>>> blocks(const std::string& deck)
{
  std::vector<std::pair<std::string, std::vector<std::vector<std::string>>>> out;
  std::istringstream in(deck);
  std::string line;
  while (std::getline(in, line))
  {
    if (line.rfind("**", 0) == 0)
      continue;
    if (line.rfind("*", 0) == 0)
    {
      out.push_back({line, {}});
      continue;
    }
    std::vector<std::string> fields;
    std::istringstream fs(line);
    std::string field;
    while (std::getline(fs, field, ','))
    {
      field.erase(0, field.find_first_not_of(' '));
      if (!field.empty())
        fields.push_back(field);
    }
    EXPECT_FALSE(out.empty()) << "data before the first keyword: " << line;
    if (!out.empty())
      out.back().second.push_back(fields);
  }
  return out;
}

TEST(CalculixDeck, HoldsTheModel)
{
  const fem::Problem problem = punch_problem(false);
  std::ostringstream text;
  CalculixOptions options;
  options.nlgeom = true;
  options.increments = 3;
  const CalculixDeckSummary summary = write_calculix_deck(problem, options, text);
  const auto deck = blocks(text.str());

  // CalculiX C3D8 faces S1..S6 (manual, section on C3D8), 1-based node positions.
  const int faces[6][4] = {{1, 2, 3, 4}, {5, 8, 7, 6}, {1, 5, 6, 2}, {2, 6, 7, 3}, {3, 7, 8, 4}, {4, 8, 5, 1}};
  std::map<int, Eigen::Vector3d> nodes;
  std::map<int, std::vector<int>> elements;
  std::map<std::string, std::set<std::set<int>>> surfaces; // surface -> faces as node sets (0-based)
  Eigen::Vector3d load = Eigen::Vector3d::Zero();
  int n_materials = 0;
  bool nlgeom = false, plane_strain = false;
  std::string increment;
  for (const auto& [keyword, lines] : deck)
  {
    for (const auto& fields : lines)
      for (const auto& field : fields)
        EXPECT_LE(field.size(), 20u) << "CalculiX reads at most 20 characters per field: " << field;
    if (keyword.rfind("*NODE,", 0) == 0)
      for (const auto& f : lines)
        nodes[std::stoi(f[0])] = {std::stod(f[1]), std::stod(f[2]), std::stod(f[3])};
    else if (keyword.rfind("*ELEMENT", 0) == 0)
    {
      EXPECT_NE(keyword.find("TYPE=C3D8"), std::string::npos);
      for (const auto& f : lines)
        for (size_t k = 1; k < f.size(); ++k)
          elements[std::stoi(f[0])].push_back(std::stoi(f[k]));
    }
    else if (keyword.rfind("*SURFACE,", 0) == 0)
    {
      const std::string name =
          keyword.substr(keyword.find("NAME=") + 5, keyword.find(", TYPE") - keyword.find("NAME=") - 5);
      for (const auto& f : lines)
      {
        const auto& cell = elements.at(std::stoi(f[0]));
        std::set<int> face;
        for (int k : faces[std::stoi(f[1].substr(1)) - 1])
          face.insert(cell[k - 1] - 1);
        surfaces[name].insert(face);
      }
    }
    else if (keyword == "*CLOAD")
      for (const auto& f : lines)
        load(std::stoi(f[1]) - 1) += std::stod(f[2]);
    else if (keyword == "*ELASTIC")
      ++n_materials;
    else if (keyword.rfind("*STEP", 0) == 0)
      nlgeom = keyword.find("NLGEOM") != std::string::npos;
    else if (keyword == "*STATIC")
      increment = lines.at(0).at(0);
    else if (keyword == "*BOUNDARY")
      for (const auto& f : lines)
        plane_strain |= f[0] == "NALL" && f[1] == "3" && f[2] == "3";
  }

  ASSERT_EQ(static_cast<int32_t>(nodes.size()), problem.mesh.n_nodes());
  ASSERT_EQ(static_cast<int32_t>(elements.size()), problem.mesh.n_cells());
  for (int32_t c = 0; c < problem.mesh.n_cells(); ++c)
    for (int k = 0; k < 8; ++k)
      EXPECT_EQ(elements.at(c + 1)[k], problem.mesh.cells[c][k] + 1);
  EXPECT_EQ(n_materials, 2);
  EXPECT_TRUE(nlgeom);
  EXPECT_TRUE(plane_strain);
  EXPECT_NEAR(std::stod(increment), 1.0 / 3, 1e-12);

  // The consistent nodal loads: total = traction x area = -1e8 Pa x 0.5 m x 0.1 m.
  const la::Vector f = problem.external_force();
  for (int i = 0; i < 3; ++i)
    EXPECT_NEAR(load(i), f(Eigen::seq(i, Eigen::last, 3)).sum(), 1e-6);
  EXPECT_NEAR(load(1), -1e8 * 0.5 * 0.1, 1e-3);
  EXPECT_EQ(summary.n_cloads, (f.array() != 0).count());

  // Surfaces: the same faces as the model's face sets.
  for (const auto& [set, name] : {std::pair{"punch_ymin", "S_punch_ymin"}, std::pair{"base_ymax", "S_base_ymax"}})
  {
    std::set<std::set<int>> expected;
    for (const auto& face : problem.mesh.face_set(set))
      expected.insert(std::set<int>(face.begin(), face.end()));
    EXPECT_EQ(surfaces.at(name), expected) << set;
  }
  EXPECT_EQ(summary.n_slave_faces, 3);
  EXPECT_EQ(summary.n_master_faces, 4);

  // The punch is held in y only by contact: shifted by 2 % of its shortest contact edge
  // (0.1 m, the layer thickness, against 1/6 m along x) into the base; the base unmoved.
  EXPECT_NEAR(summary.overclosure, 0.02 * 0.1, 1e-15);
  for (int32_t n = 0; n < problem.mesh.n_nodes(); ++n)
  {
    const bool punch = n >= problem.mesh.n_nodes() - 4 * 4 * 2;
    const Eigen::Vector3d expected =
        problem.mesh.nodes.row(n).transpose() - (punch ? summary.overclosure : 0.0) * Eigen::Vector3d::UnitY();
    EXPECT_NEAR((nodes.at(n + 1) - expected).norm(), 0, 1e-13) << "node " << n;
  }
  // K = 5 E / h with the larger E (2e11) and h = 0.1 m.
  EXPECT_NEAR(summary.contact_stiffness, 5 * 2e11 / 0.1, 1e-3 * 5 * 2e11 / 0.1);
}

TEST(CalculixDeck, SupportedSlaveIsNotShiftedAndSmallDisplacementsHaveNoNlgeom)
{
  std::ostringstream text;
  CalculixOptions options;
  options.nlgeom = false;
  const CalculixDeckSummary summary = write_calculix_deck(punch_problem(true), options, text);
  EXPECT_EQ(summary.overclosure, 0.0);
  EXPECT_EQ(text.str().find("NLGEOM"), std::string::npos);
  EXPECT_NE(text.str().find("N_punch_ymax, 2, 2, -1.000000000000e-04"), std::string::npos);
}

// Coulomb friction: *FRICTION in the interaction's block, mu and the stick slope K / 50.
TEST(CalculixDeck, CoulombFrictionGoesUnderTheInteraction)
{
  std::ostringstream plain;
  write_calculix_deck(punch_problem(false), CalculixOptions{}, plain);
  EXPECT_EQ(plain.str().find("*FRICTION"), std::string::npos);

  CalculixOptions options;
  options.friction = {{0.3}};
  std::ostringstream text;
  const CalculixDeckSummary summary = write_calculix_deck(punch_problem(false), options, text);
  const auto deck = blocks(text.str());
  std::vector<std::string> order;
  std::vector<std::string> friction;
  for (const auto& [keyword, lines] : deck)
  {
    order.push_back(keyword.substr(0, keyword.find(',')));
    if (keyword == "*FRICTION")
    {
      ASSERT_EQ(lines.size(), 1u);
      friction = lines[0];
    }
  }
  const auto at = std::find(order.begin(), order.end(), "*FRICTION");
  ASSERT_NE(at, order.end());
  EXPECT_EQ(*(at - 2), "*SURFACE INTERACTION");
  EXPECT_EQ(*(at - 1), "*SURFACE BEHAVIOR");
  ASSERT_EQ(friction.size(), 2u);
  EXPECT_EQ(std::stod(friction[0]), 0.3);
  // K = 5 E / h = 1e13 Pa/m (E = 2e11, h = 0.1 m): lambda = 2e11 Pa/m.
  EXPECT_NEAR(std::stod(friction[1]), 5 * 2e11 / 0.1 / 50, 1e-12 * 2e11);
  EXPECT_NEAR(summary.stick_slope, std::stod(friction[1]), 1e-12 * 2e11);

  options.friction = {{-0.1}};
  EXPECT_THROW(write_calculix_deck(punch_problem(false), options, text), Error);
}

// A contact surface may span bodies (CalculiX's bolt: a plate of two sections); a pair whose two
// surfaces lie on one body is refused.
TEST(CalculixDeck, ContactSurfacesMaySpanBodiesButAPairNotLieOnOne)
{
  fem::Problem problem = punch_problem(false);
  auto& slave = problem.mesh.face_sets["punch_ymin"];
  slave.push_back(problem.mesh.face_set("base_ymin").front());
  std::ostringstream text;
  write_calculix_deck(problem, CalculixOptions{}, text);
  const auto deck = blocks(text.str());
  const auto surface =
      std::ranges::find_if(deck, [](const auto& b) { return b.first.starts_with("*SURFACE, NAME=S_punch_ymin"); });
  ASSERT_NE(surface, deck.end());
  EXPECT_EQ(surface->second.size(), problem.mesh.face_set("punch_ymin").size());

  fem::Problem one_body = punch_problem(false);
  one_body.contacts.front().master = "punch_ymax";
  try
  {
    write_calculix_deck(one_body, CalculixOptions{}, text);
    FAIL() << "expected an error";
  }
  catch (const Error& e)
  {
    EXPECT_NE(std::string(e.what()).find("lies on one body"), std::string::npos) << e.what();
  }
}
} // namespace
} // namespace feticon::io
