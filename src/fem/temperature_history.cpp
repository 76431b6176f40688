#include "fem/temperature_history.hpp"

#include "common/error.hpp"

namespace feticon::fem
{
TemperatureHistory::TemperatureHistory(const Problem& problem)
{
  if (!problem.has_temperatures())
    return;
  const la::Index n = problem.mesh.n_nodes();
  _initial = problem.initial_temperatures.empty()
      ? la::Vector(la::Vector::Zero(n))
      : la::Vector(Eigen::Map<const la::Vector>(problem.initial_temperatures.data(), n));
  std::map<std::string, int> amplitude_index;
  double start_time = 0;
  la::Vector end = _initial;
  for (const Step& step : problem.steps)
  {
    Stage stage;
    stage.start = end;
    stage.target = _initial;
    stage.amplitude.assign(static_cast<size_t>(n), -1);
    stage.period = step.time;
    stage.ramp = step.ramp;
    for (const NodalTemperature& t : step.temperatures)
    {
      FETICON_CHECK(t.node >= 0 && t.node < n, "a temperature names node " << t.node << " of " << n);
      stage.target(t.node) = t.value;
      if (t.amplitude.empty())
        continue;
      const auto [it, added] = amplitude_index.emplace(t.amplitude, static_cast<int>(_amplitudes.size()));
      if (added)
        _amplitudes.push_back(problem.amplitudes.at(t.amplitude));
      stage.amplitude[t.node] = it->second;
    }
    start_time += step.time;
    end = at(stage, 1, start_time);
    _stages.push_back(std::move(stage));
  }
}

la::Vector TemperatureHistory::at(const Stage& stage, double fraction, double total_time) const
{
  la::Vector T = stage.ramp ? la::Vector(stage.start + fraction * (stage.target - stage.start)) : stage.target;
  for (la::Index i = 0; i < T.size(); ++i)
    if (const int a = stage.amplitude[i]; a >= 0)
    {
      const Amplitude& amplitude = _amplitudes[a];
      T(i) = stage.target(i) * amplitude.value(amplitude.total_time ? total_time : fraction * stage.period);
    }
  return T;
}

la::Vector TemperatureHistory::change(const LoadPoint& point) const
{
  if (empty())
    return {};
  FETICON_CHECK(point.stage >= 1 && point.stage <= std::ssize(_stages),
                "load point of stage " << point.stage << ", the history has " << _stages.size());
  return at(_stages[point.stage - 1], point.fraction, point.time) - _initial;
}
} // namespace feticon::fem
