// MuJoCo 2.2.2 on every benchmark robot, for the quantities it offers. Each call starts from the
// state (qpos, qvel, … copied into mjData, as our functions take q and v) and runs the pipeline
// stages the quantity needs. Before any case is added, M and c + g are checked against the runtime
// on this robot (1e-9); a mismatch aborts the MuJoCo benchmarks with the failing figures.
#include <algorithm>
#include <cstdio>
#include <cstdlib>
#include <vector>

#include "rbdc/bias_terms.hpp"
#include "rbdc/crba.hpp"
#include "rbdc/forward_dynamics.hpp"
#include "rbdc/inverse_dynamics.hpp"
#include "rbdc/jacobian.hpp"
#include "rbdc/kinematics.hpp"
#include "rbdc_bench/mujoco_state.hpp"
#include "registry.hpp"
#include "robot_states.hpp"

namespace rbdc_bench {
namespace {

constexpr double kAgreement = 1e-9;

struct MujocoContext {
  MujocoRobot robot;
  int nq = 0, nv = 0, nu = 0;
  std::vector<mjtNum> qpos, qvel, qacc, ctrl, f;  ///< per state, MuJoCo coordinates (f: world)
  std::vector<int> foot_body;                      ///< mjModel body of each foot
  std::vector<mjtNum> out;                         ///< nv × nv, large enough for every result
};

MujocoContext& context(void* p) { return *static_cast<MujocoContext*>(p); }

// Copies state k's qpos (and qvel, qacc, ctrl when asked) into mjData.
void load_state(MujocoContext& c, int k, bool velocity, bool acceleration, bool control) {
  mjData* d = c.robot.d.get();
  const size_t i = static_cast<size_t>(k);
  mju_copy(d->qpos, &c.qpos[i * static_cast<size_t>(c.nq)], c.nq);
  if (velocity) mju_copy(d->qvel, &c.qvel[i * static_cast<size_t>(c.nv)], c.nv);
  if (acceleration) mju_copy(d->qacc, &c.qacc[i * static_cast<size_t>(c.nv)], c.nv);
  if (control) mju_copy(d->ctrl, &c.ctrl[i * static_cast<size_t>(c.nu)], c.nu);
}

void position_stages(const mjModel* m, mjData* d) {
  mj_kinematics(m, d);
  mj_comPos(m, d);
}

void velocity_stages(const mjModel* m, mjData* d) {
  position_stages(m, d);
  mj_comVel(m, d);
}

// Largest |difference| relative to max(1, |reference|) over entries.
double relative_gap(const rbdc::MatrixX& ours, const rbdc::MatrixX& reference) {
  return (ours - reference).cwiseAbs().maxCoeff() / std::max(1.0, reference.cwiseAbs().maxCoeff());
}

// The comparison the issue asks for before timing: M and c + g on 16 random states.
void check_agreement(const LoadedRobot& loaded, const MujocoRobot& robot) {
  rbdc::Data data(robot.model);
  double worst_M = 0, worst_bias = 0;
  const rbdc::VectorX zero = rbdc::VectorX::Zero(robot.model.nv);
  for (int k = 0; k < 16; ++k) {
    const State& s = loaded.states[static_cast<size_t>(k)];
    const rbdc::MatrixX M = rbdc::mass_matrix(robot.model, data, s.q);
    worst_M = std::max(worst_M, relative_gap(mujoco_mass_matrix(robot, s.q), M));
    const rbdc::VectorX bias = rbdc::inverse_dynamics(robot.model, data, s.q, s.v, zero);
    worst_bias = std::max(worst_bias, relative_gap(mujoco_bias(robot, s.q, s.v), bias));
  }
  if (worst_M > kAgreement || worst_bias > kAgreement) {
    std::fprintf(stderr,
                 "rbdc-bench: MuJoCo disagrees with the runtime on %s (M: %.3g, c+g: %.3g relative, "
                 "limit %.0e); the MuJoCo benchmarks would not time the same robot. Aborting.\n",
                 loaded.robot.name.c_str(), worst_M, worst_bias, kAgreement);
    std::exit(3);
  }
}

std::shared_ptr<MujocoContext> make_context(const LoadedRobot& loaded) {
  auto c = std::make_shared<MujocoContext>();
  c->robot = make_mujoco_robot(loaded.model);
  check_agreement(loaded, c->robot);
  const mjModel* m = c->robot.m.get();
  mjData* d = c->robot.d.get();
  c->nq = m->nq;
  c->nv = m->nv;
  c->nu = m->nu;
  const rbdc::Model& model = c->robot.model;
  for (const State& s : loaded.states) {
    set_mujoco_state(c->robot, d, s.q, &s.v, &s.a);
    c->qpos.insert(c->qpos.end(), d->qpos, d->qpos + m->nq);
    c->qvel.insert(c->qvel.end(), d->qvel, d->qvel + m->nv);
    c->qacc.insert(c->qacc.end(), d->qacc, d->qacc + m->nv);
    std::vector<mjtNum> ctrl(static_cast<size_t>(m->nu), 0.0);
    for (int i = 1; i < model.nb; ++i) {
      const int actuator = c->robot.index.actuator[static_cast<size_t>(i)];
      if (actuator >= 0) ctrl[static_cast<size_t>(actuator)] = s.tau[i - 1];
    }
    c->ctrl.insert(c->ctrl.end(), ctrl.begin(), ctrl.end());
    c->f.insert(c->f.end(), s.f.data(), s.f.data() + s.f.size());
  }
  for (int geom : c->robot.index.foot_geom) c->foot_body.push_back(m->geom_bodyid[geom]);
  c->out.assign(static_cast<size_t>(m->nv) * static_cast<size_t>(std::max(m->nv, 3)), 0.0);
  return c;
}

void provide() {
  for_each_loaded_robot("mujoco", [](const LoadedRobot& loaded) {
    auto ctx = make_context(loaded);
    auto add = [&](const char* quantity, CallFn call) {
      add_case(loaded.robot.name, quantity, "mujoco", ctx, call);
    };
    add("kinematics", [](void* p, int k) {  // mj_kinematics + mj_comPos + mj_comVel
      MujocoContext& c = context(p);
      load_state(c, k, true, false, false);
      velocity_stages(c.robot.m.get(), c.robot.d.get());
    });
    add("feet_positions_jacobian", [](void* p, int k) {  // mj_jac at every foot point
      MujocoContext& c = context(p);
      const mjModel* m = c.robot.m.get();
      mjData* d = c.robot.d.get();
      load_state(c, k, false, false, false);
      position_stages(m, d);
      for (size_t j = 0; j < c.foot_body.size(); ++j) {
        const int geom = c.robot.index.foot_geom[j];
        mj_jac(m, d, c.out.data(), nullptr, d->geom_xpos + 3 * geom, c.foot_body[j]);
      }
    });
    add("bias", [](void* p, int k) {  // mj_rne without acceleration: c + g
      MujocoContext& c = context(p);
      load_state(c, k, true, false, false);
      velocity_stages(c.robot.m.get(), c.robot.d.get());
      mj_rne(c.robot.m.get(), c.robot.d.get(), 0, c.out.data());
    });
    add("inverse_dynamics", [](void* p, int k) {  // mj_rne with acceleration: M a + c + g
      MujocoContext& c = context(p);
      load_state(c, k, true, true, false);
      velocity_stages(c.robot.m.get(), c.robot.d.get());
      mj_rne(c.robot.m.get(), c.robot.d.get(), 1, c.out.data());
    });
    add("mass_matrix", [](void* p, int k) {  // mj_crb + mj_fullM
      MujocoContext& c = context(p);
      load_state(c, k, false, false, false);
      position_stages(c.robot.m.get(), c.robot.d.get());
      mj_crb(c.robot.m.get(), c.robot.d.get());
      mj_fullM(c.robot.m.get(), c.out.data(), c.robot.d->qM);
    });
    add("forward_dynamics", [](void* p, int k) {  // smooth dynamics with τ and foot forces
      MujocoContext& c = context(p);
      const mjModel* m = c.robot.m.get();
      mjData* d = c.robot.d.get();
      load_state(c, k, true, false, true);
      mj_fwdPosition(m, d);
      mj_fwdVelocity(m, d);
      mju_zero(d->qfrc_applied, m->nv);
      const mjtNum* f = &c.f[static_cast<size_t>(k) * 3 * c.foot_body.size()];
      const mjtNum no_torque[3] = {0, 0, 0};
      for (size_t j = 0; j < c.foot_body.size(); ++j) {
        const int geom = c.robot.index.foot_geom[j];
        mj_applyFT(m, d, f + 3 * j, no_torque, d->geom_xpos + 3 * geom, c.foot_body[j],
                   d->qfrc_applied);
      }
      mj_fwdActuation(m, d);
      mj_fwdAcceleration(m, d);
    });
  });
}

const bool registered = register_provider(provide);

}  // namespace
}  // namespace rbdc_bench
