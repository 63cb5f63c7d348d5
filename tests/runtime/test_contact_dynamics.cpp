// Contact dynamics, impulse dynamics and the contact-dynamics derivatives (contact_dynamics.hpp)
// against identities that need no stored numbers: the KKT residuals computed by other algorithms
// (RNEA, feet_force_terms = Jᵀλ, feet Jacobian, J̇v), the impact law and momentum balance, the
// empty contact set against forward dynamics, redundant contacts against the single contact, and
// the derivatives against central differences.
#include <gtest/gtest.h>

#include <string>

#include "finite_differences.hpp"
#include "rbdc/rbdc.hpp"
#include "test_robots.hpp"

namespace rbdc {
namespace {

constexpr double kIdentityTolerance = 1e-9;  // relative to max(1, largest entry)

using test::relative_error;

std::vector<int> all_feet(const Model& model) {
  std::vector<int> feet;
  for (size_t k = 0; k < model.feet.size(); ++k) feet.push_back(static_cast<int>(k));
  return feet;
}

/// λ as world forces on the feet (3 × n_feet), repeated contacts summed.
Matrix3X forces_on_feet(const Model& model, const ContactDynamicsData& contact, const VectorX& lambda) {
  Matrix3X f = Matrix3X::Zero(3, static_cast<Eigen::Index>(model.feet.size()));
  for (size_t k = 0; k < contact.contact_feet.size(); ++k) {
    f.col(contact.contact_feet[k]) += lambda.segment<3>(3 * static_cast<Eigen::Index>(k));
  }
  return f;
}

/// The contact rows of a 3·n_feet-row quantity.
VectorX contact_rows(const ContactDynamicsData& contact, const VectorX& feet_rows) {
  VectorX out(3 * static_cast<Eigen::Index>(contact.contact_feet.size()));
  for (size_t k = 0; k < contact.contact_feet.size(); ++k) {
    out.segment<3>(3 * static_cast<Eigen::Index>(k)) = feet_rows.segment<3>(3 * contact.contact_feet[k]);
  }
  return out;
}

VectorX flat(const Matrix3X& m) { return Eigen::Map<const VectorX>(m.data(), m.size()); }

struct State {
  VectorX q, v, tau;
};

State random_state(const Model& model, test::RandomState& random) {
  return {random.configuration(model), random.vector(model.nv, 2.0),
          random.vector(model.num_joints(), 5.0)};
}

/// M a + c + g − Sᵀτ − Jᵀλ by the RNEA and Alg. 4, and J a + J̇v + kd J v + kp (p − p*).
void expect_kkt_residuals_vanish(const Model& model, const ContactDynamicsData& contact,
                                 const State& s, const Matrix3X* anchors) {
  Data check(model);
  VectorX row1 = inverse_dynamics(model, check, s.q, s.v, contact.a);
  row1.tail(model.num_joints()) -= s.tau;
  row1 -= feet_force_terms(model, check, s.q, forces_on_feet(model, contact, contact.lambda));
  const VectorX tau_scale = inverse_dynamics(model, check, s.q, s.v, contact.a);
  EXPECT_LT(row1.cwiseAbs().maxCoeff() / std::max(1.0, tau_scale.cwiseAbs().maxCoeff()),
            kIdentityTolerance) << model.name;
  const MatrixX J = feet_jacobian(model, check, s.q);
  VectorX row2 = contact_rows(contact, J * contact.a) +
                 contact_rows(contact, flat(feet_bias_accelerations(model, check, s.q, s.v)));
  row2 += contact.gains.kd * contact_rows(contact, J * s.v);
  if (anchors != nullptr) {
    const Matrix3X p = feet_positions(model, check, s.q);
    for (size_t k = 0; k < contact.contact_feet.size(); ++k) {
      row2.segment<3>(3 * static_cast<Eigen::Index>(k)) +=
          contact.gains.kp * (p.col(contact.contact_feet[k]) - anchors->col(static_cast<Eigen::Index>(k)));
    }
  }
  const double acc_scale = std::max(1.0, (J * contact.a).cwiseAbs().maxCoeff());
  EXPECT_LT(row2.cwiseAbs().maxCoeff() / acc_scale, kIdentityTolerance) << model.name;
}

TEST(ContactDynamics, KktResidualsVanishOnEveryTestRobot) {
  test::RandomState random(7);
  for (const Model& model : test::all_robots()) {
    Data data(model);
    ContactDynamicsData contact(model, all_feet(model));
    for (int trial = 0; trial < 3; ++trial) {
      const State s = random_state(model, random);
      contact_dynamics(model, data, contact, s.q, s.v, s.tau);
      ASSERT_TRUE(contact.a.allFinite() && contact.lambda.allFinite()) << model.name;
      EXPECT_GT(contact.lambda.cwiseAbs().maxCoeff(), 1e-3) << model.name;  // the contacts work
      expect_kkt_residuals_vanish(model, contact, s, nullptr);
    }
  }
}

TEST(ContactDynamics, BaumgarteTermsEnterTheConstraintRows) {
  const Model model = test::mini_cheetah();
  Data data(model);
  ContactDynamicsData contact(model, {0, 3}, BaumgarteGains{100.0, 20.0});
  test::RandomState random(8);
  const State s = random_state(model, random);
  const Matrix3X anchors = Matrix3X::Random(3, 2) * 0.3;
  contact_dynamics(model, data, contact, s.q, s.v, s.tau, anchors);
  expect_kkt_residuals_vanish(model, contact, s, &anchors);
  EXPECT_THROW(contact_dynamics(model, data, contact, s.q, s.v, s.tau), std::invalid_argument);
  EXPECT_THROW(contact_dynamics(model, data, contact, s.q, s.v, s.tau, Matrix3X::Zero(3, 3)),
               std::invalid_argument);
}

TEST(ContactDynamics, EmptyContactSetIsForwardDynamics) {
  test::RandomState random(9);
  for (const Model& model : test::all_robots()) {
    Data data(model), reference(model);
    ContactDynamicsData contact(model, {});
    const State s = random_state(model, random);
    contact_dynamics(model, data, contact, s.q, s.v, s.tau);
    const VectorX a = forward_dynamics(model, reference, s.q, s.v, s.tau,
                                       Matrix3X::Zero(3, static_cast<Eigen::Index>(model.feet.size())));
    EXPECT_LT(relative_error(contact.a, a), 1e-12) << model.name;
    EXPECT_EQ(contact.lambda.size(), 0);
    impulse_dynamics(model, data, contact, s.q, s.v, 0.5);
    EXPECT_EQ(contact.v_plus, s.v);
  }
}

// Redundant contacts: the same foot twice (J has equal row blocks, A is singular). The damped
// proximal solve gives the acceleration of the single contact and splits its force evenly (the
// least-norm λ), finite.
TEST(ContactDynamics, RepeatedFootGivesTheSingleContactAccelerationAndHalfItsForce) {
  test::RandomState random(10);
  for (const Model& model : test::all_robots()) {
    Data data(model);
    ContactDynamicsData single(model, {0}), twice(model, {0, 0});
    const State s = random_state(model, random);
    contact_dynamics(model, data, single, s.q, s.v, s.tau);
    contact_dynamics(model, data, twice, s.q, s.v, s.tau);
    ASSERT_TRUE(twice.a.allFinite() && twice.lambda.allFinite()) << model.name;
    EXPECT_LT(relative_error(twice.a, single.a), 1e-7) << model.name;
    const double scale = std::max(1.0, single.lambda.cwiseAbs().maxCoeff());
    EXPECT_LT((twice.lambda.head<3>() - 0.5 * single.lambda).cwiseAbs().maxCoeff() / scale, 1e-6);
    EXPECT_LT((twice.lambda.tail<3>() - 0.5 * single.lambda).cwiseAbs().maxCoeff() / scale, 1e-6);
    impulse_dynamics(model, data, single, s.q, s.v, 0.0);
    impulse_dynamics(model, data, twice, s.q, s.v, 0.0);
    ASSERT_TRUE(twice.v_plus.allFinite()) << model.name;
    EXPECT_LT(relative_error(twice.v_plus, single.v_plus), 1e-7) << model.name;
  }
}

TEST(ContactDynamics, BadContactSetsAndRestitutionAreRefused) {
  const Model model = test::mini_cheetah();
  EXPECT_THROW(ContactDynamicsData(model, {4}), std::invalid_argument);
  EXPECT_THROW(ContactDynamicsData(model, {-1}), std::invalid_argument);
  Data data(model);
  ContactDynamicsData contact(model, {0});
  const VectorX q = test::RandomState(3).configuration(model), v = VectorX::Zero(model.nv);
  EXPECT_THROW(impulse_dynamics(model, data, contact, q, v, 1.5), std::invalid_argument);
  EXPECT_THROW(impulse_dynamics(model, data, contact, q, v, std::nan("")), std::invalid_argument);
  const Model other = test::arm7();
  ContactDynamicsData wrong(other, {0});
  EXPECT_THROW(contact_dynamics(model, data, wrong, q, v, VectorX::Zero(12)), std::invalid_argument);
}

TEST(ImpulseDynamics, ImpactLawAndMomentumBalance) {
  test::RandomState random(11);
  for (const Model& model : test::all_robots()) {
    Data data(model), check(model);
    ContactDynamicsData contact(model, all_feet(model));
    for (double e : {0.0, 0.4, 1.0}) {
      const State s = random_state(model, random);
      impulse_dynamics(model, data, contact, s.q, s.v, e);
      const MatrixX J = feet_jacobian(model, check, s.q);
      // J v⁺ = −e J v⁻
      const VectorX after = contact_rows(contact, J * contact.v_plus);
      const VectorX before = contact_rows(contact, J * s.v);
      EXPECT_LT((after + e * before).cwiseAbs().maxCoeff() / std::max(1.0, before.cwiseAbs().maxCoeff()),
                kIdentityTolerance) << model.name << " e = " << e;
      // M (v⁺ − v⁻) = JᵀΛ, with JᵀΛ by Alg. 4
      const VectorX momentum = mass_matrix(model, check, s.q) * (contact.v_plus - s.v);
      const VectorX JtL = feet_force_terms(model, check, s.q, forces_on_feet(model, contact, contact.impulse));
      EXPECT_LT(relative_error(momentum, JtL), kIdentityTolerance) << model.name << " e = " << e;
    }
  }
}

class ContactDerivatives : public ::testing::TestWithParam<int> {};

TEST_P(ContactDerivatives, MatchCentralDifferences) {
  const Model model = test::all_robots()[static_cast<size_t>(GetParam())];
  const BaumgarteGains gains{30.0, 5.0};
  Data data(model), scratch(model);
  DerivativeData derivatives(model);
  ContactDynamicsData contact(model, all_feet(model), gains), fd(model, all_feet(model), gains);
  test::RandomState random(12);
  const State s = random_state(model, random);
  const Matrix3X anchors = Matrix3X::Random(3, static_cast<Eigen::Index>(model.feet.size())) * 0.2;
  contact_dynamics_derivatives(model, data, derivatives, contact, s.q, s.v, s.tau, anchors);
  const auto both = [&](const VectorX& q, const VectorX& v, const VectorX& tau) {
    contact_dynamics(model, scratch, fd, q, v, tau, anchors);
    VectorX out(fd.a.size() + fd.lambda.size());
    out << fd.a, fd.lambda;
    return out;
  };
  const MatrixX fd_q = test::manifold_differences(model, s.q, [&](const VectorX& q) { return both(q, s.v, s.tau); });
  const MatrixX fd_v = test::plain_differences(s.v, [&](const VectorX& v) { return both(s.q, v, s.tau); });
  const MatrixX fd_tau = test::plain_differences(s.tau, [&](const VectorX& tau) { return both(s.q, s.v, tau); });
  const Eigen::Index nv = model.nv, m = contact.lambda.size();
  EXPECT_LT(relative_error(contact.da_dq, fd_q.topRows(nv)), test::kFdTolerance) << model.name;
  EXPECT_LT(relative_error(contact.dlambda_dq, fd_q.bottomRows(m)), test::kFdTolerance) << model.name;
  EXPECT_LT(relative_error(contact.da_dv, fd_v.topRows(nv)), test::kFdTolerance) << model.name;
  EXPECT_LT(relative_error(contact.dlambda_dv, fd_v.bottomRows(m)), test::kFdTolerance) << model.name;
  EXPECT_LT(relative_error(contact.da_dtau, fd_tau.topRows(nv)), test::kFdTolerance) << model.name;
  EXPECT_LT(relative_error(contact.dlambda_dtau, fd_tau.bottomRows(m)), test::kFdTolerance) << model.name;
  EXPECT_GT(contact.dlambda_dq.cwiseAbs().maxCoeff(), 1e-3);  // not trivially zero
}

INSTANTIATE_TEST_SUITE_P(TestRobots, ContactDerivatives, ::testing::Values(0, 1, 2, 3));

}  // namespace
}  // namespace rbdc
