// Operational-space recursions of paper 001 against their closed forms and against forward
// dynamics, and the big-ground-inertia accuracy study (Fig. 7, Eqs. 58-59).
#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <limits>

#include "rbdc/forward_dynamics.hpp"
#include "rbdc/jacobian.hpp"
#include "rbdc/osc.hpp"
#include "test_robots.hpp"

namespace rbdc {
namespace {

double relative(const MatrixX& a, const MatrixX& b) { return (a - b).norm() / b.norm(); }

class OpenChain : public ::testing::TestWithParam<int> {
 protected:
  // floating-base robots only: the Mini Cheetah (0) and the branched robots (2, 3)
  Model model = test::all_robots()[static_cast<size_t>(GetParam())];
  Data data{model};
  OscReferenceData closed_form{model};
  test::RandomState random{99u + static_cast<unsigned>(GetParam())};
};

TEST_P(OpenChain, RecursionEqualsClosedForm) {
  for (int trial = 0; trial < 50; ++trial) {
    const VectorX q = random.configuration(model);
    const VectorX v = random.vector(model.nv, 2.0);
    const Matrix3X f = random.forces(model);
    const OscQuantities recursion = osc_open_chain(model, data, q, v, f);
    const OscQuantities reference = osc_closed_form(model, data, closed_form, q, v, f);
    EXPECT_LE(relative(recursion.Lambda, reference.Lambda), 1e-10);
    EXPECT_LE(relative(recursion.JbarT, reference.JbarT), 1e-10);
    EXPECT_LE(relative(recursion.b, reference.b), 1e-10);
  }
}

TEST_P(OpenChain, TaskEquationHoldsForForwardDynamics) {
  // Λ_t a[0:6] + b_t = J̄_tᵀ τ with a from Eq. 43 (f_t = 0).
  for (int trial = 0; trial < 20; ++trial) {
    const VectorX q = random.configuration(model);
    const VectorX v = random.vector(model.nv, 2.0);
    const VectorX tau = random.vector(model.num_joints(), 5.0);
    const Matrix3X f = random.forces(model);
    const VectorX a = forward_dynamics(model, data, q, v, tau, f);
    const OscQuantities& osc = osc_open_chain(model, data, q, v, f);
    const Vector6 lhs = osc.Lambda * a.head<6>() + osc.b;
    const Vector6 rhs = osc.JbarT * tau;
    EXPECT_LE((lhs - rhs).norm(), 1e-10 * (1 + rhs.norm() + osc.b.norm()));
  }
}

TEST_P(OpenChain, ClosedChainWithoutContactsIsTheOpenChainWithoutForces) {
  const VectorX q = random.configuration(model);
  const VectorX v = random.vector(model.nv, 2.0);
  const OscQuantities open = osc_open_chain(model, data, q, v, Matrix3X::Zero(3, static_cast<Eigen::Index>(model.feet.size())));
  const OscQuantities closed = osc_closed_chain(model, data, q, v, {});
  EXPECT_LE(relative(closed.Lambda, open.Lambda), 1e-14);
  EXPECT_LE(relative(closed.b, open.b), 1e-14);
}

INSTANTIATE_TEST_SUITE_P(FloatingBaseRobots, OpenChain, ::testing::Values(0, 2, 3));

TEST(OscArguments, FixedBaseAndBadContactsAreRefused) {
  const Model arm = test::arm7();
  Data arm_data(arm);
  EXPECT_THROW(osc_closed_chain(arm, arm_data, VectorX::Zero(arm.nq), VectorX::Zero(arm.nv), {}),
               std::invalid_argument);
  const Model quad = test::mini_cheetah();
  Data data(quad);
  const VectorX q = test::RandomState(1).configuration(quad);
  EXPECT_THROW(osc_closed_chain(quad, data, q, VectorX::Zero(quad.nv), {0, 4}), std::invalid_argument);
  EXPECT_THROW(osc_closed_chain(quad, data, q, VectorX::Zero(quad.nv), {1, 1}), std::invalid_argument);
}

// A stance state of the quadruped: standing pose plus a perturbation, every foot at rest
// (v projected onto the null space of the contact Jacobian, paper 001 Eq. 16).
struct Stance {
  VectorX q, v;
};

Stance stance_state(const Model& model, Data& data, test::RandomState& random) {
  Stance s;
  s.q = VectorX::Zero(model.nq);
  s.q.segment<4>(3) = Eigen::Vector4d(1, 0.05 * random.unit(random.rng), 0.05 * random.unit(random.rng), 0.1 * random.unit(random.rng)).normalized();
  s.q[2] = 0.3;
  for (int leg = 0; leg < 4; ++leg) {
    s.q.segment<3>(7 + 3 * leg) = Vector3(0.0, -0.8, 1.6) + 0.3 * random.vector(3);
  }
  const MatrixX J = feet_jacobian(model, data, s.q);
  const VectorX v = random.vector(model.nv, 1.0);
  s.v = v - J.transpose() * (J * J.transpose()).ldlt().solve(J * v);
  return s;
}

TEST(ClosedChain, ErrorFallsThenRisesWithMinimumNearTheGroundMassHeuristic) {
  const Model model = test::mini_cheetah();
  Data data(model);
  OscReferenceData closed_form(model);
  test::RandomState random(2015);
  const std::vector<int> contacts = {0, 1, 2, 3};
  const double heuristic = default_ground_mass(model);  // Eq. 58
  EXPECT_NEAR(heuristic, 0.064 / std::sqrt(std::numeric_limits<double>::epsilon()), 1e-6);
  double total_mass = 0;
  for (const Body& b : model.bodies) total_mass += b.mass;

  for (int configuration = 0; configuration < 4; ++configuration) {
    const Stance s = stance_state(model, data, random);
    EXPECT_LE((feet_jacobian(model, data, s.q) * s.v).norm(), 1e-12);
    const OscQuantities reference = osc_closed_form_constrained(model, data, closed_form, s.q, s.v, contacts);
    // Ground masses from 1e-4 to 1e12 times the total mass, four per decade (Fig. 7 spans 1e-4 … 1e8).
    std::vector<double> masses, lambda_error, b_error;
    for (double e = -4; e <= 12.0001; e += 0.25) {
      const double m = total_mass * std::pow(10.0, e);
      const OscQuantities& r = osc_closed_chain(model, data, s.q, s.v, contacts, m);
      masses.push_back(m);
      lambda_error.push_back(relative(r.Lambda, reference.Lambda));
      b_error.push_back(relative(r.b, reference.b));
    }
    for (const std::vector<double>* error : {&lambda_error, &b_error}) {
      const auto global = std::min_element(error->begin(), error->end());
      double in_window = std::numeric_limits<double>::infinity();
      for (size_t n = 0; n < masses.size(); ++n) {
        if (masses[n] >= heuristic / 10 && masses[n] <= heuristic * 10) in_window = std::min(in_window, (*error)[n]);
      }
      SCOPED_TRACE("configuration " + std::to_string(configuration) + (error == &b_error ? ", b" : ", Lambda") +
                   ": minimum " + std::to_string(*global) + " at " +
                   std::to_string(masses[static_cast<size_t>(global - error->begin())]) +
                   " kg, heuristic " + std::to_string(heuristic) + " kg");
      // Eq. 59: the minimum lies within a decade of m_min / √ε. Near the bottom the curve is
      // round-off noise, so "the minimum" is read as: the best error inside the window
      // [h/10, 10h] matches the global best to a factor of 2.
      EXPECT_LE(in_window, 2 * *global);
      // It falls: light ground masses are far off; it rises again once round-off dominates.
      EXPECT_GT(error->front(), 1e6 * *global);
      EXPECT_GT(error->back(), 1e3 * *global);
      EXPECT_LT(*global, 1e-8);
    }
  }
}

}  // namespace
}  // namespace rbdc
