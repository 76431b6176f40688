#include "fem/contact_interaction.hpp"

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
} // namespace feticon::fem
