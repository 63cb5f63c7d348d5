#include "rbdc_bench/mujoco_state.hpp"

#include <Eigen/Geometry>

namespace rbdc_bench {

namespace {

using RowMatrixX = Eigen::Matrix<double, Eigen::Dynamic, Eigen::Dynamic, Eigen::RowMajor>;

rbdc::Matrix3 trunk_rotation(const rbdc::VectorX& q) {
  return Eigen::Quaterniond(q[3], q[4], q[5], q[6]).normalized().toRotationMatrix();
}

// Our tangent vector x (velocity or acceleration) in MuJoCo's dof order and free-joint convention.
void to_mujoco_tangent(const MujocoRobot& robot, const rbdc::VectorX& q, const rbdc::VectorX& x,
                       mjtNum* out) {
  const rbdc::Model& model = robot.model;
  if (model.floating_base) {
    const int dof = robot.index.dof[0];
    const rbdc::Vector3 linear_world = trunk_rotation(q) * x.segment<3>(3);
    for (int k = 0; k < 3; ++k) {
      out[dof + k] = linear_world[k];
      out[dof + 3 + k] = x[k];
    }
  }
  for (int i = 1; i < model.nb; ++i) {
    const size_t ui = static_cast<size_t>(i);
    out[robot.index.dof[ui]] = x[model.joints[ui].v_index];
  }
}

}  // namespace

MujocoRobot make_mujoco_robot(const rbdc::Model& model) {
  MujocoRobot robot;
  robot.model = model;
  robot.m = rbdc::mjcf::load_mjmodel(model);
  // Rigid-body dynamics only: no contact, limit or equality constraints enter any quantity.
  robot.m->opt.disableflags |= mjDSBL_CONTACT | mjDSBL_CONSTRAINT;
  robot.d.reset(mj_makeData(robot.m.get()));
  robot.index = rbdc::mjcf::index_mjmodel(model, robot.m.get());
  rbdc::mjcf::adopt_mujoco_inertias(robot.model, robot.m.get());
  return robot;
}

void set_mujoco_state(const MujocoRobot& robot, mjData* d, const rbdc::VectorX& q,
                      const rbdc::VectorX* v, const rbdc::VectorX* a) {
  const rbdc::Model& model = robot.model;
  if (model.floating_base) {
    const int adr = robot.index.qpos[0];
    for (int k = 0; k < 7; ++k) d->qpos[adr + k] = q[k];  // position, quaternion (w, x, y, z)
  }
  for (int i = 1; i < model.nb; ++i) {
    const size_t ui = static_cast<size_t>(i);
    d->qpos[robot.index.qpos[ui]] = q[model.joints[ui].q_index];
  }
  if (v) to_mujoco_tangent(robot, q, *v, d->qvel);
  if (a) to_mujoco_tangent(robot, q, *a, d->qacc);
}

rbdc::MatrixX mujoco_velocity_map(const MujocoRobot& robot, const rbdc::VectorX& q) {
  const int nv = robot.model.nv;
  rbdc::MatrixX T(robot.m->nv, nv);
  rbdc::VectorX unit = rbdc::VectorX::Zero(nv);
  rbdc::VectorX column(robot.m->nv);
  for (int j = 0; j < nv; ++j) {
    unit[j] = 1;
    to_mujoco_tangent(robot, q, unit, column.data());
    T.col(j) = column;
    unit[j] = 0;
  }
  return T;
}

rbdc::MatrixX mujoco_mass_matrix(const MujocoRobot& robot, const rbdc::VectorX& q) {
  const mjModel* m = robot.m.get();
  mjData* d = robot.d.get();
  set_mujoco_state(robot, d, q);
  mj_kinematics(m, d);
  mj_comPos(m, d);
  mj_crb(m, d);
  RowMatrixX M_mj(m->nv, m->nv);
  mj_fullM(m, M_mj.data(), d->qM);
  const rbdc::MatrixX T = mujoco_velocity_map(robot, q);
  return T.transpose() * M_mj * T;
}

rbdc::VectorX mujoco_bias(const MujocoRobot& robot, const rbdc::VectorX& q, const rbdc::VectorX& v) {
  const mjModel* m = robot.m.get();
  mjData* d = robot.d.get();
  set_mujoco_state(robot, d, q, &v);
  mj_kinematics(m, d);
  mj_comPos(m, d);
  mj_comVel(m, d);
  rbdc::VectorX bias_mj(m->nv);
  mj_rne(m, d, 0, bias_mj.data());
  return mujoco_velocity_map(robot, q).transpose() * bias_mj;
}

}  // namespace rbdc_bench
