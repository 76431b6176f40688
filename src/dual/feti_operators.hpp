#pragma once
/// @file The FETI dual operators, applied without forming F (ALGORITHMS.md section 1).
///
///   F = B K+ B',  G = R' B',  e = R' f,  d = B K+ f - c,
/// with B = [B_E; B_I] given as constraint rows, K+ = diag(K_s+), R = diag(R_s).
/// B is held per subdomain: the rows that touch subdomain s and a sparse block B_s, so
/// F lambda = sum_s B_s K_s+ B_s' lambda_s needs no global matrix.
///
/// Distributed over MPI ranks (the decomposition's communicator) as the DualLayout says
/// (dual/dual_layout.hpp: owned rows, ghosts, the exchanges of B' and B products), and:
///   - the coarse space (n_kernel = sum of kernel dimensions) is replicated: G lambda is
///     gathered from the owners of the subdomains, and G G' is assembled block by block
///     (block (s, t) on the rank of s, summing the rows s and t share in id order) and
///     gathered on every rank, where CoarseProjector factorizes it.

#include "decomposition/constraint_rows.hpp"
#include "decomposition/explicit_boundary_operators.hpp"
#include "decomposition/schur_complements.hpp"
#include "decomposition/subdomain_operators.hpp"
#include "dual/dual_layout.hpp"
#include "la/operator.hpp"
#include "par/block_space.hpp"

#include <functional>
#include <memory>

namespace feticon::dual
{
class FetiOperators
{
public:
  /// @param system subdomain K, R, K+ (kept by reference; must outlive this object)
  /// @param rows   the constraint rows touching this rank's subdomains (all rows on one
  ///               rank), with global ids; equality rows first
  FetiOperators(const decomposition::SubdomainSystem& system, const decomposition::ConstraintRows& rows);

  /// Where the dual unknowns live; the shortcuts below are its.
  const DualLayout& layout() const { return _layout; }
  /// Size of this rank's dual vector (its owned rows) and of the whole dual.
  int64_t n_dual() const { return _layout.n_dual(); }
  int64_t n_dual_global() const { return _layout.n_dual_global(); }
  /// Global row id of owned row i and its index in the constructor's `rows`.
  int64_t row_id(la::Index i) const { return _layout.row_id(i); }
  int64_t row_index(la::Index i) const { return _layout.row_index(i); }
  /// The owned entries of a vector given for every row in `rows` (e.g. rows.c_vector()).
  la::Vector owned(const la::Vector& per_row) const { return _layout.owned(per_row); }
  /// Reductions over dual vectors (blocks: the rows owned by one subdomain).
  const la::VectorSpace& space() const { return _layout.space(); }
  const par::Communicator& comm() const { return _layout.comm(); }

  int64_t n_primal() const { return _system.decomposition().n_primal(); }
  int64_t n_kernel() const { return _system.n_kernel(); }

  la::Vector apply_B(const la::Vector& u_stacked) const;
  la::Vector apply_Bt(const la::Vector& lambda) const;
  la::Vector apply_K_plus(const la::Vector& f_stacked) const;
  /// K+ f with the subdomain equations K_s u_s = f_s solved to double precision where the
  /// factors are single: one step of iterative refinement against K_s (in double) on the part
  /// of f_s in the range of K_s. The primal displacement then leaves no float round-off in the
  /// force residual, which would otherwise take a linear run a second QP to remove
  /// (docs/benchmarks.md, "Refined primal recovery"). With double factors it is apply_K_plus.
  la::Vector apply_K_plus_refined(const la::Vector& f_stacked) const;
  /// R alpha for the replicated coarse vector alpha (owned stacked result).
  la::Vector apply_R(const la::Vector& alpha) const;
  /// Per kernel row j of subdomain s, 1 / max_i |R_s(i, j)| (replicated): w_j (R_s' y)_j is
  /// the net force of y along a translation (R_j is 1/sqrt(n) on one component) and its net
  /// moment over the largest lever arm along a rotation, i.e. about the force that K_s K_s^+
  /// leaves on the fixing nodes when R_s' y != 0 (the orthonormal R alone would understate
  /// it by about the square root of the subdomain's nodes).
  la::Vector net_force_weights() const;
  /// R' u, replicated on every rank.
  la::Vector apply_Rt(const la::Vector& u_stacked) const;
  /// F lambda = B K+ B' lambda.
  la::Vector apply_F(const la::Vector& lambda) const;
  /// Lumped preconditioner B K B' lambda (Farhat, Mandel, Roux 1994): cheap, one sparse
  /// product per subdomain.
  la::Vector apply_lumped(const la::Vector& lambda) const;
  /// Dirichlet preconditioner B S B' lambda (decomposition/schur_complements.hpp): one K_ii
  /// solve per subdomain, a better approximate inverse of F than B K B'.
  la::Vector apply_dirichlet(const la::Vector& lambda, const decomposition::SchurComplements& schur) const;
  /// From now on the lumped preconditioner multiplies with K_s on the DOFs the rows of s
  /// touch only, B_s K_s B_s' = B_c K_cc B_c' (the rest of K_s meets zeros of B_s'): a step
  /// reads the boundary's share of K instead of all of it (hertz3d at 924k DOFs in 128
  /// subdomains: docs/benchmarks.md). The same operator to round-off.
  void use_lumped_blocks();
  /// From now on F and the Dirichlet preconditioner are dense products with the boundary
  /// blocks of `ops` (kept by reference; must outlive this object): B_b (K_s+)_bb B_b' and
  /// B_b S_s B_b', the same operators to round-off. Throws if a row touches a DOF outside b_s.
  void use_explicit(const decomposition::ExplicitBoundaryOperators& ops);
  bool is_explicit() const { return _explicit != nullptr; }

  /// G lambda = R' B' lambda (replicated) and G' alpha = B R alpha. With a mask (one flag
  /// per owned row) G_A is G with the unmasked columns removed.
  la::Vector apply_G(const la::Vector& lambda, const std::vector<char>* mask = nullptr) const;
  la::Vector apply_Gt(const la::Vector& alpha, const std::vector<char>* mask = nullptr) const;
  /// G_A G_A' (n_kernel x n_kernel), replicated on every rank.
  la::SparseMatrix coarse_matrix(const std::vector<char>* mask = nullptr) const;
  /// An entry (row id, column id, value) of B B'.
  struct GramEntry
  {
    int64_t row, col;
    int32_t subdomain; ///< s of the term B_s B_s' it comes from
    double value;
  };
  /// This rank's share of the entries of B B' = sum_s B_s B_s' whose row or column id
  /// satisfies `selected`: one entry per owned subdomain s and entry of B_s B_s' (summing
  /// every rank's share gives B B' on those rows and columns).
  std::vector<GramEntry> gram_entries(const std::function<bool(int64_t)>& selected) const;

  const decomposition::SubdomainSystem& system() const { return _system; }

private:
  /// sum_s B_s local_op(s, B_s' lambda_s) with B_s = blocks[s - first owned] (_B, or
  /// _B_boundary for the dense boundary operators): the pattern of F and the preconditioners.
  template <class LocalOperator>
  la::Vector sum_over_subdomains(const std::vector<la::SparseMatrix>& blocks, const la::Vector& lambda, int64_t work,
                                 LocalOperator&& local_op) const;

  const decomposition::SubdomainSystem& _system;
  DualLayout _layout;
  /// Per owned subdomain (indexed s - first owned): B_s (its rows: the layout's
  /// rows_of_subdomain) and B_s R_s.
  std::vector<la::SparseMatrix> _B;
  std::vector<la::Matrix> _BR;
  const decomposition::ExplicitBoundaryOperators* _explicit = nullptr;
  std::vector<la::SparseMatrix> _B_boundary; ///< per owned subdomain: B_s on the columns b_s
  std::vector<la::SparseMatrix> _B_touched;  ///< per owned subdomain: B_s on the columns it touches (c_s)
  std::vector<la::SparseMatrix> _K_touched;  ///< per owned subdomain: K_s on c_s, lower triangle
  int64_t _lumped_work = 0;                  ///< one product with the K_cc, in parallel_for's units
  /// Nonzeros of the subdomain factors per unit of parallel_for's work (its DOFs): the
  /// plane-strain meshes, where min_parallel_work was measured, have about this many per DOF.
  static constexpr int64_t factor_nonzeros_per_work_unit = 50;
  int64_t _implicit_work = 0; ///< one substitution with every owned factor, in parallel_for's units
  int64_t _explicit_work = 0; ///< one product with the dense blocks, in parallel_for's units
  /// For G G': per neighbour rank (the layout's neighbour_ranks), (kept row, owned subdomain)
  /// pairs whose B_s R_s rows are sent, and the number of values received.
  std::vector<std::vector<std::pair<int64_t, int32_t>>> _share_send;
  std::vector<size_t> _share_recv_size;
};

/// The lumped preconditioner B K B' as a LinearOperator.
class LumpedPreconditioner : public la::LinearOperator
{
public:
  explicit LumpedPreconditioner(const FetiOperators& feti) : _feti(feti) {}
  la::Index size() const override { return _feti.n_dual(); }
  const la::VectorSpace* space() const override { return &_feti.space(); }
  void apply(const la::Vector& x, la::Vector& y) const override { y = _feti.apply_lumped(x); }

private:
  const FetiOperators& _feti;
};

/// The Dirichlet preconditioner B S B' as a LinearOperator.
class DirichletPreconditioner : public la::LinearOperator
{
public:
  DirichletPreconditioner(const FetiOperators& feti, const decomposition::SchurComplements& schur)
      : _feti(feti), _schur(schur)
  {
  }
  la::Index size() const override { return _feti.n_dual(); }
  const la::VectorSpace* space() const override { return &_feti.space(); }
  void apply(const la::Vector& x, la::Vector& y) const override { y = _feti.apply_dirichlet(x, _schur); }

private:
  const FetiOperators& _feti;
  const decomposition::SchurComplements& _schur;
};

/// F + C as a LinearOperator, optionally scaled by `scale` (F / ||PFP|| in the dual penalty),
/// with C = diag(compliance) the compliance of the rows whose contact law is a penalty spring
/// (B_i u - c_i = C_i lambda_i where lambda_i > 0; dual/contact_qp.hpp), or none.
class FOperator : public la::LinearOperator
{
public:
  /// @param compliance one value per owned row (referenced), or null for C = 0
  explicit FOperator(const FetiOperators& feti, double scale = 1.0, const la::Vector* compliance = nullptr)
      : _feti(feti), _scale(scale), _compliance(compliance)
  {
  }
  la::Index size() const override { return _feti.n_dual(); }
  const la::VectorSpace* space() const override { return &_feti.space(); }
  void apply(const la::Vector& x, la::Vector& y) const override
  {
    if (_compliance)
      y = _scale * (_feti.apply_F(x) + _compliance->cwiseProduct(x));
    else
      y = _scale * _feti.apply_F(x);
  }

private:
  const FetiOperators& _feti;
  double _scale;
  const la::Vector* _compliance;
};
} // namespace feticon::dual
