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

TEST(Contact, FrictionNeverExceedsMuTimesNormalForce) {
  ContactParameters p;
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
    EXPECT_LE(c.force_C.head<2>().norm(), std::max(p.mu_static, p.mu_dynamic) * c.force_C.z() * (1 + 1e-12));
    // Friction opposes the slip.
    const Vector3 v_C = tilted.W_R_C().transpose() * v_W;
    EXPECT_LE(c.force_C.head<2>().dot(v_C.head<2>()), 1e-12);
  }
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
