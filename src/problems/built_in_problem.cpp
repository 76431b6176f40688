#include "problems/built_in_problem.hpp"

#include "common/error.hpp"
#include "problems/cantilever_obstacle.hpp"
#include "problems/hertz.hpp"
#include "problems/hertz3d.hpp"
#include "problems/hertz_axi.hpp"

namespace feticon::problems
{
namespace
{
using Type = io::SettingSpec::Type;

/// The registry: a problem's name, its keys and how it is made.
struct Entry
{
  const char* name;
  std::vector<io::SettingSpec> (*specs)();
  std::unique_ptr<BuiltInProblem> (*make)(const io::Settings&);
};
const Entry registry[] = {
    {"hertz", hertz_setting_specs, make_hertz_problem},
    {"hertz3d", hertz3d_setting_specs, make_hertz3d_problem},
    {"hertz_axi", hertz_axi_setting_specs, make_hertz_axi_problem},
    {"cantilever_obstacle", cantilever_obstacle_setting_specs, make_cantilever_obstacle_problem},
};
} // namespace

std::vector<io::SettingSpec> setting_specs()
{
  const double inf = 1e300;
  // One key per entry, as the help lists them.
  // clang-format off
  std::vector<io::SettingSpec> out = {
      {"problem", "hertz", "hertz (Vondrák et al.'s benchmark), hertz3d (a sphere on a half-space), "
                           "hertz_axi (the sphere on the half-space as an axisymmetric model), "
                           "cantilever_obstacle (a cantilever bent onto a block: finite rotations) or "
                           "custom (mesh, bodies, supports, loads, contact sections of the problem file)",
       Type::text, {}, 0, 0, false},
      {"material.young", "2e11", "Young's modulus E (Pa) of every body of a built-in problem", Type::number, {}, 0, inf, true},
      {"material.poisson", "0.3", "Poisson's ratio nu of every body of a built-in problem, in (-1, 0.5)",
       Type::number, {}, -1, 0.5, true, true},
  };
  // clang-format on
  for (const Entry& e : registry)
  {
    out.front().choices.emplace_back(e.name);
    for (io::SettingSpec& spec : e.specs())
      out.push_back(std::move(spec));
  }
  out.front().choices.emplace_back("custom");
  return out;
}

std::unique_ptr<BuiltInProblem> make_built_in_problem(const io::Settings& settings)
{
  const std::string& name = settings.text("problem");
  for (const Entry& e : registry)
    if (name == e.name)
      return e.make(settings);
  return nullptr;
}

double cattaneo_mindlin_coefficient(const io::Settings& s, const std::string& key, double tangential_load,
                                    const std::string& unit, const std::string& body)
{
  FETICON_CHECK(tangential_load == 0 || s.text("contact.friction.model") != "none",
                "" << key << " = " << tangential_load << " " << unit << " needs friction to hold the " << body
                   << ": set contact.friction.model (coulomb with contact.friction.coefficient, or tresca)");
  return s.text("contact.friction.model") == "coulomb" ? s.number("contact.friction.coefficient") : 0.0;
}

fem::Material material_setting(const io::Settings& s)
{
  return {s.number("material.young"), s.number("material.poisson")};
}

std::optional<fem::Material> block_material_setting(const io::Settings& s, const std::string& prefix,
                                                    const fem::Material& material)
{
  const std::optional<double> young = s.optional_number(prefix + ".block_young");
  const std::optional<double> poisson = s.optional_number(prefix + ".block_poisson");
  if (!young && !poisson)
    return std::nullopt;
  return fem::Material{young.value_or(material.young), poisson.value_or(material.poisson)};
}
} // namespace feticon::problems
