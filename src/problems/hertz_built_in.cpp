/// The 2D Hertz benchmark as a built-in problem: its `hertz.*` keys, and its comparison with
/// McEwen's profile.

#include "common/error.hpp"
#include "common/log.hpp"
#include "problems/cattaneo_mindlin.hpp"
#include "problems/hertz.hpp"
#include "problems/hertz_figures.hpp"

namespace feticon::problems
{
namespace
{
using Type = io::SettingSpec::Type;

class HertzProblem : public BuiltInProblem
{
public:
  /// rolls: a tangential load with large displacements, which build() warns of.
  HertzProblem(HertzParameters parameters, bool rolls) : _parameters(std::move(parameters)), _rolls(rolls) {}

  MeshPrediction predict_mesh() const override { return {hertz_node_estimate(_parameters.mesh), true}; }
  fem::Problem build() const override
  {
    fem::Problem problem = hertz_problem(_parameters);
    if (_rolls)
      log::warning("hertz: with large displacements a tangential load leaves the cylinder free to roll on its "
                   "contact (a neutral mode), and the outer loop drifts along it; hertz.tangential_displacement "
                   "with hertz.tangential_couple holds it (docs/friction.md)");
    return problem;
  }

  std::optional<TheoryComparison> compare_with_theory(const fem::Problem& problem, const la::Vector& u,
                                                      const std::vector<SurfaceSample>& samples,
                                                      bool large) const override
  {
    const HertzComparison reference = compare_with_hertz(_parameters, pressure_profile(samples, false, false));
    const HertzComparison h =
        large ? compare_with_hertz(_parameters, pressure_profile(samples, false, true)) : reference;
    TheoryComparison out = hertz_theory_comparison(h, reference, large, h.applied_load);
    out.figures["axis_approach"] = hertz_axis_approach(problem, u);
    if (_parameters.mesh.full)
      out.figures["load_face_shift"] = hertz_load_face_shift(problem, u);
    out.figures["contact_element_size"] = h.element_size;
    const HertzAnalytic analytic = hertz_analytic(_parameters);
    for (const ProfilePoint& p : pressure_profile(samples, false, large))
      out.analytic.push_back(analytic.pressure(p.r));
    if (_parameters.compared_tangential_load() > 0 && _parameters.friction_coefficient > 0)
    {
      add_cattaneo_mindlin(h, samples, large, out);
      if (_parameters.tangential_displacement > 0)
        add_support_force(problem, u, large, out.figures["friction"]);
    }
    return out;
  }

private:
  /// The Q that Cattaneo-Mindlin is evaluated at: the applied one, but under displacement
  /// control with a couple given (partial slip) the force the moved face carries, the
  /// tangential reaction of the contact (the friction and normal forces along x).
  double theory_load(const std::vector<SurfaceSample>& samples, double applied) const
  {
    if (_parameters.tangential_displacement == 0 || _parameters.tangential_couple == 0)
      return applied;
    return std::max(-tangential_reaction(samples) / _parameters.mesh.thickness, 0.0);
  }

  /// The `friction` block against Cattaneo-Mindlin, its line and the analytic shear column;
  /// a tangential displacement is compared with the full slide, Q = mu P, unless its couple is
  /// given (theory_load).
  void add_cattaneo_mindlin(const HertzComparison& h, const std::vector<SurfaceSample>& samples, bool large,
                            TheoryComparison& out) const
  {
    const double Q = _parameters.compared_tangential_load();
    const CattaneoMindlin theory = _parameters.unloaded_tangential_load
        ? mindlin_deresiewicz(_parameters.friction_coefficient, h.p0_analytic, h.a_analytic, _parameters.line_load,
                              _parameters.tangential_load, Q)
        : cattaneo_mindlin(_parameters.friction_coefficient, h.p0_analytic, h.a_analytic, _parameters.line_load,
                           theory_load(samples, Q));
    std::vector<double> x;
    for (const ProfilePoint& p : pressure_profile(samples, false, large))
    {
      x.push_back(p.r);
      out.analytic_shear.push_back(theory.shear(p.r));
    }
    const double applied = Q * _parameters.mesh.thickness;
    out.figures["friction"] = cattaneo_mindlin_figures(theory, samples, x, applied);
    out.summary_line += cattaneo_mindlin_line(out.figures["friction"], theory, applied, "half-width");
  }

  /// Under a tangential displacement: the support's force on the moved face (N) and how far
  /// the contact's tangential reaction is from balancing it (equilibrium of the cylinder).
  static void add_support_force(const fem::Problem& problem, const la::Vector& u, bool large,
                                nlohmann::ordered_json& friction)
  {
    const double support =
        hertz_load_face_support_force(problem, u, large ? fem::Kinematics::total_lagrangian : fem::Kinematics::linear);
    friction["load_face_support_force"] = support;
    friction["load_face_balance_error"] =
        std::abs(support + friction["tangential_reaction"].get<double>()) / std::max(std::abs(support), 1e-300);
  }

  HertzParameters _parameters;
  bool _rolls;
};
} // namespace

std::vector<io::SettingSpec> hertz_setting_specs()
{
  const double inf = 1e300;
  // One key per entry, as the help lists them.
  // clang-format off
  return {
      {"hertz.line_load", "4e8", "line load Q on the cylinder (N/m)", Type::number, {}, 0, inf, true},
      {"hertz.tangential_load", "0", "tangential line load along +x on the cylinder (N/m), applied after the "
       "normal load in a second load stage (needs contact.friction; the full model is meshed: the load "
       "breaks the symmetry)", Type::number, {}, 0, inf, false},
      {"hertz.tangential_unload", "", "with hertz.tangential_load: a third load stage lowers the tangential "
       "load to this (N/m, between 0 and tangential_load, exclusive), compared with Mindlin and Deresiewicz's "
       "unloading (docs/friction.md)", Type::number, {}, 0, inf, true},
      {"hertz.tangential_displacement", "0", "instead of hertz.tangential_load: the load face held along x "
       "while pressed, then moved along +x by this much (m) in a second load stage, with the couple of the "
       "full slide's force mu P (Q >= mu P: every node slides; needs Coulomb friction)", Type::number, {}, 0, inf, false},
      {"hertz.tangential_couple", "0", "with hertz.tangential_displacement: the tangential line load (N/m) "
       "the moved face is expected to carry, whose moment about the contact its couple cancels; compared "
       "with Cattaneo-Mindlin at the force the face carries (partial slip under displacement control, "
       "which holds the cylinder from rolling with large displacements); 0: mu P, the full slide",
       Type::number, {}, 0, inf, false},
      {"hertz.mesh", "graded", "graded (Gmsh quadrilaterals with a size field growing by growth_ratio "
                               "away from the contact, shape-regular) or tensor (mapped blocks with "
                               "tensor-product grading)", Type::text, {"graded", "tensor"}, 0, 0, false},
      {"hertz.cells", "quad4", "quad4 (2D plane-strain cells, thickness 0.01 m) or hex8_layer (one hex8 layer "
       "with u_z eliminated: the paper's model, for comparison)", Type::text, {"quad4", "hex8_layer"}, 0, 0, false},
      {"hertz.refinement", "1", "scales every element size by 1/refinement", Type::number, {}, 0.05, 64, false},
      {"hertz.element_size", "0.005", "element size in the contact zone at refinement 1 (m)", Type::number, {}, 0, 0.1, true},
      {"hertz.master_ratio", "1.3", "block (master) / cylinder (slave) contact element size", Type::number, {}, 0.2, 5, false},
      {"hertz.block_width", "1.5", "half-width of the block (m)", Type::number, {}, 0.2, 100, false},
      {"hertz.cylinder_width", "0.6", "half-width of the modelled cylinder segment (m), < radius", Type::number, {}, 0.1, 0.99, false},
      {"hertz.block_depth", "1.5", "depth of the block (m)", Type::number, {}, 0.2, 100, false},
      {"hertz.growth_ratio", "1.1", "cell size ratio between neighbouring cells away from the contact "
                                    "band (tensor: at refinement 1, and tables before the graded mesh "
                                    "used 1.2; 1: uniform mesh)", Type::number, {}, 1, 2, false},
      {"hertz.block_young", "", "Young's modulus of the block (Pa), if it differs from the cylinder's "
       "material.young (E* from both)", Type::number, {}, 0, inf, true},
      {"hertz.block_poisson", "", "Poisson's ratio of the block, if it differs from material.poisson",
       Type::number, {}, -1, 0.5, true, true},
  };
  // clang-format on
}

HertzParameters hertz_parameters(const io::Settings& s)
{
  HertzParameters p;
  p.line_load = s.number("hertz.line_load");
  p.tangential_load = s.number("hertz.tangential_load");
  p.tangential_displacement = s.number("hertz.tangential_displacement");
  p.tangential_couple = s.number("hertz.tangential_couple");
  p.unloaded_tangential_load = s.optional_number("hertz.tangential_unload");
  p.mesh.full = p.tangential_load > 0 || p.tangential_displacement > 0;
  p.friction_coefficient = p.tangential_displacement > 0
      ? cattaneo_mindlin_coefficient(s, "hertz.tangential_displacement", p.tangential_displacement, "m", "cylinder")
      : cattaneo_mindlin_coefficient(s, "hertz.tangential_load", p.tangential_load, "N/m", "cylinder");
  p.mesh.kind = s.text("hertz.mesh") == "tensor" ? HertzMeshKind::tensor : HertzMeshKind::graded;
  p.mesh.cells = s.text("hertz.cells") == "hex8_layer" ? HertzCells::hex8_layer : HertzCells::quad4;
  p.mesh.refinement = s.number("hertz.refinement");
  p.mesh.element_size = s.number("hertz.element_size");
  p.mesh.master_ratio = s.number("hertz.master_ratio");
  p.mesh.block_width = s.number("hertz.block_width");
  p.mesh.block_depth = s.number("hertz.block_depth");
  p.mesh.growth_ratio = s.number("hertz.growth_ratio");
  p.mesh.cylinder_width = s.number("hertz.cylinder_width");
  p.material = material_setting(s);
  p.block_material = block_material_setting(s, "hertz", p.material);
  return p;
}

std::unique_ptr<BuiltInProblem> make_hertz_problem(const io::Settings& settings)
{
  HertzParameters parameters = hertz_parameters(settings);
  const bool rolls = parameters.tangential_load > 0 && settings.text("displacements") == "large";
  return std::make_unique<HertzProblem>(std::move(parameters), rolls);
}
} // namespace feticon::problems
