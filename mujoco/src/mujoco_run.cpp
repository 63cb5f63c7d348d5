#include "rbdc/mujoco/mujoco_run.hpp"

#include <algorithm>
#include <chrono>
#include <cmath>
#include <cstdio>

#include "rbdc/sim/orientation.hpp"

namespace rbdc::mujoco {

using sim::FootContact;

void mujoco_state(const Model& model, const mjcf::MujocoIndex& index, const mjData* d, VectorX& q,
                  VectorX& v) {
  // Free joint: qpos = (p_W, quaternion wxyz), qvel = (ṗ_W in world axes, ω in body axes).
  const mjtNum* root_q = d->qpos + index.qpos[0];
  const mjtNum* root_v = d->qvel + index.dof[0];
  q.head<7>() = Eigen::Map<const Eigen::Matrix<double, 7, 1>>(root_q);
  const Matrix3 W_R_0 = sim::rotation_from_quaternion(q.segment<4>(3));
  v.head<3>() = Eigen::Map<const Vector3>(root_v + 3);
  v.segment<3>(3) = W_R_0.transpose() * Eigen::Map<const Vector3>(root_v);
  for (int i = 1; i < model.nb; ++i) {
    q[model.joints[i].q_index] = d->qpos[index.qpos[i]];
    v[model.joints[i].v_index] = d->qvel[index.dof[i]];
  }
}

std::vector<FootContact> mujoco_contacts(const mjModel* m, const mjData* d,
                                         const mjcf::MujocoIndex& index) {
  std::vector<FootContact> contacts(index.foot_geom.size());
  for (int c = 0; c < d->ncon; ++c) {
    const mjContact& con = d->contact[c];
    for (std::size_t k = 0; k < index.foot_geom.size(); ++k) {
      const int geom = index.foot_geom[k];
      if (con.geom1 != geom && con.geom2 != geom) continue;
      mjtNum local[6];
      mj_contactForce(m, d, c, local);
      // contact frame rows: normal (geom1 → geom2), then two tangents; the force acts on geom2.
      const Eigen::Map<const Eigen::Matrix<double, 3, 3, Eigen::RowMajor>> frame(con.frame);
      const Vector3 on_geom2 = frame.transpose() * Vector3(local[0], local[1], local[2]);
      const Vector3 on_foot = con.geom2 == geom ? on_geom2 : Vector3(-on_geom2);
      contacts[k].force_W += on_foot;
      contacts[k].force_C += Vector3(local[1], local[2], local[0]);
      contacts[k].penetration = std::min(contacts[k].penetration, con.dist);
      if (local[0] > 0) contacts[k].active = true;
    }
  }
  return contacts;
}

MujocoRun run_mujoco(const Model& model, const mjModel* m, sim::Controller& controller,
                     const sim::RunOptions& options) {
  using Clock = std::chrono::steady_clock;
  const mjcf::MujocoIndex index = mjcf::index_mjmodel(model, m);
  mjcf::MjDataPtr data(mj_makeData(m));
  mjData* d = data.get();
  const VectorX q0 = controller.initial_configuration();
  for (int j = 0; j < 7; ++j) d->qpos[index.qpos[0] + j] = q0[j];
  for (int i = 1; i < model.nb; ++i) d->qpos[index.qpos[i]] = q0[model.joints[i].q_index];
  mj_forward(m, d);

  VectorX q(model.nq), v(model.nv);
  MujocoRun run;
  const double dt = m->opt.timestep;
  const long steps = std::lround(options.duration / dt);
  const long sample_every =
      options.sample_interval > 0 ? std::max(1L, std::lround(options.sample_interval / dt)) : 0;
  auto sample = [&] {
    mujoco_state(model, index, d, q, v);
    run.trajectory.push_back({d->time, q, v, mujoco_contacts(m, d, index)});
  };
  if (sample_every) sample();
  Matrix3X forces;  // stays empty for controllers that do not read them
  double wall = 0;
  for (long n = 1; n <= steps; ++n) {
    const Clock::time_point start = Clock::now();
    mujoco_state(model, index, d, q, v);
    if (controller.uses_foot_forces()) sim::world_forces(mujoco_contacts(m, d, index), forces);
    const VectorX& tau = controller.update({d->time, dt, q, v, forces});
    for (int i = 1; i < model.nb; ++i) d->ctrl[index.actuator[i]] = tau[i - 1];
    mj_step(m, d);
    wall += std::chrono::duration<double>(Clock::now() - start).count();
    if (sample_every && n % sample_every == 0) sample();
    if (options.progress && n % std::lround(1.0 / dt) == 0)
      std::fprintf(stderr, "  mujoco t = %5.2f s   x = %7.3f m   z = %6.3f m\n", d->time, d->qpos[0], d->qpos[2]);
    run.steps = n;
  }
  run.wall_seconds = wall;
  return run;
}

}  // namespace rbdc::mujoco
