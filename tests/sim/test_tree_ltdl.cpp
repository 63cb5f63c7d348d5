// The tree factorisation M = Lᵀ D L the contact solver uses (tree_ltdl.hpp) against Eigen's dense
// Cholesky, on the Mini Cheetah's mass matrix (floating base, four legs) at random configurations;
// the generated factor (DynamicsModel::step_terms) against the runtime's M factorised.
#include <gtest/gtest.h>

#include <random>

#include "rbdc/crba.hpp"
#include "rbdc/sim/dynamics.hpp"
#include "rbdc/sim/robot.hpp"
#include "rbdc/sim/tree_ltdl.hpp"

using namespace rbdc;
using namespace rbdc::sim;

namespace {

void expect_solves_like_cholesky(const Model& model, unsigned seed) {
  std::mt19937 rng(seed);
  std::uniform_real_distribution<double> unit(-1, 1);
  TreeLtdl ltdl(dof_parents(model));
  Data data(model);
  for (int trial = 0; trial < 10; ++trial) {
    VectorX q = VectorX::Zero(model.nq);
    q.segment<4>(3) = Eigen::Vector4d(unit(rng), unit(rng), unit(rng), unit(rng)).normalized();
    for (int i = 7; i < model.nq; ++i) q[i] = 2 * unit(rng);
    const MatrixX M = mass_matrix(model, data, q);
    ltdl.factorise(M);
    MatrixX B = MatrixX::NullaryExpr(model.nv, 3, [&]() { return unit(rng); });
    const MatrixX expected = M.llt().solve(B);
    // M⁻¹ = L⁻¹ D⁻¹ L⁻ᵀ column by column, and Bᵀ M⁻¹ B = Yᵀ D⁻¹ Y with Y = L⁻ᵀ B.
    MatrixX Y = B;
    ltdl.solve_lt(Y);
    EXPECT_LT((Y.transpose() * ltdl.inverse_pivots().asDiagonal() * Y - B.transpose() * expected).norm(),
              1e-10 * (B.transpose() * expected).norm());
    for (int c = 0; c < B.cols(); ++c) {
      VectorX x = Y.col(c);
      ltdl.solve_dinv_l(x);
      EXPECT_LT((x - expected.col(c)).norm(), 1e-10 * expected.col(c).norm());
    }
  }
}

}  // namespace

TEST(TreeLtdl, SolvesLikeADenseCholesky) {
  const Model model = load_robot(default_urdf());
  EXPECT_EQ(dof_parents(model).size(), static_cast<size_t>(model.nv));
  expect_solves_like_cholesky(model, 1);
}

TEST(TreeLtdl, GeneratedFactorEqualsTheRuntimeOne) {
  const Model model = load_robot(default_urdf());
  const auto generated = make_generated_dynamics();
  const auto runtime = make_runtime_dynamics(model);
  TreeLtdl from_generated(dof_parents(model)), from_runtime(dof_parents(model));
  StepTerms generated_terms, runtime_terms;
  std::mt19937 rng(2);
  std::uniform_real_distribution<double> unit(-1, 1);
  for (int trial = 0; trial < 10; ++trial) {
    VectorX q = VectorX::Zero(model.nq);
    q.segment<4>(3) = Eigen::Vector4d(unit(rng), unit(rng), unit(rng), unit(rng)).normalized();
    for (int i = 7; i < model.nq; ++i) q[i] = 2 * unit(rng);
    const VectorX v = VectorX::Zero(model.nv), tau = VectorX::Zero(model.nv - 6);
    generated->step_terms(q.data(), v.data(), tau.data(), generated_terms, from_generated);
    runtime->step_terms(q.data(), v.data(), tau.data(), runtime_terms, from_runtime);
    const VectorX& d = from_runtime.inverse_pivots();
    EXPECT_LT((from_generated.inverse_pivots() - d).norm(), 1e-12 * d.norm());
    MatrixX x = MatrixX::NullaryExpr(model.nv, 2, [&]() { return unit(rng); }), y = x;
    from_generated.solve_lt(x);  // L⁻ᵀ: every entry of L takes part
    from_runtime.solve_lt(y);
    EXPECT_LT((x - y).norm(), 1e-12 * y.norm());
  }
}

TEST(TreeLtdl, RefusesAParentAfterItsChild) {
  EXPECT_THROW(TreeLtdl({-1, 2, 0}), std::invalid_argument);
}
