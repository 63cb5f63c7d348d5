// Forward dynamics (Eq. 43) undoes inverse dynamics; NaN in gives NaN out; check_finite.
#include <gtest/gtest.h>

#include <limits>

#include "rbdc/bias_terms.hpp"
#include "rbdc/check_finite.hpp"
#include "rbdc/forward_dynamics.hpp"
#include "rbdc/inverse_dynamics.hpp"
#include "rbdc/osc.hpp"
#include "test_robots.hpp"

namespace rbdc {
namespace {

constexpr double nan = std::numeric_limits<double>::quiet_NaN();

class ForwardDynamics : public ::testing::TestWithParam<int> {
 protected:
  Model model = test::all_robots()[static_cast<size_t>(GetParam())];
  Data data{model};
  test::RandomState random{57u + static_cast<unsigned>(GetParam())};
};

TEST_P(ForwardDynamics, UndoesInverseDynamics) {
  for (int trial = 0; trial < 50; ++trial) {
    const VectorX q = random.configuration(model);
    const VectorX v = random.vector(model.nv, 2.0);
    const VectorX tau = random.vector(model.num_joints(), 10.0);
    const Matrix3X f = random.forces(model);
    const VectorX a = forward_dynamics(model, data, q, v, tau, f);
    // M a + c + g - τ_e = Sᵀ τ
    VectorX generalized = inverse_dynamics(model, data, q, v, a) - feet_force_terms(model, data, q, f);
    EXPECT_LE(generalized.head(model.root_dofs()).norm(), 1e-9 * (1 + a.norm()));
    EXPECT_LE((generalized.tail(model.num_joints()) - tau).norm(), 1e-9 * (1 + tau.norm()));
  }
}

TEST_P(ForwardDynamics, NaNInGivesNaNOutWithoutACrash) {
  const VectorX q = random.configuration(model);
  const VectorX v = random.vector(model.nv);
  const VectorX tau = random.vector(model.num_joints());
  const Matrix3X f = random.forces(model);
  VectorX bad_q = q;
  bad_q[model.nq - 1] = nan;
  EXPECT_TRUE(forward_dynamics(model, data, bad_q, v, tau, f).array().isNaN().all());
  VectorX bad_v = v;
  bad_v[0] = nan;
  EXPECT_FALSE(check_finite(forward_dynamics(model, data, q, bad_v, tau, f)));
  Matrix3X bad_f = f;
  bad_f(2, 0) = std::numeric_limits<double>::infinity();
  EXPECT_FALSE(check_finite(forward_dynamics(model, data, q, v, tau, bad_f)));
  // and the workspace recovers on the next good input
  EXPECT_TRUE(check_finite(forward_dynamics(model, data, q, v, tau, f)));
}

INSTANTIATE_TEST_SUITE_P(Robots, ForwardDynamics, ::testing::Range(0, 4));

TEST(ForwardDynamicsArguments, WrongTorqueLengthIsRefused) {
  const Model model = test::quadruped();
  Data data(model);
  EXPECT_THROW(forward_dynamics(model, data, VectorX::Zero(model.nq), VectorX::Zero(model.nv),
                                VectorX::Zero(model.nv), Matrix3X::Zero(3, 4)),
               std::invalid_argument);
  EXPECT_THROW(forward_dynamics(model, data, VectorX::Zero(model.nq), VectorX::Zero(model.nv),
                                VectorX::Zero(12), Matrix3X::Zero(3, 3)),
               std::invalid_argument);
}

TEST(OscNaN, NaNConfigurationGivesNaNQuantities) {
  const Model model = test::quadruped();
  Data data(model);
  VectorX q = test::RandomState(3).configuration(model);
  q[8] = nan;
  const OscQuantities& osc = osc_closed_chain(model, data, q, VectorX::Zero(model.nv), {0, 1, 2, 3});
  EXPECT_FALSE(check_finite(osc.Lambda, osc.b));
}

TEST(CheckFinite, FlagsNaNAndInfInAnyArgument) {
  const VectorX good = VectorX::Ones(4);
  VectorX with_nan = good;
  with_nan[2] = nan;
  Matrix3X with_inf = Matrix3X::Zero(3, 2);
  with_inf(1, 1) = -std::numeric_limits<double>::infinity();
  EXPECT_TRUE(check_finite(good));
  EXPECT_TRUE(check_finite(good, Matrix3X::Zero(3, 2), Vector6::Ones()));
  EXPECT_FALSE(check_finite(with_nan));
  EXPECT_FALSE(check_finite(good, with_inf));
  EXPECT_FALSE(check_finite(with_nan, good));
}

}  // namespace
}  // namespace rbdc
