#pragma once
/// @file Dense Schur complements of sparse symmetric matrices from one partial factorization,
/// and the dense symmetric positive definite inverse (LAPACK).
///
///   S = A_bb - A_bi A_ii^{-1} A_ib   (b: the given DOFs, i: all others)
///
/// is what remains of A after eliminating i. CHOLMOD factorizes A + [0 0; 0 D] with the b
/// DOFs ordered last (CAMD with b as its last constraint set, no postordering, so the order
/// stays), supernodally (BLAS 3); the trailing block of the factor then satisfies
/// L_bb L_bb' = S + D. The shift D = diag(A_bb) keeps that block positive definite when S is
/// only semidefinite (a floating subdomain: S inherits the rigid-body kernel) and costs an
/// error of about machine epsilon times sqrt(D_kk D_ll) in S_kl, the size of the rounding
/// of A_bb itself; scaled per DOF, so that a graded mesh's small entries keep their
/// digits. A_ii must be positive definite.
///
/// This replaces |b| forward and backward substitutions with the whole factor (one per
/// column of the boundary) by the dense trailing block: about |b|^3 / 3 flops of the
/// factorization and |b|^3 / 3 for L_bb L_bb' (ESPRESO forms its explicit FETI operators
/// the same way).

#include "la/types.hpp"

#include <vector>

namespace feticon::la
{
/// S on `boundary` (distinct indices of A, any order; S(k, l) belongs to boundary[k],
/// boundary[l]). `A` is symmetric in full storage; `what` names it in errors.
Matrix schur_complement(const SparseMatrix& A, const std::vector<int32_t>& boundary, const char* what);

/// A := A^{-1} for a symmetric positive definite A (both triangles written); throws
/// feticon::Error naming `what` if A is not positive definite.
void invert_spd(Matrix& A, const char* what);
} // namespace feticon::la
