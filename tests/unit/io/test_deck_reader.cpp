/// Tests of the input deck reader. References: (1) the deck writer's model (io/calculix_deck,
/// tested on its own against the text) read back, compared entity by entity with the
/// fem::Problem it was written from; (2) hand-written decks whose content is stated in the
/// test (CalculiX manual, "Input deck format": keyword syntax, C3D8 faces S1-S6, OP=NEW/MOD);
/// (3) malformed decks, each a one-line error naming file and line.

#include "io/calculix_deck.hpp"
#include "io/deck_data.hpp"
#include "io/deck.hpp"
#include "io/problem_file.hpp"
#include "fem/assembler.hpp"
#include "fem/cell_element.hpp"

#include "common/error.hpp"
#include "io_test_files.hpp"
#include "mesh/box.hpp"
#include "mesh/cell_conversion.hpp"

#include <gtest/gtest.h>

#include <algorithm>
#include <fstream>
#include <set>
#include <sstream>

namespace feticon::io
{
namespace
{
std::filesystem::path write(const std::filesystem::path& dir, const std::string& name, const std::string& text)
{
  std::ofstream(dir / name) << text;
  return dir / name;
}

/// Base 1 x 0.5 x 0.4 and a punch 0.5 x 0.5 x 0.4 on it, supports and a traction.
fem::Problem punch_problem()
{
  fem::Problem p;
  p.name = "punch";
  mesh::append_mesh(
      p.mesh,
      mesh::generate_box(
          {.origin = {0, -0.5, 0}, .lengths = {1, 0.5, 0.4}, .nx = 4, .ny = 2, .nz = 2, .body_name = "base"}),
      "base_");
  mesh::append_mesh(
      p.mesh,
      mesh::generate_box(
          {.origin = {0, 0, 0}, .lengths = {0.5, 0.5, 0.4}, .nx = 3, .ny = 3, .nz = 2, .body_name = "punch"}),
      "punch_");
  p.materials = {{2e11, 0.3}, {1e11, 0.25}};
  p.steps.front().dirichlet = {{"base_ymin", {0.0, 0.0, 0.0}},
                               {"punch_xmin", {0.0, std::nullopt, std::nullopt}},
                               {"punch_ymax", {std::nullopt, -1e-4, std::nullopt}}};
  p.steps.front().tractions = {{"punch_ymax", {0.0, -1e7, 0.0}}};
  p.contacts = {{"punch_ymin", "base_ymax"}};
  return p;
}

/// The cells as node lists, for comparing meshes whose cells come in another order.
std::set<std::vector<int32_t>> cell_set(const mesh::CellList& cells)
{
  std::set<std::vector<int32_t>> out;
  for (const auto cell : cells)
    out.emplace(cell.begin(), cell.end());
  return out;
}

std::set<std::vector<int32_t>> face_keys(const std::vector<mesh::Face>& faces, bool sorted)
{
  std::set<std::vector<int32_t>> out;
  for (const mesh::Face& f : faces)
  {
    std::vector<int32_t> key(f.begin(), f.end());
    if (sorted)
      std::sort(key.begin(), key.end());
    else // the same cyclic order from its smallest node
      std::rotate(key.begin(), std::min_element(key.begin(), key.end()), key.end());
    out.insert(key);
  }
  return out;
}

/// The message of the feticon::Error `read_deck(path)` throws, "" if none.
std::string error_of(const std::filesystem::path& path)
{
  try
  {
    read_deck(path);
  }
  catch (const Error& e)
  {
    return e.what();
  }
  return "";
}

const char* two_cubes = R"(*HEADING
two unit cubes, the upper one pressed on the lower
** a comment line
*Node, nset=all
1, 0, 0, 0
2, 1, 0, 0
3, 1, 1, 0
4, 0, 1, 0
5, 0, 0, 1
6, 1, 0, 1
7, 1, 1, 1
8, 0, 1, 1
11, 0, 0, 1
12, 1, 0, 1
13, 1, 1, 1
14, 0, 1, 1
15, 0, 0, 2
16, 1, 0, 2
17, 1, 1, 2
18, 0, 1, 2
*ELEMENT, TYPE=C3D8, ELSET=lower
1, 1, 2, 3, 4,
   5, 6, 7, 8
*element, type=c3d8, elset=UPPER
2, 11, 12, 13, 14, 15, 16, 17, 18
*NSET, NSET=bottom, GENERATE
1, 4, 1
*NSET, NSET=top
15, 16
17, 18
*NSET, NSET=both
bottom, top
*ELSET, ELSET=EALL
lower, 2
*MATERIAL, NAME=steel
*ELASTIC
2.1e11, 0.3
*SOLID SECTION, ELSET=EALL, MATERIAL=STEEL
*SURFACE, NAME=upper_bottom, TYPE=ELEMENT
2, S1
*SURFACE, NAME=lower_top
lower, s2
*SURFACE INTERACTION, NAME=si
*SURFACE BEHAVIOR, PRESSURE-OVERCLOSURE=HARD
*CONTACT PAIR, INTERACTION=SI, TYPE=SURFACE TO SURFACE
upper_bottom, lower_top
*BOUNDARY
bottom, 1, 3
*EQUATION
2
11, 1, 1.0, 12, 1, -1.0
*STEP, NLGEOM
*STATIC
0.25, 1.0
*BOUNDARY
top, 1, 2
*DLOAD
2, P2, 1e6
*CLOAD
17, 3, -10.0
*NODE PRINT, NSET=top, TOTALS=YES
U, RF
*END STEP
*STEP
*STATIC
*CLOAD, OP=NEW
18, 3, -20.0
*DLOAD
2, P2, 2e6
*BOUNDARY
top, 1, 2, 1e-3
*END STEP
)";

/// Replaces the first `from` in `text` by `to`; a `from` that is not there fails the test.
void replace_first(std::string& text, const std::string& from, const std::string& to)
{
  const size_t at = text.find(from);
  ASSERT_NE(at, std::string::npos) << from;
  text.replace(at, from.size(), to);
}

// Every cell type through the CalculiX export and back (C3D4, C3D10, C3D20, C3D6 blocks; faces
// by S-number; 20-node elements on two lines): the same cells with the same node order, the
// same loads, and contact faces with the same outward node order. Reference: the problem that
// was written.
class DeckCellTypes : public ::testing::TestWithParam<mesh::CellKind>
{
};

TEST_P(DeckCellTypes, ExportedDeckReadsBackWithItsCellTypes)
{
  fem::Problem p = punch_problem();
  p.mesh = mesh::convert_hex8_mesh(p.mesh, GetParam());
  p.validate();
  CalculixOptions options;
  options.overclosure = 0;
  const auto dir = test::fresh_directory("deck_round_trip_" + std::string(mesh::cell_type(GetParam()).name));
  std::ostringstream text;
  write_calculix_deck(p, options, text);
  const auto path = write(dir, "punch.inp", text.str());
  const Deck deck = read_deck(path);
  const fem::Problem& q = deck.problem;
  // Its surface-to-surface pair gets mortar rows, whatever the faces' type.
  ASSERT_EQ(q.contacts.size(), 1u);
  EXPECT_EQ(q.contacts[0].interaction.formulation, fem::ContactFormulation::mortar);
  ASSERT_EQ(q.mesh.n_nodes(), p.mesh.n_nodes());
  ASSERT_EQ(q.mesh.n_cells(), p.mesh.n_cells());
  EXPECT_TRUE(q.mesh.cells.all_of_kind(GetParam()));
  EXPECT_LE((q.mesh.nodes - p.mesh.nodes).cwiseAbs().maxCoeff(), 1e-12);
  EXPECT_EQ(cell_set(p.mesh.cells), cell_set(q.mesh.cells));
  EXPECT_LE((q.external_force() - p.external_force()).cwiseAbs().maxCoeff(),
            1e-12 * p.external_force().cwiseAbs().maxCoeff());
  ASSERT_EQ(q.contacts.size(), 1u);
  EXPECT_EQ(face_keys(q.mesh.face_set(q.contacts[0].slave), false), face_keys(p.mesh.face_set("punch_ymin"), false));
  EXPECT_EQ(face_keys(q.mesh.face_set(q.contacts[0].master), false), face_keys(p.mesh.face_set("base_ymax"), false));
}

INSTANTIATE_TEST_SUITE_P(EveryType, DeckCellTypes,
                         ::testing::Values(mesh::CellKind::tet4, mesh::CellKind::tet10, mesh::CellKind::hex20,
                                           mesh::CellKind::wedge6),
                         [](const ::testing::TestParamInfo<mesh::CellKind>& info) {
  return std::string(mesh::cell_type(info.param).name);
});

// C3D20R (20-node hexahedra with 2x2x2 Gauss points, as CalculiX integrates them) beside
// C3D20 in one deck: the export writes each block with its name, the reader keeps the flag per
// cell, and the assembler integrates those cells with the reduced rule. Reference: the cells'
// own stiffness from fem::cell_element with Integration::reduced and ::full.
TEST(DeckReader, C3D20RCellsKeepTheirReducedIntegration)
{
  fem::Problem p = punch_problem();
  p.mesh = mesh::convert_hex8_mesh(p.mesh, mesh::CellKind::hex20);
  p.mesh.reduced_integration.assign(p.mesh.n_cells(), 0);
  for (int32_t c = 0; c < p.mesh.n_cells(); ++c)
    p.mesh.reduced_integration[c] = p.mesh.body_names[p.mesh.cell_body[c]] == "punch" ? 1 : 0;
  p.validate();
  CalculixOptions options;
  options.overclosure = 0;
  std::ostringstream text;
  write_calculix_deck(p, options, text);
  EXPECT_NE(text.str().find("*ELEMENT, TYPE=C3D20R, ELSET=B_punch"), std::string::npos);
  EXPECT_NE(text.str().find("*ELEMENT, TYPE=C3D20, ELSET=B_base"), std::string::npos);
  const Deck deck = read_deck(write(test::fresh_directory("deck_c3d20r"), "punch.inp", text.str()));
  const mesh::Mesh& m = deck.problem.mesh;
  ASSERT_EQ(m.n_cells(), p.mesh.n_cells());
  for (const std::string& w : deck.info.warnings)
    EXPECT_EQ(w.find("C3D20R"), std::string::npos) << w;
  int reduced = 0;
  for (int32_t c = 0; c < m.n_cells(); ++c)
  {
    EXPECT_EQ(m.reduced(c), m.body_names[m.cell_body[c]] == "B_PUNCH") << "cell " << c;
    reduced += m.reduced(c) ? 1 : 0;
  }
  EXPECT_GT(reduced, 0);

  // One cell of each kind, assembled, against its element stiffness.
  const fem::Material material = deck.problem.materials[0];
  for (const bool want_reduced : {false, true})
  {
    int32_t c = 0;
    while (m.reduced(c) != want_reduced)
      ++c;
    // The cell alone, its nodes numbered 0..19 in its own order.
    Eigen::MatrixX3d X(20, 3);
    for (int a = 0; a < 20; ++a)
      X.row(a) = m.nodes.row(m.cells[c][a]);
    mesh::Mesh one;
    one.nodes = X;
    const std::vector<int32_t> local = {0, 1, 2, 3, 4, 5, 6, 7, 8, 9, 10, 11, 12, 13, 14, 15, 16, 17, 18, 19};
    one.cells.add(mesh::CellKind::hex20, local);
    one.cell_body = {0};
    one.body_names = {"one"};
    one.reduced_integration = {static_cast<char>(want_reduced ? 1 : 0)};
    const fem::Assembler assembler(one, fem::whole_mesh_domain(one), {material}, fem::Kinematics::linear);
    const Eigen::MatrixXd K_assembled(assembler.stiffness(la::Vector::Zero(60), fem::StiffnessKind::material));
    Eigen::VectorXd f;
    Eigen::MatrixXd K_reduced, K_full;
    fem::cell_element(mesh::CellKind::hex20, X, Eigen::MatrixX3d::Zero(20, 3), material, fem::Kinematics::linear,
                      fem::StiffnessKind::material, fem::Integration::reduced, f, &K_reduced, c);
    fem::cell_element(mesh::CellKind::hex20, X, Eigen::MatrixX3d::Zero(20, 3), material, fem::Kinematics::linear,
                      fem::StiffnessKind::material, fem::Integration::full, f, &K_full, c);
    const Eigen::MatrixXd& expected = want_reduced ? K_reduced : K_full;
    const double difference = (K_assembled - expected).cwiseAbs().maxCoeff();
    EXPECT_LE(difference, 1e-12 * expected.cwiseAbs().maxCoeff()) << (want_reduced ? "reduced" : "full");
    EXPECT_GT((K_reduced - K_full).cwiseAbs().maxCoeff(), 1e-3 * K_full.cwiseAbs().maxCoeff());
  }
}

TEST(DeckReader, ExportedDeckReadsBackAsTheProblem)
{
  const fem::Problem p = punch_problem();
  CalculixOptions options;
  options.overclosure = 0; // the model as it is
  const auto dir = test::fresh_directory("deck_round_trip");
  std::ostringstream text;
  write_calculix_deck(p, options, text);
  const Deck deck = read_deck(write(dir, "punch.inp", text.str()));
  const fem::Problem& q = deck.problem;

  ASSERT_EQ(q.mesh.n_nodes(), p.mesh.n_nodes());
  ASSERT_EQ(q.mesh.n_cells(), p.mesh.n_cells());
  // The writer numbers nodes n + 1 and cells by body; the reader keeps reading order.
  EXPECT_LE((q.mesh.nodes - p.mesh.nodes).cwiseAbs().maxCoeff(), 1e-12);
  const std::set<std::vector<int32_t>> cells_p = cell_set(p.mesh.cells), cells_q = cell_set(q.mesh.cells);
  EXPECT_EQ(cells_p, cells_q);
  ASSERT_EQ(q.mesh.n_bodies(), 2);
  EXPECT_EQ(q.mesh.body_names[0], "B_BASE");
  EXPECT_EQ(q.mesh.body_names[1], "B_PUNCH");
  EXPECT_EQ(q.materials[1].young, 1e11);
  EXPECT_EQ(q.materials[1].poisson, 0.25);
  // Loads: the writer's *CLOAD are the consistent forces of the traction.
  EXPECT_LE((q.external_force() - p.external_force()).cwiseAbs().maxCoeff(),
            1e-12 * p.external_force().cwiseAbs().maxCoeff());
  const fem::ConstrainedDofs cp = p.all_constrained_dofs(), cq = q.all_constrained_dofs();
  EXPECT_EQ(cp.dofs, cq.dofs);
  EXPECT_LE((cp.values - cq.values).cwiseAbs().maxCoeff(), 1e-16);
  // Contact faces: the same faces with the same outward cyclic order.
  ASSERT_EQ(q.contacts.size(), 1u);
  EXPECT_EQ(face_keys(q.mesh.face_set(q.contacts[0].slave), false), face_keys(p.mesh.face_set("punch_ymin"), false));
  EXPECT_EQ(face_keys(q.mesh.face_set(q.contacts[0].master), false), face_keys(p.mesh.face_set("base_ymax"), false));
  EXPECT_TRUE(q.contacts[0].slave_nodes.empty());
  // The writer's penalty interaction is reported, not dropped.
  ASSERT_FALSE(deck.info.warnings.empty());
  EXPECT_TRUE(std::any_of(deck.info.warnings.begin(), deck.info.warnings.end(), [](const std::string& w) {
    return w.find("PRESSURE-OVERCLOSURE=LINEAR") != std::string::npos;
  }));
  EXPECT_EQ(deck.info.node_labels.front(), 1);
  EXPECT_EQ(deck.info.node_labels.back(), p.mesh.n_nodes());
}

// Round trip of the friction: the exported *FRICTION reads back as mu of the pair's
// interaction; the settings of a run of it do not take it (they override the pair's law only
// where given).
TEST(DeckReader, ExportedFrictionReadsBackAsCoulombsMu)
{
  CalculixOptions options;
  options.overclosure = 0;
  options.friction = {{0.35}};
  const auto dir = test::fresh_directory("deck_friction_round_trip");
  std::ostringstream text;
  write_calculix_deck(punch_problem(), options, text);
  const auto path = write(dir, "punch.inp", text.str());
  const fem::ContactInteraction read = read_deck(path).problem.contacts.at(0).interaction;
  EXPECT_EQ(read.friction.model, fem::FrictionModel::coulomb);
  EXPECT_EQ(read.friction.coefficient, 0.35);
  EXPECT_EQ(read.formulation, fem::ContactFormulation::mortar);
  EXPECT_FALSE(load_problem_file(path, {}, {}).settings.given("contact.friction.model"));
  // The same with tet10: mortar rows with friction on quadratic faces too.
  fem::Problem tet10 = punch_problem();
  tet10.mesh = mesh::convert_hex8_mesh(tet10.mesh, mesh::CellKind::tet10);
  tet10.validate();
  std::ostringstream tet10_text;
  write_calculix_deck(tet10, options, tet10_text);
  const auto tet10_path = write(dir, "punch_tet10.inp", tet10_text.str());
  EXPECT_EQ(read_deck(tet10_path).problem.contacts.at(0).interaction.formulation, fem::ContactFormulation::mortar);
}

TEST(DeckReader, PlaneStrainDeckEliminatesUz)
{
  fem::Problem p = punch_problem();
  p.eliminated = {false, false, true};
  p.steps.front().dirichlet = {{"base_ymin", {0.0, 0.0, std::nullopt}},
                               {"punch_xmin", {0.0, std::nullopt, std::nullopt}}};
  CalculixOptions options;
  options.overclosure = 0;
  const auto dir = test::fresh_directory("deck_plane_strain");
  std::ostringstream text;
  write_calculix_deck(p, options, text);
  const Deck deck = read_deck(write(dir, "punch.inp", text.str()));
  EXPECT_TRUE(deck.problem.eliminated[2]); // *BOUNDARY NALL, 3, 3 is plane strain, not a support
  EXPECT_EQ(deck.problem.all_constrained_dofs().dofs, p.all_constrained_dofs().dofs);
}

TEST(DeckReader, KeywordsSetsSurfacesAndSteps)
{
  const auto dir = test::fresh_directory("deck_keywords");
  const Deck deck = read_deck(write(dir, "two_cubes.inp", two_cubes));
  const fem::Problem& p = deck.problem;
  EXPECT_EQ(p.mesh.n_nodes(), 16);
  EXPECT_EQ(p.mesh.n_cells(), 2);
  ASSERT_EQ(p.mesh.n_bodies(), 2); // no shared node: two components
  EXPECT_EQ(p.mesh.body_names[0], "EALL_1");
  EXPECT_EQ(p.mesh.body_names[1], "EALL_2");
  EXPECT_EQ(deck.info.node_labels[8], 11);
  EXPECT_EQ(p.mesh.node_set("BOTH"), (std::vector<int32_t>{0, 1, 2, 3, 12, 13, 14, 15}));
  EXPECT_EQ(deck.info.element_sets.at("EALL"), (std::vector<int32_t>{0, 1}));
  // S1 of the upper cube is its bottom (z = 1), S2 of the lower its top: outward normals.
  const auto normal = [&](const mesh::Face& f) {
    const Eigen::Vector3d x0 = p.mesh.nodes.row(f[0]), x1 = p.mesh.nodes.row(f[1]), x3 = p.mesh.nodes.row(f[3]);
    return Eigen::Vector3d((x1 - x0).cross(x3 - x0).normalized());
  };
  EXPECT_LE((normal(p.mesh.face_set("UPPER_BOTTOM")[0]) - Eigen::Vector3d(0, 0, -1)).norm(), 1e-14);
  EXPECT_LE((normal(p.mesh.face_set("LOWER_TOP")[0]) - Eigen::Vector3d(0, 0, 1)).norm(), 1e-14);
  ASSERT_EQ(p.contacts.size(), 1u);
  EXPECT_EQ(p.contacts[0].slave, "UPPER_BOTTOM");
  ASSERT_EQ(p.equations.size(), 1u);
  EXPECT_EQ(p.equations[0].terms[1].node, 9);
  EXPECT_EQ(p.equations[0].terms[1].coefficient, -1.0);

  ASSERT_EQ(deck.info.steps.size(), 2u);
  EXPECT_TRUE(deck.info.steps[0].nlgeom);
  EXPECT_TRUE(deck.info.steps[1].nlgeom); // NLGEOM stays on
  // *STATIC 0.25, 1.0 without DIRECT: automatic, CalculiX's default minimum and maximum.
  EXPECT_FALSE(deck.info.steps[0].increments);
  ASSERT_TRUE(deck.info.steps[0].automatic);
  EXPECT_EQ(deck.info.steps[0].automatic->initial, 0.25);
  EXPECT_EQ(deck.info.steps[0].automatic->minimum, 1e-5);
  EXPECT_EQ(deck.info.steps[0].automatic->maximum, 1.0);
  EXPECT_EQ(p.steps[0].automatic->initial, 0.25);
  ASSERT_EQ(deck.info.steps[0].outputs.size(), 1u);
  EXPECT_EQ(deck.info.steps[0].outputs[0].set, "TOP");
  EXPECT_EQ(deck.info.steps[0].outputs[0].variables, (std::vector<std::string>{"U", "RF"}));
  // Step 1: bottom fixed, top held in x and y; the pressure on the upper cube's top face.
  const fem::ConstrainedDofs c = p.all_constrained_dofs();
  EXPECT_EQ(c.dofs.size(), 4u * 3 + 4 * 2);
  EXPECT_EQ(c.values.cwiseAbs().maxCoeff(), 0.0);
  const la::Vector f = p.external_force();
  EXPECT_NEAR(f(3 * 14 + 2), -10.0 - 0.25e6, 1e-6); // node 17: its force and a quarter of the pressure
  EXPECT_NEAR(f.sum(), -10.0 - 1e6, 1e-6);
  // Step 2: OP=NEW replaced the force, the pressure doubled, the top moved 1 mm.
  ASSERT_EQ(p.steps.size(), 2u);
  const fem::Step& s = p.steps[1];
  ASSERT_EQ(s.nodal_forces.size(), 1u);
  EXPECT_EQ(s.nodal_forces[0].node, 15);
  EXPECT_EQ(s.nodal_forces[0].value, -20.0);
  ASSERT_EQ(s.pressures.size(), 1u);
  EXPECT_EQ(s.pressures[0].pressure, 2e6);
  int moved = 0;
  for (const fem::DirichletCondition& d : s.dirichlet)
    moved += d.value[0] && *d.value[0] == 1e-3 ? static_cast<int>(p.mesh.node_set(d.set).size()) : 0;
  EXPECT_EQ(moved, 4);
}

// Amplitudes (issue 65, item 2): the *AMPLITUDE table with its parameters, AMPLITUDE= on the
// loads and supports of a step, and *STEP, AMPLITUDE=STEP. Reference: the deck's own numbers.
TEST(DeckReader, AmplitudesOnLoadsAndSteps)
{
  const auto dir = test::fresh_directory("deck_amplitudes");
  std::string text = two_cubes;
  const auto replace = [&](const std::string& from, const std::string& to) { replace_first(text, from, to); };
  replace("*STEP, NLGEOM",
          "*AMPLITUDE, NAME=updown, TIME=TOTAL TIME, SHIFTX=0.5\n0, 0, 0.5, 1,\n1, 0.4\n"
          "*STEP, NLGEOM");
  replace("*DLOAD\n2, P2, 1e6", "*DLOAD, AMPLITUDE=updown\n2, P2, 1e6");
  replace("*DLOAD\n2, P2, 2e6", "*DLOAD, AMPLITUDE=UPDOWN\n2, P2, 2e6");
  replace("*STEP\n*STATIC\n*CLOAD", "*STEP, AMPLITUDE=STEP\n*STATIC\n*CLOAD");
  replace("top, 1, 2, 1e-3", "*BOUNDARY, AMPLITUDE=UPDOWN\ntop, 1, 1, 1e-3");
  const fem::Problem p = read_deck(write(dir, "two_cubes.inp", text)).problem;
  ASSERT_EQ(p.amplitudes.count("UPDOWN"), 1u);
  const fem::Amplitude& a = p.amplitudes.at("UPDOWN");
  EXPECT_EQ(a.points, (std::vector<std::pair<double, double>>{{0, 0}, {0.5, 1}, {1, 0.4}}));
  EXPECT_TRUE(a.total_time);
  EXPECT_EQ(a.shift_x, 0.5);
  ASSERT_EQ(p.steps.size(), 2u);
  EXPECT_TRUE(p.steps[0].ramp);
  EXPECT_FALSE(p.steps[1].ramp);
  for (const fem::Step& step : p.steps)
  {
    ASSERT_EQ(step.pressures.size(), 1u);
    EXPECT_EQ(step.pressures[0].amplitude, "UPDOWN");
    EXPECT_EQ(step.nodal_forces[0].amplitude, "");
  }
  int with_amplitude = 0;
  for (const fem::DirichletCondition& d : p.steps[1].dirichlet)
    if (d.amplitude == "UPDOWN")
      with_amplitude += static_cast<int>(p.mesh.node_set(d.set).size());
  EXPECT_EQ(with_amplitude, 4); // u_x of the four top nodes; their u_y keeps no amplitude
  EXPECT_EQ(p.steps[1].time, 1.0);
}

// *BOUNDARY, OP=NEW in a step removes every support, the model's too (CalculiX's boundarys.f):
// step 2 holds the four top nodes in x and y only, the bottom's model support is gone; a
// parameter *NSET does not have is ignored with a warning (CalculiX's), INSTANCE refused.
// Reference: the deck's own numbers.
TEST(DeckReader, BoundaryOpNewRemovesTheModelsSupports)
{
  const auto dir = test::fresh_directory("deck_op_new");
  std::string text = two_cubes;
  replace_first(text, "*BOUNDARY\ntop, 1, 2, 1e-3", "*BOUNDARY, OP=NEW\ntop, 1, 2, 1e-3");
  replace_first(text, "*NSET, NSET=top", "*NSET, NSET=top, FREQUENCY=100");
  const Deck deck = read_deck(write(dir, "op_new.inp", text));
  const fem::Problem& p = deck.problem;
  ASSERT_EQ(p.steps.size(), 2u);
  EXPECT_EQ(p.all_constrained_dofs(0).dofs.size(), 4u * 3 + 4 * 2); // bottom in x, y, z; top in x, y
  const std::vector<int64_t> held = p.all_constrained_dofs(1).dofs;
  ASSERT_EQ(held.size(), 4u * 2);
  for (const int64_t dof : held)
    EXPECT_GE(p.mesh.nodes(dof / 3, 2), 2.0 - 1e-12) << dof; // the top (z = 2) only
  EXPECT_TRUE(std::any_of(deck.info.warnings.begin(), deck.info.warnings.end(), [](const std::string& w) {
    return w.find("parameter FREQUENCY is not one of *NSET's; ignored") != std::string::npos;
  }));
  replace_first(text, "FREQUENCY=100", "INSTANCE=part-1");
  EXPECT_NE(error_of(write(dir, "instance.inp", text)).find("INSTANCE=PART-1 names no instance placed before it"),
            std::string::npos);
}

// *CHANGE SURFACE BEHAVIOR (issue 65, item 6): a pair whose interaction is TIED in step 1 and
// HARD from step 2 on is a tie and a contact pair, each out of force where the other is in;
// one that stays TIED is a tie alone. Reference: the deck's own steps.
TEST(DeckReader, ChangeSurfaceBehaviorSwitchesATieAndAContactPair)
{
  const auto dir = test::fresh_directory("deck_change_behavior");
  std::string text = two_cubes;
  replace_first(text, "PRESSURE-OVERCLOSURE=HARD", "PRESSURE-OVERCLOSURE=TIED");
  const fem::Problem tied = read_deck(write(dir, "tied.inp", text)).problem;
  EXPECT_EQ(tied.ties.size(), 1u);
  EXPECT_TRUE(tied.contacts.empty());
  replace_first(text, "*STEP\n*STATIC\n",
                "*STEP\n*STATIC\n*CHANGE SURFACE BEHAVIOR, INTERACTION=SI\n"
                "*SURFACE BEHAVIOR, PRESSURE-OVERCLOSURE=HARD\n");
  const fem::Problem p = read_deck(write(dir, "changed.inp", text)).problem;
  ASSERT_EQ(p.ties.size(), 1u);
  ASSERT_EQ(p.contacts.size(), 1u);
  ASSERT_EQ(p.steps.size(), 2u);
  EXPECT_EQ(p.steps[0].removed_contacts, std::vector<int32_t>{0});
  EXPECT_TRUE(p.steps[0].removed_ties.empty());
  EXPECT_TRUE(p.steps[1].removed_contacts.empty());
  EXPECT_EQ(p.steps[1].removed_ties, std::vector<int32_t>{0});
  EXPECT_EQ(p.ties[0].slave, p.contacts[0].slave);
  // *MODEL CHANGE of a pair that is only ever a tie: one line naming the deck line.
  std::string removed = two_cubes;
  replace_first(removed, "PRESSURE-OVERCLOSURE=HARD", "PRESSURE-OVERCLOSURE=TIED");
  replace_first(removed, "*STEP\n*STATIC\n",
                "*STEP\n*STATIC\n*MODEL CHANGE, TYPE=CONTACT PAIR, REMOVE\nupper_bottom, lower_top\n");
  const std::string message = error_of(write(dir, "removed_tie.inp", removed));
  EXPECT_NE(message.find("*MODEL CHANGE of the tied pair UPPER_BOTTOM, LOWER_TOP is not implemented"),
            std::string::npos)
      << message;
  EXPECT_EQ(message.find('\n'), std::string::npos) << message;
}

// Temperatures (issue 65, item 4): *EXPANSION in the material, *INITIAL CONDITIONS,
// TYPE=TEMPERATURE of the model, *TEMPERATURE per step carried over (OP=MOD) and cleared
// (OP=NEW, the nodes it does not name back to T_0); the pair taken out in step 2 (*MODEL
// CHANGE, item 6). Reference: the deck's own numbers.
TEST(DeckReader, TemperaturesAndExpansion)
{
  const auto dir = test::fresh_directory("deck_temperatures");
  std::string text = two_cubes;
  const auto replace = [&](const std::string& from, const std::string& to) { replace_first(text, from, to); };
  replace("*ELASTIC\n", "*EXPANSION, ZERO=20.\n1.2e-5\n*ELASTIC\n");
  replace("*STEP, NLGEOM", "*INITIAL CONDITIONS, TYPE=TEMPERATURE\nall, 20.\n*STEP, NLGEOM");
  replace("*END STEP\n*STEP\n",
          "*TEMPERATURE, AMPLITUDE=ramp2\ntop, 120.\n*END STEP\n*STEP\n"
          "*TEMPERATURE, OP=NEW\n15, 70.\n*MODEL CHANGE, TYPE=CONTACT PAIR, REMOVE\nupper_bottom, lower_top\n");
  replace("*STEP, NLGEOM", "*AMPLITUDE, NAME=ramp2\n0, 0, 1, 2\n*STEP, NLGEOM");
  const fem::Problem p = read_deck(write(dir, "two_cubes.inp", text)).problem;
  for (const fem::Material& m : p.materials)
    EXPECT_EQ(m.expansion, 1.2e-5);
  ASSERT_EQ(p.initial_temperatures.size(), 16u);
  EXPECT_EQ(p.initial_temperatures[0], 20.0);
  ASSERT_EQ(p.steps.size(), 2u);
  ASSERT_EQ(p.steps[0].temperatures.size(), 4u); // the set top
  EXPECT_EQ(p.steps[0].temperatures[0].value, 120.0);
  EXPECT_EQ(p.steps[0].temperatures[0].amplitude, "RAMP2");
  ASSERT_EQ(p.steps[1].temperatures.size(), 1u); // OP=NEW: node 15 alone
  EXPECT_EQ(p.steps[1].temperatures[0].value, 70.0);
  EXPECT_EQ(p.steps[1].temperatures[0].amplitude, "");
  EXPECT_TRUE(p.steps[0].removed_contacts.empty());
  EXPECT_EQ(p.steps[1].removed_contacts, std::vector<int32_t>{0});
}

TEST(DeckReader, IncludeContinuationAndNodeSurface)
{
  const auto dir = test::fresh_directory("deck_include");
  std::string text = two_cubes;
  // The nodes in an included file; the slave surface as the one node 13 (CalculiX's contact1
  // has such a one-node slave surface).
  const size_t begin = text.find("*Node"), end = text.find("*ELEMENT");
  write(dir, "nodes.inc", text.substr(begin, end - begin));
  text = text.substr(0, begin) + "*INCLUDE,\n INPUT=nodes.inc\n" + text.substr(end);
  const std::string from = "*SURFACE, NAME=upper_bottom, TYPE=ELEMENT\n2, S1\n";
  text.replace(text.find(from), from.size(), "*SURFACE, NAME=upper_bottom, TYPE=NODE\n13\n");
  const Deck deck = read_deck(write(dir, "main.inp", text));
  const fem::Problem& p = deck.problem;
  EXPECT_EQ(p.mesh.n_nodes(), 16);
  ASSERT_EQ(p.contacts.size(), 1u);
  EXPECT_EQ(p.mesh.node_set(p.contacts[0].slave_nodes), (std::vector<int32_t>{10}));
  // The faces around the node on the boundary: its tributary area.
  EXPECT_EQ(p.mesh.face_set(p.contacts[0].slave).size(), 3u);
}

TEST(DeckReader, MalformedDecksEndInOneLineNamingFileAndLine)
{
  const auto dir = test::fresh_directory("deck_errors");
  struct Case
  {
    std::string from, to, expected;
  };
  const std::vector<Case> cases = {
      {"*HEADING", "*DYNAMIC", "two_cubes.inp:1: *DYNAMIC is not implemented by feticon"},
      {"*HEADING", "*FOO BAR", "two_cubes.inp:1: *FOO BAR is not a keyword feticon implements"},
      {"2, S1", "2, S7", "two_cubes.inp:40:4: *SURFACE: face 'S7'"},
      {"2, 11, 12, 13, 14, 15, 16, 17, 18", "2, 11, 12, 13, 14, 15, 16, 17, 99",
       "two_cubes.inp:25:32: *ELEMENT: node 99 is not defined"},
      {"2, 11, 12, 13, 14, 15, 16, 17, 18", "2, 11, 12, 13, 14, 15, 16, 17", "has 7 nodes, not 8"},
      {"2, 11, 12, 13, 14, 15, 16, 17, 18", "2, 11, 12, 13, 14, 15, 16, 17, 17",
       "element 2 is degenerate at its node 17"},
      {"TYPE=C3D8, ELSET=lower", "TYPE=C3D15, ELSET=lower",
       "two_cubes.inp:21: *ELEMENT: element type C3D15 is not implemented"},
      {"upper_bottom, lower_top", "lower_top, lower_top", "slave and master are the same surface 'LOWER_TOP'"},
      {"lower, s2", "nothere, s2", "two_cubes.inp:42:1: *SURFACE: no element set 'NOTHERE'"},
      {"15, 0, 0, 2", "15, 0, zero, 2", "two_cubes.inp:17:8: *NODE: 'zero' is not a finite number"},
      {"*SURFACE INTERACTION, NAME=si", "*SURFACE INTERACTION, NAME=si\n*FRICTION\n-0.3",
       "two_cubes.inp:45:1: *FRICTION: friction coefficient -0.3 is outside 0 to 100"},
      {"*SURFACE INTERACTION, NAME=si", "*SURFACE INTERACTION, NAME=si\n*FRICTION",
       "two_cubes.inp:44: *FRICTION needs a data line: friction coefficient mu"},
      {"*SURFACE INTERACTION, NAME=si", "*SURFACE INTERACTION, NAME=si\n*FRICTION, EXPONENTIAL DECAY\n0.3",
       "*FRICTION: EXPONENTIAL DECAY (a coefficient that decays with the slip rate) is not implemented"},
      {"*SURFACE INTERACTION, NAME=si", "*SURFACE INTERACTION, NAME=si\n*FRICTION, ANISOTROPIC\n0.3, 0.2",
       "ANISOTROPIC (anisotropic friction) is not implemented"},
      {"*SURFACE INTERACTION, NAME=si", "*SURFACE INTERACTION, NAME=si\n*FRICTION, ROUGH", "ROUGH (rough friction"},
      {"*SURFACE INTERACTION, NAME=si", "*SURFACE INTERACTION, NAME=si\n*FRICTION, FOO\n0.3",
       "*FRICTION: parameter FOO is not implemented by feticon"},
      {"*SURFACE INTERACTION, NAME=si", "*SURFACE INTERACTION, NAME=si\n*FRICTION\n0.3, 1e9, 0.1",
       "two_cubes.inp:45:11: *FRICTION: a coefficient that depends on slip rate"},
      {"*SURFACE INTERACTION, NAME=si", "*SURFACE INTERACTION, NAME=si\n*FRICTION\n0.3\n0.2, 1.0",
       "two_cubes.inp:46: *FRICTION: takes one data line"},
      {"*SURFACE INTERACTION, NAME=si", "*SURFACE INTERACTION, NAME=si\n*FRICTION\n0.3, -5",
       "the stick slope -5 must be positive"},
      {"*SURFACE INTERACTION, NAME=si", "*SURFACE INTERACTION, NAME=si\n*FRICTION\nmu",
       "'mu' is not a finite number (friction coefficient mu)"},
      {"*SURFACE INTERACTION, NAME=si", "*SURFACE INTERACTION, NAME=si\n*FRICTION\n0.3\n*FRICTION\n0.2",
       "two_cubes.inp:46: *FRICTION: interaction SI has a *FRICTION already (at "},
      {"*SURFACE, NAME=upper_bottom", "*FRICTION\n0.3\n*SURFACE, NAME=upper_bottom",
       "*FRICTION belongs in the block of a *SURFACE INTERACTION"},
      {"upper_bottom, lower_top", "upper_bottom, lower_top\n*FRICTION\n0.3",
       "two_cubes.inp:47: *FRICTION belongs in the block of a *SURFACE INTERACTION"},
      {"*END STEP\n*STEP\n", "*STEP\n", "has no *END STEP before this one"},
      {"*SOLID SECTION, ELSET=EALL, MATERIAL=STEEL", "*SOLID SECTION, ELSET=EALL, MATERIAL=IRON",
       "*SOLID SECTION: no material 'IRON'"},
      {"bottom, 1, 3", "bottom, 1, 9", "are not within 1 to 6"},
      {"*STEP, NLGEOM", "*AMPLITUDE, NAME=A\n0, 0\n*STEP, NLGEOM",
       "two_cubes.inp:52: *AMPLITUDE A: an amplitude needs at least two (time, value) points, it has 1"},
      {"*STEP, NLGEOM", "*AMPLITUDE, NAME=A\n1, 0, 0.5, 1\n*STEP, NLGEOM",
       "two_cubes.inp:52: *AMPLITUDE A: the amplitude's times decrease at point 2 (0.5 after 1)"},
      {"*STEP, NLGEOM", "*AMPLITUDE, NAME=A\n0, 0, 1\n*STEP, NLGEOM",
       "two_cubes.inp:53: *AMPLITUDE: an *AMPLITUDE line holds (time, value) pairs"},
      {"*STEP, NLGEOM", "*AMPLITUDE, NAME=A, TIME=WALL\n0, 0, 1, 1\n*STEP, NLGEOM",
       "TIME=WALL must be TOTAL TIME or STEP TIME"},
      {"*STEP, NLGEOM", "*AMPLITUDE, NAME=A, DEFINITION=SMOOTH STEP\n0, 0, 1, 1\n*STEP, NLGEOM",
       "DEFINITION=SMOOTH STEP is not implemented by feticon (TABULAR)"},
      {"*CLOAD\n17, 3, -10.0", "*CLOAD, AMPLITUDE=NOPE\n17, 3, -10.0",
       "two_cubes.inp:59: *CLOAD: AMPLITUDE=NOPE is not defined by any *AMPLITUDE"},
      {"*STEP, NLGEOM", "*STEP, NLGEOM, AMPLITUDE=SINE",
       "two_cubes.inp:52: *STEP: AMPLITUDE=SINE must be RAMP or STEP"},
      {"*DLOAD\n2, P2, 1e6", "*DLOAD, AMPLITUDE=A\n2, P2, 1e6\n*AMPLITUDE, NAME=A\n0, 0, 1, 1",
       "the *DLOAD on element 2, face 2 has no amplitude, in the step before AMPLITUDE=A"},
      {"*ELASTIC\n", "*EXPANSION, TYPE=ORTHO\n1e-5, 1e-5, 2e-5\n*ELASTIC\n",
       "*EXPANSION: TYPE=ORTHO is not implemented by feticon (isotropic expansion, TYPE=ISO)"},
      {"*ELASTIC\n", "*EXPANSION\n1e-5, 20\n1.1e-5, 100\n*ELASTIC\n",
       "temperature-dependent expansion coefficients are not implemented by feticon"},
      {"*STEP, NLGEOM", "*INITIAL CONDITIONS, TYPE=STRESS\n1, 1e6\n*STEP, NLGEOM",
       "*INITIAL CONDITIONS: TYPE=STRESS is not implemented by feticon (TYPE=TEMPERATURE)"},
      {"*STEP, NLGEOM", "*INITIAL CONDITIONS, TYPE=TEMPERATURE\nall, inf\n*STEP, NLGEOM",
       "is not a finite number (temperature)"},
      {"*CLOAD\n17, 3, -10.0", "*MODEL CHANGE, TYPE=ELEMENT, REMOVE\n1",
       "*MODEL CHANGE: TYPE=ELEMENT is not implemented by feticon (TYPE=CONTACT PAIR)"},
      {"*CLOAD\n17, 3, -10.0", "*MODEL CHANGE, TYPE=CONTACT PAIR\nA, B", "*MODEL CHANGE needs one of ADD and REMOVE"},
      {"*CLOAD\n17, 3, -10.0", "*MODEL CHANGE, TYPE=CONTACT PAIR, REMOVE\nupper_bottom, nowhere",
       "*MODEL CHANGE: no *CONTACT PAIR has slave UPPER_BOTTOM and master NOWHERE"},
      {"*CLOAD\n17, 3, -10.0", "*TEMPERATURE\n99, 100.", "two_cubes.inp:60:1: *TEMPERATURE: node 99 is not defined"},
  };
  for (const Case& c : cases)
  {
    std::string text = two_cubes;
    replace_first(text, c.from, c.to);
    const std::string message = error_of(write(dir, "two_cubes.inp", text));
    EXPECT_NE(message.find(c.expected), std::string::npos)
        << "expected '" << c.expected << "', got '" << message << "'";
    EXPECT_EQ(message.find('\n'), std::string::npos) << message;
  }
  // Circular includes and an empty file.
  write(dir, "a.inp", "*INCLUDE, INPUT=b.inp\n");
  write(dir, "b.inp", "*INCLUDE, INPUT=a.inp\n");
  EXPECT_NE(error_of(dir / "a.inp").find("b.inp:1: *INCLUDE: circular *INCLUDE"), std::string::npos)
      << error_of(dir / "a.inp");
  EXPECT_NE(error_of(write(dir, "empty.inp", "** nothing\n")).find("has no keyword line"), std::string::npos);
  EXPECT_NE(error_of(dir / "absent.inp").find("does not exist"), std::string::npos);
}

TEST(DeckReader, OutlineCountsWithoutReading)
{
  const auto dir = test::fresh_directory("deck_outline");
  const DeckOutline outline = deck_outline(write(dir, "two_cubes.inp", two_cubes));
  EXPECT_EQ(outline.nodes, 16);
  EXPECT_EQ(outline.elements, 3); // the continued element line counts as two lines: an upper bound
  EXPECT_TRUE(outline.nlgeom);
  EXPECT_FALSE(outline.increments); // automatic: the deck's step 1 has them, not load_steps
  std::string direct = two_cubes;
  direct.replace(direct.find("*STATIC\n0.25"), 7, "*STATIC, DIRECT");
  EXPECT_EQ(deck_outline(write(dir, "direct.inp", direct)).increments, 4);
}

TEST(DeckReader, ProblemFileOfADeckTakesItsSettings)
{
  const auto dir = test::fresh_directory("deck_settings");
  const auto path = write(dir, "two_cubes.inp", two_cubes);
  const ProblemFile file = load_problem_file(path, {"load_steps=3"}, {});
  EXPECT_EQ(file.settings.text("problem"), "custom");
  EXPECT_EQ(file.settings.text("displacements"), "large");
  // --set wins: step 1 in 3 equal increments, not the deck's automatic ones
  EXPECT_EQ(file.settings.integer("load_steps"), 3);
  EXPECT_EQ(file.deck, std::filesystem::absolute(path));
  EXPECT_EQ(custom_mesh_size(file).nodes, 16);
}
// ADJUST of a *CONTACT PAIR: a distance, or a node set (CalculiX's two forms); moved by
// contact::adjust_slave_nodes when the run builds the problem.
TEST(DeckReader, ContactPairAdjustIsADistanceOrANodeSet)
{
  const auto dir = test::fresh_directory("deck_adjust");
  const auto adjusted = [&](const std::string& name, const std::string& adjust) {
    std::string text = two_cubes;
    const std::string at = "INTERACTION=SI,";
    text.insert(text.find(at) + at.size(), "ADJUST=" + adjust + ",");
    return read_deck(write(dir, name, text)).problem.contacts.at(0);
  };
  EXPECT_EQ(adjusted("distance.inp", "0.005").adjust, 0.005);
  EXPECT_EQ(adjusted("fortran.inp", "5.D-3").adjust, 0.005);
  EXPECT_EQ(adjusted("set.inp", "top").adjust_nodes, "TOP"); // names are the deck's, upper case
  const auto error = [&](const std::string& adjust) {
    try
    {
      adjusted("bad.inp", adjust);
    }
    catch (const Error& e)
    {
      return std::string(e.what());
    }
    return std::string();
  };
  EXPECT_NE(error("-1.").find("ADJUST=-1. must be a distance >= 0 or a node set"), std::string::npos);
  EXPECT_NE(error("NOWHERE").find("ADJUST=NOWHERE names no node set"), std::string::npos);
}

/// two_cubes with `friction` (a *FRICTION keyword and its data) in the interaction's block.
std::string two_cubes_with_friction(const std::string& friction)
{
  std::string text = two_cubes;
  const std::string at = "*SURFACE BEHAVIOR, PRESSURE-OVERCLOSURE=HARD\n";
  text.insert(text.find(at) + at.size(), friction);
  return text;
}

// *FRICTION (CalculiX's "mu, stick slope") is Coulomb's law with that mu, the law of the pair
// whose interaction it is; mu = 0 is frictionless. The settings stay at their defaults, not
// given: contact.friction.* override the pair's law only where given (SolverSettings, in
// tests/unit/nonlinear/test_settings_defaults.cpp).
TEST(DeckReader, FrictionIsCoulombsLawOfThePairsInteraction)
{
  const auto dir = test::fresh_directory("deck_friction");
  const auto path = write(dir, "friction.inp", two_cubes_with_friction("*FRICTION\n0.3, 5000.\n"));
  const Deck deck = read_deck(path);
  const fem::ContactInteraction& interaction = deck.problem.contacts.at(0).interaction;
  EXPECT_EQ(interaction.name, "SI");
  EXPECT_EQ(interaction.friction.model, fem::FrictionModel::coulomb);
  EXPECT_EQ(interaction.friction.coefficient, 0.3);
  EXPECT_TRUE(std::any_of(deck.info.warnings.begin(), deck.info.warnings.end(), [](const std::string& w) {
    return w.find("stick slope 5000. of *FRICTION") != std::string::npos;
  }));
  const ProblemFile file = load_problem_file(path, {}, {});
  EXPECT_FALSE(file.settings.given("contact.friction.model"));
  EXPECT_FALSE(file.settings.given("contact.friction.coefficient"));
  EXPECT_FALSE(file.settings.given("contact.formulation"));
  EXPECT_TRUE(
      load_problem_file(path, {"contact.friction.coefficient=0.5"}, {}).settings.given("contact.friction.coefficient"));

  // mu = 0, Fortran's exponent, and an interaction no pair uses.
  const auto friction_of = [](const std::filesystem::path& deck_path) {
    return read_deck(deck_path).problem.contacts.at(0).interaction.friction;
  };
  const auto zero = write(dir, "zero.inp", two_cubes_with_friction("*FRICTION\n0.\n"));
  EXPECT_EQ(friction_of(zero).model, fem::FrictionModel::none);
  const auto fortran = write(dir, "fortran.inp", two_cubes_with_friction("*FRICTION\n2.5D-1\n"));
  EXPECT_EQ(friction_of(fortran).model, fem::FrictionModel::coulomb);
  EXPECT_EQ(friction_of(fortran).coefficient, 0.25);
  std::string unused = two_cubes;
  unused.insert(unused.find("*CONTACT PAIR"), "*SURFACE INTERACTION, NAME=spare\n*FRICTION\n0.4\n");
  const Deck spare = read_deck(write(dir, "unused.inp", unused));
  EXPECT_EQ(spare.problem.contacts.at(0).interaction.friction.model, fem::FrictionModel::none);
  EXPECT_TRUE(std::any_of(spare.info.warnings.begin(), spare.info.warnings.end(), [](const std::string& w) {
    return w.find("*FRICTION of interaction SPARE") != std::string::npos;
  }));
}

// A problem file's contact pair carries the friction law: the same settings as the keys.
TEST(DeckReader, ProblemFileContactPairCarriesFriction)
{
  const auto dir = test::fresh_directory("pair_friction");
  const std::string head = "problem: custom\nmesh: {boxes: [{name: a, lengths: [1, 1, 1], cells: [1, 1, 1]}]}\n"
                           "bodies: {a: {young: 2e11, poisson: 0.3}}\n";
  const auto build = [&](const std::string& name, const std::string& contact) {
    return build_custom_problem(load_problem_file(write(dir, name, head + contact), {}, {}));
  };
  const fem::Problem coulomb = build(
      "coulomb.yaml", "contact:\n  - {slave: a_zmin, master: a_zmax, friction: {model: coulomb, coefficient: 0.3}}\n");
  EXPECT_EQ(coulomb.contacts.at(0).interaction.friction.model, fem::FrictionModel::coulomb);
  EXPECT_EQ(coulomb.contacts.at(0).interaction.friction.coefficient, 0.3);
  EXPECT_EQ(coulomb.contacts.at(0).interaction.formulation, fem::ContactFormulation::mortar);
  // Each pair its own law and formulation.
  const fem::Problem two = build("two.yaml",
                                 "contact:\n  - {slave: a_zmin, master: a_zmax, friction: {model: tresca, "
                                 "slip_bound: 2e7}}\n  - {slave: a_xmin, master: a_xmax, formulation: "
                                 "node_to_segment}\n");
  ASSERT_EQ(two.contacts.size(), 2u);
  EXPECT_EQ(two.contacts[0].interaction.friction.model, fem::FrictionModel::tresca);
  EXPECT_EQ(two.contacts[0].interaction.friction.slip_bound, 2e7);
  EXPECT_EQ(two.contacts[1].interaction.friction.model, fem::FrictionModel::none);
  EXPECT_EQ(two.contacts[1].interaction.formulation, fem::ContactFormulation::node_to_segment);

  const auto error = [&](const std::string& contact) {
    try
    {
      build("bad.yaml", contact);
    }
    catch (const Error& e)
    {
      return std::string(e.what());
    }
    return std::string();
  };
  const std::string pair = "contact:\n  - {slave: a_zmin, master: a_zmax, friction: ";
  const std::vector<std::pair<std::string, std::string>> cases = {
      {"{model: coulomb}}\n", "bad.yaml: contact.0.friction (model coulomb) needs coefficient"},
      {"{model: tresca, coefficient: 0.3}}\n", "contact.0.friction.coefficient does not belong"},
      {"{model: coulomb, coefficient: -0.3}}\n", "contact.0.friction: coefficient must be in [0, 100]"},
      {"{model: sticky}}\n", "contact.0.friction.model = 'sticky' must be one of"},
      {"{model: coulomb, mu: 0.3}}\n", "unknown key 'mu' in contact.0.friction"},
      {"{model: none}, formulation: nts}\n", "contact.0.formulation = 'nts' must be one of"},
  };
  for (const auto& [friction, expected] : cases)
  {
    const std::string message = error(pair + friction);
    EXPECT_NE(message.find(expected), std::string::npos) << "expected '" << expected << "', got '" << message << "'";
  }
}
} // namespace
} // namespace feticon::io

namespace feticon::io
{
namespace
{
/// One hex8 cell as a part, instanced twice: as it is, and moved by (1, 0, 0) then turned 90
/// degrees about the z axis through (1, 0, 0) (Abaqus's *INSTANCE: translation, then rotation).
const char* const two_instances = R"(*PART, NAME=CUBE
*NODE
1, 0, 0, 0
2, 1, 0, 0
3, 1, 1, 0
4, 0, 1, 0
5, 0, 0, 1
6, 1, 0, 1
7, 1, 1, 1
8, 0, 1, 1
*ELEMENT, TYPE=C3D8, ELSET=ALL
1, 1, 2, 3, 4, 5, 6, 7, 8
*NSET, NSET=BOTTOM, GENERATE
1, 4
*SOLID SECTION, ELSET=ALL, MATERIAL=EL
*END PART
*ASSEMBLY, NAME=A
*INSTANCE, NAME=I1, PART=CUBE
*END INSTANCE
*INSTANCE, NAME=I2, PART=CUBE
1., 0., 0.
1., 0., 0., 1., 0., 1., 90.
*END INSTANCE
*NSET, NSET=BASE, INSTANCE=I2
BOTTOM
*END ASSEMBLY
*MATERIAL, NAME=EL
*ELASTIC
2e11, 0.3
*STEP
*STATIC
*BOUNDARY
I1.BOTTOM, 1, 3
BASE, 3, 3
*CLOAD
I2.7, 1, 5.
*END STEP
)";
} // namespace

// The mesh and names an instance gives its part (io/deck_parts.hpp), and the outline's counts.
TEST(DeckReader, InstancesPlaceTheirPartsUnderTheirNames)
{
  const auto dir = test::fresh_directory("deck_parts");
  const auto path = write(dir, "parts.inp", two_instances);
  const DeckOutline outline = deck_outline(path);
  EXPECT_EQ(outline.nodes, 16); // 8 per instance, not per part
  EXPECT_EQ(outline.elements, 2);
  const Deck deck = read_deck(path);
  const mesh::Mesh& m = deck.problem.mesh;
  ASSERT_EQ(m.n_nodes(), 16);
  ASSERT_EQ(m.n_cells(), 2);
  // I1 keeps the part's labels; I2's are shifted past them: 9..16.
  EXPECT_EQ(deck.info.node_labels[0], 1);
  EXPECT_EQ(deck.info.node_labels[8], 9);
  EXPECT_EQ(deck.info.element_labels[1], 2);
  // I2's node 7, part (1, 1, 1): moved to (2, 1, 1), then turned about the z axis through
  // (1, 0, 0): (2, 1) - (1, 0) = (1, 1) -> (-1, 1), so (0, 1, 1).
  EXPECT_NEAR(m.nodes(14, 0), 0.0, 1e-15);
  EXPECT_NEAR(m.nodes(14, 1), 1.0, 1e-15);
  EXPECT_NEAR(m.nodes(14, 2), 1.0, 1e-15);
  // Sets under the instance's names, and the assembly's set of I2's part set.
  EXPECT_EQ(m.node_set("I1.BOTTOM").size(), 4u);
  EXPECT_EQ(m.node_set("I2.BOTTOM"), m.node_set("BASE"));
  EXPECT_EQ(m.node_set("BASE").front(), 8);
  // The load on "I2.7" is on mesh node 14, component x.
  const auto& forces = deck.problem.steps.front().nodal_forces;
  ASSERT_EQ(forces.size(), 1u);
  EXPECT_EQ(forces.front().node, 14);
  EXPECT_EQ(forces.front().component, 0);
}
} // namespace feticon::io

namespace feticon::io
{
// CalculiX's forcadd.f and loadadd.f: a *CLOAD or *DLOAD given twice in one step adds up; the
// next step's first value replaces it. (CalculiX's scheibe2f2f deck lists its pressures twice.)
TEST(DeckReader, LoadsGivenTwiceInAStepAddUp)
{
  const auto dir = test::fresh_directory("deck_load_sum");
  const std::string text = R"(*NODE, NSET=NALL
1, 0, 0, 0
2, 1, 0, 0
3, 1, 1, 0
4, 0, 1, 0
5, 0, 0, 1
6, 1, 0, 1
7, 1, 1, 1
8, 0, 1, 1
*ELEMENT, TYPE=C3D8, ELSET=EALL
1, 1, 2, 3, 4, 5, 6, 7, 8
*MATERIAL, NAME=EL
*ELASTIC
2e11, 0.3
*SOLID SECTION, ELSET=EALL, MATERIAL=EL
*BOUNDARY
1, 1, 3
2, 2, 3
4, 3
*STEP
*STATIC
*CLOAD
7, 3, 1.
7, 3, 2.
*DLOAD
1, P2, 10.
*DLOAD
1, P2, 5.
*END STEP
*STEP
*STATIC
*CLOAD
7, 3, 4.
*END STEP
)";
  const Deck deck = read_deck(write(dir, "twice.inp", text));
  const auto& first = deck.problem.steps[0];
  ASSERT_EQ(first.nodal_forces.size(), 1u);
  EXPECT_EQ(first.nodal_forces.front().value, 3.0);
  ASSERT_EQ(first.pressures.size(), 1u);
  EXPECT_EQ(first.pressures.front().pressure, 15.0);
  ASSERT_EQ(deck.problem.steps[1].nodal_forces.size(), 1u);
  EXPECT_EQ(deck.problem.steps[1].nodal_forces.front().value, 4.0);
}
} // namespace feticon::io

namespace feticon::io
{
// CalculiX's reading where the manual is silent (its calinput.f, solidsections.f, surfaces.f
// and allocont.f): a keyword written without its blanks, a later *SOLID SECTION replacing an
// earlier one of the same element (with a warning), and a node surface and an element surface
// under one name (a node-to-surface pair's slave takes the node one, its master the element one).
TEST(DeckReader, ReadsDecksAsCalculixDoes)
{
  const auto dir = test::fresh_directory("deck_calculix_reading");
  std::string text = R"(*NODE, NSET=NALL
1, 0, 0, 0
2, 1, 0, 0
3, 1, 1, 0
4, 0, 1, 0
5, 0, 0, 1
6, 1, 0, 1
7, 1, 1, 1
8, 0, 1, 1
9, 0, 0, 1.001
10, 1, 0, 1.001
11, 1, 1, 1.001
12, 0, 1, 1.001
13, 0, 0, 2
14, 1, 0, 2
15, 1, 1, 2
16, 0, 1, 2
*ELEMENT, TYPE=C3D8, ELSET=EALL
1, 1, 2, 3, 4, 5, 6, 7, 8
2, 9, 10, 11, 12, 13, 14, 15, 16
*ELSET, ELSET=TOP
2
*NSET, NSET=TOPNODES
9, 10, 11, 12
*MATERIAL, NAME=SOFT
*ELASTIC
1e9, 0.3
*MATERIAL, NAME=STIFF
*ELASTIC
2e11, 0.3
*SOLID SECTION, ELSET=EALL, MATERIAL=SOFT
*SOLIDSECTION, ELSET=TOP, MATERIAL=STIFF
*SURFACE, NAME=S, TYPE=NODE
TOPNODES
*SURFACE, NAME=S, TYPE=ELEMENT
2, S1
*SURFACE, NAME=M
1, S2
*SURFACE INTERACTION, NAME=I
*SURFACE BEHAVIOR, PRESSURE-OVERCLOSURE=HARD
*CONTACT PAIR, INTERACTION=I, TYPE=NODE TO SURFACE
S, M
*BOUNDARY
1, 1, 3
2, 2, 3
3, 3
4, 1, 1
4, 3, 3
13, 1, 2
14, 2, 2
*STEP
*STATIC
*CLOAD
13, 3, -1.
*ENDSTEP
)";
  const Deck deck = read_deck(write(dir, "calculix.inp", text));
  const fem::Problem& p = deck.problem;
  ASSERT_EQ(p.mesh.n_bodies(), 2); // the top cell took the later section's material
  EXPECT_EQ(p.materials[static_cast<size_t>(p.mesh.cell_body[1])].young, 2e11);
  EXPECT_EQ(p.materials[static_cast<size_t>(p.mesh.cell_body[0])].young, 1e9);
  EXPECT_TRUE(std::any_of(deck.info.warnings.begin(), deck.info.warnings.end(), [](const std::string& w) {
    return w.find("another material; the later section holds, as in CalculiX") != std::string::npos;
  }));
  ASSERT_EQ(p.contacts.size(), 1u);
  EXPECT_EQ(p.contacts.front().slave, node_surface_key("S"));
  EXPECT_EQ(p.contacts.front().master, "M");
  EXPECT_EQ(p.mesh.face_set(node_surface_key("S")).size(), 1u);

  // A load given twice in a step with two amplitudes: CalculiX refuses it, one line.
  replace_first(text, "*CLOAD\n13, 3, -1.",
                "*CLOAD\n13, 3, -1.\n*CLOAD, AMPLITUDE=A\n13, 3, -1.\n*AMPLITUDE, NAME=A\n0, 0, 1, 1");
  EXPECT_NE(error_of(write(dir, "amplitudes.inp", text))
                .find("a second load on one degree of freedom or face in one "
                      "step with another amplitude"),
            std::string::npos);
}
} // namespace feticon::io
