// The MuJoCo benchmarks time the same robot as ours: on 64 random states of every benchmark robot,
// MuJoCo's M (mj_crb + mj_fullM) and c + g (mj_rne) agree with the runtime's to 1e-9 (relative to
// the largest entry) once converted to our coordinates (rbdc_bench/mujoco_state.hpp).
#include <gtest/gtest.h>

#include <algorithm>

#include "rbdc/crba.hpp"
#include "rbdc/inverse_dynamics.hpp"
#include "rbdc_bench/mujoco_state.hpp"
#include "rbdc_bench/random_states.hpp"
#include "stress_support.hpp"

namespace rbdc_stress {
namespace {

double relative_gap(const rbdc::MatrixX& x, const rbdc::MatrixX& reference) {
  return (x - reference).cwiseAbs().maxCoeff() / std::max(1.0, reference.cwiseAbs().maxCoeff());
}

class StressMujocoAgreement : public ::testing::TestWithParam<const char*> {};

TEST_P(StressMujocoAgreement, MassMatrixAndBiasAgreeWithTheRuntime) {
  const rbdc_bench::MujocoRobot robot = rbdc_bench::make_mujoco_robot(load_robot(GetParam()));
  rbdc::Data data(robot.model);
  const rbdc::VectorX zero = rbdc::VectorX::Zero(robot.model.nv);
  for (const auto& s : rbdc_bench::random_states(robot.model, 64, 2022)) {
    const rbdc::MatrixX M = rbdc::mass_matrix(robot.model, data, s.q);
    EXPECT_LT(relative_gap(rbdc_bench::mujoco_mass_matrix(robot, s.q), M), 1e-9);
    const rbdc::VectorX bias = rbdc::inverse_dynamics(robot.model, data, s.q, s.v, zero);
    EXPECT_LT(relative_gap(rbdc_bench::mujoco_bias(robot, s.q, s.v), bias), 1e-9);
  }
}

INSTANTIATE_TEST_SUITE_P(BenchRobots, StressMujocoAgreement,
                         ::testing::Values("mini_cheetah", "arm7", "humanoid32"));

}  // namespace
}  // namespace rbdc_stress
