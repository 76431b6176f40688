/// Linear Total FETI against an independent direct CHOLMOD solve of the undecomposed
/// problem, and numerical scalability with H/h fixed (issue 3).

#include "common/parallel.hpp"
#include "decomposition/constraint_rows.hpp"
#include "decomposition/schur_complements.hpp"
#include "decomposition/subdomain_operators.hpp"
#include "dual/equality_feti.hpp"
#include "fem/loads.hpp"
#include "la/cholmod.hpp"
#include "mesh/box.hpp"
#include "mesh/cell_conversion.hpp"

#include <gtest/gtest.h>

#include <chrono>
#include <cmath>
#include <cstdio>
#include <cstdlib>
#include <iostream>
#include <map>

using namespace feticon;

namespace
{
/// Clamped at x = 0, loaded by a traction on x = L: load and supports on different
/// subdomains for every partition used below.
struct BeamProblem
{
  mesh::Mesh mesh;
  fem::Material material{2e11, 0.3};
  fem::ConstrainedDofs dirichlet;
  la::Vector f;
};

BeamProblem beam(int nx, int ny, int nz, Eigen::Vector3d lengths, mesh::CellKind kind = mesh::CellKind::hex8)
{
  BeamProblem p;
  mesh::BoxParameters bp;
  bp.lengths = lengths;
  bp.nx = nx;
  bp.ny = ny;
  bp.nz = nz;
  p.mesh = mesh::generate_box(bp);
  if (kind != mesh::CellKind::hex8)
    p.mesh = mesh::convert_hex8_mesh(p.mesh, kind);
  p.dirichlet = fem::collect_dirichlet(p.mesh, {{"xmin", {0.0, 0.0, 0.0}}});
  p.f = la::Vector::Zero(3 * p.mesh.n_nodes());
  fem::add_face_traction(p.mesh, p.mesh.face_set("xmax"), Eigen::Vector3d(1e7, -3e7, 2e7), p.f);
  return p;
}

/// Reference: direct solve of the undecomposed problem with Dirichlet elimination.
la::Vector direct_solution(const BeamProblem& p)
{
  fem::Assembler assembler(p.mesh, fem::whole_mesh_domain(p.mesh), {p.material}, fem::Kinematics::linear);
  const la::SparseMatrix K = assembler.stiffness(la::Vector::Zero(p.f.size()), fem::StiffnessKind::tangent);
  const fem::DirichletElimination elim(p.f.size(), p.dirichlet);
  la::CholmodFactor factor;
  factor.factorize(elim.reduce_matrix(K));
  return elim.expand(factor.solve(elim.reduce_rhs(K, p.f)));
}

struct FetiRun
{
  la::Vector u_global;
  double gluing_jump;
  qp::QpReport report;
};

FetiRun feti_solution(
    const BeamProblem& p, const decomposition::Partition& partition, double rtol,
    decomposition::GeneralizedInverseMethod method = decomposition::GeneralizedInverseMethod::fixing_dofs)
{
  const decomposition::Decomposition decomp(p.mesh, partition);
  decomposition::SubdomainSystem system(decomp, {p.material}, fem::Kinematics::linear, method);
  system.update(la::Vector::Zero(decomp.n_primal()));
  const auto rows = decomposition::build_equality_rows(decomp, p.dirichlet);
  const dual::FetiOperators feti(system, rows.rows);
  qp::CgOptions options;
  options.rtol = rtol;
  const auto solution = dual::solve_equality_feti(feti, rows.rows.c_vector(), decomp.scatter_split(p.f), options);
  EXPECT_TRUE(solution.report.converged) << solution.report.reason;
  const la::Vector Bu = feti.apply_B(solution.u) - rows.rows.c_vector();
  return {decomp.gather_mean(solution.u), Bu.norm() / solution.u.norm(), solution.report};
}
} // namespace

// Reference: direct CHOLMOD solve of the same undecomposed problem. Tolerance 1e-8 relative
// (issue 3); projected CG stopped at ||P r|| <= 1e-11 ||P b||, so the dual error and with it
// the displacement error are well below that.
TEST(FetiLinear, MatchesDirectSolveStructuredAndMetis)
{
  const BeamProblem p = beam(6, 6, 6, Eigen::Vector3d(3, 1, 1));
  const la::Vector u_ref = direct_solution(p);
  struct Case
  {
    const char* name;
    decomposition::Partition partition;
  };
  std::vector<Case> cases = {
      {"structured 1", decomposition::partition_structured(p.mesh, {1, 1, 1})},
      {"structured 2", decomposition::partition_structured(p.mesh, {2, 1, 1})},
      {"structured 8", decomposition::partition_structured(p.mesh, {2, 2, 2})},
      {"structured 27", decomposition::partition_structured(p.mesh, {3, 3, 3})},
      {"metis 2", decomposition::partition_metis(p.mesh, 2)},
      {"metis 8", decomposition::partition_metis(p.mesh, 8)},
      {"metis 27", decomposition::partition_metis(p.mesh, 27)},
  };
  for (const Case& c : cases)
  {
    const FetiRun run = feti_solution(p, c.partition, 1e-11);
    const double error = (run.u_global - u_ref).norm() / u_ref.norm();
    std::printf("%-14s subdomains %3d  CG iterations %4d  |u - u_direct|/|u_direct| = %.2e  "
                "|Bu - c|/|u| = %.1e\n",
                c.name, c.partition.n_subdomains, run.report.iterations, error, run.gluing_jump);
    EXPECT_LT(error, 1e-8) << c.name;
    EXPECT_LT(run.gluing_jump, 1e-8) << c.name;
  }
  // The regularized generalized inverse gives the same answer.
  const FetiRun reg = feti_solution(p, decomposition::partition_structured(p.mesh, {2, 2, 2}), 1e-11,
                                    decomposition::GeneralizedInverseMethod::regularization);
  EXPECT_LT((reg.u_global - u_ref).norm() / u_ref.norm(), 1e-8);
}

// Every cell type through Total FETI (METIS subdomains, their kernels from the node
// coordinates, gluing rows on every shared node, corners and edge nodes alike) against the
// direct solve of the same mesh, to the same 1e-8: the element convergence orders measured
// with direct solves (test_cell_elements.cpp) hold for the FETI solutions as well.
TEST(FetiLinear, EveryCellTypeMatchesDirectSolve)
{
  for (const mesh::CellKind kind :
       {mesh::CellKind::tet4, mesh::CellKind::tet10, mesh::CellKind::hex20, mesh::CellKind::wedge6})
  {
    const BeamProblem p = beam(6, 2, 2, Eigen::Vector3d(3, 1, 1), kind);
    const la::Vector u_ref = direct_solution(p);
    const FetiRun run = feti_solution(p, decomposition::partition_metis(p.mesh, 4), 1e-11);
    const double error = (run.u_global - u_ref).norm() / u_ref.norm();
    std::printf("%-7s CG iterations %4d  |u - u_direct|/|u_direct| = %.2e  |Bu - c|/|u| = %.1e\n",
                std::string(mesh::cell_type(kind).name).c_str(), run.report.iterations, error, run.gluing_jump);
    EXPECT_LT(error, 1e-8) << mesh::cell_type(kind).name;
    EXPECT_LT(run.gluing_jump, 1e-8) << mesh::cell_type(kind).name;
  }
}

// Reference: Total FETI theory (Dostál, Horák, Kučera 2006): kappa(PFP | Im P) <= C H/h, so
// with H/h fixed the CG iteration count is bounded independently of h; the lumped
// preconditioner keeps a bound of the same form (Farhat, Mandel, Roux 1994). Issue 3 asks
// for less than 20% growth from h to h/4. Unit cube, H/h = 4, h = 1/8, 1/16, 1/32.
TEST(FetiLinear, NumericalScalabilityWithFixedHOverSmallH)
{
  std::vector<int> plain_iterations, lumped_iterations;
  std::printf("\n%6s %11s %10s %9s %14s %11s %14s\n", "1/h", "subdomains", "dual size", "CG iter", "CG s/iter",
              "PCG iter", "PCG s/iter");
  for (int n : {8, 16, 32})
  {
    const BeamProblem p = beam(n, n, n, Eigen::Vector3d(1, 1, 1));
    const int parts = n / 4;
    const decomposition::Decomposition decomp(p.mesh,
                                              decomposition::partition_structured(p.mesh, {parts, parts, parts}));
    decomposition::SubdomainSystem system(decomp, {p.material}, fem::Kinematics::linear,
                                          decomposition::GeneralizedInverseMethod::fixing_dofs);
    system.update(la::Vector::Zero(decomp.n_primal()));
    const auto rows = decomposition::build_equality_rows(decomp, p.dirichlet);
    const dual::FetiOperators feti(system, rows.rows);
    qp::CgOptions options;
    options.rtol = 1e-6;
    double seconds[2];
    qp::QpReport reports[2];
    for (int k = 0; k < 2; ++k)
    {
      const auto start = std::chrono::steady_clock::now();
      reports[k] = dual::solve_equality_feti(feti, rows.rows.c_vector(), decomp.scatter_split(p.f), options,
                                             k == 0 ? dual::FetiPreconditioner::none : dual::FetiPreconditioner::lumped)
                       .report;
      seconds[k] = std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();
      ASSERT_TRUE(reports[k].converged) << reports[k].reason;
    }
    plain_iterations.push_back(reports[0].iterations);
    lumped_iterations.push_back(reports[1].iterations);
    std::printf("%6d %11d %10ld %9d %14.2e %11d %14.2e\n", n, decomp.n_subdomains(), static_cast<long>(feti.n_dual()),
                reports[0].iterations, seconds[0] / reports[0].iterations, reports[1].iterations,
                seconds[1] / reports[1].iterations);
  }
  EXPECT_LT(lumped_iterations.back(), 1.2 * lumped_iterations.front());
  // Unpreconditioned: bounded too, measured 29, 35, 36 (the 2x2x2 case is pre-asymptotic).
  EXPECT_LT(plain_iterations.back(), 1.1 * plain_iterations[1]);
}

// Reference: Farhat, Mandel, Roux (1994), Klawonn and Widlund (2001): with the Dirichlet
// preconditioner B S B' the condition number of Total FETI grows like (1 + log(H/h))^2,
// against H/h without it, and the lumped one B K B' sits in between ((H/h)(1 + log(H/h))).
// Fixed h = 1/16, H/h = 2, 4, 8 (512, 64, 8 subdomains). The Dirichlet-preconditioned solve
// must also reproduce the direct CHOLMOD solution of the undecomposed problem.
TEST(FetiLinear, DirichletPreconditionerGrowsLogarithmicallyInHOverSmallH)
{
  const int n = 16;
  const BeamProblem p = beam(n, n, n, Eigen::Vector3d(1, 1, 1));
  const la::Vector u_ref = direct_solution(p);
  std::vector<char> supported(3 * static_cast<size_t>(p.mesh.n_nodes()), 0);
  for (int64_t dof : p.dirichlet.dofs)
    supported[dof] = 1;
  const dual::FetiPreconditioner kinds[] = {dual::FetiPreconditioner::none, dual::FetiPreconditioner::lumped,
                                            dual::FetiPreconditioner::dirichlet};
  std::map<dual::FetiPreconditioner, std::vector<int>> iterations;
  std::printf("\n%6s %11s %9s %11s %14s %14s\n", "H/h", "subdomains", "CG iter", "lumped iter", "Dirichlet iter",
              "|u-u_direct|");
  for (int parts : {8, 4, 2})
  {
    const decomposition::Decomposition decomp(p.mesh,
                                              decomposition::partition_structured(p.mesh, {parts, parts, parts}));
    decomposition::SubdomainSystem system(decomp, {p.material}, fem::Kinematics::linear,
                                          decomposition::GeneralizedInverseMethod::fixing_dofs);
    system.update(la::Vector::Zero(decomp.n_primal()));
    const decomposition::SchurComplements schur(system, supported);
    const auto rows = decomposition::build_equality_rows(decomp, p.dirichlet);
    const dual::FetiOperators feti(system, rows.rows);
    qp::CgOptions options;
    options.rtol = 1e-10;
    double error = 0.0;
    for (dual::FetiPreconditioner kind : kinds)
    {
      const auto solution =
          dual::solve_equality_feti(feti, rows.rows.c_vector(), decomp.scatter_split(p.f), options, kind, &schur);
      ASSERT_TRUE(solution.report.converged) << solution.report.reason;
      iterations[kind].push_back(solution.report.iterations);
      if (kind == dual::FetiPreconditioner::dirichlet)
        error = (decomp.gather_mean(solution.u) - u_ref).norm() / u_ref.norm();
    }
    std::printf("%6d %11d %9d %11d %14d %14.2e\n", n / parts, decomp.n_subdomains(), iterations[kinds[0]].back(),
                iterations[kinds[1]].back(), iterations[kinds[2]].back(), error);
    EXPECT_LT(error, 1e-8);
  }
  const auto& plain = iterations[dual::FetiPreconditioner::none];
  const auto& lumped = iterations[dual::FetiPreconditioner::lumped];
  const auto& dirichlet = iterations[dual::FetiPreconditioner::dirichlet];
  for (size_t k = 0; k < dirichlet.size(); ++k)
    EXPECT_LT(dirichlet[k], lumped[k]) << "H/h = " << (2 << k);
  EXPECT_LT(dirichlet.back(), plain.back());
  // Iterations ~ sqrt(kappa) ~ 1 + log(H/h): from H/h = 2 to 8 at most (1 + ln 8)/(1 + ln 2)
  // = 1.82 times more; measured 13, 17, 18 (lumped 14, 20, 28; none 48, 59, 61).
  EXPECT_LE(dirichlet.back(), (1 + std::log(8.0)) / (1 + std::log(2.0)) * dirichlet.front());
  EXPECT_LT(dirichlet.back() - dirichlet.front(), lumped.back() - lumped.front());
}

// Reference: the same solve on one thread. Subdomain loops run on threads with one BLAS
// thread per subdomain and sums in a fixed order (common/parallel.hpp), so the thread count
// must not change a single bit: same CG iterations, identical displacements.
TEST(FetiLinear, ThreadCountDoesNotChangeTheResult)
{
  // 28 611 DOFs: above min_parallel_work, so the loops do run on two threads.
  const BeamProblem p = beam(32, 16, 16, Eigen::Vector3d(2, 1, 1));
  ASSERT_GE(3 * p.mesh.n_nodes(), min_parallel_work);
  const auto partition = decomposition::partition_metis(p.mesh, 8);
  unsetenv("OMP_NUM_THREADS");
  set_threads(1);
  const FetiRun one = feti_solution(p, partition, 1e-10);
  set_threads(2);
  const FetiRun two = feti_solution(p, partition, 1e-10);
  set_threads(hardware_cores());
  EXPECT_EQ(one.report.iterations, two.report.iterations);
  EXPECT_EQ((one.u_global - two.u_global).cwiseAbs().maxCoeff(), 0.0);
}
