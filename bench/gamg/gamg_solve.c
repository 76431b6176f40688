/* The iterative floor of issue 40: the bonded system of `feticon bench --bonded-system DIR`
 * solved by PETSc's conjugate gradients preconditioned by its smoothed-aggregation algebraic
 * multigrid (GAMG) with the rigid-body modes as near kernel, to a relative residual of 1e-8
 * (unpreconditioned norm, ||b - A x|| <= 1e-8 ||b||). A bench peer only: bench/gamg/run.sh
 * builds it against Debian's petsc-dev; feticon never links PETSc.
 *
 *   mpirun -np 2 gamg_solve -dir DIR -near_kernel_vectors K [PETSc options]
 *
 * Prints one JSON line: set-up (the multigrid hierarchy) and solve seconds, CG iterations and
 * the true relative residual, computed again after the solve. */
#include <petscksp.h>

static PetscErrorCode load(const char* dir, const char* name, PetscViewer* viewer)
{
  char path[PETSC_MAX_PATH_LEN];
  PetscFunctionBeginUser;
  PetscCall(PetscSNPrintf(path, sizeof path, "%s/%s", dir, name));
  PetscCall(PetscViewerBinaryOpen(PETSC_COMM_WORLD, path, FILE_MODE_READ, viewer));
  PetscFunctionReturn(0);
}

int main(int argc, char** argv)
{
  char dir[PETSC_MAX_PATH_LEN] = ".";
  PetscInt n_kernel = 0, iterations = 0;
  KSPConvergedReason reason;
  PetscViewer viewer;
  Mat A;
  Vec b, x, r, kernel[6];
  MatNullSpace near_kernel;
  KSP ksp;
  PC pc;
  PetscLogDouble t0, t1, t2;
  PetscReal b_norm, r_norm;

  PetscCall(PetscInitialize(&argc, &argv, NULL, NULL));
  PetscCall(PetscOptionsGetString(NULL, NULL, "-dir", dir, sizeof dir, NULL));
  PetscCall(PetscOptionsGetInt(NULL, NULL, "-near_kernel_vectors", &n_kernel, NULL));
  PetscCheck(n_kernel >= 0 && n_kernel <= 6, PETSC_COMM_WORLD, PETSC_ERR_ARG_OUTOFRANGE, "0 to 6 near-kernel vectors");

  PetscCall(load(dir, "A.petsc", &viewer));
  PetscCall(MatCreate(PETSC_COMM_WORLD, &A));
  PetscCall(MatSetType(A, MATAIJ));
  PetscCall(MatLoad(A, viewer));
  PetscCall(PetscViewerDestroy(&viewer));
  PetscCall(MatSetOption(A, MAT_SPD, PETSC_TRUE));
  PetscCall(load(dir, "b.petsc", &viewer));
  PetscCall(MatCreateVecs(A, &x, &b));
  PetscCall(VecLoad(b, viewer));
  PetscCall(PetscViewerDestroy(&viewer));
  PetscCall(load(dir, "near_kernel.petsc", &viewer));
  for (PetscInt k = 0; k < n_kernel; ++k)
  {
    PetscCall(VecDuplicate(b, &kernel[k]));
    PetscCall(VecLoad(kernel[k], viewer));
  }
  PetscCall(PetscViewerDestroy(&viewer));
  /* feticon wrote them orthonormal, as MatNullSpaceCreate requires. */
  PetscCall(MatNullSpaceCreate(PETSC_COMM_WORLD, PETSC_FALSE, n_kernel, kernel, &near_kernel));
  PetscCall(MatSetNearNullSpace(A, near_kernel));

  PetscCall(KSPCreate(PETSC_COMM_WORLD, &ksp));
  PetscCall(KSPSetOperators(ksp, A, A));
  PetscCall(KSPSetType(ksp, KSPCG));
  PetscCall(KSPSetNormType(ksp, KSP_NORM_UNPRECONDITIONED));
  PetscCall(KSPSetTolerances(ksp, 1e-8, 0.0, PETSC_DEFAULT, 100000));
  PetscCall(KSPGetPC(ksp, &pc));
  PetscCall(PCSetType(pc, PCGAMG));
  PetscCall(KSPSetFromOptions(ksp));

  PetscCall(PetscTime(&t0));
  PetscCall(KSPSetUp(ksp));
  PetscCall(PetscTime(&t1));
  PetscCall(KSPSolve(ksp, b, x));
  PetscCall(PetscTime(&t2));
  PetscCall(KSPGetIterationNumber(ksp, &iterations));
  PetscCall(KSPGetConvergedReason(ksp, &reason));

  PetscCall(VecDuplicate(b, &r));
  PetscCall(MatMult(A, x, r));
  PetscCall(VecAYPX(r, -1.0, b));
  PetscCall(VecNorm(r, NORM_2, &r_norm));
  PetscCall(VecNorm(b, NORM_2, &b_norm));
  PetscCall(PetscPrintf(PETSC_COMM_WORLD,
                        "{\"gamg_setup_seconds\": %.6f, \"gamg_solve_seconds\": %.6f, \"gamg_iterations\": %d, "
                        "\"gamg_relative_residual\": %.3e, \"gamg_converged\": %s}\n",
                        t1 - t0, t2 - t1, (int)iterations, (double)(r_norm / b_norm), reason > 0 ? "true" : "false"));

  PetscCall(VecDestroy(&r));
  for (PetscInt k = 0; k < n_kernel; ++k)
    PetscCall(VecDestroy(&kernel[k]));
  PetscCall(MatNullSpaceDestroy(&near_kernel));
  PetscCall(KSPDestroy(&ksp));
  PetscCall(VecDestroy(&x));
  PetscCall(VecDestroy(&b));
  PetscCall(MatDestroy(&A));
  PetscCall(PetscFinalize());
  return 0;
}
