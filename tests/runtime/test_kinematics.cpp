// Kinematics (Alg. 1, Eqs. 14-18, 37) and the feet Jacobian (Alg. 6) against independent routes:
// a chain of 4x4 homogeneous transforms, finite differences of foot positions, J v, and finite
// differences of J v along the motion.
#include <gtest/gtest.h>

#include "rbdc/jacobian.hpp"
#include "rbdc/kinematics.hpp"
#include "test_robots.hpp"

namespace rbdc {
namespace {

using test::body_poses;
using test::Pose;

class Kinematics : public ::testing::TestWithParam<int> {
 protected:
  Model model = test::all_robots()[static_cast<size_t>(GetParam())];
  Data data{model};
  test::RandomState random{7u + static_cast<unsigned>(GetParam())};
};

TEST_P(Kinematics, FeetPositionsAndOrientationsMatchHomogeneousTransforms) {
  for (int trial = 0; trial < 50; ++trial) {
    const VectorX q = random.configuration(model);
    const Matrix3X p = feet_positions(model, data, q);
    const std::vector<Pose> pose = body_poses(model, q);
    for (size_t k = 0; k < model.feet.size(); ++k) {
      const Pose& body = pose[static_cast<size_t>(model.feet[k].body)];
      EXPECT_LE((p.col(static_cast<Eigen::Index>(k)) - body * model.feet[k].offset).norm(), 1e-13);
      EXPECT_LE((data.world_R_foot[k] - body.linear()).norm(), 1e-13);
    }
    for (int i = 0; i < model.nb; ++i) {  // Eq. 15: X_W^i from R_W^i and the body origin
      const Pose& body = pose[static_cast<size_t>(i)];
      const Matrix6 expected = motion_transform(body.linear().transpose(), body.translation());
      EXPECT_LE((data.X_world[static_cast<size_t>(i)] - expected).norm(), 1e-12) << "body " << i;
    }
  }
}

TEST_P(Kinematics, JacobianMatchesFiniteDifferencesOfFeetPositions) {
  const double h = 1e-6;
  for (int trial = 0; trial < 20; ++trial) {
    const VectorX q = random.configuration(model);
    const MatrixX J = feet_jacobian(model, data, q);
    for (int k = 0; k < model.nv; ++k) {
      const VectorX step = h * VectorX::Unit(model.nv, k);
      const Matrix3X plus = feet_positions(model, data, test::integrate(model, q, step));
      const Matrix3X minus = feet_positions(model, data, test::integrate(model, q, -step));
      const Matrix3X column = (plus - minus) / (2 * h);
      const VectorX fd = Eigen::Map<const VectorX>(column.data(), column.size());
      EXPECT_LE((J.col(k) - fd).norm(), 1e-8) << "column " << k;
    }
  }
}

TEST_P(Kinematics, FeetVelocitiesEqualJacobianTimesVelocity) {
  for (int trial = 0; trial < 50; ++trial) {
    const VectorX q = random.configuration(model);
    const VectorX v = random.vector(model.nv, 2.0);
    const Matrix3X pdot = feet_velocities(model, data, q, v);
    const VectorX Jv = feet_jacobian(model, data, q) * v;
    EXPECT_LE((Eigen::Map<const VectorX>(pdot.data(), pdot.size()) - Jv).norm(), 1e-12 * (1 + Jv.norm()));
  }
}

TEST_P(Kinematics, BiasAccelerationIsTheDerivativeOfJacobianTimesVelocity) {
  const double h = 1e-6;
  for (int trial = 0; trial < 20; ++trial) {
    const VectorX q = random.configuration(model);
    const VectorX v = random.vector(model.nv, 2.0);
    const Matrix3X Jdot_v = feet_bias_accelerations(model, data, q, v);
    // d/dt (J(q(t)) v) along q̇ given by v with v held constant. A constant trunk twist is not
    // a = 0: its classical linear acceleration is ω × v, which J maps as J·(0, ω × v, 0).
    const VectorX plus = feet_jacobian(model, data, test::integrate(model, q, h * v)) * v;
    const VectorX minus = feet_jacobian(model, data, test::integrate(model, q, -h * v)) * v;
    VectorX a_of_constant_twist = VectorX::Zero(model.nv);
    if (model.floating_base) a_of_constant_twist.segment<3>(3) = v.head<3>().cross(v.segment<3>(3));
    const VectorX fd = (plus - minus) / (2 * h) -
                       feet_jacobian(model, data, q) * a_of_constant_twist;
    EXPECT_LE((Eigen::Map<const VectorX>(Jdot_v.data(), Jdot_v.size()) - fd).norm(), 1e-7 * (1 + fd.norm()));
  }
}

TEST_P(Kinematics, ContactFrameJacobianRotatesEachBlockRow) {
  const VectorX q = random.configuration(model);
  std::vector<Matrix3> world_R_contact;
  for (size_t k = 0; k < model.feet.size(); ++k) world_R_contact.push_back(test::rpy(0.3 * k, -0.2, 1.0));
  const MatrixX Jc = feet_jacobian_contact(model, data, q, world_R_contact);
  const MatrixX J = feet_jacobian(model, data, q);
  for (size_t k = 0; k < model.feet.size(); ++k) {
    const Eigen::Index row = 3 * static_cast<Eigen::Index>(k);
    // world_R_contact · J_C,k must give back the world rows.
    EXPECT_LE((world_R_contact[k] * Jc.middleRows(row, 3) - J.middleRows(row, 3)).norm(), 1e-13);
  }
  EXPECT_GT((Jc - J).norm(), 1e-3);  // the rotation did something
}

TEST(KinematicsArguments, WrongSizesAreRefusedWithTheArgumentName) {
  const Model model = test::quadruped();
  Data data(model);
  try {
    kinematics(model, data, VectorX::Zero(model.nq - 1));
    FAIL() << "no exception";
  } catch (const std::invalid_argument& e) {
    EXPECT_NE(std::string(e.what()).find("kinematics: q has 18 entries, expected 19"), std::string::npos)
        << e.what();
  }
  EXPECT_THROW(feet_velocities(model, data, VectorX::Zero(model.nq), VectorX::Zero(3)), std::invalid_argument);
  const Model other = test::arm7();
  EXPECT_THROW(feet_positions(other, data, VectorX::Zero(other.nq)), std::invalid_argument);
}

INSTANTIATE_TEST_SUITE_P(Robots, Kinematics, ::testing::Range(0, 4));

}  // namespace
}  // namespace rbdc
