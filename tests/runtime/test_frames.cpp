// Operational frames (rbdc/frames.hpp) against independent routes: placements from the chain of
// homogeneous transforms, J v = the frame velocities, the world-aligned Jacobian against finite
// differences of the placements, J̇v against finite differences of J v along the motion at a = 0;
// the URDF loader's frames of merged links; unknown frame names.
#include <gtest/gtest.h>

#include "rbdc/frames.hpp"
#include "rbdc/kinematics.hpp"
#include "rbdc/topology_file.hpp"
#include "test_robots.hpp"

namespace rbdc {
namespace {

using test::body_poses;
using test::Pose;

/// The robot with one more frame per body, rotated and off the origin, so that models built from
/// arrays (which have no link frames) exercise every term of X_i^F.
Model with_test_frames(Model model) {
  for (int i = 0; i < model.nb; ++i) {
    model.frames.push_back({"test_frame_" + std::to_string(i), i,
                            test::rpy(0.3 * i, -0.2, 0.5 + 0.1 * i).transpose(),
                            Vector3(0.05 * i, -0.02, 0.03)});
  }
  return model;
}

/// ω from two nearby orientations: (R₊ R₋ᵀ − 1)/(2h) ≈ ω̃ in world axes.
Vector3 angular_rate(const Matrix3& plus, const Matrix3& minus, double h) {
  const Matrix3 w = (plus * minus.transpose() - Matrix3::Identity()) / (2 * h);
  return Vector3(w(2, 1) - w(1, 2), w(0, 2) - w(2, 0), w(1, 0) - w(0, 1)) / 2;
}

/// The trunk's classical acceleration of a constant twist v (its linear part ω × v_B): finite
/// differences of J(q(t)) v with v held constant see J̇v plus J times this.
VectorX constant_twist_acceleration(const Model& model, const VectorX& v) {
  VectorX a = VectorX::Zero(model.nv);
  if (model.floating_base) a.segment<3>(3) = v.head<3>().cross(v.segment<3>(3));
  return a;
}

class Frames : public ::testing::TestWithParam<int> {
 protected:
  Model model = with_test_frames(test::all_robots()[static_cast<size_t>(GetParam())]);
  Data data{model};
  test::RandomState random{11u + static_cast<unsigned>(GetParam())};
};

TEST_P(Frames, PlacementsMatchHomogeneousTransforms) {
  for (int trial = 0; trial < 20; ++trial) {
    const VectorX q = random.configuration(model);
    const Matrix3X p = frame_placements(model, data, q);
    const std::vector<Pose> pose = body_poses(model, q);
    for (size_t k = 0; k < model.frames.size(); ++k) {
      const Frame& f = model.frames[k];
      const Pose& body = pose[static_cast<size_t>(f.body)];
      EXPECT_LE((p.col(static_cast<Eigen::Index>(k)) - body * f.translation).norm(), 1e-13) << f.name;
      EXPECT_LE((data.world_R_frame[k] - body.linear() * f.rotation.transpose()).norm(), 1e-13) << f.name;
    }
  }
}

TEST_P(Frames, JacobianTimesVelocityIsTheFrameVelocity) {
  for (int trial = 0; trial < 20; ++trial) {
    const VectorX q = random.configuration(model);
    const VectorX v = random.vector(model.nv, 2.0);
    frame_velocities(model, data, q, v);
    frame_jacobians(model, data, q);
    for (size_t k = 0; k < model.frames.size(); ++k) {
      const Eigen::Index col = static_cast<Eigen::Index>(k);
      const Vector6 local = data.frame_jacobian_local[k] * v;
      const Vector6 world = data.frame_jacobian_world[k] * v;
      EXPECT_LE((local - data.frame_velocity_local.col(col)).norm(), 1e-12 * (1 + local.norm()));
      EXPECT_LE((world - data.frame_velocity_world.col(col)).norm(), 1e-12 * (1 + world.norm()));
      if (model.floating_base || model.frames[k].body != 0) {
        EXPECT_GT(world.norm(), 0.0) << model.frames[k].name;
      }
    }
  }
}

TEST_P(Frames, WorldJacobianMatchesFiniteDifferencesOfPlacements) {
  const double h = 1e-6;
  for (int trial = 0; trial < 5; ++trial) {
    const VectorX q = random.configuration(model);
    const std::vector<Matrix6X> J = frame_jacobians(model, data, q);
    for (int c = 0; c < model.nv; ++c) {
      const VectorX step = h * VectorX::Unit(model.nv, c);
      const Matrix3X p_plus = frame_placements(model, data, test::integrate(model, q, step));
      const std::vector<Matrix3> R_plus = data.world_R_frame;
      const Matrix3X p_minus = frame_placements(model, data, test::integrate(model, q, -step));
      for (size_t k = 0; k < model.frames.size(); ++k) {
        const Eigen::Index col = static_cast<Eigen::Index>(k);
        Vector6 fd;
        fd << angular_rate(R_plus[k], data.world_R_frame[k], h), (p_plus.col(col) - p_minus.col(col)) / (2 * h);
        EXPECT_LE((J[k].col(c) - fd).norm(), 1e-8) << model.frames[k].name << " column " << c;
      }
    }
  }
}

TEST_P(Frames, BiasAccelerationIsTheDerivativeOfJacobianTimesVelocity) {
  const double h = 1e-6;
  for (int trial = 0; trial < 10; ++trial) {
    const VectorX q = random.configuration(model);
    const VectorX v = random.vector(model.nv, 2.0);
    frame_bias_accelerations(model, data, q, v);
    const Matrix6X spatial = data.frame_bias_spatial, classical = data.frame_bias_classical;
    const VectorX a_twist = constant_twist_acceleration(model, v);
    const std::vector<Matrix6X> J_world = frame_jacobians(model, data, q);
    const std::vector<Matrix6X> J_local = data.frame_jacobian_local;
    const std::vector<Matrix6X> world_plus = frame_jacobians(model, data, test::integrate(model, q, h * v));
    const std::vector<Matrix6X> local_plus = data.frame_jacobian_local;
    const std::vector<Matrix6X> world_minus = frame_jacobians(model, data, test::integrate(model, q, -h * v));
    const std::vector<Matrix6X>& local_minus = data.frame_jacobian_local;
    for (size_t k = 0; k < model.frames.size(); ++k) {
      const Eigen::Index col = static_cast<Eigen::Index>(k);
      // d/dt (J v) = J̇v + J a along a constant twist; the a = 0 part is J̇v.
      const Vector6 fd_world = (world_plus[k] - world_minus[k]) * v / (2 * h) - J_world[k] * a_twist;
      const Vector6 fd_local = (local_plus[k] - local_minus[k]) * v / (2 * h) - J_local[k] * a_twist;
      EXPECT_LE((classical.col(col) - fd_world).norm(), 1e-7 * (1 + fd_world.norm())) << model.frames[k].name;
      EXPECT_LE((spatial.col(col) - fd_local).norm(), 1e-7 * (1 + fd_local.norm())) << model.frames[k].name;
    }
  }
}

INSTANTIATE_TEST_SUITE_P(Robots, Frames, ::testing::Range(0, 4));

TEST(FramesFromUrdf, EveryLinkIsAFrameAndMergedLinksKeepTheirPoses) {
  const Model model = test::branched_urdf();
  Data data(model);
  const VectorX q = test::RandomState(3).configuration(model);
  // footA is declared at (0.01, 0, -0.02) in link a_foot, which a fixed joint merged into a_slider.
  const Matrix3X p = frame_placements(model, data, q);
  const int a_foot = frame_index(model, "a_foot");
  const Vector3 via_frame = p.col(a_foot) + data.world_R_frame[static_cast<size_t>(a_foot)] * Vector3(0.01, 0, -0.02);
  EXPECT_LE((via_frame - feet_positions(model, data, q).col(0)).norm(), 1e-13);
  EXPECT_EQ(model.frames[static_cast<size_t>(a_foot)].body, model.feet[0].body);
  EXPECT_FALSE(model.frames[static_cast<size_t>(a_foot)].rotation.isIdentity(1e-9));  // rpy 0.2 0 0.7
  EXPECT_EQ(model.frames[0].name, "base");
  EXPECT_NO_THROW(frame_index(model, "plate"));
}

TEST(FramesFromUrdf, UnknownFrameNamesAreRefusedWithTheirName) {
  const Model model = test::mini_cheetah();
  try {
    frame_index(model, "no_such_frame");
    FAIL() << "no exception";
  } catch (const std::invalid_argument& e) {
    EXPECT_NE(std::string(e.what()).find("no frame 'no_such_frame'"), std::string::npos) << e.what();
  }
}

TEST(FramesArguments, WrongSizesAreRefused) {
  const Model model = test::mini_cheetah();
  Data data(model);
  EXPECT_THROW(frame_jacobians(model, data, VectorX::Zero(3)), std::invalid_argument);
  EXPECT_THROW(frame_bias_accelerations(model, data, VectorX::Zero(model.nq), VectorX::Zero(2)),
               std::invalid_argument);
  const Model other = with_test_frames(model);
  EXPECT_THROW(frame_placements(other, data, VectorX::Zero(model.nq)), std::invalid_argument);
}

}  // namespace
}  // namespace rbdc
