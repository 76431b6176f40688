#include "io/settings.hpp"

#include "common/error.hpp"

#include <algorithm>
#include <cerrno>
#include <cmath>
#include <sstream>

namespace feticon::io
{
namespace
{
using Type = SettingSpec::Type;

/// The contact pair's keys (contact.*).
std::vector<SettingSpec> contact_specs()
{
  const double inf = 1e300;
  // clang-format off
  return {
      {"contact.formulation", "mortar", "contact rows: node_to_segment (slave node on master "
                                                 "face) or mortar (dual mortar, segment-to-segment); where "
                                                 "given, for every pair, else each pair's own (a deck's "
                                                 "pair TYPE, a problem file pair's formulation; mortar)",
       Type::text, {"node_to_segment", "mortar"}, 0, 0, false},
      {"contact.law", "hard", "the contact pairs' normal law: hard (exact non-penetration, whatever a pair's "
       "own law) or deck (each pair's own: an input deck's *SURFACE BEHAVIOR, a problem file pair's law; a "
       "linear pressure-overclosure law p = K max(overclosure, 0) becomes a compliance on the pair's dual "
       "rows, FETI solver)",
       Type::text, {"hard", "deck"}, 0, 0, false},
      {"contact.friction.model", "none", "friction on the contact pair (FETI solver): none, tresca (the "
       "tangential traction bounded by contact.friction.slip_bound) or coulomb (bounded by "
       "contact.friction.coefficient times the contact pressure); where given, for every pair, else each "
       "pair's own (an input deck's *FRICTION, a problem file pair's friction: {model: coulomb, coefficient: "
       "0.3}); likewise each of the two numbers below",
       Type::text, {"none", "tresca", "coulomb"}, 0, 0, false},
      {"contact.friction.coefficient", "0", "Coulomb's friction coefficient mu", Type::number, {}, 0, 100, false},
      {"contact.friction.slip_bound", "0", "Tresca's slip bound g, the largest tangential traction (Pa)",
       Type::number, {}, 0, inf, false},
      {"contact.linear_band", "0.25", "small displacements: the QP gets the contact rows whose gap is "
       "below the smallest plus this many master face diagonals, and another QP follows with the "
       "rows near contact if the answer penetrates a row left out (a large value: every row within "
       "the search distance)", Type::number, {}, 0, inf, true},
      {"contact.first_rows", "reached", "large displacements, the first outer iteration from rest: reached (the "
       "rows near contact and those the answer of a rough QP on them, at rtol 0.1, comes within the band of; "
       "the QP then starts from zero on them) or near (the rows near contact alone)",
       Type::text, {"reached", "near"}, 0, 0, false},
      {"contact.feasibility_tolerance", "1e-3", "warn (summary.json warnings, stderr) when the dual "
       "penalty leaves ||G lambda - e|| / ||e|| above this", Type::number, {}, 0, 1, true},
  };
  // clang-format on
}

/// contact_specs with the keys that override the contact pairs' own interactions marked.
std::vector<SettingSpec> contact_specs_marked()
{
  std::vector<SettingSpec> specs = contact_specs();
  for (SettingSpec& spec : specs)
    spec.overrides_model = spec.key == "contact.formulation" || spec.key.starts_with("contact.friction.");
  return specs;
}

std::vector<SettingSpec> make_specs()
{
  const double inf = 1e300;
  // One key per entry, as the help lists them.
  // clang-format off
  std::vector<SettingSpec> specs = {
      {"problem", "custom", "custom (mesh, materials, bodies, supports, loads, contact sections of the problem file, "
                            "or an input deck)", Type::text, {"custom"}, 0, 0, false},
      {"method", "smalbe", "contact solver: smalbe (SMALBE-M, exact G lambda = e), dual_penalty "
                           "(problem (9) of Vondrák et al.), primal_penalty (undecomposed, CHOLMOD)",
       Type::text, {"smalbe", "dual_penalty", "primal_penalty"}, 0, 0, false},
      {"rho", "1", "dual penalty rho, dimensionless (F and d scaled by ||PFP||); with method = dual_penalty "
       "1000 unless given (its feasibility error falls like 1 / rho)", Type::number, {}, 0, inf, true},
      {"smalbe.M0", "1", "SMALBE-M initial M (scaled units: ||PFP|| = 1)", Type::number, {}, 0, 1e6, true},
      {"smalbe.beta", "2", "SMALBE-M: M <- M / beta when the Lagrangian increases too little", Type::number, {}, 1, 1e6, true},
      {"smalbe.rho_growth", "auto",
       "SMALBE-M: the least factor rho grows by where ||G lambda - e|| stalls (at most 1000; 1: rho stays), or "
       "auto: 3 without friction, 10 with (docs/contact.md)", Type::number, {}, 1, 1e6, false, false, true},
      {"eps_n", "100", "primal penalty eps_n as a multiple of max diag K", Type::number, {}, 0, inf, true},
      {"displacements", "large", "large (total Lagrangian, Vondrák et al.'s benchmark) or small (linear elasticity)", Type::text, {"small", "large"}, 0, 0, false},
      {"newton.stiffness", "auto", "FETI outer-loop stiffness: initial (K_0 kept, Vondrák et al.'s "
                                   "modified Newton), step or iteration (K_M(u) refreshed); auto: initial, "
                                   "iteration where a body is plastic (docs/materials.md) or a coupling turns by finite "
                                   "rotations (docs/contact.md), and from the first load step that fails under K_0 on "
                                   "(with QPs to qp.rtol alone; docs/contact.md)",
       Type::text, {"auto", "initial", "step", "iteration"}, 0, 0, false},
      {"newton.max_iterations", "15", "outer iterations per load step", Type::integer, {}, 1, 10000, false},
      {"hyperelastic.fbar", "false", "F-bar on the linear cells (quad4, hex8) of hyperelastic bodies: one volume "
       "change per cell, so that a nearly incompressible law does not lock them (docs/materials.md; CalculiX's "
       "C3D8 and CAX4 have none)", Type::boolean, {}, 0, 0, false},
      {"plasticity.fbar", "false", "F-bar on the linear cells (quad4, hex8) of plastic bodies with large "
       "displacements: one volume change per cell, so that isochoric plastic flow does not lock them "
       "(docs/materials.md; CalculiX's C3D8 and CAX4 have none)", Type::boolean, {}, 0, 0, false},
      {"newton.cutbacks", "5", "a load step whose outer loop diverges or does not converge is solved again from "
       "its start with half the increment, up to this many times in a row (CalculiX's and Abaqus's cutbacks); "
       "0 stops the run", Type::integer, {}, 0, 50, false},
      {"newton.tolerance", "1e-6", "load step converged when ||du|| <= tolerance ||u||, the residual "
       "test holds and the active set did not change", Type::number, {}, 0, 1, true},
      {"newton.residual_tolerance", "1e-6", "and ||t f_ext - f_int - B'lambda|| <= residual_tolerance "
       "max(||t f_ext||, ||f_int||) (FETI solvers)", Type::number, {}, 0, 1, true},
      {"newton.forcing", "0.001", "inexact outer iterations: the QP of outer iteration k stops at "
       "max(qp.rtol, min(1e-4, forcing * |du_(k-1)|/|u|)); 0 solves every QP to qp.rtol", Type::number, {}, 0, 1, false},
      {"load_steps", "auto", "load steps for large displacements, equal increments (a failing one is cut back, "
       "newton.cutbacks); auto: 1 without friction, whose answer does not depend on the path, 2 with friction",
       Type::integer, {}, 1, 1000, false, false, true},
      {"subdomains", "auto", "number of FETI subdomains, or auto: chosen from the mesh size and the memory "
       "budget (summary.json subdomains_reason; docs/usage.md)", Type::integer, {}, 1, 1e6, false, false, true},
      {"subdomain_cells", "0", "cells per subdomain, (H/h)^3 in 3D or (H/h)^2 for one layer; if > 0 "
                               "it sets the number of subdomains instead of 'subdomains'",
       Type::integer, {}, 0, 1e9, false},
      {"partitioner", "metis", "metis (k-way, the cut faces' area least), rcb (recursive coordinate bisection: box-like "
                              "subdomains) or structured (slabs along x)",
       Type::text, {"metis", "rcb", "structured"}, 0, 0, false},
      {"dual.operator", "auto", "F and the Dirichlet preconditioner: implicit (substitutions with the subdomain "
                                "factors), explicit (dense blocks on the subdomain boundaries, formed once per "
                                "factorization; needs qp.preconditioner=dirichlet) or auto (explicit where the "
                                "blocks fit the memory and pay for their set-up)",
       Type::text, {"implicit", "explicit", "auto"}, 0, 0, false},
      {"dual.factor_precision", "auto", "what the supernodal Cholesky factors of the subdomains (K+ and the "
       "Dirichlet preconditioner's K_ii) are kept in: double, single (half the memory and traffic of the "
       "substitutions, applied in double arithmetic; the primal recovery refines against K in double) or auto "
       "(single in 3D unless the whole interior's Dirichlet preconditioner may make the dual operators explicit; "
       "double in plane strain)",
       Type::text, {"double", "single", "auto"}, 0, 0, false},
      {"qp.rtol", "1e-8", "QP stopping tolerance ||g_P|| <= rtol ||b||", Type::number, {}, 0, 1, true},
      {"qp.force_rtol", "1e-7", "SMALBE-M also stops when ||g_P|| and ||G lambda - e|| (force units of the "
       "scaled dual) are at most force_rtol max(||f_ext||, ||f_int||) and the subdomains' net forces at most a "
       "quarter of newton.residual_tolerance times that force (method dual_penalty: when ||g_P|| is): the QP to "
       "the accuracy the outer loop asks, where ||b|| is of the order of the load; 0: qp.rtol alone", Type::number, {}, 0, 1, false},
      {"qp.expansion", "auto", "MPRGP expansion step: std (feasible half step and projected gradient step, "
       "ALGORITHMS.md 5), projcg (the CG step projected, with std as fallback where it raises the cost) or auto "
       "(projcg where the model has slender bodies, whose contact opens and closes over their length, std "
       "otherwise; summary.json expansion.reason)",
       Type::text, {"auto", "std", "projcg"}, 0, 0, false},
      {"qp.preconditioner", "auto", "MPRGP preconditioning in the face: none, lumped (P B K B' P), "
       "dirichlet (P B S B' P, S the subdomain Schur complements on their boundary) or auto (dirichlet in plane "
       "strain; in 3D dirichlet on a band of one cell layer (qp.dirichlet_layers), lumped with quadratic cells; "
       "summary.json preconditioner.reason)",
       Type::text, {"none", "lumped", "dirichlet", "auto"}, 0, 0, false},
      {"qp.dirichlet_layers", "auto", "cell layers of each subdomain's interior that the Dirichlet preconditioner's "
       "Schur complement eliminates, the rest held fixed: a cheaper, weaker S applied implicitly; 0: the whole interior; "
       "auto: 1 where qp.preconditioner = auto picks the band (3D, linear cells), else 0", Type::integer, {}, 0, 1000, false, false, true},
      {"qp.constraint_scaling", "true", "scale the preconditioner by (B B')^-1 on both sides "
       "(mortar FETI): needed when contact rows are not orthogonal to each other and to the gluing rows",
       Type::boolean, {}, 0, 0, false},
      {"qp.max_iterations", "20000", "MPRGP iteration limit", Type::integer, {}, 1, 1e9, false},
      {"qp.spectrum_steps", "0", "diagnostic: after each QP, this many preconditioned CG steps on the face "
       "of its solution estimate the spectrum of the preconditioned dual operator there "
       "and count the steps CG needs there to qp.rtol (summary.json qp.solution_face_spectrum); 0: off", Type::integer, {}, 0, 100000, false},
      {"memory_limit", "0", "memory budget of a run in bytes (e.g. 8e9): a run whose estimated peak "
       "exceeds it is refused before it allocates; 0: /proc/meminfo's MemAvailable or, if smaller, the room "
       "under the cgroup's memory limit, shared by the ranks of a node", Type::number, {}, 0, inf, false},
      {"output.vtu", "true", "write VTU/PVD files", Type::boolean, {}, 0, 0, false},
      {"output.plots", "true", "draw model.png, contact.png, contact_pressure.png and iterations.png (Debian's python3-matplotlib)",
       Type::boolean, {}, 0, 0, false},
  };
  // clang-format on
  const std::vector<SettingSpec> contact = contact_specs_marked(); // listed before eps_n
  specs.insert(std::find_if(specs.begin(), specs.end(), [](const SettingSpec& s) { return s.key == "eps_n"; }),
               contact.begin(), contact.end());
  return specs;
}

std::string trim(const std::string& s)
{
  const auto b = s.find_first_not_of(" \t");
  const auto e = s.find_last_not_of(" \t");
  return b == std::string::npos ? "" : s.substr(b, e - b + 1);
}

/// `value` with control bytes (a NUL from YAML's "\x00") as '?', for a one-line message.
std::string printable(std::string value)
{
  for (char& c : value)
    if (static_cast<unsigned char>(c) < 0x20 || c == 0x7f)
      c = '?';
  return value;
}

} // namespace

Settings::Settings() : Settings(std::vector<SettingSpec>{}) {}

Settings::Settings(std::vector<SettingSpec> declared)
{
  static const std::vector<SettingSpec> table = make_specs();
  std::vector<SettingSpec> all = std::move(declared);
  const size_t n_declared = all.size();
  for (const SettingSpec& s : table)
    if (std::none_of(all.begin(), all.begin() + n_declared, [&](const SettingSpec& d) { return d.key == s.key; }))
      all.push_back(s);
  for (const auto& s : all)
    _values[s.key] = s.default_value;
  FETICON_ASSERT(_values.size() == all.size(), "a key declared twice");
  _specs = std::make_shared<const std::vector<SettingSpec>>(std::move(all));
}

std::string Settings::help() const
{
  std::ostringstream os;
  for (const auto& s : specs())
    os << "  " << s.key << (s.default_value.empty() ? " (optional)" : " (default " + s.default_value + ")") << ": "
       << s.help << '\n';
  return os.str();
}

bool Settings::knows(const std::string& key) const { return _values.count(key) > 0; }

const SettingSpec& Settings::spec(const std::string& key, const std::string& source) const
{
  for (const auto& s : specs())
    if (s.key == key)
      return s;
  FETICON_CHECK(false,
                source << ": unknown key '" << key
                       << "'; run 'feticon run --help' for "
                          "the list of keys");
  throw; // unreachable: FETICON_CHECK(false, ...) throws
}

void Settings::set(const std::string& key, const std::string& raw, const std::string& source)
{
  const SettingSpec& s = spec(key, source);
  const std::string value = trim(raw);
  switch (s.type)
  {
  case Type::number:
  case Type::integer:
  {
    if (s.or_auto && value == "auto")
      break;
    char* end = nullptr;
    errno = 0;
    const double v = std::strtod(value.c_str(), &end);
    // The whole value, not up to a NUL byte (YAML's "\x00" is a one-byte string strtod reads as
    // empty, which std::stod refused later).
    FETICON_CHECK(!value.empty() && end == value.c_str() + value.size() && std::isfinite(v),
                  source << ": " << key << " = '" << printable(value) << "' is not a finite number"
                         << (s.or_auto ? " or auto" : ""));
    // Underflow (1e-320, subnormal) as well: no setting means anything there, and number()
    // would not read it back.
    FETICON_CHECK(errno != ERANGE,
                  source << ": " << key << " = " << value << " is out of the range of normal double-precision numbers");
    if (s.type == Type::integer)
      FETICON_CHECK(v == std::floor(v), source << ": " << key << " = " << value << " must be an integer");
    const bool below = s.min_exclusive ? v <= s.min : v < s.min;
    const bool above = s.max_exclusive ? v >= s.max : v > s.max;
    FETICON_CHECK(!below && !above,
                  source << ": " << key << " = " << value << " is out of range " << (s.min_exclusive ? "(" : "[")
                         << s.min << ", " << s.max << (s.max_exclusive ? ")" : "]") << ": " << s.help);
    break;
  }
  case Type::text:
    if (!s.choices.empty())
    {
      bool ok = false;
      std::string list;
      for (const auto& c : s.choices)
      {
        ok = ok || c == value;
        list += (list.empty() ? "" : ", ") + c;
      }
      FETICON_CHECK(ok, source << ": " << key << " = '" << printable(value) << "' must be one of: " << list);
    }
    break;
  case Type::boolean:
    FETICON_CHECK(value == "true" || value == "false",
                  source << ": " << key << " = '" << printable(value) << "' must be true or false");
    break;
  }
  _values[key] = value;
  _given.insert(key);
}

double Settings::number(const std::string& key) const
{
  const std::string& value = _values.at(key);
  FETICON_CHECK(!value.empty(), key << " has no value (it is optional)");
  return std::stod(value);
}

std::optional<double> Settings::optional_number(const std::string& key) const
{
  const std::string& value = _values.at(key);
  return value.empty() ? std::nullopt : std::optional<double>(std::stod(value));
}
int Settings::integer(const std::string& key) const
{
  FETICON_CHECK(!is_auto(key), key << " is auto: the run chooses it (app/feti_choice)");
  return static_cast<int>(std::stod(_values.at(key)));
}
const std::string& Settings::text(const std::string& key) const { return _values.at(key); }
bool Settings::flag(const std::string& key) const { return _values.at(key) == "true"; }

std::string Settings::to_yaml() const
{
  std::ostringstream os;
  os << "# effective settings of this run (defaults, problem file, --set overrides)\n";
  for (const auto& s : specs())
    if (_values.at(s.key).empty())
      os << "# " << s.key << ": not given\n";    // an optional key; `key:` would read back as null
    else if (s.overrides_model && !given(s.key)) // given, it would override the model's own
      os << "# " << s.key << ": " << _values.at(s.key) << " (not given: each contact pair's own)\n";
    else
      os << s.key << ": " << _values.at(s.key) << '\n';
  return os.str();
}
} // namespace feticon::io
