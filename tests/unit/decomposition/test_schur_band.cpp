/// The Dirichlet preconditioner's Schur complement on a band of the interior
/// (SchurComplements with interior_layers > 0, decomposition/schur_complements.hpp), against
/// dense elimination of the band's DOFs (tests/support/dense_schur.hpp) with the band found
/// independently from the structured grid's indices; and the ordering the preconditioner relies
/// on, S <= S^(2) <= S^(1) <= K_bb, with S^(k) = S once the band holds the whole interior.
///
/// Two subdomains of a 12 x 6 x 6 box, every node of the box's surface flagged: each subdomain is
/// a cube of 6 x 6 x 6 cells whose whole surface is boundary, so its interior nodes lie 1 to 3
/// cells deep.

#include "decomposition/schur_complements.hpp"
#include "mesh/box.hpp"
#include "tests/support/dense_schur.hpp"

#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>

using namespace feticon;

namespace
{
constexpr int cells_across = 6; // of each subdomain's cube
constexpr double h = 1.0 / cells_across;

struct Fixture
{
  mesh::Mesh mesh;
  decomposition::Decomposition decomp;
  decomposition::SubdomainSystem system;
  std::vector<char> flagged;

  Fixture()
      : mesh(make_mesh()), decomp(mesh, decomposition::partition_structured(mesh, {2, 1, 1})),
        system(decomp, {fem::Material{2e11, 0.3}}, fem::Kinematics::linear,
               decomposition::GeneralizedInverseMethod::fixing_dofs)
  {
    system.update(la::Vector::Zero(decomp.n_primal()));
    flagged.assign(3 * static_cast<size_t>(mesh.n_nodes()), 0);
    for (int32_t i = 0; i < mesh.n_nodes(); ++i)
      if (depth_in_box(mesh.nodes.row(i).transpose()) == 0)
        std::fill_n(flagged.begin() + 3 * i, 3, 1);
  }
  static mesh::Mesh make_mesh()
  {
    mesh::BoxParameters p;
    p.lengths = Eigen::Vector3d(2, 1, 1);
    p.nx = 2 * cells_across;
    p.ny = cells_across;
    p.nz = cells_across;
    return mesh::generate_box(p);
  }
  /// Cells between the point and the nearest face of the box.
  static int depth_in_box(const Eigen::Vector3d& x)
  {
    const Eigen::Vector3d top(2, 1, 1);
    return static_cast<int>(std::lround(std::min(x.minCoeff(), (top - x).minCoeff()) / h));
  }
  /// Cells between the point and the nearest face of subdomain s's cube (x in [s, s + 1]).
  static int depth_in_cube(const Eigen::Vector3d& x, int32_t s)
  {
    const Eigen::Vector3d low(s, 0, 0), high(s + 1, 1, 1);
    return static_cast<int>(std::lround(std::min((x - low).minCoeff(), (high - x).minCoeff()) / h));
  }

  /// S_s of `schur` as a dense matrix on its boundary (column by column through apply).
  la::Matrix dense(const decomposition::SchurComplements& schur, int32_t s) const
  {
    const auto& b = schur.boundary(s);
    const la::Index n = decomp.subdomain(s).n_dofs();
    la::Matrix S(static_cast<la::Index>(b.size()), static_cast<la::Index>(b.size()));
    for (size_t j = 0; j < b.size(); ++j)
    {
      const la::Vector y = schur.apply(s, la::Vector::Unit(n, b[j]));
      for (size_t i = 0; i < b.size(); ++i)
        S(static_cast<la::Index>(i), static_cast<la::Index>(j)) = y(b[i]);
    }
    return S;
  }

  /// The reference: K_s restricted to the boundary and the interior within `layers` cells of
  /// the cube's faces, its interior eliminated densely.
  la::Matrix reference(int32_t s, const std::vector<int32_t>& boundary, int layers) const
  {
    const auto& sub = decomp.subdomain(s);
    const la::Matrix K(la::SparseMatrix(system.operators(s).K.selfadjointView<Eigen::Lower>()));
    std::vector<int32_t> kept, kept_boundary;
    for (int32_t dof = 0; dof < sub.n_dofs(); ++dof)
    {
      const int32_t node = sub.domain.local_to_global[sub.full_of_active[dof] / 3];
      const bool on_boundary = std::binary_search(boundary.begin(), boundary.end(), dof);
      if (on_boundary || depth_in_cube(mesh.nodes.row(node).transpose(), s) <= layers)
      {
        if (on_boundary)
          kept_boundary.push_back(static_cast<int32_t>(kept.size()));
        kept.push_back(dof);
      }
    }
    return test::dense_schur(K(kept, kept), kept_boundary);
  }
};

double smallest_eigenvalue(const la::Matrix& A)
{
  return Eigen::SelfAdjointEigenSolver<la::Matrix>(A, Eigen::EigenvaluesOnly).eigenvalues().minCoeff();
}
} // namespace

TEST(SchurBand, MatchesDenseEliminationOfTheBand)
{
  const Fixture f;
  for (const int layers : {1, 2})
  {
    const decomposition::SchurComplements band(f.system, f.flagged, true, layers);
    for (int32_t s = 0; s < f.decomp.n_subdomains(); ++s)
    {
      const la::Matrix S = f.dense(band, s);
      const la::Matrix S_ref = f.reference(s, band.boundary(s), layers);
      EXPECT_LT((S - S_ref).norm(), 1e-10 * S_ref.norm()) << "layers " << layers << ", subdomain " << s;
    }
  }
}

TEST(SchurBand, LiesBetweenTheSchurComplementAndKbb)
{
  const Fixture f;
  const decomposition::SchurComplements whole(f.system, f.flagged, true, 0);
  const decomposition::SchurComplements one(f.system, f.flagged, true, 1);
  const decomposition::SchurComplements two(f.system, f.flagged, true, 2);
  const decomposition::SchurComplements deep(f.system, f.flagged, true, cells_across); // the whole interior
  for (int32_t s = 0; s < f.decomp.n_subdomains(); ++s)
  {
    ASSERT_EQ(one.boundary(s), whole.boundary(s));
    const la::Matrix S = f.dense(whole, s), S1 = f.dense(one, s), S2 = f.dense(two, s);
    const auto& b = whole.boundary(s);
    const la::Matrix K(la::SparseMatrix(f.system.operators(s).K.selfadjointView<Eigen::Lower>()));
    const la::Matrix K_bb = K(b, b);
    const double scale = S.norm();
    EXPECT_LT((S - test::dense_schur(K, b)).norm(), 1e-10 * scale);
    // Holding DOFs fixed only stiffens the boundary: S <= S^(2) <= S^(1) <= K_bb.
    EXPECT_GT(smallest_eigenvalue(S2 - S), -1e-10 * scale);
    EXPECT_GT(smallest_eigenvalue(S1 - S2), -1e-10 * scale);
    EXPECT_GT(smallest_eigenvalue(K_bb - S1), -1e-10 * scale);
    // ... strictly: each band differs from its neighbours in the ordering.
    EXPECT_GT((S1 - S2).norm(), 1e-3 * scale);
    EXPECT_GT((S2 - S).norm(), 1e-4 * scale);
    EXPECT_GT((K_bb - S1).norm(), 1e-2 * scale);
    EXPECT_LT((f.dense(deep, s) - S).norm(), 1e-12 * scale);
  }
}
