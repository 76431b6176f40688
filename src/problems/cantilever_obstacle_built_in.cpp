/// The cantilever bent onto an obstacle as a built-in problem: its `cantilever.*` keys. It
/// has no closed-form solution to compare with.

#include "problems/cantilever_obstacle.hpp"

namespace feticon::problems
{
namespace
{
using Type = io::SettingSpec::Type;

class CantileverObstacleProblem : public BuiltInProblem
{
public:
  explicit CantileverObstacleProblem(const CantileverObstacleParameters& parameters) : _parameters(parameters) {}

  MeshPrediction predict_mesh() const override { return {cantilever_obstacle_node_count(_parameters), true}; }
  fem::Problem build() const override { return cantilever_obstacle_problem(_parameters); }

private:
  CantileverObstacleParameters _parameters;
};
} // namespace

std::vector<io::SettingSpec> cantilever_obstacle_setting_specs()
{
  // One key per entry, as the help lists them.
  // clang-format off
  return {
      {"cantilever.gap", "0.25", "gap between the beam (L = 1 m) and the obstacle (m)", Type::number, {}, 0, 10, true},
      {"cantilever.load", "0.8", "tip load as its linear tip deflection over L", Type::number, {}, 0, 100, true},
      {"cantilever.cells", "40", "beam cells along its length", Type::integer, {}, 10, 10000, false},
  };
  // clang-format on
}

CantileverObstacleParameters cantilever_obstacle_parameters(const io::Settings& s)
{
  CantileverObstacleParameters p;
  p.gap = s.number("cantilever.gap");
  p.linear_deflection_ratio = s.number("cantilever.load");
  p.cells_along = s.integer("cantilever.cells");
  p.material = material_setting(s);
  return p;
}

std::unique_ptr<BuiltInProblem> make_cantilever_obstacle_problem(const io::Settings& settings)
{
  return std::make_unique<CantileverObstacleProblem>(cantilever_obstacle_parameters(settings));
}
} // namespace feticon::problems
