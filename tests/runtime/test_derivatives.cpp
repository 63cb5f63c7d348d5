// Derivatives of the dynamics (derivatives.hpp) against central finite differences on the manifold
// (q ⊕ δ by rbdc::integrate), plus the identities that need no finite differences: ∂a/∂τ = M⁻¹Sᵀ,
// ∂a/∂f = M⁻¹Jᵀ, ∂τ/∂q = ∂(c + g)/∂q + ∂(M a)/∂q, ∂τ/∂v = ∂(c + g)/∂v, zero trunk-position columns.
#include <gtest/gtest.h>

#include <limits>
#include <string>

#include "finite_differences.hpp"
#include "model_test_support.hpp"
#include "rbdc/rbdc.hpp"
#include "test_robots.hpp"

namespace rbdc {
namespace {

using test::kFdTolerance;
using test::manifold_differences;
using test::plain_differences;
using test::relative_error;

VectorX flat(const Matrix3X& m) { return Eigen::Map<const VectorX>(m.data(), m.size()); }
Matrix3X unflat(const VectorX& x) { return Eigen::Map<const Matrix3X>(x.data(), 3, x.size() / 3); }

Model load_bundled(const std::string& name) {
  UrdfOptions options;
  options.floating_base = name != "arm7";
  std::vector<std::string> warnings;  // the MIT thigh inertia breaks the triangle inequality
  return load_urdf(RBDC_SOURCE_DIR "/robots/" + name + ".urdf", options, &warnings);
}

// Geared motor rotors on every joint (docs/model.md, "Actuators").
Model mini_cheetah_with_rotors() {
  UrdfOptions options;
  options.topology_file = RBDC_SOURCE_DIR "/robots/mini_cheetah_rotors.topology.yaml";
  std::vector<std::string> warnings;
  return load_urdf(RBDC_SOURCE_DIR "/robots/mini_cheetah.urdf", options, &warnings);
}

// The bundled robots, the Mini Cheetah with rotors and, for a prismatic joint and oblique axes,
// test_robots.hpp's branched().
Model robot(const std::string& name) {
  if (name == "branched") return test::branched();
  if (name == "mini_cheetah_rotors") return mini_cheetah_with_rotors();
  return load_bundled(name);
}

class Derivatives : public ::testing::TestWithParam<std::string> {
 protected:
  Model model = robot(GetParam());
  Data data{model};
  DerivativeData derivatives{model};
  test::RandomState random{91};

  struct State {
    VectorX q, v, a, tau;
    Matrix3X f;
  };
  State state() {
    State s{random.configuration(model), random.vector(model.nv, 2.0), random.vector(model.nv, 3.0),
            random.vector(model.num_joints(), 5.0), random.forces(model)};
    return s;
  }
  static constexpr int kStates = 3;
};

TEST_P(Derivatives, InverseDynamicsMatchFiniteDifferences) {
  for (int trial = 0; trial < kStates; ++trial) {
    const State s = state();
    inverse_dynamics_derivatives(model, data, derivatives, s.q, s.v, s.a);
    Data scratch(model);
    const MatrixX fd_q = manifold_differences(
        model, s.q, [&](const VectorX& q) { return inverse_dynamics(model, scratch, q, s.v, s.a); });
    const MatrixX fd_v = plain_differences(
        s.v, [&](const VectorX& v) { return inverse_dynamics(model, scratch, s.q, v, s.a); });
    EXPECT_LT(relative_error(derivatives.dtau_dq, fd_q), kFdTolerance) << "trial " << trial;
    EXPECT_LT(relative_error(derivatives.dtau_dv, fd_v), kFdTolerance) << "trial " << trial;
    EXPECT_GT(derivatives.dtau_dq.cwiseAbs().maxCoeff(), 1e-3);  // not trivially zero
  }
}

TEST_P(Derivatives, BiasAndGravityMatchFiniteDifferencesOfTheSplitTerms) {
  for (int trial = 0; trial < kStates; ++trial) {
    const State s = state();
    bias_derivatives(model, data, derivatives, s.q, s.v);
    gravity_derivatives(model, data, derivatives, s.q);
    Data scratch(model);
    // c + g from Algs. 2 and 3, an independent route from the RNEA at a = 0
    const auto bias = [&](const VectorX& q, const VectorX& v) {
      return VectorX(quadratic_velocity_terms(model, scratch, q, v) + gravity_terms(model, scratch, q));
    };
    EXPECT_LT(relative_error(derivatives.dbias_dq,
                             manifold_differences(model, s.q, [&](const VectorX& q) { return bias(q, s.v); })),
              kFdTolerance);
    EXPECT_LT(relative_error(derivatives.dbias_dv,
                             plain_differences(s.v, [&](const VectorX& v) { return bias(s.q, v); })),
              kFdTolerance);
    EXPECT_LT(relative_error(derivatives.dg_dq,
                             manifold_differences(model, s.q, [&](const VectorX& q) {
                               return gravity_terms(model, scratch, q);
                             })),
              kFdTolerance);
  }
}

TEST_P(Derivatives, ForwardDynamicsMatchFiniteDifferences) {
  for (int trial = 0; trial < kStates; ++trial) {
    const State s = state();
    forward_dynamics_derivatives(model, data, derivatives, s.q, s.v, s.tau, s.f);
    Data scratch(model);
    const auto fd = [&](const VectorX& q, const VectorX& v, const VectorX& tau, const Matrix3X& f) {
      return forward_dynamics(model, scratch, q, v, tau, f);
    };
    EXPECT_LT(relative_error(derivatives.da_dq, manifold_differences(model, s.q, [&](const VectorX& q) {
                               return fd(q, s.v, s.tau, s.f);
                             })),
              kFdTolerance)
        << "trial " << trial;
    EXPECT_LT(relative_error(derivatives.da_dv, plain_differences(s.v, [&](const VectorX& v) {
                               return fd(s.q, v, s.tau, s.f);
                             })),
              kFdTolerance);
    EXPECT_LT(relative_error(derivatives.da_dtau, plain_differences(s.tau, [&](const VectorX& tau) {
                               return fd(s.q, s.v, tau, s.f);
                             })),
              kFdTolerance);
    EXPECT_LT(relative_error(derivatives.da_df, plain_differences(flat(s.f), [&](const VectorX& f) {
                               return fd(s.q, s.v, s.tau, unflat(f));
                             })),
              kFdTolerance);
  }
}

TEST_P(Derivatives, FeetTermsMatchFiniteDifferences) {
  for (int trial = 0; trial < kStates; ++trial) {
    const State s = state();
    feet_velocity_derivatives(model, data, derivatives, s.q, s.v);
    feet_force_term_derivatives(model, data, derivatives, s.q, s.f);
    Data scratch(model);
    EXPECT_LT(relative_error(derivatives.dpdot_dq, manifold_differences(model, s.q, [&](const VectorX& q) {
                               return flat(feet_velocities(model, scratch, q, s.v));
                             })),
              kFdTolerance);
    EXPECT_LT(relative_error(derivatives.dtau_e_dq, manifold_differences(model, s.q, [&](const VectorX& q) {
                               return feet_force_terms(model, scratch, q, s.f);
                             })),
              kFdTolerance);
    EXPECT_GT(derivatives.dpdot_dq.cwiseAbs().maxCoeff(), 1e-3);
    EXPECT_GT(derivatives.dtau_e_dq.cwiseAbs().maxCoeff(), 1e-3);
  }
}

TEST_P(Derivatives, InputDerivativesAreTheInverseMassMatrixTimesSelectorAndJacobianTranspose) {
  const State s = state();
  forward_dynamics_derivatives(model, data, derivatives, s.q, s.v, s.tau, s.f);
  Data scratch(model);
  const MatrixX M_inv = mass_matrix(model, scratch, s.q).inverse();
  const MatrixX J = feet_jacobian(model, scratch, s.q);
  EXPECT_LT(relative_error(derivatives.da_dtau, M_inv.rightCols(model.num_joints())), 1e-10);
  EXPECT_LT(relative_error(derivatives.da_df, M_inv * J.transpose()), 1e-10);
}

TEST_P(Derivatives, InverseDynamicsSplitsIntoBiasAndInertiaTerms) {
  const State s = state();
  Data scratch(model);
  inverse_dynamics_derivatives(model, data, derivatives, s.q, s.v, s.a);
  const MatrixX dtau_dq = derivatives.dtau_dq, dtau_dv = derivatives.dtau_dv;
  bias_derivatives(model, data, derivatives, s.q, s.v);
  // ∂(M a)/∂q at fixed a, by finite differences of CRBA's M (Alg. 5), not of the RNEA
  const MatrixX dMa_dq = manifold_differences(
      model, s.q, [&](const VectorX& q) { return VectorX(mass_matrix(model, scratch, q) * s.a); });
  EXPECT_LT(relative_error(dtau_dq, derivatives.dbias_dq + dMa_dq), kFdTolerance);
  // M a is independent of v: ∂τ/∂v = ∂(c + g)/∂v up to round-off
  EXPECT_LT(relative_error(dtau_dv, derivatives.dbias_dv), 1e-12);
  // ∂τ/∂q at v = 0 is ∂g/∂q + ∂(M a)/∂q
  inverse_dynamics_derivatives(model, data, derivatives, s.q, VectorX::Zero(model.nv), s.a);
  const MatrixX dtau_dq_rest = derivatives.dtau_dq;
  gravity_derivatives(model, data, derivatives, s.q);
  EXPECT_LT(relative_error(dtau_dq_rest, derivatives.dg_dq + dMa_dq), kFdTolerance);
}

TEST_P(Derivatives, TrunkPositionColumnsAreExactlyZero) {
  if (!model.floating_base) GTEST_SKIP() << "fixed base: no trunk position";
  const State s = state();
  inverse_dynamics_derivatives(model, data, derivatives, s.q, s.v, s.a);
  bias_derivatives(model, data, derivatives, s.q, s.v);
  gravity_derivatives(model, data, derivatives, s.q);
  forward_dynamics_derivatives(model, data, derivatives, s.q, s.v, s.tau, s.f);
  feet_velocity_derivatives(model, data, derivatives, s.q, s.v);
  const DerivativeData& d = derivatives;
  // nothing depends on where the trunk is, only on its orientation (through gravity and world forces)
  for (const MatrixX* m : {&d.dtau_dq, &d.dbias_dq, &d.dg_dq, &d.da_dq, &d.dpdot_dq, &d.dtau_e_dq}) {
    EXPECT_TRUE((m->middleCols<3>(3).array() == 0).all());
    EXPECT_FALSE((m->leftCols<3>().array() == 0).all());  // ...but the orientation does matter
  }
}

TEST_P(Derivatives, NonPositiveDefiniteMassMatrixGivesNaN) {
  State s = state();
  s.q[model.nq - 1] = std::numeric_limits<double>::quiet_NaN();
  forward_dynamics_derivatives(model, data, derivatives, s.q, s.v, s.tau, s.f);
  EXPECT_TRUE(derivatives.da_dq.array().isNaN().all());
  EXPECT_TRUE(derivatives.da_dtau.array().isNaN().all());
}

INSTANTIATE_TEST_SUITE_P(Robots, Derivatives,
                         ::testing::Values("mini_cheetah", "arm7", "humanoid32", "branched",
                                           "mini_cheetah_rotors"));

TEST(DerivativesWithRotors, TheRotorCaseReallyHasRotors) {
  const Model model = mini_cheetah_with_rotors();
  EXPECT_TRUE(model.has_rotors);  // otherwise its finite-difference tests above prove nothing new
}

using test::argument_error;

TEST(DerivativeArguments, WrongSizesAreRefusedNamingFunctionAndArgument) {
  const Model model = test::quadruped();
  Data data(model);
  DerivativeData derivatives(model);
  test::RandomState random(3);
  const VectorX q = random.configuration(model), v = VectorX::Zero(model.nv);
  const Matrix3X f = random.forces(model);
  EXPECT_EQ(argument_error([&] { inverse_dynamics_derivatives(model, data, derivatives, q, v, VectorX(3)); }),
            "rbdc::inverse_dynamics_derivatives: a has 3 entries, expected 18");
  EXPECT_EQ(argument_error([&] { bias_derivatives(model, data, derivatives, q, VectorX(17)); }),
            "rbdc::bias_derivatives: v has 17 entries, expected 18");
  EXPECT_EQ(argument_error([&] { gravity_derivatives(model, data, derivatives, VectorX(18)); }),
            "rbdc::gravity_derivatives: q has 18 entries, expected 19");
  EXPECT_EQ(argument_error([&] {
              forward_dynamics_derivatives(model, data, derivatives, q, v, VectorX(18), f);
            }),
            "rbdc::forward_dynamics_derivatives: tau has 18 entries, expected 12");
  EXPECT_EQ(argument_error([&] { feet_force_term_derivatives(model, data, derivatives, q, Matrix3X(3, 2)); }),
            "rbdc::feet_force_term_derivatives: f_world has 2 entries, expected 4");
  const Model arm = test::arm7();
  DerivativeData arm_derivatives(arm);
  EXPECT_EQ(argument_error([&] { feet_velocity_derivatives(model, data, arm_derivatives, q, v); }),
            "rbdc::feet_velocity_derivatives: derivative data was built for a different model than "
            "'quadruped'");
  VectorX out(model.nq);
  EXPECT_EQ(argument_error([&] { integrate(model, q, VectorX(19), out); }),
            "rbdc::integrate: delta has 19 entries, expected 18");
}

// --- The manifold helpers (manifold.hpp) -------------------------------------------------------

TEST(Manifold, IntegrateMovesTheTrunkInTrunkCoordinatesAndAddsJoints) {
  const Model model = test::quadruped();
  test::RandomState random(8);
  const VectorX q = random.configuration(model);
  VectorX delta = VectorX::Zero(model.nv);
  delta.segment<3>(3) = Vector3(0.1, -0.2, 0.3);
  delta[6] = 0.25;
  VectorX out(model.nq);
  integrate(model, q, delta, out);
  const Matrix3 R = Eigen::Quaterniond(q[3], q[4], q[5], q[6]).toRotationMatrix();
  EXPECT_LT((out.head<3>() - q.head<3>() - R * delta.segment<3>(3)).norm(), 1e-15);
  EXPECT_NEAR(out[7], q[7] + 0.25, 1e-15);
  // a rotation about the trunk's own z axis: R' = R Rz(θ)
  delta.setZero();
  delta[2] = 0.7;
  integrate(model, q, delta, out);
  const Matrix3 R_next = Eigen::Quaterniond(out[3], out[4], out[5], out[6]).toRotationMatrix();
  EXPECT_LT((R_next - R * Eigen::AngleAxisd(0.7, Vector3::UnitZ()).toRotationMatrix()).norm(), 1e-14);
  EXPECT_NEAR(out.segment<4>(3).norm(), 1.0, 1e-15);
  // in place
  VectorX in_place = q;
  integrate(model, in_place, delta, in_place);
  EXPECT_LT((in_place - out).norm(), 1e-15);
}

TEST(Manifold, TangentMapIsTheDerivativeOfIntegrateAndHasAnInverse) {
  for (const Model& model : {test::quadruped(), test::arm7()}) {
    test::RandomState random(12);
    const VectorX q = random.configuration(model);
    MatrixX T(model.nq, model.nv), T_inverse(model.nv, model.nq);
    tangent_map(model, q, T);
    tangent_map_inverse(model, q, T_inverse);
    VectorX out(model.nq);
    const MatrixX fd = plain_differences(VectorX::Zero(model.nv), [&](const VectorX& delta) {
      integrate(model, q, delta, out);
      return out;
    });
    EXPECT_LT(relative_error(T, fd), 1e-9) << model.name;
    EXPECT_LT(relative_error(T_inverse * T, MatrixX::Identity(model.nv, model.nv)), 1e-14);
  }
}

TEST(Manifold, TangentMapConvertsPlainCoordinateDerivatives) {
  const Model model = test::quadruped();
  Data data(model), scratch(model);
  DerivativeData derivatives(model);
  test::RandomState random(4);
  const VectorX q = random.configuration(model);
  gravity_derivatives(model, data, derivatives, q);
  // ∂g/∂q in plain coordinates (quaternion entries perturbed one by one; g normalises it)
  const MatrixX dg_dq_plain = plain_differences(q, [&](const VectorX& x) { return gravity_terms(model, scratch, x); });
  MatrixX T(model.nq, model.nv), T_inverse(model.nv, model.nq);
  tangent_map(model, q, T);
  tangent_map_inverse(model, q, T_inverse);
  EXPECT_LT(relative_error(dg_dq_plain * T, derivatives.dg_dq), kFdTolerance);
  EXPECT_LT(relative_error(derivatives.dg_dq * T_inverse, dg_dq_plain), kFdTolerance);
}

TEST(Manifold, SwapTrunkAngularLinearIsAnInvolutionOnTheTrunkBlock) {
  const Model model = test::quadruped();
  MatrixX m = MatrixX::Random(model.nv, model.nv);
  const MatrixX original = m;
  swap_trunk_angular_linear(model, m, true);
  EXPECT_EQ(m.row(0), original.row(3));
  EXPECT_EQ(m.row(5), original.row(2));
  EXPECT_EQ(m.bottomRows(12), original.bottomRows(12));
  swap_trunk_angular_linear(model, m, true);
  swap_trunk_angular_linear(model, m, false);
  EXPECT_EQ(m.col(4), original.col(1));
  MatrixX small(2, 2);
  EXPECT_EQ(argument_error([&] { swap_trunk_angular_linear(model, small, false); }),
            "rbdc::swap_trunk_angular_linear: the matrix has 2 columns, expected at least 6 (a "
            "floating base's velocity block)");
}

}  // namespace
}  // namespace rbdc
