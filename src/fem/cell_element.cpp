#include "fem/cell_element.hpp"

#include "common/error.hpp"
#include "fem/finite_j2_plasticity.hpp"
#include "fem/hyperelasticity.hpp"

#include <array>
#include <cmath>
#include <type_traits>

namespace feticon::fem
{
namespace
{
/// Per-cell matrices of N nodes: fixed sizes for the node counts of the cell types (3, 4, 6, 8,
/// 10, 20: cell_element dispatches on it), so that Eigen unrolls the small products (the
/// generic element was a sixth of a 2D Hertz run's profile with run-time sizes), and for any
/// other count run-time sizes bounded by the largest cell (hex20), so that the element loop
/// allocates nothing (malloc and free were a fifth of that profile before the bound).
constexpr int max_nodes = 20;
template <int N>
constexpr int max_rows = N == Eigen::Dynamic ? max_nodes : N;
template <int N>
using CellGradients = Eigen::Matrix<double, N, 3, Eigen::ColMajor, max_rows<N>, 3>;
template <int N>
using CellValues = Eigen::Matrix<double, N, 1, Eigen::ColMajor, max_rows<N>, 1>;
template <int N>
using StrainDisplacement =
    Eigen::Matrix<double, 6, N == Eigen::Dynamic ? Eigen::Dynamic : 3 * N, Eigen::ColMajor, 6, 3 * max_rows<N>>;
/// A cell's node coordinates or displacements (one row per node), viewed without a copy.
template <int N>
using CellNodes = Eigen::Map<const Eigen::Matrix<double, N, 3>>;

template <int N>
CellNodes<N> cell_nodes(const Eigen::MatrixX3d& x)
{
  return CellNodes<N>(x.data(), x.rows(), 3);
}

/// Gradients with respect to X and w det J at one quadrature point; an inverted or flat cell
/// is an error naming it. A 2D cell's gradients have no z column, its w det J is times the
/// out-of-plane measure (mesh::Planar::measure), and in axisymmetry `hoop` holds N_a / r, which
/// gives the hoop strain u_r / r.
template <int N>
struct PointGeometry
{
  CellGradients<N> dN_dX;
  double weight_det_j = 0;
  bool axisymmetric = false;
  CellValues<N> hoop; ///< set in axisymmetry only
};

template <int N>
PointGeometry<N> point_geometry(mesh::CellKind type, const CellNodes<N>& X, const PointShapes& shapes, double weight,
                                int64_t cell, const mesh::Planar& planar)
{
  FETICON_ASSERT(shapes.dN.rows() <= max_nodes, "a cell of more than " << max_nodes << " nodes");
  const CellNodes<N> dN = cell_nodes<N>(shapes.dN);
  if (!mesh::is_planar(type))
  {
    const Eigen::Matrix3d J = X.transpose() * dN; // dX_i / dxi_j
    const double det = J.determinant();
    FETICON_CHECK(det > 0,
                  "cell " << cell << " (" << mesh::cell_type(type).name
                          << ") is inverted or flat: det(dX/dxi) = " << det << " at a quadrature point");
    return {dN * J.inverse(), weight * det, false, {}};
  }
  FETICON_CHECK(planar.kind != mesh::PlanarKind::none,
                "cell " << cell << " (" << mesh::cell_type(type).name << ") is 2D but the model is 3D");
  const Eigen::Matrix2d J = X.template leftCols<2>().transpose() * dN.template leftCols<2>();
  const double det = J.determinant();
  FETICON_CHECK(det > 0,
                "cell " << cell << " (" << mesh::cell_type(type).name << ") is inverted or flat: det(dX/dxi) = " << det
                        << " at a quadrature point (2D cells run counter-clockwise in the x-y plane)");
  PointGeometry<N> geo{CellGradients<N>::Zero(dN.rows(), 3), 0, false, {}};
  geo.dN_dX.template leftCols<2>() = dN.template leftCols<2>() * J.inverse();
  const Eigen::Map<const CellValues<N>> shape_values(shapes.N.data(), shapes.N.size());
  const Eigen::Vector3d x = X.transpose() * shape_values;
  if (planar.kind == mesh::PlanarKind::axisymmetric)
  {
    FETICON_CHECK(x(0) > 0,
                  "cell " << cell << " (axisymmetric " << mesh::cell_type(type).name
                          << ") has a quadrature point at r = x = " << x(0)
                          << ": an axisymmetric model lies at x >= 0");
    geo.axisymmetric = true;
    geo.hoop = shape_values / x(0);
  }
  geo.weight_det_j = weight * det * planar.measure(x);
  return geo;
}

/// B_NL for the deformation gradient Fd (Fd = I: the linear B); in axisymmetry the hoop term
/// adds the variation of E_33 = 1/2 (F_33^2 - 1), F_33 = 1 + u_r / r, with the radial
/// displacements.
template <int N>
StrainDisplacement<N> strain_displacement(const PointGeometry<N>& geo, const Eigen::Matrix3d& Fd)
{
  const CellGradients<N>& dN = geo.dN_dX;
  StrainDisplacement<N> B(6, 3 * dN.rows());
  for (Eigen::Index a = 0; a < dN.rows(); ++a)
    for (int i = 0; i < 3; ++i)
    {
      const Eigen::Index col = 3 * a + i;
      B(0, col) = Fd(i, 0) * dN(a, 0);
      B(1, col) = Fd(i, 1) * dN(a, 1);
      B(2, col) = Fd(i, 2) * dN(a, 2);
      B(3, col) = Fd(i, 0) * dN(a, 1) + Fd(i, 1) * dN(a, 0);
      B(4, col) = Fd(i, 1) * dN(a, 2) + Fd(i, 2) * dN(a, 1);
      B(5, col) = Fd(i, 2) * dN(a, 0) + Fd(i, 0) * dN(a, 2);
    }
  if (geo.axisymmetric)
    for (Eigen::Index a = 0; a < dN.rows(); ++a)
      B(2, 3 * a) += Fd(2, 2) * geo.hoop(a);
  return B;
}

/// A 2D cell's B where its element vector and matrix are read: the rows 11, 22, 33 and 12 on
/// the x and y columns, 4 x 2N (u_z is no unknown of a 2D model, and on the x and y columns the
/// rows 23 and 31 are zero: F_13 = F_23 = 0 and no gradient in z). The products on it take a
/// third of the multiplications of the full B's.
template <int N>
using InPlaneStrainDisplacement =
    Eigen::Matrix<double, 4, N == Eigen::Dynamic ? Eigen::Dynamic : 2 * N, Eigen::ColMajor, 4, 2 * max_rows<N>>;

template <int N>
InPlaneStrainDisplacement<N> in_plane_strain_displacement(const PointGeometry<N>& geo, const Eigen::Matrix3d& Fd)
{
  const CellGradients<N>& dN = geo.dN_dX;
  InPlaneStrainDisplacement<N> B(4, 2 * dN.rows());
  for (Eigen::Index a = 0; a < dN.rows(); ++a)
    for (int i = 0; i < 2; ++i)
    {
      const Eigen::Index col = 2 * a + i;
      B(0, col) = Fd(i, 0) * dN(a, 0);
      B(1, col) = Fd(i, 1) * dN(a, 1);
      B(2, col) = 0;
      B(3, col) = Fd(i, 0) * dN(a, 1) + Fd(i, 1) * dN(a, 0);
    }
  if (geo.axisymmetric)
    for (Eigen::Index a = 0; a < dN.rows(); ++a)
      B(2, 2 * a) += Fd(2, 2) * geo.hoop(a);
  return B;
}

/// The deformation gradient used in B (I for linear kinematics) and the strain, Voigt with
/// engineering shears.
template <int N>
std::pair<Eigen::Matrix3d, Voigt> deformation(const PointGeometry<N>& geo, const CellNodes<N>& u, Kinematics kinematics,
                                              int64_t cell)
{
  Eigen::Matrix3d grad_u = u.transpose() * geo.dN_dX; // du_i / dX_j
  if (geo.axisymmetric)
    grad_u(2, 2) = u.col(0).dot(geo.hoop); // u_r / r
  Voigt strain;
  if (kinematics == Kinematics::linear)
  {
    strain << grad_u(0, 0), grad_u(1, 1), grad_u(2, 2), grad_u(0, 1) + grad_u(1, 0), grad_u(1, 2) + grad_u(2, 1),
        grad_u(2, 0) + grad_u(0, 2);
    return {Eigen::Matrix3d::Identity(), strain};
  }
  const Eigen::Matrix3d Fd = Eigen::Matrix3d::Identity() + grad_u;
  FETICON_CHECK(Fd.determinant() > 0,
                "element " << cell << " is inverted in the deformed configuration (det F = " << Fd.determinant()
                           << "); use more load steps or check the loads");
  const Eigen::Matrix3d E = 0.5 * (Fd.transpose() * Fd - Eigen::Matrix3d::Identity());
  strain << E(0, 0), E(1, 1), E(2, 2), 2 * E(0, 1), 2 * E(1, 2), 2 * E(2, 0);
  return {Fd, strain};
}
/// F-bar (de Souza Neto, Peric, Dutko and Owen 1996, Int. J. Solids Struct. 33) on the linear
/// cells of a hyperelastic body (Material::fbar): each point's volume change is replaced by the
/// cell's, F_bar = (J_0 / J)^(1/d) F with d the dimensions whose stretch is free (3; 2 in plane
/// strain, whose F_33 = 1 stays), so that a nearly incompressible law holds one volume per cell
/// instead of one per point (full-integration quad4 and hex8 lock otherwise: docs/materials.md).
/// J_0 is the cell's mean of J over its reference volume, not J at its centre: the mean passes
/// the patch test on any cell shape and in axisymmetry (a homogeneous F gives F_bar = F and the
/// forces of the standard cell), the centre's does not (the mean dilatation of Simo, Taylor and
/// Pister 1985). S = S(E(F_bar)); the internal force is the derivative of the energy of F_bar,
/// f = int B_bar' S with B_bar = dE(F_bar)/du, and K = int B_bar' C B_bar is its material part:
/// symmetric, with the rigid motions as its kernel, as FETI needs (the exact tangent is not
/// symmetric; the outer loop, which already leaves out the geometric stiffness of hyperelastic
/// bodies, converges linearly).
struct CellVolume
{
  double J = 1; ///< J_0 = int J dV / V
  /// d(ln J_0)/du_ai = int J tr(F^-1 dF/du_ai) dV / int J dV, one row per node
  Eigen::Matrix<double, Eigen::Dynamic, 3, Eigen::ColMajor, max_nodes, 3> log_derivative;
  int dimensions = 3;
};

bool uses_fbar(mesh::CellKind type, const Material& material, Kinematics kinematics)
{
  return material.fbar && (material.is_hyperelastic() || material.is_plastic()) &&
      kinematics == Kinematics::total_lagrangian && (type == mesh::CellKind::hex8 || type == mesh::CellKind::quad4);
}

/// tr(F^-1 dF/du_ai) of every node a and component i at a point: dF/du_ai = e_i g_a' (g_a the
/// gradient of N_a), and N_a / r at 33 for u_r in axisymmetry.
CellGradients<Eigen::Dynamic> log_volume_derivative(const PointGeometry<Eigen::Dynamic>& geo,
                                                    const Eigen::Matrix3d& F_inverse)
{
  CellGradients<Eigen::Dynamic> t = geo.dN_dX * F_inverse;
  if (geo.axisymmetric)
    t.col(0) += F_inverse(2, 2) * geo.hoop;
  return t;
}

/// A quad4 or hex8 cell's points (their geometry and F, computed once) and its J_0.
struct FbarCell
{
  static constexpr size_t max_points = 8; // hex8's 2 x 2 x 2
  std::array<PointGeometry<Eigen::Dynamic>, max_points> geo;
  std::array<Eigen::Matrix3d, max_points> F;
  size_t n_points = 0;
  CellVolume volume;
};

FbarCell fbar_cell(mesh::CellKind type, const Eigen::MatrixX3d& X, const Eigen::MatrixX3d& u, int64_t cell,
                   const mesh::Planar& planar, Integration integration)
{
  const QuadratureRule& rule = quadrature(type, integration);
  const std::vector<PointShapes>& shapes = quadrature_shapes(type, integration);
  FETICON_ASSERT(rule.points.size() <= FbarCell::max_points, "F-bar on a cell of more than 8 points");
  FbarCell out;
  out.n_points = rule.points.size();
  CellVolume& volume = out.volume;
  volume.dimensions = planar.kind == mesh::PlanarKind::plane_strain ? 2 : 3;
  volume.log_derivative.setZero(X.rows(), 3);
  double reference = 0, deformed = 0;
  for (size_t q = 0; q < out.n_points; ++q)
  {
    out.geo[q] = point_geometry(type, cell_nodes<Eigen::Dynamic>(X), shapes[q], rule.weights[q], cell, planar);
    out.F[q] = deformation(out.geo[q], cell_nodes<Eigen::Dynamic>(u), Kinematics::total_lagrangian, cell).first;
    const double J = out.F[q].determinant(), w = out.geo[q].weight_det_j;
    reference += w;
    deformed += w * J;
    volume.log_derivative += (w * J) * log_volume_derivative(out.geo[q], out.F[q].inverse());
  }
  volume.J = deformed / reference;
  volume.log_derivative /= deformed;
  return out;
}

/// F_bar of a point whose deformation gradient is F, and the factor (J_0 / J)^(1/d).
std::pair<Eigen::Matrix3d, double> fbar_gradient(const CellVolume& volume, const Eigen::Matrix3d& F)
{
  const double alpha = std::pow(volume.J / F.determinant(), 1.0 / volume.dimensions);
  Eigen::Matrix3d F_bar = F;
  if (volume.dimensions == 3)
    F_bar *= alpha;
  else
    F_bar.topLeftCorner<2, 2>() *= alpha;
  return {F_bar, alpha};
}

/// E(F_bar), Voigt with engineering shears.
Voigt green_lagrange(const Eigen::Matrix3d& F)
{
  const Eigen::Matrix3d E = 0.5 * (F.transpose() * F - Eigen::Matrix3d::Identity());
  return (Voigt() << E(0, 0), E(1, 1), E(2, 2), 2 * E(0, 1), 2 * E(1, 2), 2 * E(2, 0)).finished();
}

/// B_bar = dE(F_bar)/du: with G = dF/du_ai, dF_bar = alpha (G + (d ln J_0 - tr(F^-1 G)) / d F_v),
/// F_v the part of F that F_bar scales; dE = sym(F_bar' dF_bar).
StrainDisplacement<Eigen::Dynamic> fbar_strain_displacement(const PointGeometry<Eigen::Dynamic>& geo,
                                                            const CellVolume& volume, const Eigen::Matrix3d& F,
                                                            const Eigen::Matrix3d& F_bar, double alpha)
{
  const auto trace = log_volume_derivative(geo, F.inverse());
  Eigen::Matrix3d F_v = F;
  if (volume.dimensions == 2)
  {
    F_v.row(2).setZero();
    F_v.col(2).setZero();
  }
  const Eigen::Index n = geo.dN_dX.rows();
  StrainDisplacement<Eigen::Dynamic> B(6, 3 * n);
  for (Eigen::Index a = 0; a < n; ++a)
    for (int i = 0; i < 3; ++i)
    {
      Eigen::Matrix3d G = Eigen::Matrix3d::Zero();
      G.row(i) = geo.dN_dX.row(a);
      if (i == 0 && geo.axisymmetric)
        G(2, 2) = geo.hoop(a);
      const Eigen::Matrix3d dF_bar =
          alpha * (G + (volume.log_derivative(a, i) - trace(a, i)) / volume.dimensions * F_v);
      const Eigen::Matrix3d dE = 0.5 * (F_bar.transpose() * dF_bar + dF_bar.transpose() * F_bar);
      B.col(3 * a + i) << dE(0, 0), dE(1, 1), dE(2, 2), 2 * dE(0, 1), 2 * dE(1, 2), 2 * dE(2, 0);
    }
  return B;
}

/// Plane stress (sigma_33 = 0 at every point): the material tangent of the in-plane strains,
/// D - D e_3 e_3' D / D_33.
Eigen::Matrix<double, 6, 6> plane_stress_tangent(const Eigen::Matrix<double, 6, 6>& D)
{
  return D - D.col(2) * D.row(2) / D(2, 2);
}

/// Plane stress: the strain_33 at which the stress D strain - thermal (1,1,1,0,0,0) has no 33
/// component. Exact in total-Lagrangian St Venant-Kirchhoff too, whose S is linear in E.
void free_thickness_strain(const Eigen::Matrix<double, 6, 6>& D, double thermal, Voigt& strain)
{
  strain(2) = 0;
  strain(2) = (thermal - D.row(2).dot(strain)) / D(2, 2);
}

/// A hyperelastic law is not convex in E (though polyconvex in F): a nearly incompressible one
/// loses definiteness at a dilatation J - 1 of about mu_0 / K_0, and K_M can then be indefinite,
/// which FETI's factorization of K_M refuses (K_M is symmetric positive semi-definite with the
/// rigid-body kernel; the geometric stiffness is left out for the same reason).
/// StiffnessKind::material_definite takes the nearest positive definite matrix instead, dS/dE
/// with its negative eigenvalues raised to 1e-8 of the largest. Only where the factorization
/// fails (decomposition/subdomain_operators.cpp): done at every point, or with the absolute
/// values of the eigenvalues, it slowed the quad4 seal at K_0 / mu_0 = 500 from 1.2 s to 6 s and
/// 22 s, and at 5000 it did not converge.
void make_positive_definite(Eigen::Matrix<double, 6, 6>& tangent)
{
  if (Eigen::LLT<Eigen::Matrix<double, 6, 6>>(tangent).info() == Eigen::Success)
    return;
  const Eigen::SelfAdjointEigenSolver<Eigen::Matrix<double, 6, 6>> eigen(tangent);
  Eigen::Matrix<double, 6, 1> values = eigen.eigenvalues();
  values = values.cwiseMax(1e-8 * values.maxCoeff());
  tangent = eigen.eigenvectors() * values.asDiagonal() * eigen.eigenvectors().transpose();
}

/// alpha E / (1 - 2 nu) Delta T at a quadrature point (0 without a temperature change).
double thermal_stress_at(const Material& material, const Eigen::VectorXd* temperature_change, const PointShapes& shapes)
{
  if (!temperature_change || material.expansion == 0)
    return 0;
  return material.thermal_stress() * shapes.N.dot(*temperature_change);
}
/// K_G(a, b) = (grad N_a' S grad N_b) I_3 w det J; in axisymmetry also S_33 N_a N_b / r^2 on
/// the radial components (E_33 = 1/2 (F_33^2 - 1) is quadratic in u_r / r).
template <int N>
void add_geometric_stiffness(const PointGeometry<N>& geo, const Voigt& S, Eigen::MatrixXd& K)
{
  Eigen::Matrix3d St;
  St << S(0), S(3), S(5), S(3), S(1), S(4), S(5), S(4), S(2);
  const Eigen::Matrix<double, N, N, Eigen::ColMajor, max_rows<N>, max_rows<N>> G =
      geo.dN_dX * (St * geo.weight_det_j) * geo.dN_dX.transpose();
  for (Eigen::Index a = 0; a < G.rows(); ++a)
    for (Eigen::Index b = 0; b < G.rows(); ++b)
      for (int i = 0; i < 3; ++i)
        K(3 * a + i, 3 * b + i) += G(a, b);
  if (geo.axisymmetric)
    for (Eigen::Index a = 0; a < G.rows(); ++a)
      for (Eigen::Index b = 0; b < G.rows(); ++b)
        K(3 * a, 3 * b) += S(2) * geo.hoop(a) * geo.hoop(b) * geo.weight_det_j;
}
} // namespace

namespace
{
/// The J2 update of a point: at small strain the radial return on eps less the thermal stress
/// (fem/j2_plasticity.hpp), with total Lagrangian kinematics Simo's finite-strain model on E
/// (fem/finite_j2_plasticity.hpp), which has no thermal strain (the assembler refuses one).
J2Update plastic_update(const Material& material, Kinematics kinematics, const Voigt& strain, double thermal,
                        const PlasticPointState& committed, Eigen::Matrix<double, 6, 6>* tangent)
{
  if (kinematics == Kinematics::linear)
    return j2_return(material, strain, thermal, committed, tangent);
  FETICON_ASSERT(thermal == 0, "a thermal strain at a finite-strain plastic point");
  return finite_j2_return(material, strain, committed, tangent);
}

/// S(E(F_bar)) of point q of an F-bar cell and its tangent dS/dE (where `tangent`): the
/// hyperelastic law, or Simo's finite-strain J2 return from the point's committed state (its
/// updated state written where the caller asks for it), on the strain of F_bar.
Voigt fbar_stress(const Material& material, const Voigt& strain, size_t q, const CellPlasticState* plastic,
                  Eigen::Matrix<double, 6, 6>* tangent)
{
  if (!material.is_plastic())
    return hyperelastic_stress(material.hyperelastic, strain, tangent);
  const J2Update update = finite_j2_return(material, strain, plastic->committed[q], tangent);
  if (!plastic->updated.empty())
    plastic->updated[q] = update.state;
  return update.stress;
}
} // namespace

namespace
{
/// A 2D cell's point: B' S w det J into f and, unless kind is none, B' C B w det J into K, on
/// the x and y entries (in_plane_strain_displacement).
template <int N>
void add_in_plane_point(const PointGeometry<N>& geo, const Eigen::Matrix3d& Fd, const Voigt& S,
                        const Eigen::Matrix<double, 6, 6>& C, StiffnessKind kind, Eigen::VectorXd& f,
                        Eigen::MatrixXd* K)
{
  constexpr int cols = InPlaneStrainDisplacement<N>::ColsAtCompileTime;
  const InPlaneStrainDisplacement<N> B = in_plane_strain_displacement(geo, Fd);
  const Eigen::Matrix<double, cols, 1, Eigen::ColMajor, 2 * max_rows<N>, 1> fb =
      B.transpose() * (S.head<4>() * geo.weight_det_j);
  const Eigen::Index n = geo.dN_dX.rows();
  for (Eigen::Index a = 0; a < n; ++a)
    f.segment<2>(3 * a) += fb.template segment<2>(2 * a);
  if (kind == StiffnessKind::none)
    return;
  const Eigen::Matrix<double, cols, 4, Eigen::ColMajor, 2 * max_rows<N>, 4> BtC =
      B.transpose() * (C.topLeftCorner<4, 4>() * geo.weight_det_j);
  const Eigen::Matrix<double, cols, cols, Eigen::ColMajor, 2 * max_rows<N>, 2 * max_rows<N>> Kb = BtC * B;
  for (Eigen::Index b = 0; b < n; ++b)
    for (Eigen::Index a = 0; a < n; ++a)
      K->block<2, 2>(3 * a, 3 * b) += Kb.template block<2, 2>(2 * a, 2 * b);
}

/// cell_element's points where the cell is not F-bar's, for a cell of N nodes (X, u one row per node).
template <int N>
void cell_points(mesh::CellKind type, const CellNodes<N>& X, const CellNodes<N>& u, const Material& material,
                 Kinematics kinematics, StiffnessKind kind, Integration integration, Eigen::VectorXd& f,
                 Eigen::MatrixXd* K, int64_t cell, const Eigen::VectorXd* temperature_change,
                 const CellPlasticState* plastic, const mesh::Planar& planar)
{
  const Eigen::Matrix<double, 6, 6> D = material.elasticity_matrix();
  const bool plane_stress = mesh::is_planar(type) && planar.kind == mesh::PlanarKind::plane_stress;
  const Eigen::Matrix<double, 6, 6> D_in_plane = plane_stress ? plane_stress_tangent(D) : D;
  const QuadratureRule& rule = quadrature(type, integration);
  const std::vector<PointShapes>& shapes = quadrature_shapes(type, integration);
  for (size_t q = 0; q < rule.points.size(); ++q)
  {
    const PointGeometry<N> geo = point_geometry<N>(type, X, shapes[q], rule.weights[q], cell, planar);
    auto [Fd, strain] = deformation<N>(geo, u, kinematics, cell);
    // S = D E is St Venant-Kirchhoff's S = lambda tr(E) I + 2 mu E in Voigt form (engineering
    // shears), of the strain less the thermal strain (and the plastic strain).
    const double thermal = thermal_stress_at(material, temperature_change, shapes[q]);
    if (plane_stress)
      free_thickness_strain(D, thermal, strain);
    Voigt S;
    const Eigen::Matrix<double, 6, 6>* C = &D_in_plane;
    Eigen::Matrix<double, 6, 6> tangent;
    if (material.is_plastic())
    {
      FETICON_ASSERT(plastic && plastic->committed.size() == rule.points.size(),
                     "a plastic cell needs a state per quadrature point");
      // The material part of K is the elasto-plastic tangent (small strain: all of K); at a
      // point that does not yield it is D (small strain), so K_0 (u = 0) is the elastic stiffness.
      const bool with_k = kind != StiffnessKind::none;
      const J2Update update =
          plastic_update(material, kinematics, strain, thermal, plastic->committed[q], with_k ? &tangent : nullptr);
      S = update.stress;
      if (!plastic->updated.empty())
        plastic->updated[q] = update.state;
      if (with_k && kind == StiffnessKind::material_definite)
        make_positive_definite(tangent);
      if (with_k)
        C = &tangent;
    }
    else if (material.is_hyperelastic())
    {
      FETICON_ASSERT(kinematics == Kinematics::total_lagrangian,
                     "a hyperelastic cell needs total Lagrangian kinematics");
      S = hyperelastic_stress(material.hyperelastic, strain, kind != StiffnessKind::none ? &tangent : nullptr);
      if (kind == StiffnessKind::material_definite)
        make_positive_definite(tangent);
      C = &tangent;
    }
    else
    {
      S = D * strain;
      S.head<3>().array() -= thermal;
    }
    if (mesh::is_planar(type))
    {
      add_in_plane_point(geo, Fd, S, *C, kind, f, K);
      if (kind == StiffnessKind::tangent && kinematics == Kinematics::total_lagrangian)
        add_geometric_stiffness(geo, S, *K);
      continue;
    }
    const StrainDisplacement<N> B = strain_displacement(geo, Fd);
    f.noalias() += B.transpose() * (S * geo.weight_det_j);
    if (kind == StiffnessKind::none)
      continue;
    const Eigen::Matrix<double, StrainDisplacement<N>::ColsAtCompileTime, 6, Eigen::ColMajor, 3 * max_rows<N>, 6> BtC =
        B.transpose() * (*C * geo.weight_det_j);
    K->noalias() += BtC * B;
    if (kind == StiffnessKind::tangent && kinematics == Kinematics::total_lagrangian)
      add_geometric_stiffness(geo, S, *K);
  }
}

/// f(std::integral_constant<int, N>) for the node count n of a cell: N = n for the counts of
/// the cell types, Eigen::Dynamic for any other.
template <class F>
void with_node_count(Eigen::Index n, F&& f)
{
  switch (n)
  {
  case 3:
    return f(std::integral_constant<int, 3>{});
  case 4:
    return f(std::integral_constant<int, 4>{});
  case 6:
    return f(std::integral_constant<int, 6>{});
  case 8:
    return f(std::integral_constant<int, 8>{});
  case 10:
    return f(std::integral_constant<int, 10>{});
  case 20:
    return f(std::integral_constant<int, 20>{});
  default:
    return f(std::integral_constant<int, Eigen::Dynamic>{});
  }
}
} // namespace

void cell_element(mesh::CellKind type, const Eigen::MatrixX3d& X, const Eigen::MatrixX3d& u, const Material& material,
                  Kinematics kinematics, StiffnessKind kind, Integration integration, Eigen::VectorXd& f,
                  Eigen::MatrixXd* K, int64_t cell, const Eigen::VectorXd* temperature_change,
                  const CellPlasticState* plastic, const mesh::Planar& planar)
{
  const Eigen::Index n = 3 * X.rows();
  const bool plane_stress = mesh::is_planar(type) && planar.kind == mesh::PlanarKind::plane_stress;
  FETICON_CHECK(!plane_stress || material.is_st_venant_kirchhoff(),
                "cell " << cell << ": " << (material.is_plastic() ? "plasticity" : "hyperelasticity")
                        << " in plane stress is not implemented (plane strain, axisymmetric and 3D cells are)");
  f.setZero(n);
  if (kind != StiffnessKind::none)
    K->setZero(n, n);
  if (uses_fbar(type, material, kinematics))
  {
    const FbarCell points = fbar_cell(type, X, u, cell, planar, integration);
    FETICON_ASSERT(!material.is_plastic() || (plastic && plastic->committed.size() == points.n_points),
                   "a plastic cell needs a state per quadrature point");
    for (size_t q = 0; q < points.n_points; ++q)
    {
      const PointGeometry<Eigen::Dynamic>& geo = points.geo[q];
      const auto [F_bar, alpha] = fbar_gradient(points.volume, points.F[q]);
      Eigen::Matrix<double, 6, 6> C;
      const Voigt S =
          fbar_stress(material, green_lagrange(F_bar), q, plastic, kind != StiffnessKind::none ? &C : nullptr);
      const StrainDisplacement<Eigen::Dynamic> B =
          fbar_strain_displacement(geo, points.volume, points.F[q], F_bar, alpha);
      f.noalias() += B.transpose() * (S * geo.weight_det_j);
      if (kind == StiffnessKind::none)
        continue;
      if (kind == StiffnessKind::material_definite)
        make_positive_definite(C);
      K->noalias() += B.transpose() * (C * geo.weight_det_j) * B;
    }
    return;
  }
  with_node_count(X.rows(), [&](auto nodes) {
    constexpr int N = decltype(nodes)::value;
    cell_points<N>(type, cell_nodes<N>(X), cell_nodes<N>(u), material, kinematics, kind, integration, f, K, cell,
                   temperature_change, plastic, planar);
  });
}

namespace
{
/// Cauchy stress, strain and w det J at every quadrature point of a cell, each handed to
/// `visit(stress, strain, weight)` as it is computed (cell_point_results keeps them,
/// cell_cauchy_stress averages them without storing).
template <class Visit>
void for_each_point_result(mesh::CellKind type, const Eigen::MatrixX3d& X, const Eigen::MatrixX3d& u,
                           const Material& material, Kinematics kinematics, Integration integration, int64_t cell,
                           const Eigen::VectorXd* temperature_change, std::span<const PlasticPointState> plastic,
                           const mesh::Planar& planar, Visit visit)
{
  const Eigen::Matrix<double, 6, 6> D = material.elasticity_matrix();
  const bool plane_stress = mesh::is_planar(type) && planar.kind == mesh::PlanarKind::plane_stress;
  if (uses_fbar(type, material, kinematics))
  {
    const FbarCell points = fbar_cell(type, X, u, cell, planar, integration);
    for (size_t q = 0; q < points.n_points; ++q)
    {
      const Eigen::Matrix3d F_bar = fbar_gradient(points.volume, points.F[q]).first;
      const Voigt E_bar = green_lagrange(F_bar);
      FETICON_CHECK(!material.is_plastic() || plastic.size() == points.n_points,
                    "cell " << cell << " is plastic but has " << plastic.size() << " point states for "
                            << points.n_points << " quadrature points");
      const Voigt S = material.is_plastic() ? finite_j2_return(material, E_bar, plastic[q], nullptr).stress
                                            : hyperelastic_stress(material.hyperelastic, E_bar);
      visit(voigt_of(F_bar * tensor_of(S) * F_bar.transpose() / F_bar.determinant()), E_bar,
            points.geo[q].weight_det_j);
    }
    return;
  }
  const QuadratureRule& rule = quadrature(type, integration);
  const std::vector<PointShapes>& shapes = quadrature_shapes(type, integration);
  with_node_count(X.rows(), [&](auto nodes) {
    constexpr int N = decltype(nodes)::value;
    for (size_t q = 0; q < rule.points.size(); ++q)
    {
      const PointGeometry<N> geo = point_geometry<N>(type, cell_nodes<N>(X), shapes[q], rule.weights[q], cell, planar);
      auto [Fd, strain] = deformation<N>(geo, cell_nodes<N>(u), kinematics, cell);
      const double thermal = thermal_stress_at(material, temperature_change, shapes[q]);
      if (plane_stress)
      {
        free_thickness_strain(D, thermal, strain);
        if (kinematics == Kinematics::total_lagrangian)
          Fd(2, 2) = std::sqrt(1 + 2 * strain(2)); // the thickness stretch, for sigma = F S F' / det F
      }
      Voigt stress;
      if (material.is_plastic())
      {
        FETICON_CHECK(plastic.size() == rule.points.size(),
                      "cell " << cell << " is plastic but has " << plastic.size() << " point states for "
                              << rule.points.size() << " quadrature points");
        stress = plastic_update(material, kinematics, strain, thermal, plastic[q], nullptr).stress;
      }
      else if (material.is_hyperelastic())
        stress = hyperelastic_stress(material.hyperelastic, strain);
      else
      {
        stress = D * strain;
        stress.head<3>().array() -= thermal;
      }
      if (kinematics == Kinematics::total_lagrangian)
      {
        // sigma = F S F' / det F (det F > 0, checked in deformation).
        stress = voigt_of(Fd * tensor_of(stress) * Fd.transpose() / Fd.determinant());
      }
      visit(stress, strain, geo.weight_det_j);
    }
  });
}
} // namespace

CellPointResults cell_point_results(mesh::CellKind type, const Eigen::MatrixX3d& X, const Eigen::MatrixX3d& u,
                                    const Material& material, Kinematics kinematics, Integration integration,
                                    int64_t cell, const Eigen::VectorXd* temperature_change,
                                    std::span<const PlasticPointState> plastic, const mesh::Planar& planar)
{
  CellPointResults out;
  for_each_point_result(type, X, u, material, kinematics, integration, cell, temperature_change, plastic, planar,
                        [&](const Voigt& stress, const Voigt& strain, double weight) {
    out.stress.push_back(stress);
    out.strain.push_back(strain);
    out.weight.push_back(weight);
  });
  return out;
}

Voigt cell_cauchy_stress(mesh::CellKind type, const Eigen::MatrixX3d& X, const Eigen::MatrixX3d& u,
                         const Material& material, Kinematics kinematics, int64_t cell, Integration integration,
                         const Eigen::VectorXd* temperature_change, std::span<const PlasticPointState> plastic,
                         const mesh::Planar& planar)
{
  Voigt sum = Voigt::Zero();
  double volume = 0;
  for_each_point_result(type, X, u, material, kinematics, integration, cell, temperature_change, plastic, planar,
                        [&](const Voigt& stress, const Voigt&, double weight) {
    sum += stress * weight;
    volume += weight;
  });
  return sum / volume;
}

std::vector<Voigt> cell_point_strains(mesh::CellKind type, const Eigen::MatrixX3d& X, const Eigen::MatrixX3d& u,
                                      Kinematics kinematics, Integration integration, int64_t cell,
                                      const mesh::Planar& planar)
{
  std::vector<Voigt> out;
  const QuadratureRule& rule = quadrature(type, integration);
  const std::vector<PointShapes>& shapes = quadrature_shapes(type, integration);
  with_node_count(X.rows(), [&](auto nodes) {
    constexpr int N = decltype(nodes)::value;
    for (size_t q = 0; q < rule.points.size(); ++q)
      out.push_back(deformation<N>(point_geometry<N>(type, cell_nodes<N>(X), shapes[q], rule.weights[q], cell, planar),
                                   cell_nodes<N>(u), kinematics, cell)
                        .second);
  });
  return out;
}
} // namespace feticon::fem
