// The MJCF writer: MuJoCo compiles the same robot (masses, frames, feet) as our model.
#include <gtest/gtest.h>

#include <random>

#include <Eigen/Eigenvalues>

#include "rbdc/actuator_mode.hpp"
#include "rbdc/control/drive_train.hpp"
#include "rbdc/kinematics.hpp"
#include "rbdc/mjcf/mjcf_writer.hpp"
#include "rbdc/sim/robot.hpp"

using namespace rbdc;
using namespace rbdc::mjcf;

TEST(Mjcf, RefusedWithoutBalanceInertiaNamingTheThigh) {
  const Model model = sim::load_robot(sim::default_urdf());
  MjcfOptions options;
  options.balance_inertia = false;
  try {
    load_mjmodel(model, options);
    FAIL() << "MuJoCo accepted MIT's thigh inertia";
  } catch (const std::runtime_error& e) {
    EXPECT_NE(std::string(e.what()).find("_hip"), std::string::npos) << e.what();
  }
}

TEST(Mjcf, SameMassesAndFeetPositions) {
  const Model model = sim::load_robot(sim::default_urdf());
  const MjModelPtr m = load_mjmodel(model);
  const MujocoIndex index = index_mjmodel(model, m.get());
  EXPECT_EQ(m->nq, model.nq);
  EXPECT_EQ(m->nv, model.nv);
  EXPECT_EQ(m->nu, model.nv - 6);
  EXPECT_EQ(m->opt.integrator, mjINT_IMPLICIT);
  for (int i = 0; i < model.nb; ++i) EXPECT_DOUBLE_EQ(m->body_mass[index.body[i]], model.bodies[i].mass);

  MjDataPtr d(mj_makeData(m.get()));
  Data data(model);
  std::mt19937 rng(3);
  std::uniform_real_distribution<double> angle(-1.5, 1.5);
  VectorX q = VectorX::Zero(model.nq);
  q.head<3>() << 0.3, -0.1, 0.4;
  q.segment<4>(3) = Eigen::Vector4d(0.9, 0.1, -0.3, 0.2).normalized();
  for (int j = 7; j < model.nq; ++j) q[j] = angle(rng);
  for (int j = 0; j < 7; ++j) d->qpos[index.qpos[0] + j] = q[j];
  for (int i = 1; i < model.nb; ++i) d->qpos[index.qpos[i]] = q[model.joints[i].q_index];
  mj_kinematics(m.get(), d.get());
  const Matrix3X& feet = feet_positions(model, data, q);
  for (std::size_t k = 0; k < model.feet.size(); ++k) {
    const Vector3 mujoco_foot = Eigen::Map<const Vector3>(d->geom_xpos + 3 * index.foot_geom[k]);
    EXPECT_LT((mujoco_foot - feet.col(k)).norm(), 1e-12) << model.feet[k].name;
  }
}

TEST(Mjcf, AdoptedInertiasAreMujocosAndOnlyTheThighsMoved) {
  Model model = sim::load_robot(sim::default_urdf());
  const MjModelPtr m = load_mjmodel(model);
  const std::vector<InertiaChange> changes = adopt_mujoco_inertias(model, m.get());
  ASSERT_EQ(changes.size(), 4u);
  for (const InertiaChange& c : changes) {
    EXPECT_NE(c.body.find("_hip"), std::string::npos);
    EXPECT_GT(c.relative_change, 0.1);
    // Balanced: each principal moment at most the sum of the other two.
    const Vector3 moments = Eigen::SelfAdjointEigenSolver<Matrix3>(c.after).eigenvalues();
    EXPECT_LE(moments[2], moments[0] + moments[1] + 1e-12);
  }
}

// Issue 14: MuJoCo gets the drive train as armature (its dof_armature, added to M's diagonal); a
// model with rotor bodies is refused, naming the reduction to use.
TEST(Mjcf, ArmatureIsWrittenAndRotorsAreRefused) {
  const Model full = control::load_trot_robot("", ActuatorMode::Full);
  try {
    write_mjcf(full);
    FAIL() << "rotors written to MJCF";
  } catch (const std::invalid_argument& e) {
    EXPECT_NE(std::string(e.what()).find("ActuatorMode::Armature"), std::string::npos) << e.what();
  }
  const Model armature = with_actuator_mode(full, ActuatorMode::Armature);
  const MjModelPtr m = load_mjmodel(armature);
  for (int i = 1; i < armature.nb; ++i) {
    const int dof = m->jnt_dofadr[mj_name2id(m.get(), mjOBJ_JOINT, armature.joints[i].name.c_str())];
    EXPECT_NEAR(m->dof_armature[dof], armature.joints[i].armature, 1e-12 * armature.joints[i].armature)
        << armature.joints[i].name;
    EXPECT_GT(armature.joints[i].armature, 0.002);
  }
}
