/// The axisymmetric Hertz problem and its built-in form: its `hertz_axi.*` keys and its
/// comparison with Hertz's p(r).

#include "problems/hertz_axi.hpp"

#include "common/error.hpp"
#include "problems/hertz.hpp"
#include "problems/hertz_figures.hpp"

#include <cmath>
#include <numbers>

namespace feticon::problems
{
Hertz3dParameters HertzAxiParameters::as_3d() const
{
  Hertz3dParameters p;
  p.radius = mesh.cylinder_radius;
  p.load = load;
  p.material = material;
  p.block_material = block_material;
  return p;
}

fem::Problem hertz_axi_problem(const HertzAxiParameters& parameters)
{
  FETICON_CHECK(std::isfinite(parameters.load) && parameters.load > 0,
                "hertz_axi: load = " << parameters.load << " N must be positive");
  FETICON_CHECK(parameters.mesh.axisymmetric, "hertz_axi: the mesh must be axisymmetric");
  fem::Problem p;
  p.name = "hertz_axi";
  p.mesh = generate_hertz(parameters.mesh, &p.mesh_from_cache);
  p.mesh.body_names = {"sphere", "block"};
  p.materials = {parameters.material, parameters.block_material.value_or(parameters.material)};
  p.eliminated = {false, false, true};
  fem::Step& pressed = p.steps.front();
  pressed.dirichlet = {{"symmetry", {0.0, std::nullopt, std::nullopt}}, {"support", {0.0, 0.0, std::nullopt}}};
  const double disc = std::numbers::pi * std::pow(parameters.mesh.cylinder_width, 2);
  pressed.tractions = {{"load", Eigen::Vector3d(0, -parameters.load / disc, 0)}};
  p.contacts.push_back({"cylinder_contact", "block_contact"});
  p.validate();
  return p;
}

namespace
{
using Type = io::SettingSpec::Type;

class HertzAxiProblem : public BuiltInProblem
{
public:
  explicit HertzAxiProblem(HertzAxiParameters parameters) : _parameters(std::move(parameters)) {}

  MeshPrediction predict_mesh() const override { return {hertz_node_estimate(_parameters.mesh), true}; }
  fem::Problem build() const override { return hertz_axi_problem(_parameters); }

  /// Hertz's p(r) at the samples' x = r (hertz3d's figures: the RMS over the nodes with r <= a).
  std::optional<TheoryComparison> compare_with_theory(const fem::Problem& problem, const la::Vector& u,
                                                      const std::vector<SurfaceSample>& samples,
                                                      bool large) const override
  {
    const Hertz3dParameters sphere = _parameters.as_3d();
    const auto reference = compare_with_hertz3d(sphere, pressure_profile(samples, false, false));
    const auto h = large ? compare_with_hertz3d(sphere, pressure_profile(samples, false, true)) : reference;
    TheoryComparison out = hertz_theory_comparison(h, reference, large, _parameters.load);
    out.figures["rms_nodes"] = h.nodes_in_rms;
    out.figures["axis_approach"] = hertz_axis_approach(problem, u);
    out.figures["contact_element_size"] = _parameters.mesh.element_size / _parameters.mesh.refinement;
    const Hertz3dAnalytic analytic = hertz3d_analytic(sphere);
    for (const ProfilePoint& p : pressure_profile(samples, false, large))
      out.analytic.push_back(analytic.pressure(p.r));
    return out;
  }

private:
  HertzAxiParameters _parameters;
};
} // namespace

std::vector<io::SettingSpec> hertz_axi_setting_specs()
{
  const double inf = 1e300;
  // One key per entry, as the help lists them.
  // clang-format off
  return {
      {"hertz_axi.load", "4e7", "force P on the sphere (N, the full circle)", Type::number, {}, 0, inf, true},
      {"hertz_axi.radius", "1", "sphere radius R (m); the modelled sphere reaches r = 0.6 R, the block 1.5 R "
       "wide and deep", Type::number, {}, 0, inf, true},
      {"hertz_axi.refinement", "1", "scales every element size by 1/refinement", Type::number, {}, 0.05, 64, false},
      {"hertz_axi.element_size", "0.0025", "element size in the contact zone at refinement 1, for R = 1 m (m; "
       "scaled with R)", Type::number, {}, 0, 0.1, true},
      {"hertz_axi.master_ratio", "1.3", "block (master) / sphere (slave) contact element size", Type::number, {}, 0.2, 5, false},
      {"hertz_axi.block_young", "", "Young's modulus of the block (Pa), if it differs from the sphere's "
       "material.young (E* from both)", Type::number, {}, 0, inf, true},
      {"hertz_axi.block_poisson", "", "Poisson's ratio of the block, if it differs from material.poisson",
       Type::number, {}, -1, 0.5, true, true},
  };
  // clang-format on
}

std::unique_ptr<BuiltInProblem> make_hertz_axi_problem(const io::Settings& s)
{
  HertzAxiParameters p;
  const double R = s.number("hertz_axi.radius");
  // The 2D benchmark's proportions (hertz_mesh.hpp) scaled with R.
  HertzMeshParameters& m = p.mesh;
  m.cylinder_radius *= R;
  m.cylinder_width *= R;
  m.block_width *= R;
  m.block_depth *= R;
  m.fine_width *= R;
  m.fine_depth *= R;
  m.element_size = s.number("hertz_axi.element_size") * R;
  m.refinement = s.number("hertz_axi.refinement");
  m.master_ratio = s.number("hertz_axi.master_ratio");
  p.load = s.number("hertz_axi.load");
  p.material = material_setting(s);
  p.block_material = block_material_setting(s, "hertz_axi", p.material);
  return std::make_unique<HertzAxiProblem>(std::move(p));
}
} // namespace feticon::problems
