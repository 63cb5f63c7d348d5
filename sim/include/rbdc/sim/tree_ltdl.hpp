// The mass matrix of a tree factorised as M = Lᵀ D L with L unit lower triangular whose non-zeros
// are the ones the tree induces (Featherstone, RBDA Sec. 6.5, "LTDL"): row k of L is non-zero only
// at the ancestors of dof k, so nothing fills in and each solve walks parent chains. The generated
// forward dynamics unrolls the same factorisation (generator/rbdcgen/algorithms/forward_dynamics.py).
#pragma once

#include <vector>

#include "rbdc/model.hpp"

namespace rbdc::sim {

/// λ over degrees of freedom: the six trunk dofs of a floating base form a chain, each joint dof
/// hangs from the last dof of its parent body; -1 marks a root.
std::vector<int> dof_parents(const Model& model);

class TreeLtdl {
 public:
  /// `parents`: dof_parents(), each parent before its child.
  explicit TreeLtdl(const std::vector<int>& parents);
  int size() const { return static_cast<int>(d_.size()); }

  /// Factorises M (size × size, symmetric positive definite; only its lower triangle is read).
  void factorise(const MatrixX& M);
  /// Takes a factor computed elsewhere with the same dof parents (the generated
  /// mass_matrix_factor): L column-major, size × size, read at the ancestors only; D and D⁻¹.
  void assign(const double* L, const double* D, const double* D_inv);
  /// x ← L⁻ᵀ x, in place, for each column of x (size rows).
  void solve_lt(Eigen::Ref<MatrixX> x) const;
  /// x ← L⁻¹ D⁻¹ x, in place (after solve_lt, this completes M⁻¹).
  void solve_dinv_l(Eigen::Ref<VectorX> x) const;
  /// D⁻¹ (the inverse pivots).
  const VectorX& inverse_pivots() const { return inv_d_; }

 private:
  // Row k of L packed: its entries at the ancestors of dof k, nearest first, so that the ancestors
  // of an ancestor are a tail of the same list.
  int row_begin(int k) const { return begin_[static_cast<size_t>(k)]; }
  int row_length(int k) const { return begin_[static_cast<size_t>(k) + 1] - begin_[static_cast<size_t>(k)]; }
  std::vector<int> begin_;      // size + 1 offsets into ancestors_ and l_
  std::vector<int> ancestors_;  // dof indices
  std::vector<double> l_;       // L's entries, then the multipliers while factorising
  VectorX d_, inv_d_;
};

}  // namespace rbdc::sim
