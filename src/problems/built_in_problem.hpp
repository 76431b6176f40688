#pragma once
/// @file The problems feticon builds itself, behind one interface. deal.II's step-42 is the
/// model: a problem class declares its settings, reads its parameters from them, builds its
/// mesh and writes its own comparison with theory; `feticon run` knows none of them by name.
/// A `problem: custom` file or an input deck is io's (io/problem_file.hpp, io/deck.hpp).
///
/// Usage:
///   io::ProblemFile file = io::load_problem_file(path, overrides, problems::setting_specs());
///   if (auto built_in = problems::make_built_in_problem(file.settings))
///     fem::Problem problem = built_in->build();

#include "fem/material.hpp"
#include "fem/problem.hpp"
#include "io/settings.hpp"
#include "la/types.hpp"

#include <nlohmann/json.hpp>

#include <cstdint>
#include <memory>
#include <optional>
#include <string>
#include <vector>

namespace feticon::problems
{
/// The size of the mesh `build` makes, known before it is made (memory guard).
struct MeshPrediction
{
  int64_t nodes = 0;
  bool plane_strain = false;
};

/// One slave node's (plane strain: node line's) contact pressure where it is, in the reference
/// and the deformed configuration.
struct SurfaceSample
{
  double x = 0, y = 0;                   ///< reference coordinates (m)
  double deformed_x = 0, deformed_y = 0; ///< x + u_x, y + u_y (m)
  double pressure = 0;                   ///< (Pa)
  double shear_x = 0;                    ///< friction traction along x (Pa)
  double friction_force_x = 0;           ///< friction force along x (N)
  bool slipping = false;                 ///< the friction force is at its bound
  double shear_y = 0;                    ///< friction traction along y (Pa)
  double area = 0;                       ///< the sample's tributary area (m^2)
  double normal_force_x = 0;             ///< the normal contact force along x (N)
};

/// A completed run's figures against theory.
struct TheoryComparison
{
  std::string name;                   ///< of summary.json's block ("hertz")
  nlohmann::ordered_json figures;     ///< that block
  double applied_load = 0;            ///< the load the contact must carry (N): summary.json contact.applied_load
  std::vector<double> analytic;       ///< the theory's pressure at each sample, in the frame of the figures (Pa)
  std::vector<double> analytic_shear; ///< its shear traction along x (Pa), where it has one (else empty)
  std::string summary_line;           ///< for the end-of-run table
};

class BuiltInProblem
{
public:
  virtual ~BuiltInProblem() = default;
  /// The mesh size before the mesh is made; throws feticon::Error naming a parameter out of range.
  virtual MeshPrediction predict_mesh() const = 0;
  virtual fem::Problem build() const = 0;
  /// The comparison of a completed run's contact pressures (`samples`, slave surface of pair
  /// 0) and displacement `u` with theory; none for a problem without an analytic solution.
  /// `large`: total Lagrangian kinematics, the figures in the deformed frame.
  virtual std::optional<TheoryComparison> compare_with_theory(const fem::Problem& problem, const la::Vector& u,
                                                              const std::vector<SurfaceSample>& samples,
                                                              bool large) const
  {
    (void)problem, (void)u, (void)samples, (void)large;
    return std::nullopt;
  }
};

/// The keys of the built-in problems: `problem` (their names and custom), the `material` every
/// body of theirs is made of, and each problem's own; for io::load_problem_file.
std::vector<io::SettingSpec> setting_specs();

/// The built-in problem named by the `problem` setting, with its parameters from `settings`
/// (made with setting_specs); nullptr for `custom`.
std::unique_ptr<BuiltInProblem> make_built_in_problem(const io::Settings& settings);

/// `material.young` and `material.poisson`.
fem::Material material_setting(const io::Settings& settings);
/// Coulomb's mu for a Cattaneo-Mindlin comparison (0 unless contact.friction.model = coulomb);
/// throws feticon::Error if `tangential_load` (the setting `key`, in `unit`) is positive and
/// the model has no friction to hold `body`.
double cattaneo_mindlin_coefficient(const io::Settings& settings, const std::string& key, double tangential_load,
                                    const std::string& unit, const std::string& body);
/// The second body's material if `prefix`.block_young or `prefix`.block_poisson is given (the
/// other one from `material`).
std::optional<fem::Material> block_material_setting(const io::Settings& settings, const std::string& prefix,
                                                    const fem::Material& material);
} // namespace feticon::problems
