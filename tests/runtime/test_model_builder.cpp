// build_model: topology derivation (paper 000 Eqs. 1-2, κ, μ, ν) and validation of ModelSpec.
#include <gmock/gmock.h>
#include <gtest/gtest.h>

#include <cmath>
#include <limits>

#include "rbdc/model_builder.hpp"

namespace rbdc {
namespace {

using ::testing::AllOf;
using ::testing::HasSubstr;

Body unit_body(const std::string& name) {
  Body b;
  b.name = name;
  b.mass = 1.0;
  b.com = Vector3(0.01, 0.02, -0.1);
  b.inertia_com = Vector3(0.02, 0.03, 0.04).asDiagonal();
  return b;
}

// Quadruped topology of paper 000 Eq. 1: trunk 0, then four legs of three bodies.
ModelSpec quadruped_spec() {
  ModelSpec spec;
  spec.name = "quadruped";
  spec.source = "quadruped.test";
  spec.pred = {0, 1, 2, 0, 4, 5, 0, 7, 8, 0, 10, 11};
  spec.succ = {1, 2, 3, 4, 5, 6, 7, 8, 9, 10, 11, 12};
  spec.bodies.push_back(unit_body("trunk"));
  const char* legs[] = {"LF", "RF", "LH", "RH"};
  const char* links[] = {"abad", "hip", "knee"};
  for (const char* leg : legs) {
    for (int k = 0; k < 3; ++k) {
      const std::string name = std::string(leg) + "_" + links[k];
      spec.bodies.push_back(unit_body(name));
      JointSpec j;
      j.name = name + "_joint";
      j.axis = k == 0 ? Vector3::UnitX() : Vector3::UnitY();
      j.translation = Vector3(0.1, 0.05, -0.2);
      spec.joints.push_back(j);
    }
  }
  spec.feet.push_back({"LF_foot", 3, Vector3(0, -0.004, -0.195)});
  return spec;
}

std::string error_of(const ModelSpec& spec) {
  try {
    build_model(spec);
  } catch (const ModelError& e) {
    return e.what();
  }
  return "no error";
}

TEST(ModelBuilder, QuadrupedTopologyFollowsEquations1And2) {
  const Model m = build_model(quadruped_spec());
  EXPECT_EQ(m.nb, 13);
  EXPECT_EQ(m.nq, 19);
  EXPECT_EQ(m.nv, 18);
  const std::vector<int> lambda = {-1, 0, 1, 2, 0, 4, 5, 0, 7, 8, 0, 10, 11};
  EXPECT_EQ(m.parent, lambda);
  EXPECT_EQ(m.support[0], std::vector<int>{});
  EXPECT_EQ(m.support[6], (std::vector<int>{4, 5, 6}));
  EXPECT_EQ(m.children[0], (std::vector<int>{1, 4, 7, 10}));
  EXPECT_EQ(m.children[12], std::vector<int>{});
  EXPECT_EQ(m.subtree[7], (std::vector<int>{7, 8, 9}));
  EXPECT_EQ(m.subtree[0].size(), 13u);
  EXPECT_EQ(m.joints[0].type, JointType::Floating);
  EXPECT_EQ(m.joints[1].q_index, 7);
  EXPECT_EQ(m.joints[12].q_index, 18);
  EXPECT_EQ(m.joints[12].v_index, 17);
}

TEST(ModelBuilder, FixedBaseIndicesStartAtZero) {
  ModelSpec spec = quadruped_spec();
  spec.floating_base = false;
  const Model m = build_model(spec);
  EXPECT_EQ(m.joints[0].type, JointType::Fixed);
  EXPECT_EQ(m.nq, 12);
  EXPECT_EQ(m.nv, 12);
  EXPECT_EQ(m.joints[1].q_index, 0);
  EXPECT_EQ(m.joints[12].v_index, 11);
}

TEST(ModelBuilder, LambdaIsTheSmallerEndpointWhateverTheJointDirection) {
  ModelSpec spec = quadruped_spec();
  std::swap(spec.pred[4], spec.succ[4]);  // joint 5 written from body 5 to body 4
  EXPECT_EQ(build_model(spec).parent[5], 4);
}

TEST(ModelBuilder, DerivesSpatialConstants) {
  ModelSpec spec = quadruped_spec();
  spec.joints[0].axis = Vector3(0, 0, -2);  // normalized to (0, 0, -1)
  spec.joints[1].type = JointType::Prismatic;
  spec.joints[1].rotation = coordinate_rotation(Vector3(0, 1, 1).normalized(), 0.3);
  const Model m = build_model(spec);
  EXPECT_TRUE(m.joints[1].axis.isApprox(Vector3(0, 0, -1)));
  Vector6 revolute = Vector6::Zero(), prismatic = Vector6::Zero();
  revolute(2) = -1;
  prismatic(4) = 1;
  EXPECT_TRUE(m.motion_subspace[1].isApprox(revolute));
  EXPECT_TRUE(m.motion_subspace[2].isApprox(prismatic));
  EXPECT_TRUE(m.motion_subspace[0].isZero());
  EXPECT_TRUE(m.X_tree[2].isApprox(motion_transform(spec.joints[1].rotation, spec.joints[1].translation)));
  const Body& b = spec.bodies[3];
  EXPECT_TRUE(m.inertia[3].isApprox(spatial_inertia(b.mass, b.com, b.inertia_com)));
}

TEST(ModelBuilder, RefusesMismatchedArraySizes) {
  ModelSpec spec = quadruped_spec();
  spec.succ.pop_back();
  const std::string e = error_of(spec);
  EXPECT_THAT(e, HasSubstr("quadruped.test"));
  EXPECT_THAT(e, HasSubstr("SUCC has 11"));
}

TEST(ModelBuilder, RefusesIrregularNumberingAndCycles) {
  ModelSpec spec = quadruped_spec();
  spec.pred[2] = 5;  // joint 3 from body 5 to body 3: λ(3) would not be < 3
  EXPECT_THAT(error_of(spec), HasSubstr("joint 'LF_knee_joint' (3)"));
  spec = quadruped_spec();
  spec.pred[1] = 2;  // joint 2 joins body 2 to itself
  EXPECT_THAT(error_of(spec), HasSubstr("cycle"));
  spec = quadruped_spec();
  spec.pred[1] = 13;
  EXPECT_THAT(error_of(spec), HasSubstr("out of range"));
}

TEST(ModelBuilder, RefusesBadJointParameters) {
  const double nan = std::numeric_limits<double>::quiet_NaN();
  ModelSpec spec = quadruped_spec();
  spec.joints[4].axis = Vector3::Zero();
  EXPECT_THAT(error_of(spec), HasSubstr("'RF_hip_joint' (5): axis is zero"));
  spec = quadruped_spec();
  spec.joints[4].translation.x() = nan;
  EXPECT_THAT(error_of(spec), HasSubstr("'RF_hip_joint' (5): translation has NaN"));
  spec = quadruped_spec();
  spec.joints[4].rotation(0, 1) = 0.5;
  EXPECT_THAT(error_of(spec), HasSubstr("not a proper orthonormal"));
  spec = quadruped_spec();
  spec.joints[4].rotation = -Matrix3::Identity();
  EXPECT_THAT(error_of(spec), HasSubstr("not a proper orthonormal"));
  spec = quadruped_spec();
  spec.joints[4].type = JointType::Floating;
  EXPECT_THAT(error_of(spec), HasSubstr("only revolute and prismatic"));
}

TEST(ModelBuilder, RefusesBadInertias) {
  ModelSpec spec = quadruped_spec();
  spec.bodies[2].mass = -1;
  EXPECT_THAT(error_of(spec), HasSubstr("body 'LF_hip' (2): mass is negative"));
  spec = quadruped_spec();
  spec.bodies[2].inertia_com(0, 0) = -0.5;
  EXPECT_THAT(error_of(spec), HasSubstr("'LF_hip' (2): rotational inertia is not positive semi-definite"));
  spec = quadruped_spec();
  spec.bodies[2].inertia_com(0, 1) = 0.01;
  EXPECT_THAT(error_of(spec), HasSubstr("'LF_hip' (2): rotational inertia is not symmetric"));
  spec = quadruped_spec();
  spec.bodies[2].com.y() = std::numeric_limits<double>::infinity();
  EXPECT_THAT(error_of(spec), HasSubstr("COM has NaN or Inf"));
}

TEST(ModelBuilder, RepairsInertiaDefectsWithinRoundOffWithAWarning) {
  ModelSpec spec = quadruped_spec();
  const double tr = spec.bodies[2].inertia_com.trace();
  spec.bodies[2].inertia_com(0, 1) = 1e-10 * tr;  // asymmetric by 1e-10 tr: within 1e-9 tr
  spec.bodies[3].inertia_com = Vector3(-5e-12, 0.01, 0.01).asDiagonal();  // within 1e-9 tr + 1e-12
  spec.bodies[4].mass = 0;  // keeps its rotational inertia
  std::vector<std::string> warnings;
  const Model m = build_model(spec, &warnings);
  ASSERT_EQ(warnings.size(), 3u);
  EXPECT_THAT(warnings[0], HasSubstr("'LF_hip' (2): rotational inertia is not symmetric by"));
  EXPECT_THAT(warnings[1], HasSubstr("'LF_knee' (3): rotational inertia has principal moments"));
  EXPECT_THAT(warnings[1], HasSubstr("clipped to zero"));
  EXPECT_THAT(warnings[2], HasSubstr("(4): zero mass but non-zero rotational inertia; kept"));
  EXPECT_EQ(m.bodies[2].inertia_com, m.bodies[2].inertia_com.transpose());
  EXPECT_DOUBLE_EQ(m.bodies[2].inertia_com(0, 1), 0.5e-10 * tr);
  EXPECT_NEAR(m.bodies[3].inertia_com(0, 0), 0.0, 1e-18);
  EXPECT_EQ(m.bodies[4].inertia_com, spec.bodies[4].inertia_com);
  spec.bodies[2].inertia_com(0, 1) = 1e-8 * tr;  // beyond: refused as before
  EXPECT_THAT(error_of(spec), HasSubstr("'LF_hip' (2): rotational inertia is not symmetric"));
}

TEST(ModelBuilder, ChecksCouplings) {
  ModelSpec spec = quadruped_spec();
  spec.couplings = {{5, 2, -1.0, 0.5}};
  const Model m = build_model(spec);
  ASSERT_EQ(m.couplings.size(), 1u);
  EXPECT_EQ(m.couplings[0].leader, 2);
  spec.couplings = {{5, 5, 1.0, 0.0}};
  EXPECT_THAT(error_of(spec), HasSubstr("a joint cannot follow itself"));
  spec.couplings = {{5, 2, 1.0, 0.0}, {5, 3, 1.0, 0.0}};
  EXPECT_THAT(error_of(spec), HasSubstr("the joint is coupled twice"));
  spec.couplings = {{5, 2, 1.0, 0.0}, {2, 3, 1.0, 0.0}};
  EXPECT_THAT(error_of(spec), HasSubstr("which itself follows another joint"));
  spec.couplings = {{5, 13, 1.0, 0.0}};
  EXPECT_THAT(error_of(spec), HasSubstr("joint index out of range"));
  spec.couplings = {{5, 2, std::numeric_limits<double>::quiet_NaN(), 0.0}};
  EXPECT_THAT(error_of(spec), HasSubstr("multiplier or offset is NaN"));
}

// A massless moving leaf loads with a warning and marks M singular (docs/model.md, "Singular mass
// matrix"); the functions that need M⁻¹ refuse such a model (test_singular_mass.cpp).
TEST(ModelBuilder, MarksAMasslessMovingLeafSingular) {
  ModelSpec spec = quadruped_spec();
  spec.bodies[6].mass = 0;
  spec.bodies[6].inertia_com.setZero();
  std::vector<std::string> warnings;
  const Model m = build_model(spec, &warnings);
  EXPECT_THAT(m.singular_mass_matrix, AllOf(HasSubstr("the mass matrix is singular"),
                                            HasSubstr("body 'RF_knee' is a moving leaf with zero mass")));
  ASSERT_FALSE(warnings.empty());
  EXPECT_THAT(warnings.back(), HasSubstr("forward dynamics and OSC refuse it"));
  spec.bodies[5].mass = 0;  // a massless inner body carrying a massive leaf is fine
  spec.bodies[5].inertia_com.setZero();
  spec.bodies[6] = unit_body("RF_knee");
  EXPECT_EQ(build_model(spec).singular_mass_matrix, "");
}

TEST(ModelBuilder, RefusesAFootOnAMissingBody) {
  ModelSpec spec = quadruped_spec();
  spec.feet[0].body = 13;
  EXPECT_THAT(error_of(spec), HasSubstr("foot 'LF_foot': body 13 does not exist"));
}

TEST(ModelBuilder, WarnsOnTriangleInequalityAndTinyMass) {
  ModelSpec spec = quadruped_spec();
  spec.bodies[2].inertia_com = Vector3(0.01, 0.01, 0.03).asDiagonal();  // 0.01 + 0.01 < 0.03
  spec.bodies[9].mass = 1e-6;
  std::vector<std::string> warnings;
  build_model(spec, &warnings);
  ASSERT_EQ(warnings.size(), 2u);
  EXPECT_THAT(warnings[0], HasSubstr("'LF_hip' (2): rotational inertia breaks the triangle inequality"));
  EXPECT_THAT(warnings[1], HasSubstr("'LH_knee' (9): tiny mass"));
}

}  // namespace
}  // namespace rbdc
