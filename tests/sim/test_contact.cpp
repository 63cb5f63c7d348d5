// Contact model of paper 000 Section 5: detection (Eq. 31), Hertz + ramped damping (Eqs. 34-36),
// smooth stick-slip friction (Eq. 38).
#include <gtest/gtest.h>

#include <cmath>
#include <random>

#include "rbdc/sim/contact.hpp"

using namespace rbdc;
using namespace rbdc::sim;

TEST(Contact, NoForceAboveTheGround) {
  const ContactParameters p;
  const FootContact c = foot_contact(p, GroundPlane(), Vector3(0, 0, p.foot_radius + 1e-6), Vector3(0, 0, -1));
  EXPECT_FALSE(c.active);
  EXPECT_EQ(c.force_W, Vector3::Zero());
  EXPECT_NEAR(c.penetration, 1e-6, 1e-15);
}

TEST(Contact, HertzSpringAtRestMatchesEq34) {
  ContactParameters p;
  const double depth = 0.05e-3;  // 0.05 mm
  const FootContact c = foot_contact(p, GroundPlane(), Vector3(0.3, -0.2, p.foot_radius - depth), Vector3::Zero());
  ASSERT_TRUE(c.active);
  EXPECT_NEAR(c.force_W.z(), p.stiffness * std::pow(depth / p.length_unit, p.exponent), 1e-9);
  EXPECT_NEAR(c.force_W.head<2>().norm(), 0, 1e-12);
}

TEST(Contact, DampingRampsUpOverTheRampDistance) {
  ContactParameters p;
  p.stiffness = 0;  // damping only
  const Vector3 sinking(0, 0, -0.01);
  const double at_surface = foot_contact(p, GroundPlane(), Vector3(0, 0, p.foot_radius - 1e-12), sinking).force_C.z();
  const double half = foot_contact(p, GroundPlane(), Vector3(0, 0, p.foot_radius - p.ramp_distance / 2), sinking).force_C.z();
  const double deep = foot_contact(p, GroundPlane(), Vector3(0, 0, p.foot_radius - 2 * p.ramp_distance), sinking).force_C.z();
  EXPECT_NEAR(at_surface, 0, 1e-9);
  EXPECT_NEAR(half, 0.5 * p.damping * 0.01, 1e-12);  // smoothstep(1/2) = 1/2
  EXPECT_NEAR(deep, p.damping * 0.01, 1e-12);
}

TEST(Contact, FrictionCoefficientIsSmoothOddAndReachesTheTableValues) {
  ContactParameters p;
  p.mu_dynamic = 1.5;  // distinct from μ_s so the static → sliding blend is visible
  EXPECT_DOUBLE_EQ(friction_coefficient(p, 0), 0);
  EXPECT_NEAR(friction_coefficient(p, p.v_static), p.mu_static, 1e-12);
  EXPECT_NEAR(friction_coefficient(p, -p.v_static), -p.mu_static, 1e-12);
  EXPECT_NEAR(friction_coefficient(p, p.v_dynamic), p.mu_dynamic, 1e-12);
  EXPECT_NEAR(friction_coefficient(p, 10.0), p.mu_dynamic, 1e-12);
  EXPECT_NEAR(friction_coefficient(p, -0.3e-4), -friction_coefficient(p, 0.3e-4), 1e-15);
  // Continuous at the joins: no jump across v_s.
  EXPECT_NEAR(friction_coefficient(p, p.v_static * (1 - 1e-9)), friction_coefficient(p, p.v_static * (1 + 1e-9)), 1e-6);
}

// Isotropic friction stays inside the cone |f_t| ≤ μ f_n; Eq. 38 per axis bounds each axis by μ f_n
// (so |f_t| ≤ √2 μ f_n). Both oppose the slip.
class FrictionBound : public ::testing::TestWithParam<FrictionModel> {};

TEST_P(FrictionBound, FrictionStaysWithinItsBoundAndOpposesTheSlip) {
  ContactParameters p;
  p.friction = GetParam();
  p.mu_dynamic = 1.2;
  std::mt19937 rng(5);
  std::uniform_real_distribution<double> unit(-1, 1);
  const GroundPlane tilted(Vector3(0.1, 0, 0), Vector3(0.2, -0.3, 1));
  for (int trial = 0; trial < 10000; ++trial) {
    const Vector3 p_W = tilted.point() + tilted.W_R_C() * Vector3(unit(rng), unit(rng), p.foot_radius - 2e-4 * (unit(rng) + 1));
    const Vector3 v_W = std::pow(10.0, 3 * unit(rng) - 2) * Vector3(unit(rng), unit(rng), unit(rng));
    const FootContact c = foot_contact(p, tilted, p_W, v_W);
    if (!c.active) continue;
    EXPECT_GT(c.force_C.z(), 0);
    const double bound = std::max(p.mu_static, p.mu_dynamic) * c.force_C.z() * (1 + 1e-12);
    if (p.friction == FrictionModel::Isotropic) {
      EXPECT_LE(c.force_C.head<2>().norm(), bound);
    } else {
      EXPECT_LE(c.force_C.head<2>().cwiseAbs().maxCoeff(), bound);
    }
    const Vector3 v_C = tilted.W_R_C().transpose() * v_W;
    EXPECT_LE(c.force_C.head<2>().dot(v_C.head<2>()), 1e-12);
  }
}

INSTANTIATE_TEST_SUITE_P(Contact, FrictionBound,
                         ::testing::Values(FrictionModel::PerAxis, FrictionModel::Isotropic));

TEST(Contact, PerAxisFrictionIsEq38OnEachAxis) {
  ContactParameters p;
  const Vector3 v(0.3e-4, -2e-3, 0);  // x inside the stiction band, y sliding
  const FootContact c = foot_contact(p, GroundPlane(), Vector3(0, 0, p.foot_radius - 0.05e-3), v);
  ASSERT_TRUE(c.active);
  EXPECT_NEAR(c.force_C.x(), -friction_coefficient(p, v.x()) * c.force_C.z(), 1e-12);
  EXPECT_NEAR(c.force_C.y(), p.mu_dynamic * c.force_C.z(), 1e-12);
}

TEST(Contact, ImplicitFrictionSolvesTheBackwardEulerEquation) {
  const ContactParameters p;
  const double f_n = 20, compliance = 1e-4 / 0.01;  // dt / m for a 10 g foot
  for (double u_free : {-1.0, -3e-3, -1e-5, 0.0, 2e-6, 5e-5, 0.04, 2.0}) {
    const double f = implicit_friction(p, u_free, compliance, f_n);
    const double u = u_free + compliance * f;
    // f = −μ(u) f_n up to the solver's velocity tolerance (the slope is 1.5 μ_s f_n / v_s ≈ 6e5 N s/m).
    const double eps = 1e-4 * p.v_static;
    const double f_lo = -friction_coefficient(p, u + eps) * f_n, f_hi = -friction_coefficient(p, u - eps) * f_n;
    EXPECT_GE(f, f_lo - 1e-12) << u_free;
    EXPECT_LE(f, f_hi + 1e-12) << u_free;
    EXPECT_LE(std::abs(f), p.mu_static * f_n * (1 + 1e-12));
    EXPECT_LE(f * u_free, 0);               // opposes the slip
    EXPECT_LE(std::abs(u), std::abs(u_free));  // and never reverses it
  }
  // A force below μ_s f_n that would slip the foot at 1 m/s in one step is held: u ≈ 0.
  const double holding = 1.0 / 30;  // μ_s f_n · holding = 1.33 m/s > 1 m/s
  EXPECT_LT(std::abs(1.0 + holding * implicit_friction(p, 1.0, holding, f_n)), p.v_static);
}

TEST(Contact, StandingMiniCheetahPenetrationPerInterpretation) {
  // 8.252 kg on four feet (docs/simulator.md): δ = (F / K)^(1/e) in the chosen length unit.
  const double foot_load = 8.252 * 9.81 / 4;
  ContactParameters mm;
  const double depth_mm = mm.length_unit * std::pow(foot_load / mm.stiffness, 1 / mm.exponent);
  EXPECT_NEAR(depth_mm, 0.0596e-3, 0.001e-3);
  ContactParameters si = mm;
  si.length_unit = 1;
  const double depth_si = std::pow(foot_load / si.stiffness, 1 / si.exponent);
  EXPECT_NEAR(depth_si, 0.0596, 0.001);
  // And the contact model really balances that load at that depth.
  const FootContact c = foot_contact(mm, GroundPlane(), Vector3(0, 0, mm.foot_radius - depth_mm), Vector3::Zero());
  EXPECT_NEAR(c.force_W.z(), foot_load, 1e-9);
}
