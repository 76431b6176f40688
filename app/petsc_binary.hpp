#pragma once
/// @file Matrices and vectors in PETSc's binary format (MatLoad, VecLoad), for `feticon bench
/// --bonded-system`: the bonded system handed to PETSc's algebraic multigrid in bench/gamg,
/// the iterative floor of issue 40. PETSc is a peer measured in bench/, not a dependency:
/// the format is written here (big-endian 32-bit integers and doubles; PETSc's
/// PetscBinaryWrite layout for 32-bit PetscInt, Debian's libpetsc-real).

#include "la/types.hpp"

#include <filesystem>

namespace feticon::app
{
/// `A` (symmetric, both triangles stored) as an AIJ matrix.
void write_petsc_matrix(const std::filesystem::path& path, const la::SparseMatrix& A);
/// The columns of `V`, one PETSc vector after the other in one file.
void write_petsc_vectors(const std::filesystem::path& path, const la::Matrix& V);
} // namespace feticon::app
