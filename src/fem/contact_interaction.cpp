#include "fem/contact_interaction.hpp"

#include <algorithm>
#include <cmath>

namespace feticon::fem
{
const char* friction_model_name(FrictionModel model)
{
  return model == FrictionModel::tresca ? "tresca" : model == FrictionModel::coulomb ? "coulomb" : "none";
}

const char* formulation_name(ContactFormulation formulation)
{
  return formulation == ContactFormulation::mortar ? "mortar" : "node_to_segment";
}

NormalLaw::Tangent NormalLaw::tangent(double overclosure) const
{
  switch (kind)
  {
  case NormalLawKind::exponential:
  {
    const double beta = std::log(100.0) / c0;
    const double d = std::max(overclosure, zero_at_contact ? 0.0 : -c0);
    const double stiffness = beta * p0 * std::exp(beta * d);
    const double pressure = zero_at_contact ? p0 * (std::exp(beta * d) - 1) : p0 * std::exp(beta * d);
    return {stiffness, d - pressure / stiffness};
  }
  case NormalLawKind::tabular:
  {
    // Segment j from table[j] to table[j + 1]; problem input checks make every slope positive.
    const auto above =
        std::upper_bound(table.begin(), table.end(), overclosure,
                         [](double d, const std::pair<double, double>& point) { return d < point.first; });
    const auto j = std::clamp<std::ptrdiff_t>(above - table.begin() - 1, 0, std::ssize(table) - 2);
    const auto& [d0, p0_] = table[static_cast<size_t>(j)];
    const auto& [d1, p1] = table[static_cast<size_t>(j) + 1];
    const double stiffness = (p1 - p0_) / (d1 - d0);
    return {stiffness, d0 - p0_ / stiffness};
  }
  case NormalLawKind::linear:
  case NormalLawKind::hard:
    break;
  }
  return {slope, slope > 0 ? sigma_inf / slope : 0.0};
}

double NormalLaw::overclosure_at(double pressure) const
{
  switch (kind)
  {
  case NormalLawKind::linear:
    return (pressure + sigma_inf) / slope;
  case NormalLawKind::exponential:
    return std::log((zero_at_contact ? pressure + p0 : pressure) / p0) * c0 / std::log(100.0);
  case NormalLawKind::tabular:
    for (size_t j = 0; j + 1 < table.size(); ++j)
      if (pressure <= table[j + 1].second || j + 2 == table.size())
      {
        const Tangent line = tangent(0.5 * (table[j].first + table[j + 1].first));
        return line.zero_overclosure + pressure / line.stiffness;
      }
    break;
  case NormalLawKind::hard:
    break;
  }
  return 0;
}

const char* normal_law_name(NormalLawKind kind)
{
  switch (kind)
  {
  case NormalLawKind::linear:
    return "linear";
  case NormalLawKind::exponential:
    return "exponential";
  case NormalLawKind::tabular:
    return "tabular";
  case NormalLawKind::hard:
    break;
  }
  return "hard";
}
} // namespace feticon::fem
