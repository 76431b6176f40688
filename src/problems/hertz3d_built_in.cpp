/// The 3D Hertz problem (a sphere on a half-space) as a built-in problem: its `hertz3d.*`
/// keys, and its comparison with Hertz's p(r) and approach.

#include "common/error.hpp"
#include "problems/cattaneo_mindlin.hpp"
#include "problems/hertz3d.hpp"
#include "problems/hertz_figures.hpp"

namespace feticon::problems
{
namespace
{
using Type = io::SettingSpec::Type;

class Hertz3dProblem : public BuiltInProblem
{
public:
  explicit Hertz3dProblem(const Hertz3dParameters& parameters) : _parameters(parameters) {}

  MeshPrediction predict_mesh() const override { return {hertz3d_node_count(_parameters), false}; }
  fem::Problem build() const override { return hertz3d_problem(_parameters); }

  std::optional<TheoryComparison> compare_with_theory(const fem::Problem& problem, const la::Vector& u,
                                                      const std::vector<SurfaceSample>& samples,
                                                      bool large) const override
  {
    const auto reference = compare_with_hertz3d(_parameters, pressure_profile(samples, true, false));
    const auto h = large ? compare_with_hertz3d(_parameters, pressure_profile(samples, true, true)) : reference;
    TheoryComparison out = hertz_theory_comparison(h, reference, large, _parameters.modelled() * _parameters.load);
    out.figures["rms_nodes"] = h.nodes_in_rms;
    out.figures["approach_analytic"] = h.approach_analytic;
    out.figures["approach_computed"] = hertz3d_approach(problem, u);
    out.figures["contact_element_size"] = _parameters.element_size / _parameters.refinement;
    const Hertz3dAnalytic analytic = hertz3d_analytic(_parameters);
    for (const ProfilePoint& p : pressure_profile(samples, true, large))
      out.analytic.push_back(analytic.pressure(p.r));
    if (_parameters.half_model() && _parameters.friction_coefficient > 0)
      add_cattaneo_mindlin(h, samples, large, out);
    return out;
  }

private:
  /// The `friction` block against Mindlin's sphere, its line and the analytic shear column.
  void add_cattaneo_mindlin(const Hertz3dComparison& h, const std::vector<SurfaceSample>& samples, bool large,
                            TheoryComparison& out) const
  {
    const double Q = _parameters.compared_tangential_load();
    const CattaneoMindlin theory = cattaneo_mindlin(_parameters.friction_coefficient, h.p0_analytic, h.a_analytic,
                                                    _parameters.load, Q, HertzContact::sphere);
    for (const ProfilePoint& p : pressure_profile(samples, true, large))
      out.analytic_shear.push_back(theory.shear(p.r));
    const double applied = _parameters.modelled() * Q;
    out.figures["friction"] = cattaneo_mindlin_sphere_figures(theory, samples, large, applied);
    out.summary_line += cattaneo_mindlin_line(out.figures["friction"], theory, applied, "radius");
  }

  Hertz3dParameters _parameters;
};
} // namespace

std::vector<io::SettingSpec> hertz3d_setting_specs()
{
  const double inf = 1e300;
  // One key per entry, as the help lists them.
  // clang-format off
  return {
      {"hertz3d.radius", "0.05", "sphere radius R (m)", Type::number, {}, 0, inf, true},
      {"hertz3d.load", "2e4", "force F on the whole sphere (N); the quarter model carries F/4, the half model F/2", Type::number, {}, 0, inf, true},
      {"hertz3d.tangential_load", "0", "tangential force along +x on the whole sphere (N), applied after the normal "
       "load in a second load stage (needs contact.friction; the half model y >= 0 is meshed: the load breaks "
       "the symmetry x -> -x)", Type::number, {}, 0, inf, false},
      {"hertz3d.tangential_displacement", "0", "instead of hertz3d.tangential_load: the sphere's far face held "
       "along x while pressed, then moved along +x by this much (m) in a second load stage, with the couple of "
       "the full slide's force mu F (Q >= mu P: every node slides; needs Coulomb friction)", Type::number, {}, 0,
       inf, false},
      {"hertz3d.refinement", "1", "divides hertz3d.element_size", Type::number, {}, 0.05, 64, false},
      {"hertz3d.element_size", "0.00025", "sphere cell size in the contact core at refinement 1 (m)", Type::number, {}, 0, 0.1, true},
      {"hertz3d.master_ratio", "1.3", "block (master) / sphere (slave) cell size in the contact core", Type::number, {}, 0.2, 5, false},
      {"hertz3d.block_radius", "0.04", "radius of the modelled half-space, an octant ball fixed on its curved face (m)",
       Type::number, {}, 0, inf, true},
      {"hertz3d.cap_radius", "0.025", "radius of the modelled part of the sphere about the contact point (m), "
       "at most R / 2", Type::number, {}, 0, inf, true},
      {"hertz3d.radial_aspect", "1.5", "radial / tangential cell size outside the contact core", Type::number, {}, 0.5, 3, false},
      {"hertz3d.cell", "hex8", "cell type: hex8 as meshed, or its cells split into tet4 / tet10 (six tetrahedra each), "
       "wedge6 (two), or hex20; quadratic cells keep their edge nodes on the sphere", Type::text,
       {"hex8", "tet4", "tet10", "hex20", "wedge6"}, 0, 0, false},
      {"hertz3d.mesh", "octant", "octant: the graded octant balls built here (cells of hertz3d.cell); gmsh: the "
       "sphere and the block as OpenCASCADE solids meshed by Gmsh with tetrahedra graded from the contact point "
       "(hertz3d.cell tet10 or tet4; quarter model only)", Type::text, {"octant", "gmsh"}, 0, 0, false},
      {"hertz3d.block_young", "", "Young's modulus of the block (Pa), if it differs from the sphere's "
       "material.young (E* from both)", Type::number, {}, 0, inf, true},
      {"hertz3d.block_poisson", "", "Poisson's ratio of the block, if it differs from material.poisson",
       Type::number, {}, -1, 0.5, true, true},
  };
  // clang-format on
}

Hertz3dParameters hertz3d_parameters(const io::Settings& s)
{
  Hertz3dParameters p;
  p.radius = s.number("hertz3d.radius");
  p.load = s.number("hertz3d.load");
  p.tangential_load = s.number("hertz3d.tangential_load");
  p.tangential_displacement = s.number("hertz3d.tangential_displacement");
  p.friction_coefficient = p.tangential_displacement > 0
      ? cattaneo_mindlin_coefficient(s, "hertz3d.tangential_displacement", p.tangential_displacement, "m", "sphere")
      : cattaneo_mindlin_coefficient(s, "hertz3d.tangential_load", p.tangential_load, "N", "sphere");
  p.material = material_setting(s);
  p.block_material = block_material_setting(s, "hertz3d", p.material);
  p.element_size = s.number("hertz3d.element_size");
  p.refinement = s.number("hertz3d.refinement");
  p.master_ratio = s.number("hertz3d.master_ratio");
  p.block_radius = s.number("hertz3d.block_radius");
  p.cap_radius = s.number("hertz3d.cap_radius");
  p.radial_aspect = s.number("hertz3d.radial_aspect");
  for (const mesh::CellKind kind : mesh::all_cell_kinds)
    if (mesh::cell_type(kind).name == s.text("hertz3d.cell"))
      p.cell = kind;
  p.gmsh_mesh = s.text("hertz3d.mesh") == "gmsh";
  return p;
}

std::unique_ptr<BuiltInProblem> make_hertz3d_problem(const io::Settings& settings)
{
  return std::make_unique<Hertz3dProblem>(hertz3d_parameters(settings));
}
} // namespace feticon::problems
